/* aero: vortex sound of a turbulent box of air (Dobashi et al. 2004), the
 * offline half: one sound texture channel Q(u, t) per average flow speed
 * u.
 *
 * Howe's compact vortex-sound formula (Howe 2003, eq. 2.3.x, which
 * corrects Dobashi et al. 2004's eq. 1: c0^2 goes in the denominator and
 * the far field falls as 1/r, not 1/r^3):
 *     p(x, t) = rho0 x_a x_b / (12 pi c0^2 |x|^3) d^3/dt^3 S_ab(t - r/c0),
 *     S_ab = INT y_a (y x omega)_b dy,
 * with y measured from the source volume's centre. A texture holds the
 * pressure at r = 1 m, Q = rho0 / (12 pi c0^2) xh_a xh_b S'''_ab (Pa m),
 * so that a player radiates p = Q(u, t - r/c0) / r.
 *
 * Two ways to evaluate the integral:
 *  - window (default): one origin at the box centre, the integrand
 *    multiplied by a smooth (C-infinity) window that vanishes at the
 *    inflow, the open top and the periodic sides. Eddies fade in and out
 *    of the source volume smoothly instead of jumping across a boundary
 *    (a jump makes a click in a third derivative), and the inflow's
 *    imposed perturbation is not counted as sound. A pattern convected
 *    unchanged through a uniform flow gives a moment quadratic in t, whose
 *    third derivative is zero: only changing vorticity radiates.
 *  - cells: the paper's integral cells (eq. 3-4): each voxel l carries the
 *    moment of its 27-voxel neighbourhood about its own centre, weighted
 *    by w(r) = exp(-alpha r) / sum exp(-alpha r') (alpha = 3, r in
 *    voxels). Written out, every voxel whose whole neighbourhood lies in
 *    the box contributes exactly zero (the neighbourhood's second moment
 *    is isotropic, and x_a x_b eps_bcd delta_ac = 0), so only the voxels
 *    on the box faces make sound: the method measures the boundary, not
 *    the turbulence (tests/unit/test_vortex_sound.c shows it). Kept for
 *    comparison (`aerotex vortex --source cells`).
 *
 * Averaging receivers: the direction average of a quadrupole's pressure
 * is zero (S_ab is traceless in the sense that matters: the trace of
 * y_a (y x omega)_b vanishes), so averaging the receivers' pressures, as
 * the paper does, cancels most of the sound. The texture is the average
 * over the virtual receivers (a ring around the box), rescaled so that its
 * mean square equals the receivers' mean square.
 *
 * Third derivative: a linear-phase FIR filter (i 2 pi f)^3 T(f) with a
 * raised-cosine taper T that is 1 up to 0.2 and 0 above 0.35 of the
 * solver's step rate (the grid resolves eddies of ~2 cells, advected at U:
 * f <~ U / (2 h) = cfl / 2 of the step rate), so step-to-step noise is not
 * amplified by f^3. Then a band-limited (windowed-sinc) resampling to the
 * texture rate.
 *
 * No globals; the simulation allocates its own solver. */
#ifndef AERO_VORTEX_SOUND_H
#define AERO_VORTEX_SOUND_H

#include "flow3d.h"

#include <stddef.h>
#include <stdint.h>

enum { AERO_VORTEX_WINDOW = 0, AERO_VORTEX_CELLS = 1 };

typedef struct {
    double speed;        /* average inflow speed u, m/s */
    double box;          /* box width (x, y), m */
    int n;               /* cells across the width */
    int nz;              /* cells along the flow (height) */
    double nu;           /* kinematic viscosity, m^2/s */
    double confinement;  /* vorticity confinement eps: a = eps (h / box)
                            u (N x omega) (flow3d.h) */
    double turbulence;   /* rms inflow perturbation / u */
    double cfl;          /* step = cfl h / u */
    double settle;       /* start-up discarded, in flow-through times */
    int receivers;       /* virtual receivers on a ring */
    double elevation;    /* of the ring, deg */
    int source;          /* AERO_VORTEX_WINDOW or AERO_VORTEX_CELLS */
    uint32_t seed;
    /* FFTW's planner is not thread-safe: when simulations run in
       parallel, this (if set) is called with on = 1 before and on = 0
       after the solver's init and free, with the ctx of simulate */
    void (*plan_lock)(void *ctx, int on);
} aero_vortex_params;

