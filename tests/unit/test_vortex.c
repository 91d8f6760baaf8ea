/* aero: tests of the vortex texture player (src/core/play/vortex.c) with
 * synthetic textures: 1/r, the Doppler factor of a moving source and of a
 * moving listener, speed interpolation and the u^4 law below the smallest
 * speed, clip, n sources adding in power, hostile input, the paper's 1/r^3
 * option and combustion noise through the player. */
#include "unit.h"
#include "aero_air.h"
#include "aero_util.h"
#include "vortex.h"
#include "multi_instance.h"

#include <stdlib.h>
#include <string.h>

#define SR 48000.0
#define RATE 16000.0

/* a texture of 2 speeds (2 and 4 m/s): channel k is a sine of f Hz and
   amplitude amp[k], or noise when f = 0 */
static aero_texture *synthetic(double f, const double amp[2], int frames)
{
    const double speeds[2] = {2.0, 4.0};
    aero_texture *t = malloc(sizeof *t);
    uint32_t rng = 3;
    aero_texture_init_speeds(t, frames, 2, speeds, RATE);
    for (int n = 0; n < frames; n++)
        for (int k = 0; k < 2; k++)
            t->data[(size_t)n * 2 + k] = (float)(
                amp[k] * (f > 0.0 ? sin(2.0 * AERO_PI * f * n / RATE)
                                  : aero_uniform(&rng)));
    return t;
}

static void render(aero_vortex *m, float speed, float *out, int n)
{
    float in[64];
    for (int k = 0; k < 64; k++) in[k] = speed;
    for (int k = 0; k < n; k += 64) {
        float *o[2] = {out + k, NULL};
        aero_vortex_process(m, in, o, 64);
    }
}

static double rms(const float *x, int n)
{
    double e = 0.0;
    for (int k = 0; k < n; k++) e += (double)x[k] * x[k];
    return sqrt(e / n);
}

/* frequency from the rising zero crossings (linear interpolation) */
static double zero_cross_hz(const float *x, int n)
{
    double first = -1.0, last = -1.0;
    int count = 0;
    for (int k = 1; k < n; k++)
        if (x[k - 1] < 0.0f && x[k] >= 0.0f) {
            double t = k - 1 + x[k - 1] / (x[k - 1] - x[k]);
            if (first < 0.0) first = t;
            else count++;
            last = t;
        }
    return count > 0 ? count * SR / (last - first) : 0.0;
}

static void setup(aero_vortex *m, aero_texture *t, int n)
{
    char err[128];
    aero_vortex_init(m, SR, 1, 42);
    aero_vortex_set_count(m, n);
    if (aero_vortex_set_texture(m, t, err, sizeof err))
        printf("  texture refused: %s\n", err);
}

UNIT_TEST(distance_and_speed)
{
    const double amp[2] = {1.0, 3.0};
    aero_vortex m;
    enum { N = 48000 };
    static float a[N], b[N];
    printf("1/r, speed interpolation, u^4 below the smallest speed\n");
    setup(&m, synthetic(500.0, amp, 16000), 1);
    aero_vortex_set_ears(&m, &(aero_ears){1, {{0.0, 2.0, 0.0}}});
    render(&m, 3.0f, a, N);
    aero_vortex_set_ears(&m, &(aero_ears){1, {{0.0, 4.0, 0.0}}});
    render(&m, 3.0f, b, 4800); /* the ramp */
    render(&m, 3.0f, b, N);
    UNIT_NEAR_REL(rms(b + 4800, N - 4800) / rms(a + 4800, N - 4800), 0.5,
                  0.002, "level ratio at 4 m over 2 m");
    /* 3 m/s is halfway between the channels: amplitude (1 + 3) / 2 = 2,
       a sine of rms 2 / sqrt 2 at 2 m */
    UNIT_NEAR_REL(rms(a + 4800, N - 4800), 2.0 / sqrt(2.0) / 2.0, 0.01,
                  "rms at 3 m/s, 2 m (Pa)");
    render(&m, 8.0f, a, N);
    UNIT_NEAR_REL(rms(a + 4800, N - 4800), 3.0 / sqrt(2.0) / 4.0, 0.01,
                  "above the largest speed: clamped to it");
    render(&m, 1.0f, a, N);
    UNIT_NEAR_REL(rms(a + 4800, N - 4800), pow(0.5, 4.0) / sqrt(2.0) / 4.0,
                  0.01, "1 m/s, half the smallest speed: (1/2)^4");
    render(&m, 0.0f, a, N);
    UNIT_CHECK(rms(a + 4800, N - 4800) == 0.0, "silent at u = 0");
    aero_vortex_free(&m);
}

