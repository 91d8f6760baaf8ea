/* aero: a rotor (fan, propeller, drone rotor, wind turbine): B blades of
 * radius R and chord c turning at a speed given per sample in rpm, with a
 * steady thrust and torque, placed and turned by a pose, heard at one
 * listener or two ears.
 *
 * Tones (blade passing B rpm/60 and its harmonics): each blade is split
 * into strips along its radius; each strip is a compact source turning
 * with the blade, carrying its share of the steady loading (thrust and
 * torque, per strip ~ r^2 dr, the local dynamic pressure) and its
 * thickness. Formulation: the far field of a rotating compact force in
 * the frequency domain, Gutin's (1936) closed form applied per strip and
 * summed coherently over the strips of a straight blade (Gutin's own
 * radial integral; one strip sits at his effective radius 0.8 R), with the
 * compact thickness term of the same derivation (Deming 1940: the
 * displaced volume V of a strip, J_n of the same argument, in quadrature
 * with the loading). Harmonic n = mB at the observer direction (theta
 * from the thrust axis, phi around it) in the rotor frame:
 *   p_n = (n Omega B / (4 pi c0 r)) (-i)^n e^{i n phi} (-i L_n - Th_n)
 *   L_n  = SUM_s J_n(z_s) (-T_s cos(theta) + D_s c0 / (Omega r_s))
 *   Th_n = n Omega rho0 c0 SUM_s V_s J_n(z_s),   z_s = n Omega r_s sin(theta)/c0
 * (T_s, D_s: thrust and in-plane drag of a strip of one blade). Why the
 * closed form and not a time-domain Farassat 1A sum over strips: it is
 * exact for steady loading in the far field, band-limited by construction
 * (no aliasing of the sharp pulses near the plane at high tip Mach), and
 * costs one oscillator bank per rotor instead of a retarded-time solve
 * per strip per sample: a drone's four rotors fit in 1 % of a core.
 * The whole rotor is then a moving point source at its hub, heard through
 * the arrival rings (arrivals.h): retarded time, exact Doppler of the
 * hub's motion per ear, interaural delay.
 * Unsteady loading from an inflow distortion (the wakes of N struts, a
 * fan's stand or a turbine's tower, fixed in space, the first along the
 * rotor's x axis): each blade's loading at azimuth psi is
 * F (1 + SUM_k a_k cos(k N psi)), and a loading harmonic of order
 * sigma = kN radiates at harmonic n through J_{n-sigma} and J_{n+sigma}
 * of the same argument (Lowson 1965, Lowson and Ollerhead 1969; the
 * rotor-stator rule n - kN of Tyler and Sofrin 1962):
 *   L_n += SUM_k SUM_{nu = n -+ k N} e^{i (nu - n)(phi - pi/2)} (a_k/2)
 *          SUM_s J_nu(z_s) (-T_s cos(theta) + (nu/n) D_s c0 / (Omega r_s))
 * (derived from the far field of a rotating point force in the frame and
 * phase above, sigma = 0 giving Gutin's terms; test_rotor checks it
 * against a direct time-domain sum). Only sigma = n reaches the axis
 * (J_0), where the steady tones vanish: there p = n Omega B |SUM_s T_s
 * a_k,s| / (4 pi c0 r) (peak), kN = n. Each wake is a Gaussian change of
 * the loading by `distortion` of the steady (negative: a rise) over
 * `wake` metres (full width at half depth, the same at every radius):
 * its angle wake / r_s is wider near the hub, so a_k falls as
 * exp(-(k N s_s)^2 / 2), s_s = wake / (2.355 r_s) (a wake's Gaussian
 * defect, as a plane body's far wake: Schlichting and Gersten 2000). The
 * change's mean is taken out: `thrust` and `torque` stay the means.
 * Left out: other unsteady loading (blade-vortex interaction, inflow
 * turbulence's tones), the blade's unsteady response (Sears 1941: the
 * loading follows the inflow quasi-steadily), the near field (r of the
 * order of R),
 * forward-flight convective factors of the tones (Garrick & Watkins 1954)
 * beyond the hub's Doppler, ground reflection, quadrupole noise.
 *
 * Loading follows the speed: thrust and torque are given at the `design`
 * rpm and scale with (rpm/design)^2 (constant thrust and torque
 * coefficients), so a rotor spinning down falls quiet.
 *
 * Life cycle: init, set_*, process (any block size), free. No globals. */