/* defaults: u 4 m/s, box 0.1 m, 32 x 32 x 48 cells, air, eps 9.6 (the
   forcing eps 0.3 had at 32 cells before it scaled with h),
   turbulence 0.3, cfl 0.5, settle 3, 8 receivers at 0 deg, window, seed 1 */
void aero_vortex_defaults(aero_vortex_params *p);

/* what a simulation measured */
typedef struct {
    long steps;          /* solver steps, start-up included */
    double dt;           /* solver step, s */
    double rms;          /* of the texture channel, Pa at 1 m */
    double receiver_rms; /* mean over receivers (rms of the ring average
                            before the level correction: rms / gain) */
    double gain;         /* the level correction */
    double max_div;      /* largest |div u| h after the last step, m/s */
    double mean_vort;    /* mean |omega| in the window, 1/s */
} aero_vortex_stats;

/* called every `every` steps (may be NULL): progress and snapshots */
typedef void (*aero_vortex_hook)(void *ctx, const aero_flow3d *s, long step,
                                 int recording);

/* Runs the box at p->speed and writes nout samples of Q (Pa at 1 m) at
   `rate` Hz to out[k * stride]. 0, or -1 with a message in err. */
int aero_vortex_simulate(const aero_vortex_params *p, double rate,
                         float *out, int stride, int nout,
                         aero_vortex_stats *st, aero_vortex_hook hook,
                         long every, void *ctx, char *err, size_t errlen);
/* solver steps a simulation of nout samples will take */
long aero_vortex_steps(const aero_vortex_params *p, double rate, int nout);

/* --- the building blocks (also used by the tests) ---------------------- */

/* smooth window on [0, 1]: 0 below `margin` and above 1 - margin, 1
   between margin + ramp and 1 - margin - ramp, C-infinity in between */
double aero_vortex_window1d(double s, double margin, double ramp);
/* the box's window, one value per cell (nx * ny * nz) */
void aero_vortex_window(const aero_flow3d *s, float *win);
/* S_ab = sum win y_a (y x omega)_b h^3 about the box centre, from the
   solver's cell vorticity (aero_flow3d_vorticity first); out: the
   symmetric part xx yy zz xy xz yz (m^5/s) */
void aero_vortex_moment(const aero_flow3d *s, const float *win,
                        double sym[6]);
/* the paper's integral cells (eq. 3-4) for a receiver at x (m, from the
   box centre): sum over voxels l and their neighbours k of
   w(r_k) f(x - y_l, y_k - y_l) h^3, f = ((x-y_l).(y_k-y_l))
   (((y_k-y_l) x omega_k).(x-y_l)) (m^7/s), alpha per voxel */
double aero_vortex_cells(const aero_flow3d *s, const double x[3],
                         double alpha);
/* xh_a xh_b S_ab for the symmetric part */
double aero_vortex_contract(const double sym[6], const double xh[3]);

/* FIR third derivative, per sample^3: h[0..2K], centre K, response
   (i 2 pi nu)^3 T(nu), T 1 below nu1, 0 above nu2 (cycles per sample) */
void aero_vortex_d3_kernel(double *h, int K, double nu1, double nu2);
/* band-limited resampling of x (n samples at rate_in, x[0] at time 0):
   nout samples at rate_out from time t0, cut-off 0.45 min(rate_in,
   rate_out); out[k * stride] */
void aero_vortex_resample(const double *x, int n, double rate_in, double t0,
                          double rate_out, float *out, int stride, int nout);

#endif