UNIT_TEST(doppler)
{
    const double amp[2] = {1.0, 1.0}, v = 60.0;
    aero_vortex m;
    enum { N = 96000 };
    static float a[N];
    double xyz[3] = {0.0, 200.0, 0.0}, f;
    printf("Doppler (500 Hz, 60 m/s)\n");
    /* a source approaching a still listener: f c0 / (c0 - v) */
    setup(&m, synthetic(500.0, amp, 16000), 1);
    aero_vortex_set_ears(&m, &(aero_ears){1, {{0.0, 0.0, 0.0}}});
    aero_vortex_set_positions(&m, xyz, 1);
    render(&m, 3.0f, a, 4800);
    aero_vortex_set_ramp_ms(&m, 2000.0);
    xyz[1] = 200.0 - 2.0 * v;
    aero_vortex_set_positions(&m, xyz, 1);
    render(&m, 3.0f, a, N);
    f = zero_cross_hz(a + 9600, 72000);
    UNIT_NEAR_REL(f / 500.0, AERO_C0 / (AERO_C0 - v), 5e-4,
                  "approaching source: f'/f = c0 / (c0 - v)");
    aero_vortex_free(&m);
    /* a listener approaching a still source: f (c0 + v) / c0 */
    setup(&m, synthetic(500.0, amp, 16000), 1);
    aero_vortex_set_ears(&m, &(aero_ears){1, {{0.0, 200.0, 0.0}}});
    render(&m, 3.0f, a, 4800);
    aero_vortex_set_ramp_ms(&m, 2000.0);
    aero_vortex_set_ears(&m,
            &(aero_ears){1, {{0.0, 200.0 - 2.0 * v, 0.0}}});
    render(&m, 3.0f, a, N);
    f = zero_cross_hz(a + 9600, 72000);
    UNIT_NEAR_REL(f / 500.0, (AERO_C0 + v) / AERO_C0, 5e-4,
                  "approaching listener: f'/f = (c0 + v) / c0");
    aero_vortex_free(&m);
}

UNIT_TEST(clip_and_sources)
{
    const double amp[2] = {1.0, 1.0};
    aero_vortex m;
    enum { N = 48000 };
    static float a[N], b[N];
    double peak = 0.0, one, many;
    printf("clip, n sources\n");
    setup(&m, synthetic(0.0, amp, 16000), 1);
    aero_vortex_set_ears(&m, &(aero_ears){1, {{0.0, 0.5, 0.0}}});
    aero_vortex_set_clip(&m, 0.3);
    render(&m, 3.0f, a, N);
    for (int k = 0; k < N; k++) peak = fmax(peak, fabs(a[k]));
    /* 0.3 as a float is 0.3 + 1.2e-8 */
    UNIT_CHECK(peak <= (double)0.3f && peak > 0.29, "clip 0.3 Pa: peak %.9g",
               peak);
    aero_vortex_set_clip(&m, 0.0);
    peak = 0.0;
    render(&m, 3.0f, a, N);
    for (int k = 0; k < N; k++) peak = fmax(peak, fabs(a[k]));
    UNIT_CHECK(peak > 1.0, "no clip: peak %.3g (negative control)", peak);
    one = rms(a, N);
    aero_vortex_free(&m);
    /* 16 equal sources at one place: independent offsets add in power */
    setup(&m, synthetic(0.0, amp, 16000), 16);
    aero_vortex_set_ears(&m, &(aero_ears){1, {{0.0, 0.5, 0.0}}});
    render(&m, 3.0f, b, N);
    render(&m, 3.0f, b, N);
    many = rms(b, N);
    /* +12.04 dB; +-1 dB: 16 noise signals of 1 s from a 1 s loop at
       random offsets are not exactly uncorrelated (residual correlation
       ~ 1/sqrt(frames)), far from the coherent +24 dB */
    UNIT_CHECK(fabs(20.0 * log10(many / one) - 10.0 * log10(16.0)) < 1.0,
               "16 sources: %+.2f dB (power sum +12.04, coherent +24.1)",
               20.0 * log10(many / one));
    aero_vortex_free(&m);
}