#ifndef AERO_ROTOR_H
#define AERO_ROTOR_H

#include <stddef.h>
#include <stdint.h>

#include "moving_player.h"
#include "pose_glide.h"

#define AERO_ROTOR_CHUNK 128
#define AERO_ROTOR_MAX_DELAY_S 1.0
#define AERO_ROTOR_HARMONICS_MAX 40 /* of the blade-passing frequency */
#define AERO_ROTOR_MACH_TIP_MAX 0.9 /* rpm is clamped to this tip Mach */
/* the near-field limit (aero_near_field), in radii from the hub: Gutin's
   far field and the strips' 1/r^2 do not hold within the rotor's diameter */
#define AERO_ROTOR_NEAR_RADII 2.0

#define AERO_ROTOR_BLADES_MIN 1
#define AERO_ROTOR_BLADES_MAX 16
#define AERO_ROTOR_BLADES_DEFAULT 2
#define AERO_ROTOR_RADIUS_MIN 0.01 /* m */
#define AERO_ROTOR_RADIUS_MAX 100.0
#define AERO_ROTOR_RADIUS_DEFAULT 0.12 /* a 9.5-inch drone propeller */
#define AERO_ROTOR_CHORD_MIN 0.001 /* m */
#define AERO_ROTOR_CHORD_MAX 10.0
#define AERO_ROTOR_CHORD_DEFAULT 0.02
#define AERO_ROTOR_THICKNESS_MIN 0.0 /* of the chord */
#define AERO_ROTOR_THICKNESS_MAX 0.5
#define AERO_ROTOR_THICKNESS_DEFAULT 0.12
#define AERO_ROTOR_HUB_MIN 0.0 /* of the radius */
#define AERO_ROTOR_HUB_MAX 0.9
#define AERO_ROTOR_HUB_DEFAULT 0.2
#define AERO_ROTOR_STRIPS_MIN 1
#define AERO_ROTOR_STRIPS_MAX 32
#define AERO_ROTOR_STRIPS_DEFAULT 8
#define AERO_ROTOR_THRUST_LIMIT 1e7 /* N, either sign */
#define AERO_ROTOR_THRUST_DEFAULT 4.0 /* a 1.6 kg quadcopter's rotor */
#define AERO_ROTOR_TORQUE_LIMIT 1e8 /* N m */
#define AERO_ROTOR_TORQUE_DEFAULT 0.06
#define AERO_ROTOR_DESIGN_MIN 1.0 /* rpm */
#define AERO_ROTOR_DESIGN_MAX 1e5
#define AERO_ROTOR_DESIGN_DEFAULT 6000.0
/* the blades' self-noise against Brooks et al.'s (1989) level, dB */
#define AERO_ROTOR_NOISE_DB_MIN -200.0
#define AERO_ROTOR_NOISE_DB_MAX 40.0
#define AERO_ROTOR_NOISE_DB_DEFAULT 0.0
/* the inflow distortion: its struts (wakes), their loading dip (of the
   steady loading; 0: steady loading alone; negative: the loading rises in
   a wake, as a fan's or propeller's does, the slower inflow meeting the
   blade at a larger angle of attack; positive: it falls, as a wind
   turbine's behind its tower) and their wakes' width */
