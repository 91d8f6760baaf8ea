/* Unit tests of src/core/common/strouhal and [aeolian~]'s model mode
 * (src/core/play/aeolian_model.c, through aeolian.h): the published laws
 * (written here again, independently of the core) and the behaviour at
 * the edges: silence below onset, bad input, block-size independence. */
#include "aeolian.h"
#include "multi_instance.h"
#include "strouhal.h"
#include "unit.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SR 48000.0

/* Williamson (1996) laminar fit and Roshko's form (Roshko 1954, as the Pd aeroacoustics report uses it) */
static double williamson(double re) { return -3.3265 / re + 0.1816 + 1.6e-4 * re; }
static double roshko(double re) { return 0.198 * (1.0 - 19.7 / re); }

static double render_rms(aero_aeolian *m, float speed, double seconds,
                         int block, int *nonfinite)
{
    int total = (int)(seconds * SR);
    float *in = malloc(sizeof(float) * block), *out = malloc(sizeof(float) * block);
    float *outs[2] = {out, out};
    double sum = 0;
    long count = 0;
    for (int done = 0; done < total; done += block) {
        for (int i = 0; i < block; i++)
            in[i] = speed;
        aero_aeolian_process(m, in, outs, block);
        for (int i = 0; i < block; i++) {
            if (!isfinite(out[i]))
                (*nonfinite)++;
            else if (done > total / 10) { /* skip the first 10 % */
                sum += (double)out[i] * out[i];
                count++;
            }
        }
    }
    free(in);
    free(out);
    return count ? sqrt(sum / count) : 0;
}

UNIT_TEST(strouhal)
{
    UNIT_NEAR_REL(aero_reynolds(10, 0.01), 1.225 * 10 * 0.01 / 1.81e-5, 1e-9,
                  "Re = rho U d / mu");
    UNIT_NEAR_REL(aero_strouhal(100), williamson(100), 1e-9, "St(100) Williamson");
    UNIT_NEAR_REL(aero_strouhal(100), 0.1648, 0.01, "St(100) ~ 0.164-0.167 (published)");
    UNIT_NEAR_REL(aero_strouhal(5000), roshko(5000), 1e-9, "St(5000) Roshko");
    UNIT_CHECK(aero_shedding_strength(40) == 0 && aero_shedding_strength(46.9) == 0,
               "no shedding below Re 47");
    UNIT_CHECK(aero_shedding_strength(60) > 0, "shedding at Re 60");
    aero_aeolian tone;
    aero_aeolian_init(&tone, SR, 1, 1);
    UNIT_NEAR_REL(aero_aeolian_tone_hz(&tone, 10.0),
                  roshko(1.225 * 10 * 0.01 / 1.81e-5) * 10.0 / 0.01, 1e-9,
                  "tone f = St U / d for the default 1 cm at 10 m/s");
    UNIT_CHECK(aero_aeolian_tone_hz(&tone, 0.05) == 0.0,
               "no tone below onset (Re 34)");
    double worst_jump = 0, prev = aero_strouhal(150);
    for (double re = 151; re <= 300; re += 1) {
        double st = aero_strouhal(re);
        if (fabs(st - prev) > worst_jump)
            worst_jump = fabs(st - prev);
        prev = st;
    }
    UNIT_CHECK(worst_jump < 0.002, "St(Re) continuous across the blend: max "
               "step %.5f per unit Re", worst_jump);
}

/* Norberg (2003, J. Fluids Struct. 17): sectional rms lift coefficient of a
 * circular cylinder. Points read from his fits (laminar 47-190, 260-1600,
 * 1600-5400, 5400-2.25e5); the measured values scatter by ~10-20 % around
 * them, the tolerance here is the arithmetic of the fit (1 %). */
UNIT_TEST(lift_rms)
{
    UNIT_CHECK(aero_lift_rms(40) == 0.0, "no lift below onset");
    UNIT_NEAR_REL(aero_lift_rms(100), 0.227, 0.01,
                  "C_L'(100) = 0.227 (laminar fit; Norberg's data 0.23)");
    UNIT_NEAR_REL(aero_lift_rms(1000), 0.0577, 0.01,
                  "C_L'(1000) = 0.058 (the minimum near Re 1e3-3e3)");
    UNIT_NEAR_REL(aero_lift_rms(6768), 0.3175, 0.01,
                  "C_L'(6768) = 0.318 (steep rise, 5400 < Re < 2.25e5 fit)");
    UNIT_NEAR_REL(aero_lift_rms(2e4), 0.473, 0.01, "C_L'(2e4) = 0.47");
    UNIT_NEAR_REL(aero_lift_rms(1e5), 0.507, 0.01, "C_L'(1e5) = 0.51");
    /* continuous where the fits meet */
    double jump_5400 = fabs(aero_lift_rms(5399.9) - aero_lift_rms(5400.1));
    double jump_1600 = fabs(aero_lift_rms(1599.9) - aero_lift_rms(1600.1));
    UNIT_CHECK(jump_5400 < 0.005 && jump_1600 < 0.005,
               "fits meet at Re 1600 (%.4f) and 5400 (%.4f)", jump_1600, jump_5400);
    double worst = 0;
    for (double re = 48; re < 3e5; re *= 1.01) {
        double c = aero_lift_rms(re);
        if (!(c > 0 && c < 0.7))
            worst = c;
    }
    UNIT_CHECK(worst == 0, "0 < C_L' < 0.7 from onset to 3e5 (bad %g)", worst);
}

