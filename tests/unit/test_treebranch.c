/* unit tests of src/core/play/treebranch.c: branch sound of Matsuyama et al.
 * 2005 with the physics corrected (amplitude ~ U^3 sqrt(l) / r, Curle 1955). */
#include "../../src/core/common/aero_air.h"
#include "../../src/core/common/strouhal.h"
#include "../../src/core/play/treebranch.h"
#include "unit.h"
#include "multi_instance.h"

#include <stdlib.h>
#include <string.h>

#define SR 48000.0
#define MAXBINS 8192

/* a vertical rod 1 m long, diameter d, at the origin */
static int rod(aero_treebranch *tb, double d, double stiffness)
{
    char text[200], err[100];
    aero_tree t;
    snprintf(text, sizeof text, "branch 0 -1 0 0 0 0 0 1 %g %g\n", d, d);
    if (aero_tree_parse(text, &t, NULL, NULL, err, sizeof err))
        return -1;
    aero_treebranch_init(tb, SR, 7);
    aero_treebranch_set_stiffness(tb, stiffness);
    return aero_treebranch_set_tree(tb, &t);
}

/* power-weighted mean frequency and total power in [f1, f2] */
static void band(const double *p, int nbins, double bin_hz, double f1,
                 double f2, double *fmean, double *total)
{
    double s = 0.0, sf = 0.0;
    int k;
    for (k = 0; k < nbins; k++) {
        double f = k * bin_hz;
        if (f >= f1 && f <= f2) {
            s += p[k];
            sf += p[k] * f;
        }
    }
    *total = s;
    *fmean = s > 0.0 ? sf / s : 0.0;
}

static double total_power(const double *p, int nbins)
{
    double s = 0.0;
    int k;
    for (k = 0; k < nbins; k++)
        s += p[k];
    return s;
}

UNIT_TEST(strouhal_peak)
{
    static double p[MAXBINS];
    aero_treebranch tb;
    double cases[][2] = {{10.0, 0.01}, {5.0, 0.004}, {20.0, 0.02}};
    int c, n, k, kmax = 0;
    for (c = 0; c < 3; c++) {
        double u = cases[c][0], d = cases[c][1], wind[3] = {u, 0.0, 0.0};
        double f0 = 0.2 * u / d, fm, tot;
        char what[100];
        rod(&tb, d, 1000.0);
        aero_treebranch_set_wind(&tb, wind);
        {
            float buf[512];
            for (k = 0; k < 200; k++) /* 2 s: the rod settles */
                aero_treebranch_process(&tb, buf, NULL, 480);
        }
        n = aero_treebranch_frame_power(&tb, p, MAXBINS);
        band(p, n, tb.bin_hz, 0.5 * f0, 1.5 * f0, &fm, &tot);
        snprintf(what, sizeof what, "U %g m/s, d %g m: tone at 0.2 U/d, Hz",
                 u, d);
        /* St(Re) is 0.197 at Re ~ 7000 (Roshko): 1.5 % under 0.2 */
        UNIT_NEAR_REL(fm, f0, 0.03, what);
        if (c == 0) {
            for (k = 1; k < n; k++)
                if (p[k] > p[kmax])
                    kmax = k;
            UNIT_CHECK(fabs(kmax * tb.bin_hz - f0) <= tb.bin_hz + 0.03 * f0,
                       "the spectrum's highest bin is the tone's (%g Hz)",
                       kmax * tb.bin_hz);
            UNIT_CHECK(tot > 0.5 * total_power(p, n),
                       "most power in the tone (%.0f %%)",
                       100.0 * tot / total_power(p, n));
        }
        aero_treebranch_free(&tb);
    }
}

/* amplitude ~ U^3 (Curle 1955): +18.06 dB per doubling; the paper's
   I ~ U^6 applied to amplitudes would give +36 */
