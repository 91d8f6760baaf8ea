/* Unit tests of [aeolian~]'s texture mode (src/core/play/aeolian_texture.c,
 * through aeolian.h): the player of aeolian textures for moving sticks, on synthetic textures whose content is known exactly. */
#include <stdlib.h>
#include <string.h>

#include "aeolian.h"
#include "clicks.h"
#include "multi_instance.h"
#include "unit.h"

#define SR 48000.0
#define PI 3.14159265358979323846
/* the click measure's scatter allowed between two whirls (issue 39's
   +0.5): the whirl posed every 5 ms and the reference pose at other
   instants, and one measure's worst 2 ms window over 2 s moves by that
   much from one sine to the next (reference 1.6-2.1 at 60-120 Hz) */
#define WHIRL_MARGIN 0.5
#ifndef WHIRL_HZ
#define WHIRL_HZ 40.0 /* the sword's tone at v0 (St 0.15, 4 cm) */
#endif

/* a texture of `dirs` directions; direction k holds a sine of freq[k] Hz
 * (at v0 = 10 m/s, d = 1 cm) in its lift (y) channel, or white noise when
 * freq[k] is 0 */
static aero_texture *make_texture(int dirs, const double *freq,
                                  const char *symmetry, const char *mirror,
                                  const char *angles)
{
    aero_texture *t = calloc(1, sizeof(*t));
    int frames = 16000; /* 1 s at 16 kHz: whole periods of 100, 200 Hz */
    aero_texture_init(t, frames, dirs, 16000.0);
    uint32_t rng = 12345;
    for (int n = 0; n < frames; n++)
        for (int k = 0; k < dirs; k++) {
            float v;
            if (freq[k] > 0)
                v = (float)sin(2.0 * PI * freq[k] * n / 16000.0);
            else {
                rng ^= rng << 13, rng ^= rng >> 17, rng ^= rng << 5;
                v = (float)((double)rng / 4294967296.0 - 0.5);
            }
            t->data[(size_t)n * t->channels + 3 * k + 1] = v;
        }
    aero_texture_set(t, "kind", "aeolian");
    aero_texture_set(t, "v0", "10");
    aero_texture_set(t, "diameter", "0.01");
    aero_texture_set(t, "symmetry", symmetry);
    aero_texture_set(t, "mirror", mirror);
    aero_texture_set(t, "st", "0.1");
    aero_texture_set(t, "angles", angles);
    for (int k = 0; k < dirs; k++) /* what the loader would parse */
        t->angles[k] = dirs > 1 ? 45.0 * k / (dirs - 1) : 0.0;
    return t;
}

/* the exact-pitch checks freeze the sources' phases; section 9 tests their
 * wander */
static void setup(aero_aeolian *s, aero_texture *t, uint32_t seed)
{
    char err[128];
    aero_aeolian_init(s, SR, 1, seed);
    if (aero_aeolian_set_texture(s, t, err, sizeof(err)))
        printf("  set_texture: %s\n", err);
    aero_aeolian_set_ramp_ms(s, 0);
    aero_aeolian_set_phase_wander(s, 0.0);
}

/* renders n samples in blocks of `block` */
static void render(aero_aeolian *s, float *out, int n, int block)
{
    for (int i = 0; i < n; i += block) {
        int m = n - i < block ? n - i : block;
        float *o[1] = {out + i};
        aero_aeolian_process(s, NULL, o, m);
    }
}

/* mean power of n sources against one on the same stick (default pose,
 * 0.5 m along z, listener 1 m across), in dB, over `seconds` of a 100 Hz
 * texture with the phases wandering at `width` */
static double sources_db(int sources, double width, uint32_t seed,
                         double seconds)
{
    double power[2];
    int len = (int)(seconds * SR);
    float *x = calloc(len, sizeof(float));
    double f100[1] = {100.0}, wind[3] = {10.0, 0, 0};
    for (int k = 0; k < 2; k++) {
        aero_aeolian s;
        setup(&s, make_texture(1, f100, "0", "1", "0"), seed);
        aero_aeolian_set_phase_wander(&s, width);
        aero_aeolian_set_sources(&s, k ? sources : 1);
        aero_aeolian_set_wind(&s, wind);
        render(&s, x, len, 64);
        power[k] = unit_rms(x + 4800, len - 4800);
        power[k] *= power[k];
        aero_aeolian_free(&s);
    }
    free(x);
    return 10.0 * log10(power[1] / power[0]);
}

static double zero_crossing_hz(const float *x, int n)
{
    return unit_zero_crossing_hz(x, n, SR);
}

#define rms unit_rms