UNIT_TEST(onset_and_level)
{
    aero_aeolian m;
    int bad = 0;
    /* d = 0.5 mm: 1 m/s is Re 34 (below onset), 2 m/s Re 68 */
    aero_aeolian_init(&m, SR, 1, 1);
    aero_aeolian_set_diameter(&m, 0.0005);
    double below = render_rms(&m, 1.0f, 0.5, 64, &bad);
    UNIT_CHECK(below == 0.0, "silent below the shedding onset (rms %g Pa)", below);
    double above = render_rms(&m, 2.0f, 0.5, 64, &bad);
    UNIT_CHECK(above > 0.0, "sound above the onset (rms %g Pa)", above);

    /* Curle, incoherent segments: p_rms = rho U^3 St C_L' L_c / (4 c0 r)
     * for one segment (l = 3 d) across the flow at r = 3 m, C_L'(6768) =
     * 0.3175 (Norberg 2003) */
    aero_aeolian_init(&m, SR, 1, 2);
    aero_aeolian_set_diameter(&m, 0.01);
    aero_aeolian_set_length(&m, 0.03);
    aero_aeolian_set_ears(&m, &(aero_ears){1, {{0, 3, 0}}});
    double re = aero_reynolds(10, 0.01);
    double want = 1.225 * 1000 * roshko(re) * 0.3175 * 0.03 / (4 * 343 * 3);
    double got = render_rms(&m, 10.0f, 2.0, 64, &bad);
    UNIT_CHECK(fabs(20 * log10(got / want)) < 1.0,
               "absolute level: %.4g Pa, Curle gives %.4g Pa", got, want);

    /* 16 incoherent segments radiate 4x (12 dB) the pressure of one when
     * far away: the span powers add */
    aero_aeolian_set_length(&m, 0.48);
    aero_aeolian_set_ears(&m, &(aero_ears){1, {{0, 30, 0}}});
    double far16 = render_rms(&m, 10.0f, 2.0, 64, &bad);
    aero_aeolian_set_length(&m, 0.03);
    double far1 = render_rms(&m, 10.0f, 2.0, 64, &bad);
    UNIT_CHECK(fabs(20 * log10(far16 / far1) - 12.04) < 1.0,
               "16 incoherent segments: +%.2f dB (want +12.04)",
               20 * log10(far16 / far1));
    UNIT_CHECK(bad == 0, "no NaN/Inf (%d)", bad);
}

UNIT_TEST(block_sizes)
{
    static const int blocks[] = {1, 7, 64, 1000, 4096};
    double ref = 0;
    int bad = 0;
    for (size_t k = 0; k < sizeof(blocks) / sizeof(blocks[0]); k++) {
        aero_aeolian m;
        aero_aeolian_init(&m, SR, 1, 3);
        double rms = render_rms(&m, 12.0f, 2.0, blocks[k], &bad);
        if (k == 0)
            ref = rms;
        UNIT_CHECK(fabs(20 * log10(rms / ref)) < 0.5,
                   "block size %d: level %+.2f dB re block 1", blocks[k],
                   20 * log10(rms / ref));
    }
    UNIT_CHECK(bad == 0, "no NaN/Inf at any block size");
}

