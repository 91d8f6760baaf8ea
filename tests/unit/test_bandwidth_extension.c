/* aero: tests of the spectral bandwidth extension
 * (src/core/bandwidth_extension.c, after Chadwick & James 2011) on a
 * synthetic texture: noise with |X|^2 ~ f^-3 up to a simulation-like
 * taper (1 kHz .. 1.75 kHz), its level breathing at 6 Hz. The extension
 * must leave the physical band below f1 untouched, continue the law
 * above it (slope and level) up to f_top, carry the band's envelope, and
 * add nothing to a spectrum that still rises. */
#include "unit.h"
#include "aero_air.h"
#include "aero_util.h"
#include "bandwidth_extension.h"

#include <fftw3.h>
#include <stdlib.h>
#include <string.h>

#define RATE 32000.0
#define N 16000 /* 0.5 s: the 6 Hz breathing loops (3 cycles) */

static double *spectrum(const float *x, fftw_complex *X)
{
    double *t = fftw_malloc(sizeof(double) * N);
    fftw_plan p = fftw_plan_dft_r2c_1d(N, t, X, FFTW_ESTIMATE);
    for (int k = 0; k < N; k++) t[k] = x[k];
    fftw_execute(p);
    fftw_destroy_plan(p);
    return t;
}

/* synthetic texture with |X|^2 ~ f^expo, tapered from f1 to f2 */
static void make(float *x, double expo, double f1, double f2, uint32_t seed)
{
    double *t = fftw_malloc(sizeof(double) * N);
    fftw_complex *X = fftw_malloc(sizeof(fftw_complex) * (N / 2 + 1));
    fftw_plan p = fftw_plan_dft_c2r_1d(N, X, t, FFTW_ESTIMATE);
    uint32_t rng = seed;
    for (int k = 0; k <= N / 2; k++) {
        double f = k * RATE / N, a = 0.0, ph = AERO_PI * aero_uniform(&rng);
        if (f >= 20.0) {
            double tt = f <= f1 ? 1.0 : f >= f2 ? 0.0
                        : 0.5 + 0.5 * cos(AERO_PI * (f - f1) / (f2 - f1));
            a = pow(f, 0.5 * expo) * tt;
        }
        X[k][0] = a * cos(ph);
        X[k][1] = a * sin(ph);
    }
    fftw_execute(p);
    for (int k = 0; k < N; k++)
        x[k] = (float)(t[k] * (1.0 + 0.8 * sin(2.0 * AERO_PI * 6.0 * k / RATE)));
    fftw_destroy_plan(p);
    fftw_free(t);
    fftw_free(X);
}

static double band_power(fftw_complex *X, double f0, double f1)
{
    int k0 = (int)ceil(f0 * N / RATE), k1 = (int)floor(f1 * N / RATE);
    double s = 0.0;
    for (int k = k0; k <= k1; k++) s += X[k][0] * X[k][0] + X[k][1] * X[k][1];
    return s / (k1 - k0 + 1);
}

static double slope_of(fftw_complex *X, double f0, double f1)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int m = 0;
    for (double f = f0; f * 1.26 <= f1 * 1.0001; f *= 1.26) {
        double lx = log10(f * 1.122), ly = log10(band_power(X, f, f * 1.26));
        sx += lx; sy += ly; sxx += lx * lx; sxy += lx * ly; m++;
    }
    return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