UNIT_TEST(static_stick_pitch)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    double f100[1] = {100.0};
    double wind[3] = {10.0, 0, 0};
    aero_aeolian s;

    /* 1. static stick in wind: f = St v / d, also for another diameter */
    setup(&s, make_texture(1, f100, "0", "1", "0"), 1);
    aero_aeolian_set_wind(&s, wind);
    render(&s, a, n, 64);
    UNIT_NEAR_REL(zero_crossing_hz(a + 4800, n - 4800), 100.0, 0.001,
                  "tone of a 1 cm stick at v0 (St v / d)");
    aero_aeolian_set_diameter(&s, 0.005);
    double w20[3] = {20.0, 0, 0};
    aero_aeolian_set_wind(&s, w20);
    render(&s, a, n, 64);
    UNIT_NEAR_REL(zero_crossing_hz(a + 4800, n - 4800), 400.0, 0.001,
                  "tone of a 5 mm stick at 2 v0");
    UNIT_NEAR_REL(aero_aeolian_tone_hz(&s, 20.0), 400.0, 1e-9,
                  "tone_hz agrees");
    aero_aeolian_free(&s);
    free(a);
    free(b);
}

UNIT_TEST(block_sizes)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    double f100[1] = {100.0};
    double wind[3] = {10.0, 0, 0};
    aero_aeolian s;

    /* 2. any block size gives the same sound (static geometry) */
    setup(&s, make_texture(1, f100, "0", "1", "0"), 7);
    aero_aeolian_set_wind(&s, wind);
    render(&s, a, n, 64);
    aero_aeolian_free(&s);
    setup(&s, make_texture(1, f100, "0", "1", "0"), 7);
    aero_aeolian_set_wind(&s, wind);
    render(&s, b, n, 1);
    double diff = 0; /* after the first chunk's fade-in */
    for (int i = 4800; i < n; i++)
        diff = fmax(diff, fabs(a[i] - b[i]));
    UNIT_CHECK(diff <= 1e-3 * rms(a, n) && rms(a, n) > 0,
               "blocks of 1 and of 64 samples agree: max diff %g (rms %g)",
               diff, rms(a, n));
    aero_aeolian_free(&s);
    free(a);
    free(b);
}

UNIT_TEST(doppler_approach)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    double f100[1] = {100.0};
    aero_aeolian s;

    /* 3. Doppler, exact for a moving source: a one-source stick flies at
     *    40 m/s straight at the listener, carried by a wind of the same
     *    velocity plus 10 m/s across; the tone rises by c0 / (c0 - v) */
    setup(&s, make_texture(1, f100, "0", "1", "0"), 3);
    aero_aeolian_set_sources(&s, 1);
    double wind_moving[3] = {10.0, 40.0, 0.0};
    aero_aeolian_set_wind(&s, wind_moving);
    aero_aeolian_set_ears(&s, &(aero_ears){1, {{0, 100, 0}}});
    for (int i = 0; i < n; i += 48) { /* a pose every 1 ms */
        double t = i / SR;
        double pa[3] = {0, -20 + 40 * t, -0.01}, pb[3] = {0, -20 + 40 * t, 0.01};
        aero_aeolian_set_pose(&s, pa, pb, 0.001);
        float *o[1] = {a + i};
        aero_aeolian_process(&s, NULL, o, 48);
    }
    UNIT_NEAR_REL(zero_crossing_hz(a + 24000, n - 24000),
                  100.0 * 343.0 / (343.0 - 40.0), 0.002,
                  "approaching at 40 m/s: c0 / (c0 - v)");
    aero_aeolian_free(&s);
    free(a);
    free(b);
}

UNIT_TEST(level_with_speed)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    double f100[1] = {100.0};
    aero_aeolian s;

    /* 4. level: (v/v0)^3, and the paper's ^6 on request */
    double lv[2];
    for (int k = 0; k < 2; k++) {
        setup(&s, make_texture(1, f100, "0", "1", "0"), 1);
        aero_aeolian_set_sources(&s, 1);
        double w[3] = {k ? 20.0 : 10.0, 0, 0};
        aero_aeolian_set_wind(&s, w);
        render(&s, a, n, 64);
        lv[k] = 20 * log10(rms(a + 4800, n - 4800));
        aero_aeolian_free(&s);
    }
    UNIT_NEAR_REL(lv[1] - lv[0], 18.06, 0.005, "dB per speed doubling");
    free(a);
    free(b);
}

UNIT_TEST(incoherent_sources)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    double noise[1] = {0.0}, lv[2];
    double wind[3] = {10.0, 0, 0};
    aero_aeolian s;

    /* 5. incoherent sources: 16 sources with their own offsets sum in
     *    power (-12 dB against one source of the whole length) */
    for (int k = 0; k < 2; k++) {
        setup(&s, make_texture(1, noise, "0", "1", "0"), 9);
        aero_aeolian_set_sources(&s, k ? 16 : 1);
        aero_aeolian_set_length(&s, 0.02); /* compact: same r */
        aero_aeolian_set_wind(&s, wind);
        render(&s, a, n, 64);
        lv[k] = 20 * log10(rms(a + 4800, n - 4800));
        aero_aeolian_free(&s);
    }
    UNIT_CHECK(fabs(lv[1] - lv[0] + 10 * log10(16.0)) < 1.0,
               "16 sources of 1/16 the span: %+.2f dB (incoherent -12.04, "
               "coherent 0)", lv[1] - lv[0]);
    free(a);
    free(b);
}

