/* aero: the sound of a tree's branches in the wind (Matsuyama et al. 2005,
 * section "Generation of Branch Sound"), in real time.
 *
 * Every branch (internode) of a tree (tree.h) moves with the wind
 * (tree_motion.h). Once per synthesis frame, for every branch:
 *   - the wind relative to the branch, U_rel = W - v, at both ends, and its
 *     component perpendicular to the (moved) branch axis, U;
 *   - the shedding frequency f = St(Re) U / d at each end (St ~ 0.2 for
 *     4e2 < Re < 2e5, their eq. 5; St(Re) of strouhal.h, silent below
 *     Re ~ 47) and the radiated power per unit length at each end,
 *     p^2 ~ (rho St C_L' U^3 / (4 c0))^2 L_c / 3 (Curle, a compact lift
 *     dipole coherent over L_c = 3 d, averaged over directions as Matsuyama
 *     et al. treat the branch as non-directional): amplitude ~ U^3 sqrt(l) /
 *     r (Curle 1955; their eq. 6 is an intensity law);
 *   - the "frequency group" between the two ends: frequency and power
 *     interpolated linearly along the branch (their Fig. 8), integrated
 *     so the group's total power does not depend on the FFT resolution;
 *   - the high-frequency tail I = I_0 (f / f_0)^-alpha above the group's
 *     top frequency f_0 (their eq. 8), as a spectral density.
 * All branches are summed as powers in one spectrum (their phases are
 * random and independent, so their powers add), given random phases and
 * turned into sound by one inverse FFT per frame (FFTW, planned at init),
 * Gaussian-windowed (their eq. 7) and overlap-added with a hop of 1/8
 * frame, where the shifted Gaussians sum to a constant (ripple < 1e-7), so
 * frames join without clicks or tremolo.
 *
 * Rendering (their section "Sound Rendering"): the tree's sound, as pressure
 * at 1 m, is written to a delay line and read at the distance d from the
 * listener to the trunk (the midpoint of the first root branch) by a moving
 * stylus (Doppler follows), scaled by 1/d (amplitude; their (d0/d)^2 is an
 * intensity law) and by the cardioid microphone S(mu) = ((1 + cos mu)/2)^k
 * (eq. 16), mu the angle between the mic's axis and the direction from the
 * mic to the tree. Mono, or two ears.
 *
 * Life cycle: init, set_tree, set_*, process, free. No globals. */
#ifndef AERO_TREEBRANCH_H
#define AERO_TREEBRANCH_H

#include "aero_ears.h"
#include "tree.h"
#include "tree_motion.h"

/* ranges of the settings, stated once: the core checks them, the hosts
   quote them (stiffness and beta: tree_motion.h; gain, ramp:
   aero_ranges.h) */
#define AERO_TREEBRANCH_ALPHA_MIN 0.5
#define AERO_TREEBRANCH_ALPHA_MAX 8.0
#define AERO_TREEBRANCH_MIC_K_MIN 0.0
#define AERO_TREEBRANCH_MIC_K_MAX 20.0
/* defaults (stiffness and beta: tree_motion.h; gain and ramp:
   aero_ranges.h) */
#define AERO_TREEBRANCH_ALPHA_DEFAULT 2.0
#define AERO_TREEBRANCH_MIC_K_DEFAULT 1.0 /* a cardioid */

#include <stdint.h>

typedef struct aero_treebranch_fft aero_treebranch_fft; /* FFTW, private */

typedef struct aero_treebranch {
    double sample_rate;
    uint32_t seed, rng;
    int has_tree;
    aero_tree tree;            /* owned */
    aero_tree_motion motion;
    double source[3];          /* where distance is measured from */

    /* parameters */
    double wind[3];            /* m/s */
    double speed_dir[3];       /* unit: the direction speeds blow along */
    double speed;              /* the last speed given, m/s */
    double alpha;              /* tail exponent */
    double mic_k;              /* cardioid exponent */
    double mic_dir[3];         /* unit axis; 0 0 0: aimed at the tree */
    double gain;               /* linear */
    double ramp_samples;
    int stereo;
    double ear_target[2][3], ear[2][3]; /* listener (ear 0) or two ears */
    double ramp_left;

    /* synthesis */
    int fft_size, hop, nbins;
    double bin_hz;
    double *power;             /* per bin, this frame */
    double *tail_start;        /* tail coefficients entering at each bin */
    double *tail_shape;        /* f_k^-alpha */
    float *window;             /* Gaussian, normalised for power */
    float *ola;                /* overlap-add accumulator, fft_size */
    aero_treebranch_fft *fft;
    int frames;                /* frames made so far */

    /* the delay line: the tree's sound at 1 m */
    float *ring;
    long ring_len;
    long long written, now;    /* samples made / samples output */
    double delay[2], level[2]; /* current, per ear: samples and factor */
    aero_near near; /* a listener came within 0.1 m (aero_near_field) */
} aero_treebranch;