UNIT_TEST(speed_law)
{
    static double p[MAXBINS];
    aero_treebranch tb;
    double level[3], speeds[3] = {5.0, 10.0, 20.0};
    int s, k;
    for (s = 0; s < 3; s++) {
        double wind[3] = {0.0, speeds[s], 0.0};
        float buf[480];
        rod(&tb, 0.01, 1000.0);
        aero_treebranch_set_wind(&tb, wind);
        for (k = 0; k < 200; k++)
            aero_treebranch_process(&tb, buf, NULL, 480);
        level[s] = 10.0 * log10(total_power(p, aero_treebranch_frame_power(
                                                    &tb, p, MAXBINS)));
        aero_treebranch_free(&tb);
    }
    /* St and the lift strength vary little between Re 3400 and 27000:
       0.5 dB */
    UNIT_CHECK(fabs(level[1] - level[0] - 18.06) < 0.5,
               "5 -> 10 m/s: %+.2f dB (want +18.06)", level[1] - level[0]);
    UNIT_CHECK(fabs(level[2] - level[1] - 18.06) < 0.5,
               "10 -> 20 m/s: %+.2f dB (want +18.06)", level[2] - level[1]);
}

/* sqrt(l): twice the length, +3 dB (incoherent segments) */
UNIT_TEST(length_law)
{
    static double p[MAXBINS];
    aero_treebranch tb;
    aero_tree t;
    double lv[2], wind[3] = {10.0, 0.0, 0.0};
    const char *trees[2] = {"branch 0 -1 0 0 0 0 0 1 0.01 0.01\n",
                            "branch 0 -1 0 0 0 0 0 2 0.01 0.01\n"};
    int i, k;
    for (i = 0; i < 2; i++) {
        float buf[480];
        aero_tree_parse(trees[i], &t, NULL, NULL, NULL, 0);
        aero_treebranch_init(&tb, SR, 3);
        aero_treebranch_set_stiffness(&tb, 1000.0);
        aero_treebranch_set_tree(&tb, &t);
        aero_treebranch_set_wind(&tb, wind);
        for (k = 0; k < 100; k++)
            aero_treebranch_process(&tb, buf, NULL, 480);
        lv[i] = 10.0 * log10(total_power(p, aero_treebranch_frame_power(
                                                 &tb, p, MAXBINS)));
        aero_treebranch_free(&tb);
    }
    UNIT_CHECK(fabs(lv[1] - lv[0] - 3.01) < 0.3,
               "twice the length: %+.2f dB (want +3.01, amplitude ~ sqrt l)",
               lv[1] - lv[0]);
}

/* renders `seconds` of sound; returns rms, worst sample step */
static double render(aero_treebranch *tb, double seconds, double *maxstep,
                     int *finite)
{
    int n = (int)(seconds * SR), i, k;
    float buf[64];
    double sum = 0.0, prev = 0.0;
    *maxstep = 0.0;
    *finite = 1;
    for (i = 0; i < n / 64; i++) {
        aero_treebranch_process(tb, buf, NULL, 64);
        for (k = 0; k < 64; k++) {
            double v = buf[k];
            if (!(v == v) || fabs(v) > 1e6)
                *finite = 0;
            sum += v * v;
            if ((i || k) && fabs(v - prev) > *maxstep)
                *maxstep = fabs(v - prev);
            prev = v;
        }
    }
    return sqrt(sum / ((n / 64) * 64));
}