UNIT_TEST(bad_input)
{
    aero_aeolian m;
    aero_aeolian_init(&m, SR, 2, 4);
    UNIT_CHECK(aero_aeolian_set_diameter(&m, 0) < 0 &&
                   aero_aeolian_set_diameter(&m, -1) < 0 &&
                   aero_aeolian_set_diameter(&m, NAN) < 0 &&
                   aero_aeolian_set_diameter(&m, INFINITY) < 0,
               "diameter 0, negative, NaN, Inf rejected");
    UNIT_CHECK(m.target[AERO_AEO_DIAMETER] == 0.01, "default diameter kept");
    UNIT_CHECK(aero_aeolian_set_length(&m, 0) < 0 &&
                   aero_aeolian_set_ears(&m,
                           &(aero_ears){1, {{NAN, 0, 0}}}) < 0 &&
                   aero_aeolian_set_ears(&m,
                           &(aero_ears){3, {{0, 0, 0}, {0, 0, 0}}}) < 0 &&
                   aero_aeolian_set_gain_db(&m, INFINITY) < 0 &&
                   aero_aeolian_set_ramp_ms(&m, -1) < 0 &&
                   aero_aeolian_set_sample_rate(&m, 0) < 0,
               "bad length, ear, gain, ramp, sample rate rejected");

    float in[256], l[256], r[256];
    float *outs[2] = {l, r};
    const float speeds[] = {0.0f, -10.0f, 1e30f, -1e30f, NAN, INFINITY,
                            -INFINITY, 1e-30f};
    int bad = 0, clamped = 0;
    for (size_t k = 0; k < sizeof(speeds) / sizeof(speeds[0]); k++) {
        for (int i = 0; i < 256; i++)
            in[i] = speeds[k];
        clamped |= aero_aeolian_process(&m, in, outs, 256);
        for (int i = 0; i < 256; i++)
            bad += !isfinite(l[i]) || !isfinite(r[i]) || fabsf(l[i]) > 1e4f;
    }
    UNIT_CHECK(bad == 0, "speeds 0, -10, +-1e30, NaN, +-Inf: output finite "
               "(%d bad samples)", bad);
    UNIT_CHECK(clamped, "huge speeds report a Mach 0.3 clamp");
    /* in place: Pd may give the same buffer for input and output */
    for (int i = 0; i < 256; i++)
        in[i] = 10.0f;
    float *inplace[2] = {in, r};
    aero_aeolian_process(&m, in, inplace, 256);
    UNIT_CHECK(isfinite(in[255]), "in-place processing works");
}

/* --- two instances at once (tests/unit/multi_instance.h) --- */
static void *mi_make(int variant)
{
    aero_aeolian *m = calloc(1, sizeof(*m));
    aero_aeolian_init(m, 44100.0, 1, 11u + variant);
    aero_aeolian_set_diameter(m, variant ? 0.004 : 0.01);
    return m;
}
static void mi_run(void *s, const float *speed, float *out, int n)
{
    aero_aeolian_process(s, speed, (float *[]){out}, n);
}
static void mi_drop(void *s)
{
    aero_aeolian_free(s);
    free(s);
}

UNIT_TEST(multi_instance)
{
    unit_multi_instance("aeolian~", "model mode", mi_make, mi_run, mi_drop);
}

/* The near-field policy (aero_util.h, aero_near_field; issue 49): one
 * segment (l = 3 d), the listener passing through it along its lift (+y).
 * Curle's (1955) compact far field does not hold closer than the diameter
 * (at least AERO_AEOLIAN_NEAR_MIN): there the listener is heard as at the
 * limit, the same on both sides and exactly at the segment, never silent */
static double near_rms(double y, int *hit, int *bad)
{
    aero_aeolian m;
    aero_aeolian_init(&m, SR, 1, 4);
    aero_aeolian_set_diameter(&m, 0.01);
    aero_aeolian_set_length(&m, 0.03);
    aero_aeolian_set_ears(&m, &(aero_ears){1, {{0, y, 0}}});
    double r = render_rms(&m, 10.0f, 0.5, 64, bad);
    *hit = m.near.hit;
    aero_aeolian_free(&m);
    return r;
}

UNIT_TEST(listener_through_source)
{
    int hit, bad = 0;
    double at_limit = near_rms(0.01, &hit, &bad);
    UNIT_CHECK(!hit && at_limit > 0.0, "at the limit, 1 cm: sound (rms %g "
               "Pa), not within it", at_limit);
    UNIT_NEAR_REL(near_rms(0.02, &hit, &bad), 0.5 * at_limit, 1e-3,
                  "beyond it, 1/r: half at 2 cm");
    const double ys[] = {-0.005, -1e-13, 0.0, 1e-13, 0.002, 0.00999};
    for (size_t i = 0; i < sizeof(ys) / sizeof(ys[0]); i++) {
        char what[96];
        snprintf(what, sizeof what, "listener at y = %g m: heard as at the "
                 "limit, 1 cm", ys[i]);
        UNIT_NEAR_REL(near_rms(ys[i], &hit, &bad), at_limit, 1e-4, what);
        UNIT_CHECK(hit, "... and the object knows it (to warn once)");
    }
    UNIT_CHECK(bad == 0, "no NaN or infinity (%d samples)", bad);
}

UNIT_MAIN(UNIT_CASE(listener_through_source), UNIT_CASE(strouhal), UNIT_CASE(lift_rms), UNIT_CASE(onset_and_level), UNIT_CASE(block_sizes), UNIT_CASE(bad_input), UNIT_CASE(multi_instance))
