/* aero: a minimal unit-test harness for src/core.
 * Each tests/unit/test_<module>.c includes this header, runs its checks in
 * main() and ends with `return unit_summary();`, which prints the closing
 * line `N passed, N failed` that tests/run.sh adds up. */
#ifndef AERO_UNIT_H
#define AERO_UNIT_H

#include <math.h>
#include <stdio.h>

static int unit_passed, unit_failed;

/* UNIT_CHECK(condition, "what was measured: %g", value) */
#define UNIT_CHECK(cond, ...)                                              \
    do {                                                                   \
        if (cond) {                                                        \
            unit_passed++;                                                 \
            printf("  ok    ");                                            \
        } else {                                                           \
            unit_failed++;                                                 \
            printf("  FAIL  %s:%d: ", __FILE__, __LINE__);                 \
        }                                                                  \
        printf(__VA_ARGS__);                                               \
        printf("\n");                                                      \
    } while (0)

/* |got - want| <= tol * |want| */
#define UNIT_NEAR_REL(got, want, tol, what)                                \
    UNIT_CHECK(fabs((double)(got) - (double)(want)) <=                     \
                   (tol) * fabs((double)(want)),                           \
               "%s: got %g, want %g (+-%g%%)", what, (double)(got),        \
               (double)(want), 100.0 * (tol))

/* frequency of a tone from its positive-going zero crossings
   (interpolated), sr samples per second */
static inline double unit_zero_crossing_hz(const float *x, int n, double sr)
{
    double first = -1, last = -1;
    int count = 0;
    for (int i = 1; i < n; i++)
        if (x[i - 1] < 0 && x[i] >= 0) {
            double t = i - 1 + x[i - 1] / (x[i - 1] - x[i]);
            if (first < 0)
                first = t;
            else
                count++;
            last = t;
        }
    return count > 0 ? count * sr / (last - first) : 0;
}

static inline double unit_rms(const float *x, int n)
{
    double sum = 0;
    for (int i = 0; i < n; i++)
        sum += (double)x[i] * x[i];
    return sqrt(sum / n);
}

/* the change from coarse to fine in percent of coarse (a grid-convergence
   figure) */
static inline double unit_change_percent(double fine, double coarse)
{
    return 100.0 * (fine - coarse) / coarse;
}

static int unit_summary(void)
{
    printf("%d passed, %d failed\n", unit_passed, unit_failed);
    return unit_failed ? 1 : 0;
}

#endif