UNIT_TEST(rendering)
{
    static double p[MAXBINS];
    aero_treebranch tb;
    double wind[3] = {10.0, 0.0, 0.0}, lis5[3] = {0.0, -5.0, 0.5};
    double lis10[3] = {0.0, -10.0, 0.5}, step, rms5, rms10, ptot;
    int fin, k;
    float buf[480];
    rod(&tb, 0.01, 1000.0);
    aero_treebranch_set_wind(&tb, wind);
    aero_treebranch_set_ears(&tb,
                             &(aero_ears){1, {{lis5[0], lis5[1], lis5[2]}}});
    for (k = 0; k < 100; k++)
        aero_treebranch_process(&tb, buf, NULL, 480);
    ptot = total_power(p, aero_treebranch_frame_power(&tb, p, MAXBINS));
    rms5 = render(&tb, 4.0, &step, &fin);
    /* the frames' power arrives: p_rms = sqrt(P) / r, within 1 dB for 4 s
       of noise-like sound */
    UNIT_CHECK(fabs(20.0 * log10(rms5 / (sqrt(ptot) / 5.0))) < 1.0,
               "level at 5 m: %.2f dB re sqrt(P)/r",
               20.0 * log10(rms5 / (sqrt(ptot) / 5.0)));
    /* a join between frames without a window would jump by about the
       signal's peak (3..4.5 rms for noise-like sound); the smooth part of
       the signal (tone ~200 Hz, tail falling as f^-2) steps less than
       ~0.5 rms per sample at 48 kHz: bound 1.5 rms */
    UNIT_CHECK(step < 1.5 * rms5,
               "no clicks: largest step %.3g = %.2f rms", step, step / rms5);
    UNIT_CHECK(fin, "finite output");
    aero_treebranch_set_ears(
        &tb, &(aero_ears){1, {{lis10[0], lis10[1], lis10[2]}}});
    for (k = 0; k < 20; k++)
        aero_treebranch_process(&tb, buf, NULL, 480);
    rms10 = render(&tb, 4.0, &step, &fin);
    UNIT_CHECK(fabs(20.0 * log10(rms10 / rms5) + 6.02) < 1.0,
               "twice the distance: %+.2f dB (want -6.02, 1/r)",
               20.0 * log10(rms10 / rms5));
    /* cardioid: mic facing away from the tree (mu = 180 deg) hears nothing
       with k 1; sideways (90 deg) half; k 2 a quarter */
    {
        double away[3] = {0.0, -1.0, 0.0}, side[3] = {1.0, 0.0, 0.0}, r;
        aero_treebranch_set_mic(&tb, side);
        for (k = 0; k < 20; k++)
            aero_treebranch_process(&tb, buf, NULL, 480);
        r = render(&tb, 4.0, &step, &fin);
        /* the tree's source is at z 0.5, the listener too: mu = 90 deg */
        UNIT_CHECK(fabs(20.0 * log10(r / rms10) + 6.02) < 1.0,
                   "mic sideways, k 1: %+.2f dB (want -6.02)",
                   20.0 * log10(r / rms10));
        aero_treebranch_set_mic_k(&tb, 2.0);
        for (k = 0; k < 20; k++)
            aero_treebranch_process(&tb, buf, NULL, 480);
        r = render(&tb, 4.0, &step, &fin);
        UNIT_CHECK(fabs(20.0 * log10(r / rms10) + 12.04) < 1.0,
                   "mic sideways, k 2: %+.2f dB (want -12.04)",
                   20.0 * log10(r / rms10));
        aero_treebranch_set_mic(&tb, away);
        for (k = 0; k < 20; k++)
            aero_treebranch_process(&tb, buf, NULL, 480);
        r = render(&tb, 1.0, &step, &fin);
        UNIT_CHECK(r < 1e-6 * rms10, "mic facing away: silent (%g)", r);
    }
    aero_treebranch_free(&tb);
}

UNIT_TEST(still_and_bad)
{
    aero_treebranch tb;
    aero_tree t;
    aero_tree_shape shape = {3, 200, 1.5, 0.08, 0.06, 0.04, 5};
    double step, r, nanv[3] = {0.0 / 0.0, 0.0, 0.0}, huge[3] = {1e9, 0, 0};
    double ok[3] = {8.0, 3.0, 0.0};
    int fin;
    aero_tree_generate(&t, &shape);
    aero_treebranch_init(&tb, SR, 1);
    aero_treebranch_set_tree(&tb, &t);
    r = render(&tb, 0.5, &step, &fin);
    UNIT_CHECK(r == 0.0 && fin, "no wind, no sound (%g)", r);
    UNIT_CHECK(aero_treebranch_set_wind(&tb, nanv) == -1,
               "a NaN wind is refused");
    UNIT_CHECK(aero_treebranch_set_wind(&tb, huge) == 1
                   && fabs(tb.wind[0] - 0.3 * 343.0) < 1e-6,
               "1e9 m/s is clamped to Mach 0.3 (%g)", tb.wind[0]);
    r = render(&tb, 1.0, &step, &fin);
    UNIT_CHECK(fin && r > 0.0, "at Mach 0.3: finite, sounding (%g Pa)", r);
    UNIT_CHECK(aero_treebranch_set_alpha(&tb, -1.0) == -1
                   && aero_treebranch_set_beta(&tb, 7.0) == -1
                   && aero_treebranch_set_stiffness(&tb, 0.0) == -1
                   && aero_treebranch_set_mic_k(&tb, 1.0 / 0.0) == -1
                   && aero_treebranch_set_ears(&tb, &(aero_ears){1,
                          {{nanv[0], nanv[1], nanv[2]}}}) == -1
                   && aero_treebranch_set_gain_db(&tb, 1e9) == -1,
               "bad parameters are refused");
    aero_treebranch_set_wind(&tb, ok);
    r = render(&tb, 1.0, &step, &fin);
    UNIT_CHECK(fin && r > 0.0, "a generated tree in 8.5 m/s sounds (%g Pa)",
               r);
    UNIT_CHECK(aero_treebranch_set_sample_rate(&tb, 96000.0) == 0
                   && tb.fft_size == 8192,
               "96 kHz: frames of 8192");
    r = render(&tb, 0.5, &step, &fin);
    UNIT_CHECK(fin && r > 0.0, "still sounding after a rate change");
    aero_treebranch_free(&tb);

    /* no tree at all: silent, alive */
    aero_treebranch_init(&tb, SR, 1);
    aero_treebranch_set_wind(&tb, ok);
    r = render(&tb, 0.1, &step, &fin);
    UNIT_CHECK(r == 0.0 && fin, "no tree: silence");
    aero_treebranch_free(&tb);
}