/* Defaults: no tree (silent), wind 0, the constants above with the mic
 * aimed at the tree, listener at (0, -10, 1.7), mono.
 * 0, or -1 when out of memory (then silent). */
int aero_treebranch_init(aero_treebranch *tb, double sample_rate,
                         uint32_t seed);
void aero_treebranch_free(aero_treebranch *tb);

/* takes the tree over (it is freed by the object; *t is emptied);
   0, or -1 (no branch, out of memory: silent) */
int aero_treebranch_set_tree(aero_treebranch *tb, aero_tree *t);

/* Setters: 0 when accepted, -1 when invalid (the old value stays). */
int aero_treebranch_set_sample_rate(aero_treebranch *tb, double sr);
/* wind vector, m/s; its speed is clamped to Mach 0.3: returns 1 then */
int aero_treebranch_set_wind(aero_treebranch *tb, const double w[3]);
/* the wind as a speed along speed_dir (+x until set_direction): sets the
   wind vector; 1 when clamped (Mach 0.3), -1 when not finite */
int aero_treebranch_set_speed(aero_treebranch *tb, double speed);
/* the direction of later speeds (not the wind now); 0, or -1 when zero or
   not finite */
int aero_treebranch_set_direction(aero_treebranch *tb, const double d[3]);
int aero_treebranch_set_alpha(aero_treebranch *tb, double alpha);
int aero_treebranch_set_stiffness(aero_treebranch *tb, double s);
int aero_treebranch_set_beta(aero_treebranch *tb, double beta);
int aero_treebranch_set_gain_db(aero_treebranch *tb, double db);
int aero_treebranch_set_ramp_ms(aero_treebranch *tb, double ms);
int aero_treebranch_set_mic(aero_treebranch *tb, const double dir[3]);
int aero_treebranch_set_mic_k(aero_treebranch *tb, double k);
/* e->n 1: the listener (in stereo the head moves there, the ears keep
   their spacing); 2: left and right ear (used in stereo; mono hears the
   left). Positions finite, within 1e5 m. */
int aero_treebranch_set_ears(aero_treebranch *tb, const aero_ears *e);
void aero_treebranch_set_stereo(aero_treebranch *tb, int stereo);
/* restarts the motion and the phases from this seed (allocates: not from
   the audio thread); 0 or -1 */
int aero_treebranch_set_seed(aero_treebranch *tb, uint32_t seed);

/* n samples of pressure at the listener (Pa): out0 (left / mono), out1
   (right, may be NULL when mono) */
void aero_treebranch_process(aero_treebranch *tb, float *out0, float *out1,
                             int n);
/* the same, with the wind's speed along speed_dir from the mean of speed[0..
   n-1] (m/s; NULL: the wind as set; a block whose mean is not finite or
   beyond 1e30 counts as 0), read before any output (speed may alias
   out0); 1 when that speed was clamped (Mach 0.3) */
int aero_treebranch_process_speed(aero_treebranch *tb, const float *speed,
                                  float *out0, float *out1, int n);

/* one frame's spectrum for tests: per-bin power (Pa^2 at 1 m, before
   rendering), nbins values, from the current motion and wind; returns
   nbins or -1 */
int aero_treebranch_frame_power(aero_treebranch *tb, double *power,
                                int max_bins);

/* For a host that builds a new core in a worker and swaps it in (Pd's
   [treebranch~]): the settings of src (wind, speed and its direction,
   alpha, mic, gain, ramp, stereo, ears, stiffness, beta) given to
   dst, reading only src's numbers (src may be a copy of a live core made
   in the host's thread); not the seed, which restarts the motion (the
   host builds a core with a new seed in the worker too). 0, or -1. */
int aero_treebranch_copy_settings(aero_treebranch *dst,
                                  const aero_treebranch *src);
/* moves src's whole state into dst (dst's own is overwritten, not freed);
   src is left empty (free it or init it again) */
void aero_treebranch_move(aero_treebranch *dst, aero_treebranch *src);

#endif
