/* aero: real-time vortex sound from a vortex texture Q(u, t) (Dobashi et al.
 * 2004, section 6), the core of [vortex~].
 *
 * n source volumes, each with an average flow speed u_i and a position;
 * the listener (mono) or two ears (stereo) hear
 *     p(t) = SUM_i Q(u_i, t - r_i / c0) / r_i          (1/r: Howe 2003;
 * the paper's 1/r^3 of eq. 5 is its misprinted eq. 1). Details:
 *  - u_i = |speed inlet| + the source's own speed (`speeds`); Q is
 *    interpolated linearly between the stored speeds, clamped at the
 *    largest (as the paper truncates u at U), and below the smallest it
 *    is the smallest's channel scaled by (u / u_1)^4 (the quadrupole law,
 *    pressure ~ u^4), so silence at u = 0;
 *  - each source reads the looped texture from its own random offset
 *    (seeded), so n equal sources add in power (+10 log10 n dB), not in
 *    amplitude;
 *  - the retarded time t - r_i/c0 is a fractional read position (4-point
 *    cubic interpolation) that advances at (1 - v_l/c0) / (1 + v_s/c0)
 *    frames per frame, v_s and v_l the rates at which the source's and
 *    the listener's own motion change r (the exact Doppler factor of a
 *    source moving through still air, heard by a moving listener);
 *  - the texture is a seamless loop (aerotex cross-fades its ends), read
 *    modulo its length;
 *  - `falloff 3` renders the paper's 1/r^3 (Dobashi et al. 2004, eq. 5)
 *    instead of the far field's 1/r (the default);
 *  - combustion noise (combustion_noise.h), off until a `power` is set:
 *    one monopole of the flame's unsteady heat release at the mean of the
 *    volumes' positions, its gas speed the mean of their speeds u_i;
 *  - `clip` limits |p| at the microphone (the paper's treatment of
 *    explosions), then `gain` scales the result.
 * Speeds, positions, the listener and the gain glide linearly over
 * `ramp` ms.
 *
 * Life cycle: init, set_*, process, free. No globals; no allocation in
 * process (set_count and set_texture allocate). */
#ifndef AERO_VORTEX_H
#define AERO_VORTEX_H

#include "aero_ears.h"
#include "aero_ranges.h"
#include "combustion_noise.h"
#include "texture.h"

#include <stddef.h>
#include <stdint.h>

#define AERO_VORTEX_MIN_SOURCES 1
#define AERO_VORTEX_MAX_SOURCES 4096
/* its own gain range reaches higher than AERO_GAIN_DB_MAX (aero_ranges.h),
   the microphone limit, Pa */
#define AERO_VORTEX_GAIN_DB_MAX 200.0
#define AERO_VORTEX_CLIP_MIN 0.0 /* 0: off */
#define AERO_VORTEX_CLIP_MAX 1e6
/* the falloff exponent: 1 (p ~ 1/r) or 3 (1/r^3), nothing between */
#define AERO_VORTEX_FALLOFF_MIN 1
#define AERO_VORTEX_FALLOFF_MAX 3
/* source speeds, m/s: up to Mach 0.3 */
#define AERO_VORTEX_SPEED_MIN 0.0
#define AERO_VORTEX_SPEED_MAX (AERO_MACH_LIMIT * AERO_C0)
/* defaults (gain and ramp: aero_ranges.h; combustion noise:
   combustion_noise.h) */
#define AERO_VORTEX_SOURCES_DEFAULT 1
#define AERO_VORTEX_CLIP_DEFAULT 0.0 /* off */
#define AERO_VORTEX_FALLOFF_DEFAULT 1 /* p ~ 1/r */