#define AERO_ROTOR_STRUTS_MIN 1
#define AERO_ROTOR_STRUTS_MAX 32
#define AERO_ROTOR_STRUTS_DEFAULT 1
#define AERO_ROTOR_DISTORTION_MIN -1.0
#define AERO_ROTOR_DISTORTION_MAX 1.0
#define AERO_ROTOR_DISTORTION_DEFAULT 0.0
#define AERO_ROTOR_WAKE_MIN 0.001 /* m */
#define AERO_ROTOR_WAKE_MAX 100.0
#define AERO_ROTOR_WAKE_DEFAULT 0.03
/* loading harmonics k N kept, k = 1..AERO_ROTOR_LOADS: beyond them a
   wake's harmonics are left out (one strut's wake R/4 wide: below -53 dB
   of its first at the tip; R/5, a desk fan's: -34 dB, on the axis from
   the 7th blade-passing harmonic up) */
#define AERO_ROTOR_LOADS 32

/* a blade's chord and twist along its radius (a small text file, as
 * trees are): rows of r/R, chord in m and twist in degrees (the section's
 * angle from the plane of rotation, its leading edge turned into the flow
 * through the disc), r/R rising strictly within 0..1, at least 2 rows.
 * The strips take them interpolated linearly at their radii (held beyond
 * the first and last rows). */
#define AERO_ROTOR_BLADE_ROWS_MAX 64
#define AERO_ROTOR_BLADE_FILE_MAX 65536 /* bytes: larger files are refused */
#define AERO_ROTOR_TWIST_MAX 90.0       /* deg, either sign */
typedef struct {
    int n;
    double r[AERO_ROTOR_BLADE_ROWS_MAX];     /* r/R */
    double chord[AERO_ROTOR_BLADE_ROWS_MAX]; /* m */
    double twist[AERO_ROTOR_BLADE_ROWS_MAX]; /* deg */
} aero_rotor_blade;

/* one strip's geometry */
typedef struct {
    double r;      /* radius, m */
    double chord;  /* m */
    double twist;  /* rad, from the disc (a blade table's; else unused) */
    double thrust; /* per blade at the design rpm, N */
    double drag;   /* in-plane, per blade at the design rpm, N */
    double volume; /* displaced volume, m^3 */
    double load[AERO_ROTOR_LOADS]; /* a_k / 2 of the inflow distortion */
} aero_rotor_strip;

/* the broadband: octave bands 63 Hz .. 16 kHz, an envelope of harmonics
   0..AERO_ROTOR_ENVELOPE of the blade passing, sampled at
   AERO_ROTOR_AZIMUTHS positions over one blade passing */
#define AERO_ROTOR_BANDS 9
#define AERO_ROTOR_THIRDS (3 * AERO_ROTOR_BANDS)
#define AERO_ROTOR_ENVELOPE 2
#define AERO_ROTOR_AZIMUTHS 8
#define AERO_ROTOR_ENVELOPE_SAMPLES 256 /* between two envelopes */
/* the self-noise spectrum is made at speeds on a grid of this ratio (its
   frequencies off by at most half of it: 3 %, a 24th of an octave) */
#define AERO_ROTOR_NOISE_TOLERANCE 0.06

/* what one ear hears, at a chunk's end: the coefficients of cos(n Psi)
   and sin(n Psi) per harmonic, the broadband's envelope (its mean, then
   cos and sin of k B Psi), and the hub's delay in samples */
typedef struct {
    double c[AERO_ROTOR_HARMONICS_MAX], s[AERO_ROTOR_HARMONICS_MAX];
    double env[2 * AERO_ROTOR_ENVELOPE + 1];
    double delay;
    int h; /* harmonics above the floor; those beyond are 0 */
} aero_rotor_ear;

/* the sound at a place the rotor jumped from (`place`, a pose after a
   pause): each ear's tones and envelope as they were, its level then
   (the start's fade-in, if not done) and the samples since the jump */
#define AERO_ROTOR_GHOSTS 4 /* jumps heard fading at once: 8 ms apart */
typedef struct {
    aero_rotor_ear ear[AERO_EARS_MAX];
    double level, samples;
    int active;
} aero_rotor_ghost;

