/* aero: spectral bandwidth extension of a looped texture (see
 * bandwidth_extension.h). */
#include "bandwidth_extension.h"
#include "aero_air.h"
#include "aero_util.h"

#include <fftw3.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* raised-cosine taper: 1 below a, 0 above b */
static double taper(double f, double a, double b)
{
    if (f <= a) return 1.0;
    if (f >= b) return 0.0;
    return 0.5 + 0.5 * cos(AERO_PI * (f - a) / (b - a));
}

int aero_bandext_apply(float *x, int n, int stride, double rate, double f1,
                       double f2, double f_top, uint32_t seed,
                       aero_bandext_info *info)
{
    const int nh = n / 2 + 1;
    const double df = rate / n, fit_lo = f1 / 4.0, fit_hi = f1;
    double *t = NULL, *e = NULL;
    fftw_complex *X = NULL, *W = NULL, *z = NULL;
    fftw_plan fwd = NULL, inv = NULL, zinv = NULL;
    double sx = 0, sy = 0, sxx = 0, sxy = 0, slope, icpt, ms = 0.0;
    int bands = 0, status = -1;
    uint32_t rng = seed ? seed : 1;
    aero_bandext_info dummy;
    if (!info) info = &dummy;
    memset(info, 0, sizeof *info);
    if (n < 64 || stride < 1 || !(rate > 0.0) || !(f1 > 0.0) || !(f2 > f1) ||
        !(f_top >= f2) || !(f_top < 0.5 * rate) || fit_lo < 2.0 * df)
        return -1;
    info->fit_lo = fit_lo;
    info->fit_hi = fit_hi;
    t = fftw_malloc(sizeof(double) * (size_t)n);
    e = fftw_malloc(sizeof(double) * (size_t)n);
    X = fftw_malloc(sizeof(fftw_complex) * (size_t)nh);
    W = fftw_malloc(sizeof(fftw_complex) * (size_t)nh);
    z = fftw_malloc(sizeof(fftw_complex) * (size_t)n);
    if (!t || !e || !X || !W || !z)
        goto out;
    fwd = fftw_plan_dft_r2c_1d(n, t, X, FFTW_ESTIMATE);
    inv = fftw_plan_dft_c2r_1d(n, W, t, FFTW_ESTIMATE);
    zinv = fftw_plan_dft_1d(n, z, z, FFTW_BACKWARD, FFTW_ESTIMATE);
    if (!fwd || !inv || !zinv)
        goto out;

    /* 1. the law on the top two octaves of the resolved band */
    for (int k = 0; k < n; k++)
        t[k] = x[(size_t)k * stride];
    fftw_execute(fwd);
    for (double f = fit_lo; f * 1.2599 <= fit_hi * 1.0001; f *= 1.2599) {
        int k0 = (int)ceil(f / df), k1 = (int)floor(f * 1.2599 / df);
        double p = 0.0;
        if (k1 < k0) continue;
        for (int k = k0; k <= k1; k++)
            p += X[k][0] * X[k][0] + X[k][1] * X[k][1];
        p /= k1 - k0 + 1;
        if (!(p > 0.0)) continue;
        {
            double lx = log10(f * 1.1225), ly = log10(p);
            sx += lx; sy += ly; sxx += lx * lx; sxy += lx * ly;
            bands++;
        }
    }
    status = 0;
    if (bands < 3)
        goto out;
    slope = (bands * sxy - sx * sy) / (bands * sxx - sx * sx);
    icpt = (sy - slope * sx) / bands;
    info->slope = slope;
    if (!(slope < 0.0))
        goto out; /* nothing to continue */

    /* 2. the band's envelope: |analytic signal|, low-passed */
    memset(z, 0, sizeof(fftw_complex) * (size_t)n);
    for (int k = 1; k < nh; k++) {
        double f = k * df;
        if (f >= fit_lo && f <= fit_hi) {
            z[k][0] = 2.0 * X[k][0] / n;
            z[k][1] = 2.0 * X[k][1] / n;
        }
    }
    fftw_execute(zinv);
    for (int k = 0; k < n; k++)
        t[k] = sqrt(z[k][0] * z[k][0] + z[k][1] * z[k][1]);
    fftw_execute(fwd); /* t -> X (the signal's spectrum is used up) */
    for (int k = 0; k < nh; k++) {
        double g = taper(k * df, 0.5 * fit_lo, fit_lo) / n;
        W[k][0] = X[k][0] * g;
        W[k][1] = X[k][1] * g;
    }
    fftw_execute(inv);
    for (int k = 0; k < n; k++) {
        e[k] = t[k] > 0.0 ? t[k] : 0.0;
        ms += e[k] * e[k];
    }
    ms /= n;
    if (!(ms > 0.0))
        goto out;
    /* 3. enveloped noise with the law's spectrum above the band */
    for (int k = 0; k < n; k++)
        t[k] = e[k] / sqrt(ms) *
               (aero_uniform(&rng) + aero_uniform(&rng) + aero_uniform(&rng));
    fftw_execute(fwd);
    for (int k = 0; k < nh; k++) {
        double f = k * df, g, tt, p;
        if (f <= f1) {
            W[k][0] = W[k][1] = 0.0;
            continue;
        }
        tt = taper(f, f1, f2);
        g = (1.0 - tt * tt) * taper(f, f_top, fmin(1.1 * f_top, 0.5 * rate));
        p = pow(10.0, icpt + slope * log10(f)); /* the law's |X|^2 */
        g = sqrt(p * g / n) / n; /* to the law, and c2r's factor n */
        W[k][0] = X[k][0] * g;
        W[k][1] = X[k][1] * g;
    }
    fftw_execute(inv);
    for (int k = 0; k < n; k++)
        x[(size_t)k * stride] += (float)t[k];
    info->extended = 1;
out:
    if (fwd) fftw_destroy_plan(fwd);
    if (inv) fftw_destroy_plan(inv);
    if (zinv) fftw_destroy_plan(zinv);
    fftw_free(t);
    fftw_free(e);
    fftw_free(X);
    fftw_free(W);
    fftw_free(z);
    return status;
}
