/* aero: [aeolian~], the aeolian tone of a cylinder in a flow (wind past a
 * wire, a rod, a branch), or, with a texture, of any stick that moves and
 * turns (a sword, a thrown stick). One object, two modes, one set of
 * settings:
 *
 * Model mode (aeolian_model.c). The light-weight model of the Pd
 * aeroacoustics report and Dobashi et al. 2003, with amplitudes that grow
 * as U^3 (Curle 1955): a cylinder of diameter d and length l, its axis
 * along z, in a flow of speed U along x (the speed is a signal). The wake
 * sheds at f = St(Re) U / d; the fluctuating lift (a dipole along y)
 * radiates at f, the fluctuating drag (a dipole along x, ~10x weaker) at
 * 2f. Far field of a compact force (Curle):
 *     p = x_i dF_i/dt / (4 pi c0 r^2),
 * per unit span F' = 1/2 rho U^2 d C_L' (C_L'(Re) from Norberg's 2003 fits,
 * strouhal.h), dF/dt ~ 2 pi f F', so the pressure amplitude grows as U^3
 * (not U^6, the intensity law the papers apply to amplitude). The span is
 * split into incoherent segments of ~3 d (the spanwise correlation length,
 * Dobashi et al. 2003): their powers add. The shedding is a narrow-band
 * process: its phase diffuses and its envelope wanders, the peak widening
 * as the wake turns turbulent. The oscillator is a set of rotating phasors
 * (no per-sample sine), so one object costs a few ns per sample and a
 * thousand run in real time.
 *
 * Texture mode (aeolian_texture.c), once a texture is given: a stick from
 * end A to end B played from a sound texture (Dobashi et al. 2003,
 * real-time part), pressure ~ U^exponent and 1/r (Curle 1955). The stick
 * carries n point sources at the centres of n equal segments (spacing ~
 * the correlation length 3 d unless n is given). Per source and chunk of
 * AERO_AEOLIAN_TEXTURE_CHUNK samples: the air's velocity relative to it,
 * its component normal to the axis (an inclined stick sees v cos(phi)) and
 * that component's direction in the body's cross-section pick and blend
 * the texture's directions; the texture is read at (v/v0)(d_tex/d) (eq. 3
 * of the paper: frequency St v / d) and scaled by (v/v0)^exponent times
 * the segment length; Curle's far field (q - o).g / (4 pi c0 r^2) per ear
 * is added into one delay ring per ear at the arrival time, so Doppler and
 * the interaural delay come for free. Each source starts at its own
 * texture offset and its phase wanders, so their powers add, as model
 * mode's segments do.
 *
 * The object holds every setting once (below: sample rate, ears, diameter,
 * length, gain, ramp, seed, and the texture mode's wind, roll, sources,
 * exponent and phase wander); each setter validates and stores it, and
 * each mode's process reads it. The model mode's state is a part of the
 * struct (1.3 KB in all); the texture mode's (a delay ring of 256 KB per
 * ear at 48 kHz, 40 KB of sources and the pose) is allocated by the first
 * texture-mode message (texture, pose, reference, wind, roll, sources,
 * exponent), so model-mode objects, the common case by the hundred, do
 * not pay for it.
 *
 * Life cycle: init, set_*, process (any block size), free. No globals. */
#ifndef AERO_AEOLIAN_H
#define AERO_AEOLIAN_H

#include <stddef.h>
#include <stdint.h>

#include "aero_ears.h"
#include "aero_ranges.h"
#include "moving_player.h" /* the exponent's and the wind's ranges */
#include "texture.h"

