/* aero: the unit-test harness of src/core (the project's own, one header).
 * A test file tests/unit/test_<module>.c holds named cases and ends with
 * the list of them:
 *
 *     UNIT_TEST(rossiter_modes) { ... UNIT_CHECK(...); ... }
 *     ...
 *     UNIT_MAIN(UNIT_CASE(rossiter_modes), UNIT_CASE(lock_in))
 *
 * The binary runs every case in that order, or only those named:
 *     build/tests/test_<module> --list        the names of its cases
 *     build/tests/test_<module> NAME...       these cases only
 * (make check-unit ONLY=<module> CASE=NAME; tests/unit/run.sh). Every check
 * prints one line `ok`/`FAIL` with what it measured; the binary ends with
 * `N passed, N failed` (tests/run.sh adds these up) and exits 1 on a
 * failure, 2 on an unknown case name. A case that makes no check fails (a
 * test must be able to fail) unless it says why it cannot run (UNIT_SKIP).
 * Why its own and not cmocka, Check or Criterion (Debian packages all
 * three): the same test sources are built by gcc with ASan/UBSan (make
 * check-asan), run under valgrind, and cross-compile with mingw-w64 and
 * the arm gcc (run under wine and qemu: test_tree does, unchanged); a
 * library would be one more dependency to build for each of those beside
 * FFTW and libsndfile (platforms/deps.sh). Check and Criterion run each
 * test in a child process, which valgrind and wine follow poorly; and
 * all three print a passing check's name only, where these print what
 * was measured (the figure a physics check is judged by).
 * Convergence tests (tests/convergence/) use the checks with a plain main()
 * ending in `return unit_summary();`. */
#ifndef AERO_UNIT_H
#define AERO_UNIT_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int unit_passed, unit_failed, unit_skipped;

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

/* the largest |x[i]|, or -1 when a sample is NaN or infinite */
static inline double unit_finite_peak(const float *x, int n)
{
    double peak = 0.0;
    for (int i = 0; i < n; i++) {
        if (!isfinite(x[i]))
            return -1.0;
        if (fabs(x[i]) > peak)
            peak = fabs(x[i]);
    }
    return peak;
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

/* --- named cases --------------------------------------------------------- */
#define UNIT_TEST(name) static void unit_case_##name(void)

typedef struct {
    const char *name;
    void (*run)(void);
} unit_case;

#define UNIT_CASE(name) {#name, unit_case_##name}

/* UNIT_SKIP("what is missing"): the case cannot run here (a tool not
   built); it returns, and counts as neither passed nor failed */
#define UNIT_SKIP(...)                                                     \
    do {                                                                   \
        unit_skipped++;                                                    \
        printf("  skip  ");                                                \
        printf(__VA_ARGS__);                                               \
        printf("\n");                                                      \
        return;                                                            \
    } while (0)

/* 1 under the sanitizers (tests/robust/check-asan.sh sets
   AERO_TEST_SANITIZED): a long solver test then runs shortened, for the
   memory checks only, and skips the physics that make check judges */
static inline int unit_sanitized(void)
{
    return getenv("AERO_TEST_SANITIZED") != NULL;
}

/* run one case: its header line, its checks; no check at all fails it.
   1 when it failed */
static inline int unit_run_case(const unit_case *c)
{
    int before = unit_passed + unit_failed, failed_before = unit_failed,
        skipped_before = unit_skipped;
    printf("[%s]\n", c->name);
    c->run();
    if (unit_passed + unit_failed == before &&
        unit_skipped == skipped_before) {
        unit_failed++;
        printf("  FAIL  case %s made no check\n", c->name);
    }
    return unit_failed > failed_before;
}

static inline int unit_main(int argc, char **argv, const unit_case *cases,
                            int n)
{
    char failed[n]; /* which cases failed, for the closing list */
    int nfailed = 0;
    if (argc > 1 && !strcmp(argv[1], "--list")) {
        for (int i = 0; i < n; i++)
            printf("%s\n", cases[i].name);
        return 0;
    }
    for (int a = 1; a < argc; a++) { /* every name known before any runs */
        int found = 0;
        for (int i = 0; i < n; i++)
            found |= !strcmp(argv[a], cases[i].name);
        if (!found) {
            fprintf(stderr, "%s: no case %s (--list names them)\n", argv[0],
                    argv[a]);
            return 2;
        }
    }
    for (int i = 0; i < n; i++) {
        int wanted = argc <= 1;
        for (int a = 1; a < argc; a++)
            wanted |= !strcmp(argv[a], cases[i].name);
        failed[i] = wanted && unit_run_case(&cases[i]);
        nfailed += failed[i];
    }
    if (nfailed) {
        printf("failed case%s:", nfailed > 1 ? "s" : "");
        for (int i = 0; i < n; i++)
            if (failed[i])
                printf(" %s", cases[i].name);
        printf("\n");
    }
    return unit_summary();
}

/* main() of a test file: UNIT_MAIN(UNIT_CASE(a), UNIT_CASE(b), ...) */
#define UNIT_MAIN(...)                                                     \
    int main(int argc, char **argv)                                        \
    {                                                                      \
        static const unit_case unit_cases[] = {__VA_ARGS__};               \
        return unit_main(argc, argv, unit_cases,                           \
                         (int)(sizeof unit_cases / sizeof unit_cases[0])); \
    }

#endif
