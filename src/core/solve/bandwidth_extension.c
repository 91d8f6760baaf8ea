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

/* the FFT buffers and plans of one extension over n frames */
typedef struct {
    int n, nh;
    double df;
    double *t, *e;
    fftw_complex *X, *W, *z;
    fftw_plan fwd, inv, zinv;
} bandext_work;

static void work_close(bandext_work *w)
{
    if (w->fwd) fftw_destroy_plan(w->fwd);
    if (w->inv) fftw_destroy_plan(w->inv);
    if (w->zinv) fftw_destroy_plan(w->zinv);
    AERO_RELEASE_ALL(fftw_free, w->t, w->e, w->X, w->W, w->z);
}

/* 0, or -1 (out of memory: w closed) */
static int work_open(bandext_work *w, int n, double rate)
{
    memset(w, 0, sizeof *w);
    w->n = n;
    w->nh = n / 2 + 1;
    w->df = rate / n;
    w->t = fftw_malloc(sizeof(double) * (size_t)n);
    w->e = fftw_malloc(sizeof(double) * (size_t)n);
    w->X = fftw_malloc(sizeof(fftw_complex) * (size_t)w->nh);
    w->W = fftw_malloc(sizeof(fftw_complex) * (size_t)w->nh);
    w->z = fftw_malloc(sizeof(fftw_complex) * (size_t)n);
    if (w->t && w->e && w->X && w->W && w->z) {
        w->fwd = fftw_plan_dft_r2c_1d(n, w->t, w->X, FFTW_ESTIMATE);
        w->inv = fftw_plan_dft_c2r_1d(n, w->W, w->t, FFTW_ESTIMATE);
        w->zinv = fftw_plan_dft_1d(n, w->z, w->z, FFTW_BACKWARD,
                                   FFTW_ESTIMATE);
        if (w->fwd && w->inv && w->zinv)
            return 0;
    }
    work_close(w);
    return -1;
}

/* 1. the law |X|^2 = 10^icpt f^slope on third octaves of [lo, hi] (the
   spectrum of x left in w->X): the number of bands it rests on */
static int fit_law(bandext_work *w, const float *x, int stride, double lo,
                   double hi, double *slope, double *icpt)
{
    const double df = w->df;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int bands = 0;
    for (int k = 0; k < w->n; k++)
        w->t[k] = x[(size_t)k * stride];
    fftw_execute(w->fwd);
    for (double f = lo; f * 1.2599 <= hi * 1.0001; f *= 1.2599) {
        int k0 = (int)ceil(f / df), k1 = (int)floor(f * 1.2599 / df);
        double p = 0.0;
        if (k1 < k0) continue;
        for (int k = k0; k <= k1; k++)
            p += w->X[k][0] * w->X[k][0] + w->X[k][1] * w->X[k][1];
        p /= k1 - k0 + 1;
        if (!(p > 0.0)) continue;
        {
            double lx = log10(f * 1.1225), ly = log10(p);
            sx += lx; sy += ly; sxx += lx * lx; sxy += lx * ly;
            bands++;
        }
    }
    if (bands >= 3) {
        *slope = (bands * sxy - sx * sy) / (bands * sxx - sx * sx);
        *icpt = (sy - *slope * sx) / bands;
    }
    return bands;
}

/* 2. the envelope of [lo, hi] of the spectrum in w->X: |analytic signal|,
   low-passed below lo, into w->e; its mean square (w->X used up) */
static double envelope(bandext_work *w, double lo, double hi)
{
    const int n = w->n;
    const double df = w->df;
    double ms = 0.0;
    memset(w->z, 0, sizeof(fftw_complex) * (size_t)n);
    for (int k = 1; k < w->nh; k++) {
        double f = k * df;
        if (f >= lo && f <= hi) {
            w->z[k][0] = 2.0 * w->X[k][0] / n;
            w->z[k][1] = 2.0 * w->X[k][1] / n;
        }
    }
    fftw_execute(w->zinv);
    for (int k = 0; k < n; k++)
        w->t[k] = sqrt(w->z[k][0] * w->z[k][0] + w->z[k][1] * w->z[k][1]);
    fftw_execute(w->fwd);
    for (int k = 0; k < w->nh; k++) {
        double g = taper(k * df, 0.5 * lo, lo) / n;
        w->W[k][0] = w->X[k][0] * g;
        w->W[k][1] = w->X[k][1] * g;
    }
    fftw_execute(w->inv);
    for (int k = 0; k < n; k++) {
        w->e[k] = w->t[k] > 0.0 ? w->t[k] : 0.0;
        ms += w->e[k] * w->e[k];
    }
    return ms / n;
}

/* 3. noise under the envelope w->e (mean square ms), shaped to the law
   above f1 (cross-faded over [f1, f2], faded out over [f_top, 1.1 f_top]),
   added to x */
static void add_noise(bandext_work *w, float *x, int stride, double ms,
                      double rate, double f1, double f2, double f_top,
                      double slope, double icpt, uint32_t *rng)
{
    const int n = w->n;
    for (int k = 0; k < n; k++)
        w->t[k] = w->e[k] / sqrt(ms) *
                  (aero_uniform(rng) + aero_uniform(rng) + aero_uniform(rng));
    fftw_execute(w->fwd);
    for (int k = 0; k < w->nh; k++) {
        double f = k * w->df, g, tt, p;
        if (f <= f1) {
            w->W[k][0] = w->W[k][1] = 0.0;
            continue;
        }
        tt = taper(f, f1, f2);
        g = (1.0 - tt * tt) * taper(f, f_top, fmin(1.1 * f_top, 0.5 * rate));
        p = pow(10.0, icpt + slope * log10(f)); /* the law's |X|^2 */
        g = sqrt(p * g / n) / n; /* to the law, and c2r's factor n */
        w->W[k][0] = w->X[k][0] * g;
        w->W[k][1] = w->X[k][1] * g;
    }
    fftw_execute(w->inv);
    for (int k = 0; k < n; k++)
        x[(size_t)k * stride] += (float)w->t[k];
}

int aero_bandext_apply(float *x, int n, int stride, double rate, double f1,
                       double f2, double f_top, uint32_t seed,
                       aero_bandext_info *info)
{
    const double fit_lo = f1 / 4.0, fit_hi = f1;
    bandext_work w;
    double slope = 0.0, icpt = 0.0, ms;
    uint32_t rng = seed ? seed : 1;
    aero_bandext_info dummy;
    if (!info) info = &dummy;
    memset(info, 0, sizeof *info);
    if (n < 64 || stride < 1 || !(rate > 0.0) || !(f1 > 0.0) || !(f2 > f1) ||
        !(f_top >= f2) || !(f_top < 0.5 * rate) || fit_lo < 2.0 * (rate / n))
        return -1;
    info->fit_lo = fit_lo;
    info->fit_hi = fit_hi;
    if (work_open(&w, n, rate))
        return -1;
    if (fit_law(&w, x, stride, fit_lo, fit_hi, &slope, &icpt) >= 3) {
        info->slope = slope;
        /* a rising spectrum has no law to continue */
        if (slope < 0.0 && (ms = envelope(&w, fit_lo, fit_hi)) > 0.0) {
            add_noise(&w, x, stride, ms, rate, f1, f2, f_top, slope, icpt,
                      &rng);
            info->extended = 1;
        }
    }
    work_close(&w);
    return 0;
}