#define AERO_AEOLIAN_MAX_EARS AERO_EARS_MAX
/* ranges (gain and ramp: aero_ranges.h; wind: moving_player.h) */
#define AERO_AEOLIAN_SR_MIN 1.0      /* Hz */
#define AERO_AEOLIAN_SR_MAX 1e7      /* Hz */
#define AERO_AEOLIAN_D_MIN 1e-5      /* m */
#define AERO_AEOLIAN_D_MAX 10.0      /* m */
#define AERO_AEOLIAN_L_MIN 1e-5      /* m */
#define AERO_AEOLIAN_L_MAX 1000.0    /* m */
#define AERO_AEOLIAN_SOURCES_MIN 0   /* 0: the default count, length / (3 d) */
#define AERO_AEOLIAN_SOURCES_MAX 256 /* point sources of texture mode */
#define AERO_AEOLIAN_ROLL_MAX 1e6    /* deg, either way */
#define AERO_AEOLIAN_PHASE_WANDER_MAX 0.1
/* texture mode's amplitude law, (v/v0)^exponent */
#define AERO_AEOLIAN_EXPONENT_MIN 0.0
#define AERO_AEOLIAN_EXPONENT_MAX 12.0
/* model mode's near-field limit: a diameter, at least this (m) */
#define AERO_AEOLIAN_NEAR_MIN 0.01

/* defaults (gain and ramp: aero_ranges.h) */
#define AERO_AEOLIAN_DIAMETER_DEFAULT 0.01 /* m */
#define AERO_AEOLIAN_LENGTH_DEFAULT 0.5    /* m */
#define AERO_AEOLIAN_LISTENER_DEFAULT {0.0, 1.0, 0.0} /* m, across flow
                                        and axis; stereo: ears at x -+
                                        AERO_EAR_HALF_SPACING from it */
/* a compact dipole's pressure ~ U^3 (Curle 1955) */
#define AERO_AEOLIAN_EXPONENT_DEFAULT 3.0
#define AERO_AEOLIAN_SOURCES_DEFAULT 0     /* 0: length / (3 d) */
#define AERO_AEOLIAN_ROLL_DEFAULT 0.0      /* deg */
#define AERO_AEOLIAN_WIND_DEFAULT {0.0, 0.0, 0.0} /* m/s */
/* full width at half maximum of each texture source's phase wander,
   relative to f (aeolian_texture.c says why 1 %) */
#define AERO_AEOLIAN_PHASE_WANDER_DEFAULT 0.01

/* Model mode: samples per inner chunk (frequency, phase diffusion and the
 * envelope are updated per chunk, 1.3 ms at 48 kHz, levels interpolated
 * per sample), parallel phasors, span integration points. */
#define AERO_AEOLIAN_CHUNK 64
#define AERO_AEOLIAN_LANES 8
#define AERO_AEOLIAN_MAX_POINTS 256
/* Texture mode: samples per geometry update, sound travel time kept */
#define AERO_AEOLIAN_TEXTURE_CHUNK 32
#define AERO_AEOLIAN_MAX_DELAY_S 1.0 /* 343 m */

/* The settings that glide to their targets (no zipper noise). */
enum {
    AERO_AEO_DIAMETER,
    AERO_AEO_LENGTH,
    AERO_AEO_GAIN, /* linear factor */
    AERO_AEO_EAR,  /* 3 * AERO_AEOLIAN_MAX_EARS coordinates follow */
    AERO_AEO_COUNT = AERO_AEO_EAR + 3 * AERO_AEOLIAN_MAX_EARS
};

typedef struct aero_cplx {
    double re, im;
} aero_cplx;