UNIT_TEST(directions)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    double two[2] = {100.0, 200.0}, diff;
    double wind[3] = {10.0, 0, 0};
    aero_aeolian s;

    /* 6. directions: square-like symmetry (period 90, mirrored), sampled at
     *    0 and 45 deg. The flow angle in the body is -roll. */
    double out_angle[4];
    const double rolls[4] = {0.0, -45.0, -90.0, -135.0};
    for (int k = 0; k < 4; k++) {
        setup(&s, make_texture(2, two, "4", "1", "0,45"), 5);
        aero_aeolian_set_wind(&s, wind);
        aero_aeolian_set_roll_deg(&s, rolls[k]);
        render(&s, a, n, 64);
        out_angle[k] = zero_crossing_hz(a + 4800, n - 4800);
        aero_aeolian_free(&s);
    }
    UNIT_NEAR_REL(out_angle[0], 100.0, 0.01, "flow at 0 deg: direction 0");
    UNIT_NEAR_REL(out_angle[1], 200.0, 0.01, "flow at 45 deg: direction 1");
    UNIT_NEAR_REL(out_angle[2], 100.0, 0.01, "flow at 90 deg = 0 (period)");
    UNIT_NEAR_REL(out_angle[3], 200.0, 0.01, "flow at 135 deg = 45");

    /* mirror: 60 deg is 30 deg seen in a mirror: the lift changes sign */
    setup(&s, make_texture(2, two, "4", "1", "0,45"), 5);
    aero_aeolian_set_wind(&s, wind);
    aero_aeolian_set_roll_deg(&s, -30.0);
    render(&s, a, n, 64);
    aero_aeolian_free(&s);
    setup(&s, make_texture(2, two, "4", "1", "0,45"), 5);
    aero_aeolian_set_wind(&s, wind);
    aero_aeolian_set_roll_deg(&s, -60.0);
    render(&s, b, n, 64);
    aero_aeolian_free(&s);
    diff = 0;
    for (int i = 4800; i < n; i++)
        diff = fmax(diff, fabs(a[i] + b[i]));
    UNIT_CHECK(diff < 1e-4 * rms(a, n) && rms(a, n) > 0,
               "60 deg = mirrored 30 deg (lift negated): max |a + b| %g", diff);

    /* interpolation: halfway between the sampled angles, half of each */
    float *c = calloc(n, sizeof(float));
    const double mid_rolls[3] = {0.0, -45.0, -22.5};
    float *dst[3] = {a, b, c};
    for (int k = 0; k < 3; k++) {
        setup(&s, make_texture(2, two, "4", "1", "0,45"), 5);
        aero_aeolian_set_wind(&s, wind);
        aero_aeolian_set_roll_deg(&s, mid_rolls[k]);
        render(&s, dst[k], n, 64);
        aero_aeolian_free(&s);
    }
    diff = 0;
    for (int i = 4800; i < n; i++)
        diff = fmax(diff, fabs(c[i] - 0.5f * (a[i] + b[i])));
    UNIT_CHECK(diff < 1e-4 * rms(a, n),
               "22.5 deg = (0 deg + 45 deg) / 2: max diff %g", diff);
    free(c);
    free(a);
    free(b);
}

