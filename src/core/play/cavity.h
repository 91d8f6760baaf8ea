/* aero: cavity tones (a draft through a gap, wind over a hollow, a bottle).
 *
 * A rectangular cavity of length L (along the flow), depth D and width W in
 * a wall, grazed by a flow of speed U (a signal). Two modes:
 *
 * Model mode. The shear layer over the opening locks onto the Rossiter
 * modes (Rossiter 1964, with Heller's compressibility form)
 *     f_m = (U / L) (m - alpha) / (M + 1/kappa),  alpha 0.25, kappa 0.57,
 * m = 1..4, M = U / c0; the cavity's depth resonance (quarter wave)
 *     f_n = (2n - 1) c0 / (4 (D + delta)),  delta = 0.82 a  (flanged end
 * correction, a = sqrt(L W / pi) the radius of the same opening area),
 * and a Rossiter mode near a depth mode locks in: it grows and its frequency
 * holds on the depth mode over a range of speeds (the whistle of
 * a bottle or a window gap); the others stay weak. Broadband shear-layer
 * noise lies under the tones. The pressure amplitude grows as U^n, n = 2 by
 * default (Dobashi's "amplitude ~ v^4" is an intensity law), and falls as
 * 1/r. Each tone is a narrow line whose phase wanders (a Lorentzian of
 * width 3 % of f, narrower when locked). It is rendered in float, 64
 * samples at a time as four lanes of 16 (two-term recurrences, the noise
 * filters run per lane and joined by their carried states, on the four
 * lanes of aero_lanes.h), the laws and the phase's steps per chunk and
 * lane; U^n per sample for n = 2, else once per chunk, gliding
 * (cavity_model.c). With two ears, each hears the same field at its own
 * distance (1/r); the sound reaches both at once (no interaural delay:
 * the ears differ in level only, in both modes).
 *
 * Texture mode. A cavity texture from `aerotex cavity` (g = dF/dt per unit
 * width at the base speed v0) is read at a rate v/v0, scaled by (v/v0)^n
 * (n = 2; the paper's 4 on request) and radiated as a compact dipole
 * (Curle): p = (x . g) W / (4 pi c0 r^2), at each ear (cavity_texture.c).
 *
 * The object (cavity.c) holds every setting once; each setter validates
 * and stores it, and each mode's process reads it.
 *
 * Life cycle: init, set_*, process, free (the texture, if any, belongs to
 * the object after set_texture). No globals. */
#ifndef AERO_CAVITY_H
#define AERO_CAVITY_H

#include "aero_ears.h"
#include "aero_ranges.h"
#include "texture.h"

#include <stdint.h>

#define AERO_CAVITY_MODES 4
#define AERO_CAVITY_DEPTH_MODES 3
#define AERO_CAVITY_MAX_EARS AERO_EARS_MAX
/* ranges of the sample rate, Hz, of length, depth and width, m, and of
   the exponent (gain and ramp: aero_ranges.h) */
#define AERO_CAVITY_SR_MIN 1.0
#define AERO_CAVITY_SR_MAX 1e7
#define AERO_CAVITY_SIZE_MIN 1e-4
#define AERO_CAVITY_SIZE_MAX 100.0
#define AERO_CAVITY_EXPONENT_MIN 0.0
#define AERO_CAVITY_EXPONENT_MAX 8.0
/* defaults (gain and ramp: aero_ranges.h) */
#define AERO_CAVITY_LENGTH_DEFAULT 0.02 /* m */
#define AERO_CAVITY_DEPTH_DEFAULT 0.01  /* m */
#define AERO_CAVITY_WIDTH_DEFAULT 0.05  /* m */
#define AERO_CAVITY_EXPONENT_DEFAULT 2.0
/* 1 m out of the opening (+y, the wall's normal); stereo: ears at
   x -+AERO_EAR_HALF_SPACING */
#define AERO_CAVITY_LISTENER_DEFAULT {0.0, 1.0, 0.0} /* m */

enum {
    AERO_CAV_LENGTH,
    AERO_CAV_DEPTH,
    AERO_CAV_WIDTH,
    AERO_CAV_GAIN, /* linear */
    AERO_CAV_EAR,  /* x y z of each ear */
    AERO_CAV_COUNT = AERO_CAV_EAR + 3 * AERO_CAVITY_MAX_EARS
};

