/* aero: combustion noise, the roar of a flame (a model calibrated on
 * published laws; the source [vortex~] adds to its vortex sound).
 *
 * A flame's unsteady heat release Q(t) expands the gas; a flame small
 * against the wavelength is a monopole (Strahle 1971, J. Fluid Mech. 49):
 *     p(r, t) = (gamma - 1) / (4 pi c0^2 r) dQ/dt (t - r/c0),
 * gamma = 1.4. Q = P (1 + eps xi(t)): P the mean heat release (the fuel
 * power), eps = Q'_rms / P (`fluctuation`), xi a unit-rms random process
 * whose spectrum is flat below the peak frequency f_p and falls as
 * f^-4.5 above it, so that the pressure spectrum (f^2 times it) rises as
 * f^2 below f_p and falls as f^-2.5 above: the broadband shape measured
 * for open turbulent flames (Rajaram & Lieuwen 2009, J. Fluid Mech. 637,
 * high-frequency slopes scattering about -2.5). The peak follows a
 * Strouhal number on the flame's length L and its gas speed U,
 * f_p = St U / L (Rajaram & Lieuwen), so that
 *     p_rms = (gamma - 1) eps P 2 pi f_p kappa / (4 pi c0^2 r),
 * kappa = sqrt(INT x^2 S(x) dx / INT S(x) dx) of the shape S (~0.9): the
 * level grows as P f_p, their OASPL ~ (f_p m_f H)^2 and Hurle et al.'s
 * (1968, Proc. R. Soc. A 303) p ~ d(fuel consumption rate)/dt.
 *
 * xi is white noise through a 2nd-order Butterworth low-pass at f_p (the
 * f^-4) and a tilt of pole-zero pairs one per decade above it (the f^-0.5
 * more); dxi/dt comes out of the same filter with s / w_p on the
 * low-pass (a band-pass), made from the analogue prototype by the
 * bilinear transform with pre-warping, re-made when f_p moves by more
 * than 0.5 % (f_p glides at most 3 % per 64 samples). The retarded time
 * is a delay line of dQ/dt (1 s: listeners beyond 343 m hear it 1 s
 * late) read with linear interpolation at t - r/c0 for each ear; a
 * distance that changes over a block slides the read point (Doppler).
 *
 * Life cycle: init, set_*, process, free. No globals; no allocation in
 * process (init and set_sample_rate allocate). */
#ifndef AERO_COMBUSTION_NOISE_H
#define AERO_COMBUSTION_NOISE_H

#include <stddef.h>
#include <stdint.h>

#define AERO_COMBUSTION_GAMMA 1.4
#define AERO_COMBUSTION_TILTS 4   /* pole-zero pairs, one per decade */
/* ranges of the settings */
#define AERO_COMBUSTION_POWER_KW_MIN 0.0
#define AERO_COMBUSTION_POWER_KW_MAX 1e6
/* rms over the mean */
#define AERO_COMBUSTION_FLUCTUATION_MIN 0.0
#define AERO_COMBUSTION_FLUCTUATION_MAX 1.0
#define AERO_COMBUSTION_LENGTH_MIN 1e-3 /* m */
#define AERO_COMBUSTION_LENGTH_MAX 100.0
#define AERO_COMBUSTION_ST_MIN 0.01
#define AERO_COMBUSTION_ST_MAX 100.0
/* defaults: no combustion noise until a power is set */
#define AERO_COMBUSTION_POWER_KW_DEFAULT 0.0
#define AERO_COMBUSTION_LENGTH_DEFAULT 0.02 /* m */
#define AERO_COMBUSTION_ST_DEFAULT 1.0
#define AERO_COMBUSTION_FLUCTUATION_DEFAULT 0.03 /* rms over the mean */

typedef struct aero_combustion {
    double sample_rate;
    double power;        /* mean heat release P, W (0: silent) */
    double length;       /* flame length L, m */
    double strouhal;     /* f_p L / U */
    double fluctuation;  /* eps = Q'_rms / P */
    uint32_t rng;
    /* filter: section 0 the Butterworth biquad, then the tilt pairs */
    int nsec;
    double b[1 + AERO_COMBUSTION_TILTS][3], a[1 + AERO_COMBUSTION_TILTS][2];
    double z[1 + AERO_COMBUSTION_TILTS][2];
    double peak;         /* f_p the filter was made for, Hz (0: none yet) */
    double noise_scale;  /* input rms that gives unit-rms xi */
    double shape_i0;     /* INT |H(x)|^2 dx of the prototype */
    /* delay line of dQ/dt, W/s */
    float *line;
    int line_len, line_pos;
    double dist[2];      /* distance to each ear at the last block's end
                            (< 0: not yet known) */
} aero_combustion;

/* Defaults: the AERO_COMBUSTION_*_DEFAULT above (power 0: silent).
   0, or -1 when out of memory. */
int aero_combustion_init(aero_combustion *m, double sample_rate,
                         uint32_t seed);
void aero_combustion_free(aero_combustion *m);

/* 0 when accepted, -1 when invalid (the old value stays) */
int aero_combustion_set_sample_rate(aero_combustion *m, double sr);
int aero_combustion_set_power_kw(aero_combustion *m, double kw);
int aero_combustion_set_length(aero_combustion *m, double l);
int aero_combustion_set_strouhal(aero_combustion *m, double st);
int aero_combustion_set_fluctuation(aero_combustion *m, double eps); /* 0..1 */
int aero_combustion_set_seed(aero_combustion *m, uint32_t seed); /* any: 0 */

/* f_p of gas speed u (m/s): St u / L, kept within 1 Hz .. 0.2 sr */
double aero_combustion_peak_hz(const aero_combustion *m, double u);
/* the shape's kappa (see above) */
double aero_combustion_kappa(void);
/* the law: p_rms at r (m) of a flame at speed u, Pa */
double aero_combustion_rms_law(const aero_combustion *m, double u, double r);
/* Strahle's monopole: the pressure at r of a heat-release rate change */
double aero_combustion_monopole(double dqdt, double r);

/* n samples of a flame at src (x y z, m) whose gas speed is u (m/s, for
   this block), heard at nears ears (3 numbers each); ADDS the pressure
   (Pa) to out[e][0..n-1]. */
void aero_combustion_process(aero_combustion *m, double u, const double src[3],
                             const double *ears, int nears,
                             float *const *out, int n);

#endif