UNIT_TEST(bad_values)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    double f100[1] = {100.0};
    aero_aeolian s;

    /* 7. bad values are refused and nothing non-finite comes out */
    setup(&s, make_texture(1, f100, "0", "1", "0"), 1);
    double bad3[3] = {NAN, 0, 0}, zero3[3] = {0, 0, 0}, huge3[3] = {1e30, 0, 0};
    int refused = (aero_aeolian_set_wind(&s, bad3) != 0) +
                  (aero_aeolian_set_wind(&s, huge3) != 0) +
                  (aero_aeolian_set_pose(&s, zero3, zero3, 0.01) != 0) +
                  (aero_aeolian_set_pose(&s, bad3, zero3, 0.01) != 0) +
                  (aero_aeolian_set_reference(&s, zero3) != 0) +
                  (aero_aeolian_set_diameter(&s, -1) != 0) +
                  (aero_aeolian_set_diameter(&s, NAN) != 0) +
                  (aero_aeolian_set_sources(&s, -2) != 0) +
                  (aero_aeolian_set_sources(&s, 100000) != 0) +
                  (aero_aeolian_set_exponent(&s, NAN) != 0) +
                  (aero_aeolian_set_roll_deg(&s, INFINITY) != 0) +
                  (aero_aeolian_set_ears(&s,
                          &(aero_ears){1, {{NAN, 0, 0}}}) != 0) +
                  (aero_aeolian_set_ears(&s,
                          &(aero_ears){2, {{0, 0, 0}, {0, 0, 0}}}) != 0) +
                  (aero_aeolian_set_sample_rate(&s, 0) != 0);
    UNIT_CHECK(refused == 14, "bad values refused: %d of 14", refused);
    float *speed = calloc(n, sizeof(float));
    for (int i = 0; i < n; i++)
        speed[i] = i % 3 == 0 ? NAN : i % 3 == 1 ? 1e30f : -1e9f;
    float *o[1] = {a};
    int clamped = aero_aeolian_process(&s, speed, o, n);
    int finite = 1;
    for (int i = 0; i < n; i++)
        finite &= isfinite(a[i]) && fabs(a[i]) < 1e3;
    UNIT_CHECK(finite && clamped, "NaN and huge speeds: finite output, "
               "clamp reported (%d)", clamped);
    /* a listener inside the stick does not blow up */
    aero_aeolian_set_ears(&s, &(aero_ears){1, {{0, 0, 0}}});
    render(&s, a, n, 64);
    finite = 1;
    for (int i = 0; i < n; i++)
        finite &= isfinite(a[i]) && fabs(a[i]) < 1e4;
    UNIT_CHECK(finite, "listener on the stick: finite, max bounded");
    aero_aeolian_free(&s);
    free(speed);
    free(a);
    free(b);
}

UNIT_TEST(wrong_kind)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    double f100[1] = {100.0};
    aero_aeolian s;

    /* 8. a texture of the wrong kind is refused and not taken */
    aero_texture *wrong = make_texture(1, f100, "0", "1", "0");
    aero_texture_set(wrong, "kind", "cavity");
    char err[128] = "";
    aero_aeolian_init(&s, SR, 1, 1);
    UNIT_CHECK(aero_aeolian_set_texture(&s, wrong, err, sizeof(err)) &&
                   strstr(err, "cavity"),
               "cavity texture refused: %s", err);
    aero_aeolian_free(&s);
    aero_texture_free(wrong);
    free(wrong);
    free(a);
    free(b);
}

UNIT_TEST(phase_wander)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    double f100[1] = {100.0};
    double diff;
    aero_aeolian s;

    /* 9. the sources' phases wander, so they add their powers, as model
     *    mode's incoherent segments do: n sources of length L/n give 1/n of
     *    the power of one source of length L (-10 dB for 10), for every
     *    seed; with frozen phases the sum in the texture's line is a
     *    random phasor sum instead. Over 16 s the estimate has about 50
     *    coherence times of the 1 % line (0.6 dB rms): +-2 dB */
    int frozen_off = 0;
    for (uint32_t seed = 1; seed <= 4; seed++) {
        double db = sources_db(10, 0.01, seed, 16.0);
        UNIT_CHECK(fabs(db + 10.0) <= 2.0,
                   "seed %u: 10 sources over 1: %+.2f dB (want -10 +- 2)",
                   (unsigned)seed, db);
        double frozen = sources_db(10, 0.0, seed, 16.0);
        frozen_off += fabs(frozen + 10.0) > 2.0;
        printf("    (frozen phases, seed %u: %+.2f dB)\n", (unsigned)seed,
               frozen);
    }
    UNIT_CHECK(frozen_off >= 1, "control: frozen phases miss -10 +- 2 dB for "
               "%d of 4 seeds", frozen_off);
    /* the wander keeps the pitch: one source's mean frequency over 16 s
     * (phase std sqrt(2 pi B t) = 10 rad of 10^4 rad at 1 %) */
    {
        int len = (int)(16.0 * SR);
        float *x = calloc(len, sizeof(float)), *y = calloc(len, sizeof(float));
        double wind16[3] = {10.0, 0, 0};
        setup(&s, make_texture(1, f100, "0", "1", "0"), 2);
        aero_aeolian_set_phase_wander(&s, 0.01);
        aero_aeolian_set_sources(&s, 1);
        aero_aeolian_set_wind(&s, wind16);
        render(&s, x, len, 64);
        UNIT_NEAR_REL(zero_crossing_hz(x + 4800, len - 4800), 100.0, 0.003,
                      "phase wander: one source's mean pitch over 16 s");
        aero_aeolian_free(&s);
        /* and any block size still gives the same sound */
        setup(&s, make_texture(1, f100, "0", "1", "0"), 2);
        aero_aeolian_set_phase_wander(&s, 0.01);
        aero_aeolian_set_sources(&s, 1);
        aero_aeolian_set_wind(&s, wind16);
        render(&s, y, len, 1);
        UNIT_CHECK(aero_aeolian_set_phase_wander(&s, NAN) &&
                       aero_aeolian_set_phase_wander(&s, -0.1) &&
                       aero_aeolian_set_phase_wander(&s, 5.0),
                   "phase wander: NaN, negative and huge widths refused");
        aero_aeolian_free(&s);
        diff = 0;
        for (int i = 4800; i < len; i++)
            diff = fmax(diff, fabs(x[i] - y[i]));
        UNIT_CHECK(diff <= 1e-3 * rms(x, len) && rms(x, len) > 0,
                   "phase wander: blocks of 1 and 64 agree: max diff %g "
                   "(rms %g)", diff, rms(x, len));
        free(x);
        free(y);
    }
    free(a);
    free(b);
}