/* an ear's strip sums of harmonics 1..h (rotor.c: the Bessel functions,
   which depend on Omega sin(theta) alone), kept while that moves less
   than AERO_ROTOR_SUMS_TOLERANCE */
#define AERO_ROTOR_SUMS_TOLERANCE 2e-3
typedef struct {
    double key;        /* Omega sin(theta) they were made for */
    int h, layout;     /* harmonics held; the layout they were made for */
    double thrust[AERO_ROTOR_HARMONICS_MAX]; /* SUM J_n (-T_s) */
    double drag[AERO_ROTOR_HARMONICS_MAX];   /* SUM J_n D_s c0 / r_s */
    double volume[AERO_ROTOR_HARMONICS_MAX]; /* SUM J_n V_s */
    /* the inflow distortion's, per loading harmonic k, nu = n -+ k N:
       SUM J_nu (-T_s) a_k/2 and SUM J_nu (nu/n) D_s c0 / r_s a_k/2 */
    double thrust_lo[AERO_ROTOR_HARMONICS_MAX][AERO_ROTOR_LOADS];
    double thrust_hi[AERO_ROTOR_HARMONICS_MAX][AERO_ROTOR_LOADS];
    double drag_lo[AERO_ROTOR_HARMONICS_MAX][AERO_ROTOR_LOADS];
    double drag_hi[AERO_ROTOR_HARMONICS_MAX][AERO_ROTOR_LOADS];
} aero_rotor_sums;

/* the blades' self-noise (Brooks et al. 1989, airfoil_noise.h): each
   strip's level at 1 m straight above its trailing edge, the spectrum's
   shape as gains of a bank of octave band-passes fed one white noise */
#define AERO_ROTOR_LANES 12 /* the bands padded for SIMD (zero gains) */
#define AERO_ROTOR_SPECTRA 8 /* self-noise spectra kept per rotor */
typedef struct {
    /* per band (lane): b0 (b2 = -b0), a1, a2, gain (unit total power),
       its own white noise's state, the two stages' x1 x2 y1 y2 / y1 y2 */
    float b0[AERO_ROTOR_LANES], a1[AERO_ROTOR_LANES], a2[AERO_ROTOR_LANES];
    float gain[AERO_ROTOR_LANES];
    uint32_t rng[AERO_ROTOR_LANES];
    float x1[AERO_ROTOR_LANES], x2[AERO_ROTOR_LANES];
    float y1[AERO_ROTOR_LANES], y2[AERO_ROTOR_LANES];
    float u1[AERO_ROTOR_LANES], u2[AERO_ROTOR_LANES];
    double unmix[AERO_ROTOR_BANDS * AERO_ROTOR_BANDS]; /* band leakage^-1 */
    int bands;                        /* under Nyquist */
    double power[AERO_ROTOR_STRIPS_MAX]; /* Pa^2 at 1 m, D_h = 1, a blade */
    double mach[AERO_ROTOR_STRIPS_MAX];
    double alpha[AERO_ROTOR_STRIPS_MAX]; /* angle of attack, rad */
    double cos_alpha[AERO_ROTOR_STRIPS_MAX], sin_alpha[AERO_ROTOR_STRIPS_MAX];
    /* cos and sin of the envelope's blade azimuths (AERO_ROTOR_AZIMUTHS
       per blade passing, each blade), made for psi_blades blades */
    double psi_cos[AERO_ROTOR_AZIMUTHS * AERO_ROTOR_BLADES_MAX];
    double psi_sin[AERO_ROTOR_AZIMUTHS * AERO_ROTOR_BLADES_MAX];
    int psi_blades;
    double scale; /* the speed against the grid's: powers as U^5 */
    int layout, step, have; /* the grid step held, whether any */
    /* the spectra made, by grid step (a drone's rotors move among a few) */
    int cached, next, cache_step[AERO_ROTOR_SPECTRA];
    float cache_gain[AERO_ROTOR_SPECTRA][AERO_ROTOR_LANES];
    double cache_power[AERO_ROTOR_SPECTRA][AERO_ROTOR_STRIPS_MAX];
    double cache_mach[AERO_ROTOR_SPECTRA][AERO_ROTOR_STRIPS_MAX];
    double cache_alpha[AERO_ROTOR_SPECTRA][AERO_ROTOR_STRIPS_MAX];
} aero_rotor_noise;