typedef struct aero_cavity {
    double sample_rate;
    int n_ears;
    uint32_t rng;
    double exponent;         /* amplitude ~ U^exponent */

    double ctl[AERO_CAV_COUNT], ctl_target[AERO_CAV_COUNT];
    double ramp_samples, ramp_left;
    int primed;

    /* laws of the geometry, the listener and the level (recomputed when a
       control or the exponent moves: laws_dirty) */
    int laws_dirty;
    double depth_hz[AERO_CAVITY_DEPTH_MODES];
    double lock_scale[AERO_CAVITY_DEPTH_MODES]; /* 1 / (LOCK_WIDTH f_n) */
    double mode_level[AERO_CAVITY_MODES]; /* tone amplitude per U^n, unlocked */
    double level;                         /* p_rms per U^n, Pa (ear 0) */
    double ear_scale[AERO_CAVITY_MAX_EARS]; /* r_0 / r_e: 1/r at ear e */
    double speed_power;  /* U^n at the end of the last chunk (n != 2) */

    /* model mode, per Rossiter mode m */
    double phasor[AERO_CAVITY_MODES][2]; /* e^{i 2 pi phase} after the last chunk */
    double mode_gain[AERO_CAVITY_MODES]; /* at the end of the last chunk */
    double freq_factor[AERO_CAVITY_MODES]; /* f_m / U, Hz per m/s */
    double noise_state[2];   /* band-pass of the shear-layer noise */
    uint32_t noise_rng[4];   /* the white noise's four generators */
    uint32_t tone_rng[4];    /* the tones' phase steps' */

    /* texture mode */
    aero_texture *texture;   /* NULL: model mode */
    double texture_v0;
    double texture_length; /* L0 the texture was made for, m (0: unknown) */
    double texture_pos;      /* frames */
    aero_near near; /* a listener came within sqrt(L W) (aero_near_field) */
} aero_cavity;

/* Defaults: the AERO_CAVITY_*_DEFAULT above (L 2 cm, D 1 cm, W 5 cm,
 * exponent 2, listener 1 m out of the opening), gain and ramp from
 * aero_ranges.h; n_ears 1 or 2. 0, or -1 when the sample rate is not
 * usable (AERO_SAMPLE_RATE_FALLBACK is taken: the object plays). */
int aero_cavity_init(aero_cavity *m, double sample_rate, int n_ears,
                     uint32_t seed);
void aero_cavity_free(aero_cavity *m);

/* Setters: 0 when accepted, -1 when invalid (the old value stays). */
int aero_cavity_set_sample_rate(aero_cavity *m, double sr);
int aero_cavity_set_length(aero_cavity *m, double l);
int aero_cavity_set_depth(aero_cavity *m, double d);
int aero_cavity_set_width(aero_cavity *m, double w);
int aero_cavity_set_gain_db(aero_cavity *m, double db);
int aero_cavity_set_ramp_ms(aero_cavity *m, double ms);
int aero_cavity_set_exponent(aero_cavity *m, double n);
/* ears 0..e->n-1 (e->n at most the ears the object was made with) */
int aero_cavity_set_ears(aero_cavity *m, const aero_ears *e);
/* any seed is accepted: 0 */
int aero_cavity_set_seed(aero_cavity *m, uint32_t seed);

/* Texture mode: takes ownership of a loaded texture (kind=cavity, at least
 * one direction, v0 > 0); returns -1 (and frees nothing) if it is not
 * usable. NULL returns to model mode. */
int aero_cavity_set_texture(aero_cavity *m, aero_texture *t, char *err,
                            size_t errlen);

/* Rossiter frequency of mode m (1..4) at speed U, Hz. */
double aero_cavity_rossiter_hz(double speed, double length, int mode);
/* The frequency a shear-layer tone at f (Hz) sounds at in a cavity: near a
 * depth mode fd it locks onto it (f - fd shrinks by x^4 / (1 + x^4),
 * x = (f - fd) / (0.04 fd)), so the tone holds a plateau at fd over a range
 * of speeds, as deep cavities do (Elder 1978), instead of gliding through. */
double aero_cavity_locked_hz(double f, double depth, double length,
                             double width);
/* Quarter-wave depth resonance n (1, 2, ...) with the end correction, Hz. */
double aero_cavity_depth_hz(double depth, double length, double width,
                            int n);

/* n samples; speed in m/s (NaN -> 0, |U| clamped at Mach 0.3); out[e]
 * in Pa at ear e. Each chunk of speed is read before that chunk of out is
 * written (they may share a buffer). Returns 1 if a speed was clamped. */
int aero_cavity_process(aero_cavity *m, const float *speed,
                        float *const *out, int n);

#endif