/* --- a whirl without clicks ----------------------------------------------- */


/* one direction, a WHIRL_HZ sine at v0 in every channel (whole periods),
   the sword's diameter */
static aero_texture *sine_blade_texture(void)
{
    aero_texture *t = calloc(1, sizeof(*t));
    aero_texture_init(t, 16000, 1, 16000.0);
    for (int n = 0; n < 16000; n++) /* WHIRL_HZ at v0: whole periods */
        for (int c = 0; c < 3; c++)
            t->data[(size_t)n * 3 + c] =
                (float)sin(2.0 * PI * WHIRL_HZ * n / 16000.0);
    aero_texture_set(t, "kind", "aeolian");
    aero_texture_set(t, "v0", "10");
    aero_texture_set(t, "diameter", "0.04");
    aero_texture_set(t, "symmetry", "0");
    aero_texture_set(t, "mirror", "1");
    aero_texture_set(t, "st", "0.16");
    aero_texture_set(t, "angles", "0");
    return t;
}

/* the worse ear's click measure after `skip` samples; frees both ears */
static double worse_ear(float *ear[2], long total, long skip, double sr)
{
    double worst = fmax(click_ratio(ear[0] + skip, total - skip, sr),
                        click_ratio(ear[1] + skip, total - skip, sr));
    free(ear[0]);
    free(ear[1]);
    return worst;
}

enum { WHIRL_CHUNK, WHIRL_TIMED, WHIRL_BLOCK, WHIRL_CUT };

/* the sword test's whirl (16-sword.sh 1): a stick from 0.5 to 1.5 m on a
   radius turning at 2 turns/s, ears 3 m out in the plane of the turn, a
   sine in every channel (nothing in it clicks), one source, 44.1 kHz.
   Posed every 64 samples at its sample (CHUNK; 32 would be below the
   1 ms an interval is taken as at least), every 5 ms at its sample within
   64-sample blocks (TIMED: what the wrapper does), every 5 ms at the
   start of the block it falls in (BLOCK: what Pd delivers without the
   offset) or with the blocks cut at each pose's sample (CUT). The worse
   ear's click measure over 2 s; keep (if not NULL) gets the left ear. */
static double whirl_clicks(int mode, float *keep)
{
    const double sr = 44100.0, turn = 4.0 * PI; /* rad/s */
    const long total = 97024, skip = (long)(0.2 * sr); /* 2.2 s */
    float *ear[2] = {calloc(total, sizeof(float)),
                     calloc(total, sizeof(float))};
    aero_texture *t = sine_blade_texture();
    aero_aeolian s;
    char err[128];
    aero_aeolian_init(&s, sr, 2, 5);
    aero_aeolian_set_texture(&s, t, err, sizeof(err));
    aero_aeolian_set_phase_wander(&s, 0.0);
    aero_aeolian_set_sources(&s, 1); /* its clicks not blurred by others' */
    aero_aeolian_set_ears(&s, &(aero_ears){2, {{-0.1, 3, 0}, {0.1, 3, 0}}});
    const double period = mode == WHIRL_CHUNK ? 64.0 / sr : 0.005;
    const int block = 64;
    long k = 0; /* poses given */
    for (long b = 0; b < total; b += block) {
        int done = 0; /* WHIRL_CUT: the block cut at each pose's sample */
        /* the poses falling in this block, each at its sample */
        for (;; k++) {
            double at = k * period * sr; /* the pose's sample */
            if (at >= b + block)
                break;
            double f = turn * k * period, c = cos(f), sn = sin(f);
            double pa[3] = {0.5 * c, 0.5 * sn, 0},
                   pb[3] = {1.5 * c, 1.5 * sn, 0};
            double interval = k ? period : -1.0;
            if (mode == WHIRL_CUT && (long)at > b + done) {
                float *o[2] = {ear[0] + b + done, ear[1] + b + done};
                aero_aeolian_process(&s, NULL, o, (int)((long)at - b - done));
                done = (int)((long)at - b);
            }
            if (mode == WHIRL_BLOCK || mode == WHIRL_CUT)
                aero_aeolian_set_pose(&s, pa, pb, interval);
            else
                aero_aeolian_set_pose_at(&s, pa, pb, NULL, interval,
                                         (int)(at - b));
        }
        float *o[2] = {ear[0] + b + done, ear[1] + b + done};
        aero_aeolian_process(&s, NULL, o, block - done);
    }
    if (keep)
        memcpy(keep, ear[0], sizeof(float) * (size_t)total);
    aero_aeolian_free(&s);
    return worse_ear(ear, total, skip, sr);
}