typedef struct aero_rotor {
    /* sample rate, rings, ears, wind, gain, ramp, clamp */
    aero_moving_player base;

    int blades, strips;
    double radius, chord, thickness, hub;
    double thrust, torque, design_rpm;
    double noise_gain;   /* linear, of the self-noise */
    int struts;          /* the inflow distortion: its order N */
    double distortion, wake; /* its loading dip, its wakes' width (m) */
    int loads;           /* loading harmonics k in use (0: steady alone) */
    aero_rotor_blade blade; /* chord and twist per radius, when has_blade */
    int has_blade;
    aero_rotor_strip strip[AERO_ROTOR_STRIPS_MAX];
    int layout;          /* counts the layouts: the sums' key */
    aero_rotor_sums sums[AERO_EARS_MAX];
    aero_rotor_noise noise;

    double rpm;          /* smoothed, clamped */
    double psi;          /* blade 0's azimuth, rad, in [0, 2 pi) */
    int harmonics;       /* in use (Nyquist) */

    /* pose: position and quaternion (w, x, y, z) now, its path through
       the poses (pose_glide.h) and the poses waiting for their sample */
    double pose[7];
    aero_pose_path path;
    aero_pose_queue queue;
    int pose_set;

    aero_rotor_ear then[AERO_EARS_MAX]; /* at the last chunk's end */
    int primed;
    /* a start and each jump fade the sound in over AERO_GHOST_FADE_S
       (ghost_fade.h): the samples since; the sound at the places left
       goes on there as ghosts fading out over the same time */
    double fade_in;
    int jumped; /* a jump while sounding, for the next chunk */
    aero_rotor_ghost ghost[AERO_ROTOR_GHOSTS];
    int envelope_due; /* samples until the broadband's envelope is made again */
} aero_rotor;

/* 0, or -1 when out of memory (silent then, until a sample rate is set)
 * or the sample rate is not usable (48 kHz is taken). Defaults: the
 * AERO_ROTOR_*_DEFAULT values, the hub at the origin with its thrust along
 * +z, still air, one listener 1 m away along +y (stereo: ears at
 * x = -+AERO_EAR_HALF_SPACING), gain and ramp as moving_player.h's. */
int aero_rotor_init(aero_rotor *r, double sample_rate, int n_ears,
                    uint32_t seed);
void aero_rotor_free(aero_rotor *r);

/* the seed of the blades' broadband noise (0 is taken as 1): the same seed,
   the same sound; always 0 */
int aero_rotor_set_seed(aero_rotor *r, uint32_t seed);