/* model mode's state (aeolian_model.c) */
typedef struct {
    uint32_t rng;
    double ctl[AERO_AEO_COUNT]; /* the settings' values now, gliding */
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

/* texture mode's state (aeolian_texture.c) */
typedef struct aero_aeolian_texture aero_aeolian_texture;

typedef struct aero_aeolian {
    /* the settings */
    double sample_rate;
    int n_ears;
    uint32_t seed;
    double target[AERO_AEO_COUNT]; /* diameter, length, gain, ears */
    int diameter_set;   /* given: texture mode uses it, else the texture's */
    double ramp_ms;
    double wind[3];     /* m/s */
    double roll_deg;
    int sources;        /* 0: length / (3 d) */
    double exponent;
    double phase_wander;

    /* a listener came within the near-field limit (aero_near_field:
       model mode max(d, AERO_AEOLIAN_NEAR_MIN), texture mode d / 2) */
    aero_near near;

    /* the modes */
    aero_aeolian_model model;
    aero_aeolian_texture *texture; /* NULL until texture mode is needed */
} aero_aeolian;

/* The AERO_AEOLIAN_*_DEFAULT above, gain and ramp from aero_ranges.h,
 * n_ears 1 or 2. 0, or -1 when the sample rate is not usable (44.1 kHz is
 * taken). */
int aero_aeolian_init(aero_aeolian *a, double sample_rate, int n_ears,
                      uint32_t seed);
void aero_aeolian_free(aero_aeolian *a);

/* 1 while a texture plays, else 0 (the model) */
int aero_aeolian_texture_mode(const aero_aeolian *a);

/* Takes ownership of a loaded texture of kind aeolian: 0, or -1 with a
 * message in err (then the texture is NOT taken). NULL returns to the
 * model. */
int aero_aeolian_set_texture(aero_aeolian *a, aero_texture *t, char *err,
                             size_t errlen);

/* Setters: 0 accepted, -1 invalid or out of memory (the previous value
 * stays). Diameter, length, gain, ears and (texture mode) wind and roll
 * glide over the ramp time. */
int aero_aeolian_set_sample_rate(aero_aeolian *a, double sr);
int aero_aeolian_set_diameter(aero_aeolian *a, double d);
int aero_aeolian_set_length(aero_aeolian *a, double l);
int aero_aeolian_set_gain_db(aero_aeolian *a, double db);
int aero_aeolian_set_ramp_ms(aero_aeolian *a, double ms);
int aero_aeolian_set_seed(aero_aeolian *a, uint32_t seed); /* any: 0 */
/* ears 0..e->n-1 (e->n at most the ears the object was made with) */
int aero_aeolian_set_ears(aero_aeolian *a, const aero_ears *e);
/* texture mode: ends A and B, applied now; interval_s is the time since
 * the previous pose: the ends move on a smooth path to it over that time
 * (at least 1 ms; pose_glide.h). The first
 * pose, a pose more than 0.5 s after the previous one (a new gesture) and
 * interval_s < 0 (a placement) jump there without motion. */
int aero_aeolian_set_pose(aero_aeolian *a, const double end_a[3],
                          const double end_b[3], double interval_s);
/* the same at sample `offset` of the next process call (as [vline~]
 * times its segments; a host gives each pose its logical time within the
 * block), with the body's x axis when axis is not NULL: queued (up to
 * AERO_GLIDE_QUEUE; beyond, the oldest is applied at once), the process
 * call split there; a pose beyond the call waits for the next (each
 * call counts its samples off). 0, or -1 invalid (nothing queued). */
int aero_aeolian_set_pose_at(aero_aeolian *a, const double end_a[3],
                             const double end_b[3], const double *axis,
                             double interval_s, int offset);
/* the body's x axis (angle 0 of the texture's directions); projected onto
 * the plane normal to the stick and carried along as it turns */
int aero_aeolian_set_reference(aero_aeolian *a, const double x[3]);
int aero_aeolian_set_wind(aero_aeolian *a, const double w[3]);
int aero_aeolian_set_roll_deg(aero_aeolian *a, double deg);
int aero_aeolian_set_sources(aero_aeolian *a, int n);
int aero_aeolian_set_exponent(aero_aeolian *a, double e);
/* 0 freezes the texture sources' phases, as unit tests of exact pitch
 * need; 0..AERO_AEOLIAN_PHASE_WANDER_MAX */
int aero_aeolian_set_phase_wander(aero_aeolian *a, double width);

/* n samples. speed[i]: model mode, the flow speed in m/s across the axis
 * (its sign the flow direction); texture mode, a wind along +x added to
 * `wind` (speed may be NULL there). NaN counts as 0, |U| is clamped at
 * Mach 0.3. out[e][i]: sound pressure in Pa at ear e. Each chunk of speed
 * is read before that chunk of out is written (they may share a buffer).
 * Returns 1 if a speed was clamped. */
int aero_aeolian_process(aero_aeolian *a, const float *speed,
                         float *const *out, int n);

/* the tone of a stick normal to a steady flow v in the mode in use, Hz
 * (model mode: 0 below the shedding onset) */
double aero_aeolian_tone_hz(const aero_aeolian *a, double v);
/* texture mode's point sources now (0 before texture mode is needed) */
int aero_aeolian_source_count(const aero_aeolian *a);

#endif