/* The polyline path stepped the Doppler rate at every pose: posed every
   5 ms at each pose's sample it measured 12.7 here against 3.8 posed every
   64 samples (Hermite arriving with the chord's velocity: 4.0 / 3.6). */
UNIT_TEST(whirl_without_clicks)
{
    float *x = calloc(97024, sizeof(float)), *y = calloc(97024, sizeof(float));
    double chunk = whirl_clicks(WHIRL_CHUNK, NULL),
           timed = whirl_clicks(WHIRL_TIMED, x),
           block = whirl_clicks(WHIRL_BLOCK, NULL);
    whirl_clicks(WHIRL_CUT, y);
    double diff = 0;
    for (int i = 0; i < 97024; i++)
        diff = fmax(diff, fabs(x[i] - y[i]));
    UNIT_CHECK(diff <= 1e-6 * rms(y, 97024) && rms(y, 97024) > 0,
               "poses queued at their samples = blocks cut there: max diff "
               "%g (rms %g)", diff, rms(y, 97024));
    free(x);
    free(y);
    UNIT_CHECK(timed <= chunk + WHIRL_MARGIN,
               "whirled, posed every 5 ms at the pose's sample: clicks %.2f "
               "<= %.2f posed every 64 samples + %.2f", timed, chunk,
               WHIRL_MARGIN);
    printf("  (posed every 5 ms at the block's start: %.2f)\n", block);
}

/* --- a start and a jump without clicks ------------------------------------ */

/* the sword test's whirl as whirl_clicks's TIMED, recorded from 0.1 s
   before its first pose, its ears given with the first pose (as at load,
   or at a spawn); PLACE: placed 0.9 s into the render, 144 deg on (a
   jump while sounding), and whirled on from there. The worse ear's click
   measure over the whole render. */
enum { GESTURE_START, GESTURE_PLACE };

static double gesture_clicks(int what)
{
    const double sr = 44100.0, turn = 4.0 * PI, period = 0.005;
    const long total = (long)(1.5 * sr);
    float *ear[2] = {calloc(total, sizeof(float)),
                     calloc(total, sizeof(float))};
    aero_texture *t = sine_blade_texture();
    aero_aeolian s;
    char err[128];
    aero_aeolian_init(&s, sr, 2, 5);
    aero_aeolian_set_texture(&s, t, err, sizeof(err));
    aero_aeolian_set_phase_wander(&s, 0.0);
    aero_aeolian_set_sources(&s, 1);
    int place = what == GESTURE_PLACE;
    long k = 0, last = -1, skip = 0;
    for (long b = 0; b < total; b += 64) {
        for (;; k++) {
            long at = (long)((0.1 + k * period) * sr);
            if (at >= b + 64)
                break;
            int jump = place && k * period + 0.1 >= 0.9 && !skip;
            if (jump)
                skip = 40; /* the placement: 40 poses' angle on */
            if (k == 0) /* the listener given with the first pose */
                aero_aeolian_set_ears(
                    &s, &(aero_ears){2, {{-0.1, 3, 0}, {0.1, 3, 0}}});
            double f = turn * (k + skip) * period, c = cos(f), sn = sin(f);
            double pa[3] = {0.5 * c, 0.5 * sn, 0},
                   pb[3] = {1.5 * c, 1.5 * sn, 0};
            double interval = last < 0 || jump ? -1.0 : (at - last) / sr;
            aero_aeolian_set_pose_at(&s, pa, pb, NULL, interval, (int)(at - b));
            last = at;
        }
        float *o[2] = {ear[0] + b, ear[1] + b};
        aero_aeolian_process(&s, NULL, o, total - b < 64 ? (int)(total - b) : 64);
    }
    aero_aeolian_free(&s);
    return worse_ear(ear, total, 0, sr);
}

/* Issue 48: a blade whirled from rest clicked ~20 ms in (its ears, given
   with the first pose, glided 2 m in 20 ms and the Doppler compression
   stepped where the glide ended), and a jump while sounding cut the sound
   where the new place's arrivals began. Over the whole render, from before
   the first pose: within the steady whirl's (whirl_clicks TIMED, its first
   0.2 s left out) + WHIRL_MARGIN. Before the fix: 236 and 565 (the steady
   whirl 1.87). A stop (the velocity's 8 ms smoothing, the amplitude as
   its cube) fades a pure 50 Hz sine by 94 % in 8 ms and reads 2.8-3.5 on
   this measure; 16-sword.sh 1b and 45-body.sh check stops and pauses on
   the shipped textures. */
