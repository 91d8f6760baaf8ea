/* aero: the band limit of a looped texture (see band_limit.h). */
#include "band_limit.h"
#include "aero_air.h"

#include <fftw3.h>
#include <math.h>
#include <stddef.h>

void aero_band_limit_grid(double v0, double h, double *f_pass,
                          double *f_stop)
{
    *f_pass = v0 / (AERO_BAND_LIMIT_CELLS_PASS * h);
    *f_stop = v0 / (AERO_BAND_LIMIT_CELLS_STOP * h);
}

int aero_band_limit_apply(float *x, int n, int stride, double rate,
                          double f_pass, double f_stop)
{
    const int nh = n / 2 + 1;
    double *t;
    fftw_complex *X;
    fftw_plan fwd = NULL, inv = NULL;
    int status = -1;
    if (!x || n < 2 || stride < 1 || !(rate > 0.0) || !(f_pass > 0.0) ||
        !(f_stop > f_pass) || !isfinite(f_stop))
        return -1;
    if (f_pass >= 0.5 * rate)
        return 0;
    t = fftw_malloc(sizeof(double) * (size_t)n);
    X = fftw_malloc(sizeof(fftw_complex) * (size_t)nh);
    if (t && X) {
        fwd = fftw_plan_dft_r2c_1d(n, t, X, FFTW_ESTIMATE);
        inv = fftw_plan_dft_c2r_1d(n, X, t, FFTW_ESTIMATE);
    }
    if (fwd && inv) {
        for (int k = 0; k < n; k++)
            t[k] = x[(size_t)k * stride];
        fftw_execute(fwd);
        /* a real gain: zero phase; 1/n undoes c2r's factor */
        for (int k = 0; k < nh; k++) {
            double g = aero_band_limit_gain(k * rate / n, f_pass, f_stop) / n;
            X[k][0] *= g;
            X[k][1] *= g;
        }
        fftw_execute(inv);
        for (int k = 0; k < n; k++)
            x[(size_t)k * stride] = (float)t[k];
        status = 0;
    }
    if (fwd) fftw_destroy_plan(fwd);
    if (inv) fftw_destroy_plan(inv);
    fftw_free(t);
    fftw_free(X);
    return status;
}