UNIT_TEST(falling_spectrum_extended)
{
    float *x = malloc(sizeof(float) * N), *y = malloc(sizeof(float) * N);
    fftw_complex *X = fftw_malloc(sizeof(fftw_complex) * (N / 2 + 1));
    fftw_complex *Y = fftw_malloc(sizeof(fftw_complex) * (N / 2 + 1));
    aero_bandext_info info;
    double worst = 0.0, law1k, s_out, lev, want;

    printf("bandwidth extension of a f^-3 texture tapered at 1-1.75 kHz\n");
    make(x, -3.0, 1000.0, 1750.0, 5);
    memcpy(y, x, sizeof(float) * N);
    UNIT_CHECK(aero_bandext_apply(y, N, 1, RATE, 1000.0, 1750.0, 14000.0, 9,
                                  &info) == 0 && info.extended,
               "extended: fitted slope %.2f on %g-%g Hz", info.slope,
               info.fit_lo, info.fit_hi);
    UNIT_CHECK(fabs(info.slope + 3.0) < 0.3,
               "the law found: |X|^2 ~ f^%.2f (made as f^-3)", info.slope);
    fftw_free(spectrum(x, X));
    fftw_free(spectrum(y, Y));
    /* from 50 Hz (below, the synthetic band is empty: float rounding of
       the sum is all that differs there) */
    for (int k = 25; k * RATE / N < 1000.0; k++) {
        double a = hypot(X[k][0], X[k][1]),
               d = hypot(Y[k][0] - X[k][0], Y[k][1] - X[k][1]);
        if (a > 0.0 && d / a > worst) worst = d / a;
    }
    UNIT_CHECK(worst < 1e-4, "the physical band below f1 untouched: largest "
               "relative change of a bin %.2g", worst);
    s_out = slope_of(Y, 2500.0, 12000.0);
    UNIT_CHECK(fabs(s_out + 3.0) < 0.3,
               "the extension continues the law: f^%.2f over 2.5-12 kHz",
               s_out);
    /* its level: the law extrapolated from the band below f1 */
    law1k = band_power(X, 700.0, 1000.0) / pow(836.0, -3.0);
    lev = band_power(Y, 4000.0, 8000.0);
    want = law1k * pow(5657.0, -3.0);
    UNIT_CHECK(fabs(10.0 * log10(lev / want)) < 2.0,
               "4-8 kHz at the law's level: %+.2f dB",
               10.0 * log10(lev / want));
    UNIT_CHECK(band_power(Y, 15500.0, 15900.0) <
                   1e-3 * band_power(Y, 12000.0, 13000.0),
               "nothing above 1.1 f_top");
    {
        /* the breathing carried up: 20 ms rms of the added high band
           follows 1 + 0.8 sin(2 pi 6 t) */
        double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
        int m = 0;
        for (int w = 0; w + 640 <= N; w += 640) {
            double r = 0.0, env;
            for (int k = w; k < w + 640; k++) {
                double d = y[k] - x[k];
                r += d * d;
            }
            r = sqrt(r / 640);
            env = 1.0 + 0.8 * sin(2.0 * AERO_PI * 6.0 * (w + 320) / RATE);
            sa += r; sb += env; saa += r * r; sbb += env * env; sab += r * env;
            m++;
        }
        double c = (m * sab - sa * sb) /
                   sqrt((m * saa - sa * sa) * (m * sbb - sb * sb));
        UNIT_CHECK(c > 0.8, "the extension's envelope follows the band's: "
                   "correlation %.2f", c);
    }
    free(x);
    free(y);
    fftw_free(X);
    fftw_free(Y);
}

UNIT_TEST(rising_spectrum_left_alone)
{
    float *x = malloc(sizeof(float) * N), *y = malloc(sizeof(float) * N);
    aero_bandext_info info;

    make(x, 1.0, 1000.0, 1750.0, 6);
    memcpy(y, x, sizeof(float) * N);
    aero_bandext_apply(y, N, 1, RATE, 1000.0, 1750.0, 14000.0, 9, &info);
    UNIT_CHECK(!info.extended && memcmp(x, y, sizeof(float) * N) == 0,
               "slope %+.2f: not extended, unchanged", info.slope);
    UNIT_CHECK(aero_bandext_apply(y, N, 1, RATE, 1000.0, 900.0, 14000.0, 9,
                                  NULL) == -1 &&
                   aero_bandext_apply(y, N, 1, RATE, 1000.0, 1750.0, 17000.0,
                                      9, NULL) == -1,
               "bad bands refused");
    free(x);
    free(y);
}

UNIT_MAIN(UNIT_CASE(falling_spectrum_extended),
          UNIT_CASE(rising_spectrum_left_alone))