UNIT_TEST(gestures_without_clicks)
{
    static const char *name[] = {
        "whirled from rest, the ears given with the first pose",
        "placed 144 deg on while whirling, and whirled on"};
    double steady = whirl_clicks(WHIRL_TIMED, NULL);
    for (int g = GESTURE_START; g <= GESTURE_PLACE; g++) {
        double c = gesture_clicks(g);
        UNIT_CHECK(c <= steady + WHIRL_MARGIN,
                   "%s: clicks %.2f over the whole render <= %.2f steady "
                   "+ %.2f", name[g], c, steady, WHIRL_MARGIN);
    }
}

/* --- two instances at once (tests/unit/multi_instance.h) --- */
/* a stick at rest in a 10 m/s wind, one source, a WHIRL_HZ sine in every
   channel at 44.1 kHz, its phase wandering at `width`: the worse ear's
   click measure over 2 s */
static double wander_clicks(double width)
{
    const double sr = 44100.0;
    const long total = 97024, skip = (long)(0.2 * sr);
    float *ear[2] = {calloc(total, sizeof(float)),
                     calloc(total, sizeof(float))};
    aero_texture *t = sine_blade_texture();
    aero_aeolian s;
    char err[128];
    double wind[3] = {10.0, 0, 0};
    aero_aeolian_init(&s, sr, 2, 5);
    aero_aeolian_set_texture(&s, t, err, sizeof(err));
    aero_aeolian_set_ramp_ms(&s, 0);
    aero_aeolian_set_phase_wander(&s, width);
    aero_aeolian_set_sources(&s, 1);
    aero_aeolian_set_wind(&s, wind);
    aero_aeolian_set_ears(&s, &(aero_ears){2, {{3, -0.1, 0}, {3, 0.1, 0}}});
    for (long b = 0; b < total; b += 64) {
        float *o[2] = {ear[0] + b, ear[1] + b};
        aero_aeolian_process(&s, NULL, o, 64);
    }
    aero_aeolian_free(&s);
    return worse_ear(ear, total, skip, sr);
}

/* The phase wander's rate stepped at every draw (each 32-sample chunk), a
   kink of the phase each time: a sine at rest measured 2.51 with the 1 %
   wander against 1.09 frozen (1.52 gliding). Gliding from draw to draw it keeps the line
   width (phase_wander above) without the kinks. */
UNIT_TEST(wander_without_clicks)
{
    double frozen = wander_clicks(0.0), wandering = wander_clicks(0.01);
    UNIT_CHECK(wandering <= frozen + WHIRL_MARGIN,
               "a sine at rest, phase wandering 1 %%: clicks %.2f <= %.2f "
               "frozen + %.2f", wandering, frozen, WHIRL_MARGIN);
}

static void *mi_make(int variant)
{
    char err[128];
    aero_aeolian *s = calloc(1, sizeof(*s));
    aero_aeolian_init(s, 44100.0, 1, 3u + variant);
    aero_aeolian_set_texture(s, unit_mi_texture("aeolian", 2), err,
                             sizeof(err));
    double wind[3] = {variant ? 7.0 : 12.0, 1.0, 0.0};
    aero_aeolian_set_wind(s, wind);
    aero_aeolian_set_sources(s, variant ? 3 : 5);
    return s;
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
    unit_multi_instance("aeolian~", "texture mode (a moving stick)", mi_make,
                        mi_run, mi_drop);
}

/* the same texture marked as a blade's (its section and band limit in the
   metadata, as aerotex writes them): each source's noise band above the
   band limit (blade_noise.h) lives in its instance */
static aero_texture *blade_texture(aero_texture *t)
{
    aero_texture_setd(t, "band_limit_pass", 500);
    aero_texture_setd(t, "band_limit_stop", 1000);
    aero_texture_setd(t, "blade_chord", 0.04);
    aero_texture_setd(t, "blade_te_thickness", 0);
    aero_texture_setd(t, "blade_te_angle", 27.3);
    aero_texture_set(t, "blade_boundary_layer", "tripped");
    return t;
}
static void *mi_make_blade(int variant)
{
    char err[128];
    aero_aeolian *s = calloc(1, sizeof(*s));
    aero_aeolian_init(s, 44100.0, 1, 3u + variant);
    aero_aeolian_set_texture(s, blade_texture(unit_mi_texture("aeolian", 2)),
                             err, sizeof(err));
    double wind[3] = {variant ? 17.0 : 25.0, 1.0, 0.0};
    aero_aeolian_set_wind(s, wind);
    aero_aeolian_set_sources(s, variant ? 3 : 5);
    return s;
}

UNIT_TEST(multi_instance_blade)
{
    unit_multi_instance("aeolian~", "texture mode, a blade's noise band",
                        mi_make_blade, mi_run, mi_drop);
}

/* the band above a texture's band limit: a blade texture's holds the
   model's noise, the same texture without the blade keys holds nothing
   there (every texture without a blade plays as before) */