/* the same seed gives the same sound; another seed another */
UNIT_TEST(seed)
{
    aero_treebranch a, b;
    aero_tree t1, t2;
    aero_tree_shape shape = {3, 100, 1.5, 0.08, 0.06, 0.04, 5};
    double wind[3] = {7.0, 0.0, 0.0};
    float x[256], y[256];
    int k, same = 1, differ = 0;
    aero_tree_generate(&t1, &shape);
    aero_tree_generate(&t2, &shape);
    aero_treebranch_init(&a, SR, 42);
    aero_treebranch_init(&b, SR, 42);
    aero_treebranch_set_tree(&a, &t1);
    aero_treebranch_set_tree(&b, &t2);
    aero_treebranch_set_wind(&a, wind);
    aero_treebranch_set_wind(&b, wind);
    for (k = 0; k < 100; k++) {
        aero_treebranch_process(&a, x, NULL, 256);
        aero_treebranch_process(&b, y, NULL, 256);
        if (memcmp(x, y, sizeof x))
            same = 0;
    }
    aero_treebranch_set_seed(&b, 43);
    for (k = 0; k < 100; k++) {
        aero_treebranch_process(&a, x, NULL, 256);
        aero_treebranch_process(&b, y, NULL, 256);
        if (memcmp(x, y, sizeof x))
            differ = 1;
    }
    UNIT_CHECK(same, "the same seed renders the same samples");
    UNIT_CHECK(differ, "another seed renders others (negative control)");
    aero_treebranch_free(&a);
    aero_treebranch_free(&b);
}

/* --- two instances at once (tests/unit/multi_instance.h) --- */
static void *mi_make(int variant)
{
    aero_tree t;
    aero_treebranch *tb = calloc(1, sizeof(*tb));
    aero_treebranch_init(tb, 44100.0, 9u + variant);
    unit_mi_tree(&t, variant);
    aero_treebranch_set_tree(tb, &t);
    aero_treebranch_set_ears(tb,
                             &(aero_ears){1, {{0.0, variant ? -2.0 : -4.0,
                                               1.5}}});
    return tb;
}
static void mi_run(void *s, const float *speed, float *out, int n)
{
    double w[3] = {unit_mi_block_mean(speed, n), 0.0, 0.0};
    aero_treebranch_set_wind(s, w);
    aero_treebranch_process(s, out, NULL, n);
}
static void mi_drop(void *s)
{
    aero_treebranch_free(s);
    free(s);
}

UNIT_TEST(multi_instance)
{
    unit_multi_instance("treebranch~", "a small tree", mi_make, mi_run,
                        mi_drop);
}

UNIT_MAIN(UNIT_CASE(strouhal_peak), UNIT_CASE(speed_law), UNIT_CASE(length_law), UNIT_CASE(rendering), UNIT_CASE(still_and_bad), UNIT_CASE(seed), UNIT_CASE(multi_instance))