UNIT_TEST(hostile)
{
    const double amp[2] = {1.0, 1.0};
    aero_vortex m;
    enum { N = 9600 };
    static float a[N];
    float in[64];
    double bad[3] = {NAN, 0.0, 0.0};
    aero_ears e = {2, {{1, 2, 3}, {4, 5, INFINITY}}};
    int finite = 1;
    char err[128];
    printf("hostile input\n");
    setup(&m, synthetic(0.0, amp, 16000), 4);
    UNIT_CHECK(aero_vortex_set_positions(&m, bad, 1) == -1 &&
                   aero_vortex_set_ears(&m, &e) == -1 &&
                   aero_vortex_set_count(&m, 0) == -1 &&
                   aero_vortex_set_clip(&m, -1.0) == -1 &&
                   aero_vortex_set_gain_db(&m, NAN) == -1,
               "NaN/Inf positions, zero sources, negative clip, NaN gain "
               "refused");
    {
        aero_texture *t = malloc(sizeof *t);
        aero_texture_init(t, 100, 1, RATE);
        aero_texture_set(t, "kind", "aeolian");
        UNIT_CHECK(aero_vortex_set_texture(&m, t, err, sizeof err) == -1,
                   "an aeolian texture refused: %s", err);
        aero_texture_free(t);
        free(t);
    }
    for (int k = 0; k < N; k += 64) {
        float *o[2] = {a + k, NULL};
        for (int q = 0; q < 64; q++)
            in[q] = (k / 64) % 3 == 0 ? NAN : (k / 64) % 3 == 1 ? 1e30f : -5.0f;
        aero_vortex_process(&m, in, o, 64);
    }
    for (int k = 0; k < N; k++)
        if (!isfinite(a[k]) || fabs(a[k]) > 1e3) finite = 0;
    UNIT_CHECK(finite, "NaN, 1e30 and negative speeds: finite output");
    aero_vortex_free(&m);
}

/* the paper's 1/r^3 (Dobashi et al. 2004, eq. 5) as an option: -18.06 dB
   per doubling of the distance, the same level at 1 m */
UNIT_TEST(falloff)
{
    const double amp[2] = {1.0, 3.0};
    aero_vortex m;
    enum { N = 48000 };
    static float a[N], b[N], c[N];
    printf("falloff 3: the paper's 1/r^3\n");
    setup(&m, synthetic(500.0, amp, 16000), 1);
    UNIT_CHECK(aero_vortex_set_falloff(&m, 2) == -1 &&
                   aero_vortex_set_falloff(&m, 0) == -1,
               "falloff other than 1 or 3 refused");
    aero_vortex_set_ears(&m, &(aero_ears){1, {{0.0, 1.0, 0.0}}});
    render(&m, 3.0f, a, 4800);
    render(&m, 3.0f, a, N);
    aero_vortex_set_falloff(&m, 3);
    render(&m, 3.0f, c, N);
    UNIT_NEAR_REL(rms(c, N), rms(a, N), 0.002, "1/r^3 and 1/r agree at 1 m");
    aero_vortex_set_ears(&m, &(aero_ears){1, {{0.0, 2.0, 0.0}}});
    render(&m, 3.0f, b, 4800);
    render(&m, 3.0f, b, N);
    UNIT_NEAR_REL(rms(b, N) / rms(a, N), 0.125, 0.002,
                  "1/r^3: level ratio at 2 m over 1 m");
    aero_vortex_free(&m);
}

/* combustion noise through the player: off by default; with a power, the
   law of combustion_noise.h at the listener, with or without a texture */
