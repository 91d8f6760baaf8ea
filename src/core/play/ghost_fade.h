/* aero: the ghosts of a texture player that jumped or changed its texture
 * while sounding ([aeolian~]'s texture mode, [body~]). Cutting the sources
 * steps the sound, so they stay where they were as ghosts whose velocity
 * falls to 0 over AERO_GHOST_FADE_S on a half cosine, smooth where it
 * begins and where it ends, as a stopped stream's velocity falls
 * (pose_glide.h, then AERO_VELOCITY_TAU_S): each ghost's rate follows the
 * velocity and its amplitude the velocity to the player's exponent, while
 * the sources at the new place fade in as the ghosts fade out. After a
 * texture change the ghosts go on moving and only fade. No globals. */
#ifndef AERO_GHOST_FADE_H
#define AERO_GHOST_FADE_H

#include <math.h>

#include "aero_air.h"
#include "aero_ears.h"

#define AERO_VELOCITY_TAU_S 0.008 /* smoothing of pose-derived velocities */
#define AERO_GHOST_FADE_S (4.0 * AERO_VELOCITY_TAU_S)

/* a source's fade as a ghost: its amplitude and rate when it began to
   fade, the samples since, and its delays' rates then */
typedef struct aero_ghost {
    double amp, inc, samples;
    double rate[AERO_EARS_MAX];
} aero_ghost;

/* the rate of a ghost's delay when it began to fade, from its arrival
   step (samples of delay per sample; 0 before the first chunk) */
static inline double aero_ghost_rate(double step)
{
    return step > 0.0 ? step - 1.0 : 0.0;
}

/* a source becomes a ghost: amplitude, texture rate and each ear's arrival
   step as they were */
static inline void aero_ghost_begin(aero_ghost *g, double amp, double inc,
                                    const double step[AERO_EARS_MAX])
{
    g->amp = amp;
    g->inc = inc;
    g->samples = 0.0;
    for (int e = 0; e < AERO_EARS_MAX; e++)
        g->rate[e] = aero_ghost_rate(step[e]);
}

/* the velocity's fraction t samples after the jump, span samples of fade */
static inline double aero_ghost_velocity(double t, double span)
{
    return t < span ? 0.5 + 0.5 * cos(AERO_PI * t / span) : 0.0;
}

/* the ghosts' amplitude factor t samples after the jump: the velocity's
   fraction to the exponent */
static inline double aero_ghost_fade(double t, double sample_rate,
                                     double exponent)
{
    double span = AERO_GHOST_FADE_S * sample_rate;
    if (!(t < span))
        return 0.0;
    return pow(0.5 + 0.5 * cos(AERO_PI * t / span), exponent);
}

/* the sources' amplitude factor at the end of the next m samples, *fade_in
   samples after the jump (HUGE_VAL: none): they fade in as the ghosts fade
   out (a body in a wind sounds at once at its new place) */
static inline double aero_ghost_fade_in(double *fade_in, int m,
                                        double sample_rate, double exponent)
{
    if (!(*fade_in < AERO_GHOST_FADE_S * sample_rate))
        return 1.0;
    *fade_in += m;
    return 1.0 - aero_ghost_fade(*fade_in, sample_rate, exponent);
}

/* a ghost's next m samples (*samples since the jump, advanced here): its
   velocity's fraction at their start and end, both 1 for a ghost that
   moves on (a texture change) */
static inline void aero_ghost_advance(double *samples, int m, double span,
                                      int moving, double *v_then, double *v)
{
    *v_then = aero_ghost_velocity(*samples, span);
    *samples += m;
    *v = aero_ghost_velocity(*samples, span);
    if (moving)
        *v = *v_then = 1.0;
}

#endif