/* setters: 0 accepted, -1 invalid (the previous value stays) */
int aero_rotor_set_sample_rate(aero_rotor *r, double sr);
int aero_rotor_set_blades(aero_rotor *r, double blades);
int aero_rotor_set_radius(aero_rotor *r, double m);
int aero_rotor_set_chord(aero_rotor *r, double m);
int aero_rotor_set_thickness(aero_rotor *r, double ratio);
int aero_rotor_set_hub(aero_rotor *r, double ratio);
int aero_rotor_set_strips(aero_rotor *r, double strips);
int aero_rotor_set_thrust(aero_rotor *r, double newton);
int aero_rotor_set_torque(aero_rotor *r, double newton_metre);
int aero_rotor_set_design(aero_rotor *r, double rpm);
int aero_rotor_set_noise_db(aero_rotor *r, double db);
int aero_rotor_set_struts(aero_rotor *r, double struts);
int aero_rotor_set_distortion(aero_rotor *r, double dip);
int aero_rotor_set_wake(aero_rotor *r, double m);
int aero_rotor_set_gain_db(aero_rotor *r, double db);
int aero_rotor_set_ramp_ms(aero_rotor *r, double ms);
int aero_rotor_set_wind(aero_rotor *r, const double w[3]);
/* ears 0..e->n-1 (e->n at most the ears the rotor was made with) */
int aero_rotor_set_ears(aero_rotor *r, const aero_ears *e);
/* the hub's position and orientation (unit quaternion w x y z, normalised
 * here; the thrust axis is the turned +z), at sample `offset` of the next
 * process call, moving there on a smooth path over interval_s (the first
 * pose, one after a 0.5 s pause and interval_s < 0 jump): as
 * aero_body_set_pose_at (body.h). 0, or -1 invalid. */
int aero_rotor_set_pose_at(aero_rotor *r, const double pos[3],
                           const double quat[4], double interval_s,
                           int offset);
/* The blade's chord and twist per radius from a table (NULL: the uniform
 * `chord` again, the twist that of the design's angle of attack). A table
 * with fewer than 2 rows, r/R not rising strictly within 0..1, a chord
 * outside AERO_ROTOR_CHORD_MIN..MAX or a twist beyond
 * AERO_ROTOR_TWIST_MAX is refused: -1, the old kept. */
int aero_rotor_set_blade(aero_rotor *r, const aero_rotor_blade *b);
/* A blade table from text: lines of three numbers r/R chord twist_deg;
 * '#' starts a comment; blank lines are skipped. 0, or -1 with the first
 * problem (its line) in err: a line that is not three finite numbers,
 * values out of range (as aero_rotor_set_blade), r/R not rising, more
 * than AERO_ROTOR_BLADE_ROWS_MAX rows, fewer than 2. */
int aero_rotor_blade_parse(const char *text, aero_rotor_blade *b, char *err,
                           size_t errlen);
/* the same from a file of at most AERO_ROTOR_BLADE_FILE_MAX bytes (larger,
   unreadable or not text: -1 with why in err) */
int aero_rotor_blade_load(const char *path, aero_rotor_blade *b, char *err,
                          size_t errlen);

/* a rotation vector (axis times angle in degrees) as a unit quaternion */
static inline void aero_rotor_quaternion_from_rotvec(const double r[3],
                                                     double q[4])
{
    aero_quat_from_rotvec(r, q);
}
/* the orientation of the last pose given (w x y z) */
void aero_rotor_orientation(const aero_rotor *r, double quat[4]);

/* n samples; rpm[i] (NULL: 0) the speed of rotation in rev/min (sign:
 * the sense of rotation); out[e][i] the sound pressure at ear e in Pa.
 * Returns 1 when an rpm was clamped (tip Mach AERO_ROTOR_MACH_TIP_MAX). */
int aero_rotor_process(aero_rotor *r, const float *rpm, float *const *out,
                       int n);

/* Gutin's (1936) harmonic n = mB of the strips at the far-field observer
 * direction theta (rad, from the thrust axis) and distance d (m), at
 * angular speed omega (rad/s): the amplitude (peak, Pa) of the tone the
 * process renders there (the renderer's coefficients, for the tests) */
double aero_rotor_harmonic_amplitude(const aero_rotor *r, int m,
                                     double omega, double theta, double d);
/* the same at azimuth phi (rad, from the rotor's x axis, where the first
   strut's wake is, turning towards y with omega > 0): the coefficients of
   cos(n Psi) and sin(n Psi) of the pressure, Psi blade 0's azimuth at the
   retarded time from the hub (as the process renders them) */
void aero_rotor_harmonic_at(const aero_rotor *r, int m, double omega,
                            double theta, double phi, double d, double *c,
                            double *s);

#endif
