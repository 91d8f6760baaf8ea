/* aero: the linear glide of controls that move over the ramp time in
 * blocks of any size (aeolian_model, cavity_model, vortex_player,
 * field_render): each block goes the fraction n / (samples left) of the
 * way, so the values arrive exactly when the ramp time is over whatever
 * the block sizes. aero_ramp (aero_util.h) is its sibling for players that
 * update in whole chunks of a fixed size. */
#ifndef AERO_GLIDE_H
#define AERO_GLIDE_H

#include <string.h>

/* the fraction of the way a block of n samples goes, with *left samples
   of the glide to go (counted down here); 1 once there */
static inline double aero_glide_fraction(double *left, int n)
{
    double f = *left > 0.0 ? (n >= *left ? 1.0 : n / *left) : 1.0;
    *left = *left > n ? *left - n : 0.0;
    return f;
}

/* count values moved the fraction f of the way to their targets (f 1:
   the targets themselves) */
static inline void aero_glide_values(double *v, const double *target,
                                     int count, double f)
{
    if (f >= 1.0) {
        memcpy(v, target, sizeof(double) * (size_t)count);
        return;
    }
    for (int k = 0; k < count; k++)
        v[k] += (target[k] - v[k]) * f;
}

#endif