UNIT_TEST(combustion)
{
    aero_vortex m;
    enum { N = 8 * 48000 };
    static float a[N];
    double xyz[6] = {0.1, 0.0, 0.0, -0.1, 0.0, 0.0}, want, got;
    printf("combustion noise in the player\n");
    aero_vortex_init(&m, SR, 1, 42);
    aero_vortex_set_count(&m, 2);
    aero_vortex_set_positions(&m, xyz, 2);
    aero_vortex_set_ears(&m, &(aero_ears){1, {{0.0, 2.0, 0.0}}});
    render(&m, 3.0f, a, N);
    UNIT_CHECK(rms(a, N) == 0.0, "no texture, no power: silent");
    aero_combustion_set_power_kw(&m.combustion, 30.0);
    aero_combustion_set_length(&m.combustion, 0.02);
    render(&m, 3.0f, a, 9600);
    render(&m, 3.0f, a, N);
    got = rms(a, N);
    want = aero_combustion_rms_law(&m.combustion, 3.0, 2.0);
    UNIT_NEAR_REL(got, want, 0.05, "30 kW at 2 m, 3 m/s: p_rms (Pa)");
    aero_vortex_set_gain_db(&m, -20.0);
    render(&m, 3.0f, a, 9600);
    render(&m, 3.0f, a, N);
    UNIT_NEAR_REL(rms(a, N), 0.1 * want, 0.05, "gain -20 dB scales it");
    aero_vortex_free(&m);
}

/* --- two instances at once (tests/unit/multi_instance.h): a synthetic
   vortex texture of 3 speeds, 4 sources --- */
static void *mi_make(int variant)
{
    char err[128];
    double speeds[3] = {5.0, 10.0, 20.0}, pos[12];
    aero_vortex *m = calloc(1, sizeof(*m));
    aero_texture *t = calloc(1, sizeof(*t));
    aero_vortex_init(m, 44100.0, 1, 7u + variant);
    aero_texture_init_speeds(t, 2048, 3, speeds, 8000.0);
    for (int n = 0; n < 2048 * 3; n++)
        t->data[n] = (float)sin(0.05 * n) * (float)cos(0.0031 * n);
    aero_vortex_set_texture(m, t, err, sizeof(err));
    aero_vortex_set_count(m, 4);
    for (int i = 0; i < 12; i++)
        pos[i] = 0.1 * i * (variant ? -1 : 1);
    aero_vortex_set_positions(m, pos, 4);
    return m;
}
static void mi_run(void *s, const float *speed, float *out, int n)
{
    aero_vortex_process(s, speed, (float *[]){out}, n);
}
static void mi_drop(void *s)
{
    aero_vortex_free(s);
    free(s);
}

UNIT_TEST(multi_instance)
{
    unit_multi_instance("vortex~", "4 sources", mi_make, mi_run, mi_drop);
}

/* the object contract (CONTRIBUTING.md): init answers -1 for a sample
   rate it cannot use and the core stays usable (silent without a
   texture, finite); n_ears 2 puts the ears AERO_EAR_HALF_SPACING either
   side of the listener; set_seed answers 0 like every setter */
UNIT_TEST(init_contract)
{
    aero_vortex m;
    float l[64], r[64], in[64] = {0};
    float *o[2] = {l, r};
    int silent = 1;
    UNIT_CHECK(aero_vortex_init(&m, NAN, 2, 1) == -1,
               "init at a NaN sample rate answers -1");
    aero_vortex_process(&m, in, o, 64);
    for (int i = 0; i < 64; i++)
        silent &= l[i] == 0.0f && r[i] == 0.0f;
    UNIT_CHECK(silent, "and the core plays silence without a texture");
    UNIT_CHECK(m.ear[0] == -AERO_EAR_HALF_SPACING &&
                   m.ear[3] == AERO_EAR_HALF_SPACING,
               "two ears at x = %g and %g m", m.ear[0], m.ear[3]);
    UNIT_CHECK(aero_vortex_set_seed(&m, 0) == 0 &&
                   aero_vortex_set_seed(&m, 0xffffffffu) == 0,
               "set_seed answers 0 for any seed");
    aero_vortex_free(&m);
}

UNIT_MAIN(UNIT_CASE(falloff), UNIT_CASE(combustion), UNIT_CASE(distance_and_speed), UNIT_CASE(doppler), UNIT_CASE(clip_and_sources), UNIT_CASE(hostile), UNIT_CASE(multi_instance), UNIT_CASE(init_contract))