typedef struct aero_vortex {
    double sample_rate;
    int stereo;
    uint32_t rng;
    double gain, gain_target;   /* linear, glides like the others */
    double clip;                /* Pa; 0 = off */
    double ramp_samples, ramp_left;
    int started;      /* a block was made: geometry glides from then on */
    double r_min;               /* distances below are clamped, m */
    int falloff;                /* 1: p ~ 1/r (default), 3: the paper's 1/r^3 */
    aero_combustion combustion; /* the flame's roar (power 0: off) */

    /* texture, channel-major, each channel padded by one frame before and
       three after (wrapped) for the cubic read */
    aero_texture *texture;
    float *tab;
    int frames, nspeeds;
    double *speeds;             /* points into the texture */
    double rate;

    /* sources */
    int n;
    double *pos;                /* texture read position, frames */
    double *speed, *speed_target;
    double *xyz, *xyz_target;   /* 3 n */
    double *dist;               /* 2 n: distance to each ear at the end of
                                   the last block (<0: not yet known) */
    double *rd;                 /* 2 n: read position for each ear, frames */
    double ear[6], ear_target[6]; /* mono uses ear 0 */
    aero_near near;             /* a listener came within r_min */
} aero_vortex;

/* n_ears 1 (the listener) or 2 (the ears). Defaults: the
   AERO_VORTEX_*_DEFAULT above (1 source, at the origin, no clip, 1/r),
   gain and ramp from aero_ranges.h, listener at (0, 1, 0), ears at
   x = -+AERO_EAR_HALF_SPACING from it, no texture (silence). 0, or -1
   when out of memory (silent then: no sources) or the sample rate is not
   usable (AERO_SAMPLE_RATE_FALLBACK is taken). */
int aero_vortex_init(aero_vortex *m, double sample_rate, int n_ears,
                     uint32_t seed);
void aero_vortex_free(aero_vortex *m);

/* Setters: 0 when accepted, -1 when invalid (the old value stays). */
int aero_vortex_set_sample_rate(aero_vortex *m, double sr);
/* number of source volumes 1..AERO_VORTEX_MAX_SOURCES (allocates; new
   sources start at the origin, speed 0, with fresh random offsets) */
int aero_vortex_set_count(aero_vortex *m, int n);
static inline int aero_vortex_count(const aero_vortex *m)
{
    return m->n;
}
/* per-source speeds (m/s, >= 0), count values for sources 0..count-1 */
int aero_vortex_set_speeds(aero_vortex *m, const double *u,
                           int count);
/* per-source positions x y z (m), count sources */
int aero_vortex_set_positions(aero_vortex *m,
                              const double *xyz, int count);
/* one listener (both ears there) or two ears */
int aero_vortex_set_ears(aero_vortex *m, const aero_ears *e);
int aero_vortex_set_gain_db(aero_vortex *m, double db);
/* microphone limit, Pa (0: off) */
int aero_vortex_set_clip(aero_vortex *m, double pa);
int aero_vortex_set_ramp_ms(aero_vortex *m, double ms);
/* 1 (1/r, the far field) or 3 (the paper's 1/r^3) */
int aero_vortex_set_falloff(aero_vortex *m, int exponent);
/* the combustion noise (combustion_noise.h, its ranges): the flame's
   mean heat release (kW, 0: off), length (m), Strouhal number and
   fluctuation (0..1); 0, or -1 when out of range */
int aero_vortex_set_power_kw(aero_vortex *m, double kw);
int aero_vortex_set_flame_length(aero_vortex *m, double l);
int aero_vortex_set_strouhal(aero_vortex *m, double st);
int aero_vortex_set_fluctuation(aero_vortex *m, double eps);
/* new random texture offsets from this seed (any seed: 0) */
int aero_vortex_set_seed(aero_vortex *m, uint32_t seed);
/* takes ownership of a loaded kind=vortex texture (returns -1 and frees
   nothing when it is not usable); NULL: silence */
int aero_vortex_set_texture(aero_vortex *m, aero_texture *t,
                            char *err, size_t errlen);

/* n samples; speed in m/s (NaN -> 0, |u| clamped at Mach 0.3; may be
   NULL: 0); out[0] (and out[1] in stereo) in Pa. Returns 1 if a speed was
   clamped. The outputs may alias the speed input. */
int aero_vortex_process(aero_vortex *m, const float *speed,
                        float *const *out, int n);

#endif