static double top_power(int blade)
{
    char err[128];
    aero_aeolian s;
    float *out = calloc(44100, sizeof(float));
    double wind[3] = {25.0, 0.0, 0.0}, sum = 0;
    aero_texture *t = unit_mi_texture("aeolian", 2);
    if (blade)
        blade_texture(t);
    aero_aeolian_init(&s, 44100.0, 1, 9);
    aero_aeolian_set_texture(&s, t, err, sizeof(err));
    aero_aeolian_set_wind(&s, wind);
    aero_aeolian_set_sources(&s, 1);
    aero_aeolian_set_ears(&s, &(aero_ears){1, {{0, 3, 0}}});
    for (int b = 0; b < 44100; b += 64)
        aero_aeolian_process(&s, NULL, (float *[]){out + b},
                             44100 - b < 64 ? 44100 - b : 64);
    /* the second difference weighs the top: |1 - z^-1|^2 is 16 dB more at
       8 kHz than at 1.3 kHz */
    for (int i = 4410; i < 44100; i++) {
        double d = out[i] - 2.0 * out[i - 1] + out[i - 2];
        sum += d * d;
    }
    aero_aeolian_free(&s);
    free(out);
    return sum;
}

UNIT_TEST(blade_top)
{
    double with = top_power(1), without = top_power(0);
    UNIT_CHECK(with > 10.0 * without,
               "25 m/s: the second difference's power with the blade keys "
               "%.3g, without %.3g (more than 10 x)", with, without);
}

/* 10. The near-field policy (aero_util.h, aero_near_field; issue 49): a
 * listener passing through a source along the lift (+y here: the stick
 * along z, the wind along x). Curle's (1955) compact far field does not
 * hold inside the body, d / 2 = 5 mm of this 1 cm stick: closer, the
 * listener is heard as at 5 mm, so the level is flat there and continuous
 * at the limit, and exactly at the source it is the same (heard along the
 * lift), neither silent nor NaN. Beyond the limit nothing changes (1/r). */
static double near_rms(double y, int *hit)
{
    const int n = 12000;
    float *x = calloc(n, sizeof(float));
    double f100[1] = {100.0}, wind[3] = {10.0, 0, 0};
    double a[3] = {0, 0, -0.1}, b[3] = {0, 0, 0.1};
    aero_aeolian s;
    setup(&s, make_texture(1, f100, "0", "1", "0"), 1);
    aero_aeolian_set_sources(&s, 1); /* one source, at the middle */
    aero_aeolian_set_pose(&s, a, b, -1.0);
    aero_aeolian_set_wind(&s, wind);
    aero_aeolian_set_ears(&s, &(aero_ears){1, {{0.0, y, 0.0}}});
    render(&s, x, n, 64);
    double r = rms(x + 4800, n - 4800);
    *hit = s.near.hit;
    if (!isfinite(r))
        r = -1.0;
    aero_aeolian_free(&s);
    free(x);
    return r;
}

UNIT_TEST(listener_through_source)
{
    const double limit = 0.005; /* d / 2 */
    int hit, far_hit;
    double at_limit = near_rms(limit, &hit);
    double outside = near_rms(2.0 * limit, &far_hit);
    UNIT_NEAR_REL(20.0 * log10(at_limit / outside), 6.0206, 0.002,
                  "beyond the limit, 1/r: 5 mm is 6 dB above 1 cm");
    UNIT_CHECK(!far_hit, "a listener at 1 cm is not within the limit");
    UNIT_NEAR_REL(near_rms(limit * (1.0 + 1e-6), &hit), at_limit, 1e-4,
                  "continuous at the limit, from outside");
    const double ys[] = {-0.004, -0.002, -0.0005, -1e-13, 0.0, 1e-13,
                         0.0005, 0.002, 0.004};
    for (size_t i = 0; i < sizeof(ys) / sizeof(ys[0]); i++) {
        char what[96];
        snprintf(what, sizeof what, "listener at y = %g m: heard as at the "
                 "limit, 5 mm", ys[i]);
        UNIT_NEAR_REL(near_rms(ys[i], &hit), at_limit, 1e-4, what);
        UNIT_CHECK(hit, "... and the object knows it (to warn once)");
    }
}

UNIT_MAIN(UNIT_CASE(listener_through_source),
          UNIT_CASE(static_stick_pitch), UNIT_CASE(block_sizes),
          UNIT_CASE(doppler_approach), UNIT_CASE(level_with_speed),
          UNIT_CASE(incoherent_sources), UNIT_CASE(directions),
          UNIT_CASE(bad_values), UNIT_CASE(wrong_kind),
          UNIT_CASE(phase_wander), UNIT_CASE(whirl_without_clicks),
          UNIT_CASE(wander_without_clicks),
          UNIT_CASE(gestures_without_clicks),
          UNIT_CASE(multi_instance), UNIT_CASE(multi_instance_blade),
          UNIT_CASE(blade_top))
