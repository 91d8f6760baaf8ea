/* aero: aeolian tone of a circular cylinder, Strouhal/Reynolds model mode.
 *
 * The light-weight model of the Pd aeroacoustics report and Dobashi et al.
 * 2003, with amplitudes that grow as U^3 (Curle 1955):
 * a cylinder of diameter d and length l, its axis along z, in a flow of
 * speed U along x (the speed is a signal). The wake sheds at f = St(Re) U / d;
 * the fluctuating lift (a dipole along y) radiates at f, the fluctuating drag
 * (a dipole along x, ~10x weaker) at 2f. Far field of a compact force (Curle):
 *     p = x_i dF_i/dt / (4 pi c0 r^2),
 * per unit span F' = 1/2 rho U^2 d C_L' (C_L'(Re) from Norberg's 2003 fits,
 * strouhal.h), dF/dt ~ 2 pi f F', so the pressure
 * amplitude grows as U^3 (not U^6, the intensity law the papers apply to
 * amplitude). The span is split into incoherent segments of ~3 d (the
 * spanwise correlation length, Dobashi et al. 2003): their powers add.
 *
 * The shedding is a narrow-band process: its phase diffuses and its envelope
 * wanders, the peak widening continuously as the wake turns turbulent. The
 * oscillator is a set of rotating phasors (no per-sample sine), so one
 * object costs a few ns per sample and a thousand run in real time.
 *
 * Life cycle: init, set_*, process (any block size), no free needed (no
 * allocation). All state is in the struct; no globals. */
#ifndef AERO_AEOLIAN_MODEL_H
#define AERO_AEOLIAN_MODEL_H

#include "aero_ears.h"
#include "aero_ranges.h"

#include <stdint.h>

#define AERO_AEOLIAN_MAX_EARS AERO_EARS_MAX
/* ranges of the cylinder, m (gain and ramp: aero_ranges.h) */
#define AERO_AEOLIAN_D_MIN 1e-5
#define AERO_AEOLIAN_D_MAX 10.0
#define AERO_AEOLIAN_L_MIN 1e-5
#define AERO_AEOLIAN_L_MAX 1000.0
/* Samples per inner chunk: frequency, phase diffusion and the envelope are
 * updated per chunk (1.3 ms at 48 kHz), levels interpolated per sample. */
#define AERO_AEOLIAN_CHUNK 64
#define AERO_AEOLIAN_LANES 8 /* parallel phasors of the oscillator */
#define AERO_AEOLIAN_MAX_POINTS 256 /* span integration points (geometry) */

/* Controls that ramp linearly to their targets (no zipper noise). */
enum {
    AERO_CTL_DIAMETER,
    AERO_CTL_LENGTH,
    AERO_CTL_GAIN, /* linear factor */
    AERO_CTL_EAR,  /* 3 * AERO_AEOLIAN_MAX_EARS coordinates follow */
    AERO_CTL_COUNT = AERO_CTL_EAR + 3 * AERO_AEOLIAN_MAX_EARS
};

typedef struct aero_cplx {
    double re, im;
} aero_cplx;

typedef struct aero_aeolian_model {
    double sample_rate;
    int n_ears;
    uint32_t rng;

    /* ramped controls */
    double ctl[AERO_CTL_COUNT], ctl_target[AERO_CTL_COUNT];
    double ramp_samples;  /* ramp length for new targets */
    double ramp_left;     /* samples until the targets are reached */
    int geometry_dirty;

    /* geometric radiation factors per ear, sqrt(sum (x_i / r^2)^2) over the
     * span segments: lift (y) and drag (x) dipoles, 1/m^2 */
    double lift_geometry[AERO_AEOLIAN_MAX_EARS];
    double drag_geometry[AERO_AEOLIAN_MAX_EARS];
    double centre_distance; /* mean ear distance, for Doppler */
    double prev_distance;   /* the same at the previous block */

    /* coefficients at the end of the previous chunk, from which the next
     * chunk interpolates */
    int primed;
    double lift_coef[AERO_AEOLIAN_MAX_EARS]; /* Pa per (m/s)^3 */
    double drag_coef[AERO_AEOLIAN_MAX_EARS];
    double envelope_gain;

    /* cache of the speed-dependent laws (recomputed when the speed or the
     * diameter changes) */
    double cached_speed, cached_diameter;
    int cached_n, levels_dirty;
    double st;
    double lift_level[AERO_AEOLIAN_MAX_EARS], drag_level[AERO_AEOLIAN_MAX_EARS];
    double phase_jitter;   /* per chunk, cycles (uniform amplitude) */
    double envelope_alpha, envelope_scale;

    /* oscillator state */
    aero_cplx phasor;   /* e^{i 2 pi phase} at the start of the next chunk */
    double increment;   /* phase increment at the end of the last chunk,
                           cycles per sample */
    aero_cplx increment_turn; /* e^{i 2 pi increment} */
    int primed_phase;
    double envelope, envelope_lp; /* low-passed noise of the envelope */

    float scratch_amp[AERO_AEOLIAN_CHUNK];
    float scratch_sin[AERO_AEOLIAN_CHUNK];
    float scratch_cos[AERO_AEOLIAN_CHUNK];
} aero_aeolian_model;

/* Defaults: d = 1 cm, l = 0.5 m, one listener 1 m away along +y (across the
 * flow and the axis), gain 0 dB, ramp 20 ms. 0, or -1 when the sample rate
 * is not usable (44.1 kHz is taken). */
int aero_aeolian_model_init(aero_aeolian_model *m, double sample_rate,
                            int n_ears, uint32_t seed);

/* Setters return 0 when accepted, -1 when the value is invalid (then the
 * previous value stays). Geometry ramps over the ramp time. */
int aero_aeolian_model_set_sample_rate(aero_aeolian_model *m, double sr);
int aero_aeolian_model_set_diameter(aero_aeolian_model *m, double d);
int aero_aeolian_model_set_length(aero_aeolian_model *m, double l);
int aero_aeolian_model_set_gain_db(aero_aeolian_model *m, double db);
int aero_aeolian_model_set_ramp_ms(aero_aeolian_model *m, double ms);
/* ears 0..e->n-1 (e->n at most the ears the model was made with) */
int aero_aeolian_model_set_ears(aero_aeolian_model *m, const aero_ears *e);
void aero_aeolian_model_set_seed(aero_aeolian_model *m, uint32_t seed);

/* Render n samples. speed[i]: flow speed in m/s across the axis (sign is
 * the flow direction; NaN counts as 0; |U| is clamped at Mach 0.3).
 * out[e][i]: sound pressure in Pa at ear e. Returns 1 if this block had to
 * clamp a speed, else 0. */
int aero_aeolian_model_process(aero_aeolian_model *m, const float *speed,
                               float *const *out, int n);

/* Peak frequency of the lift tone for a steady speed (Hz), 0 below onset. */
double aero_aeolian_model_tone_hz(const aero_aeolian_model *m, double speed);

#endif
