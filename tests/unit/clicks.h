/* the unit tests' click measure, shared by the players that move, jump
 * and start (test_aeolian_texture.c, test_rotor.c) */
#ifndef AERO_TEST_CLICKS_H
#define AERO_TEST_CLICKS_H

#include <math.h>
#include <stdlib.h>

/* the worst 2 ms window's largest |second difference| over the largest of
   its three neighbours on each side (aero-analyze's `clicks`, the sword
   test's measure): 1 for a smooth sound, large where one window jumps */
static inline double click_ratio(const float *x, long n, double sr)
{
    long w = (long)(0.002 * sr), windows = n / w;
    double *peak = calloc((size_t)windows + 1, sizeof(double)), global = 0;
    for (long k = 0; k < windows; k++) {
        for (long i = k * w; i < (k + 1) * w; i++)
            if (i >= 2)
                peak[k] = fmax(peak[k], fabs(x[i] - 2 * x[i - 1] + x[i - 2]));
        global = fmax(global, peak[k]);
    }
    double worst = 1.0;
    for (long k = 3; k + 3 < windows; k++) {
        double around = 0;
        for (long j = k - 3; j <= k + 3; j++)
            if (j != k)
                around = fmax(around, peak[j]);
        around = fmax(around, 1e-6 * global);
        if (around > 0)
            worst = fmax(worst, peak[k] / around);
    }
    free(peak);
    return worst;
}

/* the largest |second difference| of x[0..n): a sound's roughest
   instant, for a change that lasts longer than click_ratio's neighbours
   (a cut followed by tens of ms of torn signal reads as smooth there) */
static inline double second_difference_peak(const float *x, long n)
{
    double peak = 0.0;
    for (long i = 2; i < n; i++)
        peak = fmax(peak, fabs(x[i] - 2.0 * x[i - 1] + x[i - 2]));
    return peak;
}

#endif
