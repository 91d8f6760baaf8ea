/* aero: 2D section to 3D body, calibrated on the circular cylinder (see
 * span3d.h). */
#include "span3d.h"

#include "aero_air.h"
#include "strouhal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void aero_span3d_none(aero_span3d *c, double re)
{
    memset(c, 0, sizeof *c);
    c->re = re;
    c->frequency_scale = c->force_scale = 1.0;
}

int aero_span3d_calibrate(aero_span3d *c, double re, double st_2d_circle,
                          double cl_rms_2d_circle)
{
    aero_span3d_none(c, re);
    c->st_2d = st_2d_circle;
    c->cl_rms_2d = cl_rms_2d_circle;
    c->st_ref = aero_strouhal(re);
    c->cl_rms_ref = aero_lift_rms(re);
    if (!(st_2d_circle > 0.0) || !(cl_rms_2d_circle > 1e-3) || !(re > AERO_RE_ONSET))
        return -1;
    if (re <= AERO_SPAN3D_RE_2D)
        return 0;
    c->frequency_scale = c->st_ref / st_2d_circle;
    c->force_scale = c->cl_rms_ref / cl_rms_2d_circle;
    c->applied = 1;
    return 0;
}

/* power of the Hann-windowed segment [i0, i0 + m) of x at frequency f
   (cycles per sample) */
static double segment_power(const double *x, const double *win, int i0, int m,
                            double f)
{
    double re = 0, im = 0, w = 2.0 * AERO_PI * f;
    double cr = cos(w), ci = sin(w), pr = 1.0, pi = 0.0;
    for (int k = 0; k < m; k++) {
        double a = x[i0 + k] * win[k];
        re += a * pr;
        im += a * pi;
        double t = pr * cr - pi * ci;
        pi = pr * ci + pi * cr;
        pr = t;
    }
    return re * re + im * im;
}

/* c(t) linearly interpolated at m uniform times t[0] + k step, its mean
   removed */
static void resample_uniform(const double *t, const double *c, int n,
                             double step, double *x, int m)
{
    double mean = 0;
    for (int k = 0, i = 0; k < m; k++) {
        double tk = t[0] + k * step;
        while (i < n - 2 && t[i + 1] < tk)
            i++;
        double a = (tk - t[i]) / (t[i + 1] - t[i]);
        a = a < 0 ? 0 : a > 1 ? 1 : a;
        x[k] = c[i] + a * (c[i + 1] - c[i]);
        mean += x[k];
    }
    mean /= m;
    for (int k = 0; k < m; k++)
        x[k] -= mean;
}

/* does scan point k stand 10 x above the mean power on either side of it
   (St / 2 to St and St to 2 St, without its own Hann main lobe, +-2
   resolutions = +-8 scan steps)? */
static int is_tonal(const double *power, int nf, int k, double st_min,
                    double df)
{
    double st_k = st_min + k * df, below = 0, above = 0;
    int lo = (int)((st_k / 2.0 - st_min) / df), nb = 0, na = 0;
    int hi = (int)((st_k * 2.0 - st_min) / df);
    if (lo < 0) lo = 0;
    if (hi > nf - 1) hi = nf - 1;
    for (int q = lo; q < k - 8; q++, nb++)
        below += power[q];
    for (int q = k + 9; q <= hi; q++, na++)
        above += power[q];
    return !(nb == 0 || na == 0 || power[k] < 10.0 * below / nb ||
             power[k] < 10.0 * above / na);
}

/* the strongest tonal peak inside the scan: a slow drift of the force (an
   irregular wake wanders) can hold more power at low frequencies than the
   shedding, at the scan's edge or in the random maxima of its falling
   spectrum; without a tonal peak, the strongest interior maximum. Its
   index, or -1 (*best its power) */
static int strongest_peak(const double *power, int nf, double st_min,
                          double df, double *best)
{
    int best_k = -1;
    *best = 0;
    for (int pass = 0; pass < 2 && best_k < 0; pass++)
        for (int k = 1; k < nf - 1; k++) {
            if (!(power[k] > power[k - 1] && power[k] >= power[k + 1] &&
                  power[k] > *best))
                continue;
            if (!pass && !is_tonal(power, nf, k, st_min, df))
                continue;
            *best = power[k];
            best_k = k;
        }
    return best_k;
}

/* the peak's St, refined by a parabola through the log powers around it */
static double refine_peak(const double *power, int nf, int best_k,
                          double st_min, double df)
{
    double best_st = best_k >= 0 ? st_min + best_k * df : 0.0;
    if (best_k > 0 && best_k < nf - 1 && power[best_k - 1] > 0 &&
        power[best_k + 1] > 0) {
        double a = log(power[best_k - 1]), b = log(power[best_k]),
               e = log(power[best_k + 1]);
        double den = a - 2.0 * b + e;
        if (den < 0)
            best_st += 0.5 * df * (a - e) / den;
    }
    return best_st;
}

double aero_spectral_st(const double *t, const double *c, int n,
                        double st_min, double st_max)
{
    if (n < 64 || !(t[n - 1] > t[0]) || !(st_max > st_min) || !(st_min > 0))
        return 0.0;
    /* uniform resampling at ~ the mean step, at least 8 points per period
       of st_max */
    double span = t[n - 1] - t[0];
    double step = span / (n - 1);
    if (step > 0.125 / st_max)
        step = 0.125 / st_max;
    int m = (int)(span / step);
    if (m > 1 << 16) {
        m = 1 << 16;
        step = span / m;
    }
    int seg = m / 2;
    /* scan in steps of a quarter of the segment's frequency resolution */
    double df = 0.25 / (seg * step), best;
    int nf = (int)((st_max - st_min) / df) + 1, best_k = -1;
    double *x = malloc(sizeof(double) * (size_t)m);
    double *win = malloc(sizeof(double) * (size_t)(m / 2 + 1));
    double *power = malloc(sizeof(double) * (size_t)nf);
    if (x && win && power) {
        resample_uniform(t, c, n, step, x, m);
        for (int k = 0; k < seg; k++)
            win[k] = 0.5 - 0.5 * cos(2.0 * AERO_PI * k / seg);
        /* three Hann-windowed half-length segments, overlapping (Welch
           1967) */
        for (int k = 0; k < nf; k++) {
            double f = (st_min + k * df) * step;
            power[k] = 0;
            for (int s = 0; s < 3; s++)
                power[k] += segment_power(x, win, s * (m - seg) / 2, seg, f);
        }
        best_k = strongest_peak(power, nf, st_min, df, &best);
    }
    double best_st = best_k >= 0 ? refine_peak(power, nf, best_k, st_min, df)
                                 : 0.0;
    free(power);
    free(x);
    free(win);
    return best_k >= 0 && best > 0 ? best_st : 0.0;
}
