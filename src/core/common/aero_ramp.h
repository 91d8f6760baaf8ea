/* aero: the one linear ramp of the real-time players' controls.
 *
 * The glide is block-size-free: a block of n samples goes the fraction
 * n / (samples left) of the way, so the values arrive exactly when the
 * ramp time is over whatever the block sizes (aeolian's model mode,
 * cavity, vortex, fieldsound, and the ears of leafwave and treebranch,
 * move several values on one count).
 * aero_ramp is one value on that glide, advanced in whole chunks of a
 * fixed size (moving_player: body.c; aeolian's texture mode glides
 * the same way, its targets read from the object): a ramp of
 * ramp_samples takes ceil(ramp_samples / chunk) chunks and lands on its
 * target at the last. */
#ifndef AERO_RAMP_H
#define AERO_RAMP_H

#include <math.h>
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

/* one value gliding to its target in whole chunks of samples */
typedef struct {
    double value, target;
    double left;   /* samples of the glide to go, whole chunks */
    int chunk;     /* samples per advance */
} aero_ramp;

static inline void aero_ramp_jump(aero_ramp *r, double v)
{
    r->value = r->target = v;
    r->left = 0.0;
}

/* reaches v after ~ramp_samples, in whole chunks of `chunk` samples */
static inline void aero_ramp_to(aero_ramp *r, double v, double ramp_samples,
                                int chunk)
{
    double chunks = ceil(ramp_samples / chunk);
    r->target = v;
    r->chunk = chunk;
    if (!(chunks >= 1.0)) {
        aero_ramp_jump(r, v);
        return;
    }
    r->left = chunks * chunk;
}

/* the value after one more chunk */
static inline double aero_ramp_advance(aero_ramp *r)
{
    if (r->left > 0.0)
        aero_glide_values(&r->value, &r->target, 1,
                          aero_glide_fraction(&r->left, r->chunk));
    return r->value;
}

#endif
