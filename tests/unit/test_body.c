/* Unit tests of src/core/play/body: the player of 3D object textures
 * for moving bodies, on synthetic textures whose content is known exactly:
 * pitch St v / d, U^3 level, 1/r, dipole directivity, exact Doppler of a
 * body flying at the listener and of a whirled one, direction
 * interpolation, the mirror fold, bad input. */
#include <stdlib.h>
#include <string.h>

#include "body.h"
#include "multi_instance.h"
#include "unit.h"

#define SR 48000.0
#define PI 3.14159265358979323846

/* a texture of `dirs` directions x `regions` regions at v0 = 10 m/s,
 * d = 0.1 m: component `comp` of direction k holds a 100 Hz sine of
 * amplitude amp[k] (region 0 only, unless all_regions) */
static aero_texture *make_texture(int dirs, int regions, const double *angles,
                                  const double *amp, int comp,
                                  const char *symmetry, int mirror,
                                  const char *centres)
{
    aero_texture *t = calloc(1, sizeof(*t));
    int frames = 16000; /* 1 s at 16 kHz: whole periods of 100 Hz */
    char buf[256];
    aero_texture_init_regions(t, frames, dirs, regions, 16000.0);
    for (int n = 0; n < frames; n++)
        for (int k = 0; k < dirs; k++)
            t->data[(size_t)n * t->channels + 3 * (k * regions) + comp] =
                (float)(amp[k] * sin(2.0 * PI * 100.0 * n / 16000.0));
    aero_texture_set(t, "kind", "object");
    aero_texture_set(t, "v0", "10");
    aero_texture_set(t, "diameter", "0.1");
    aero_texture_set(t, "symmetry", symmetry);
    aero_texture_setd(t, "mirror", mirror);
    aero_texture_set(t, "centres", centres);
    for (int k = 0; k < dirs; k++)
        t->angles[k] = angles[k];
    snprintf(buf, sizeof buf, "%d", regions);
    aero_texture_set(t, "regions", buf);
    return t;
}

static aero_texture *sphere(int comp)
{
    double angle = 90.0, amp = 1.0;
    return make_texture(1, 1, &angle, &amp, comp, "sphere", 0, "0,0,0");
}

static void setup(aero_body *s, aero_texture *t, uint32_t seed)
{
    char err[256];
    aero_body_init(s, SR, 1, seed);
    if (aero_body_set_texture(s, t, err, sizeof(err)))
        printf("  set_texture: %s\n", err);
    aero_body_set_ramp_ms(s, 0);
}

static void render(aero_body *s, float *out, int n, int block)
{
    for (int i = 0; i < n; i += block) {
        int m = n - i < block ? n - i : block;
        float *o[1] = {out + i};
        aero_body_process(s, NULL, o, m);
    }
}

static double zero_crossing_hz(const float *x, int n)
{
    return unit_zero_crossing_hz(x, n, SR);
}

#define rms unit_rms

/* rms of a static body in a wind, heard at the listener */
static double static_rms(aero_texture *t, const double *wind,
                         const double *ear, double scale, float *buf, int n,
                         double *hz)
{
    aero_body s;
    setup(&s, t, 5);
    aero_body_set_wind(&s, wind);
    aero_body_set_ears(&s,
                               &(aero_ears){1, {{ear[0], ear[1], ear[2]}}});
    aero_body_set_scale(&s, scale);
    render(&s, buf, n, 64);
    aero_body_free(&s);
    if (hz)
        *hz = zero_crossing_hz(buf + n / 4, n - n / 4);
    return rms(buf + n / 4, n - n / 4);
}

/* the winds and listeners the cases share */
static const double w10[3] = {10, 0, 0}, w20[3] = {20, 0, 0};
static const double side5[3] = {0, 5, 0}, side10[3] = {0, 10, 0};
static const double axis5[3] = {0, 0, 5};

UNIT_TEST(static_sphere_laws)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    double hz, r1, r2;

    /* 1. a sphere at rest in a wind along x: its lift (texture y = e2 =
     *    axis x flow = +y) is heard across the flow at St v / d */
    r1 = static_rms(sphere(1), w10, side5, 1.0, a, n, &hz);
    UNIT_NEAR_REL(hz, 100.0, 0.001, "sphere at v0: the texture's 100 Hz");
    r2 = static_rms(sphere(1), w20, side5, 1.0, a, n, &hz);
    UNIT_NEAR_REL(hz, 200.0, 0.001, "at 2 v0 the tone doubles (St v / d)");
    UNIT_NEAR_REL(20.0 * log10(r2 / r1), 20.0 * log10(8.0), 0.002,
                  "doubling the speed: +18 dB (amplitude ~ U^3)");
    r2 = static_rms(sphere(1), w20, side5, 2.0, a, n, &hz);
    UNIT_NEAR_REL(hz, 100.0, 0.001, "a sphere twice the size at 2 v0: "
                  "St v / (2 d) = 100 Hz");
    UNIT_NEAR_REL(20.0 * log10(r2 / r1), 20.0 * log10(16.0), 0.002,
                  "... and U^3 d: 8 x 2 = +24 dB");
    r2 = static_rms(sphere(1), w10, side10, 1.0, a, n, NULL);
    UNIT_NEAR_REL(20.0 * log10(r2 / r1), -6.0206, 0.002,
                  "doubling the distance: -6 dB (1/r)");
    r2 = static_rms(sphere(1), w10, axis5, 1.0, a, n, NULL);
    UNIT_CHECK(r2 < 1e-4 * r1, "dipole: the lift is silent along the body "
               "axis (rms %g vs %g across)", r2, r1);
    free(a);
    free(b);
}

UNIT_TEST(block_sizes)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    /* 2. any block size gives the same sound */
    {
        aero_body s;
        double diff = 0.0;
        setup(&s, sphere(1), 9);
        aero_body_set_wind(&s, w10);
        render(&s, a, n, 64);
        aero_body_free(&s);
        setup(&s, sphere(1), 9);
        aero_body_set_wind(&s, w10);
        render(&s, b, n, 1);
        aero_body_free(&s);
        for (int i = 4800; i < n; i++)
            diff = fmax(diff, fabs(a[i] - b[i]));
        UNIT_CHECK(diff <= 1e-3 * rms(a, n) && rms(a, n) > 0,
                   "blocks of 1 and of 64 samples agree: max diff %g", diff);
    }
    free(a);
    free(b);
}

UNIT_TEST(doppler_approach)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    /* 3. Doppler: the sphere flies at 40 m/s straight at the listener,
     *    carried by a wind of that velocity plus 10 m/s across, so the air
     *    it meets is the static case's: the tone rises by c0 / (c0 - v) */
    {
        aero_body s;
        const double wind[3] = {10, 40, 0}, q[4] = {1, 0, 0, 0};
        setup(&s, sphere(0), 3); /* the drag component: along the flow */
        aero_body_set_wind(&s, wind);
        aero_body_set_ears(&s, &(aero_ears){1, {{0.5, 100, 0}}});
        for (int i = 0; i < n; i += 48) { /* a pose every 1 ms */
            double p[3] = {0, -20 + 40 * i / SR, 0};
            float *o[1] = {a + i};
            aero_body_set_pose(&s, p, q, i ? 0.001 : -1.0);
            aero_body_process(&s, NULL, o, 48);
        }
        aero_body_free(&s);
        /* from 0.5 s: the first sound (emitted while the body's velocity
           rose from 0, in a faster relative air flow) has arrived */
        UNIT_NEAR_REL(zero_crossing_hz(a + 24000, n - 24000),
                      100.0 * 343.0 / (343.0 - 40.0), 0.003,
                      "approaching at 40 m/s: c0 / (c0 - v)");
    }
    free(a);
    free(b);
}

UNIT_TEST(whirled_sphere)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    /* 4. a sphere whirled on a 2 m cord at 30 m/s in still air, heard
     *    50 m away in the plane of the circle: its drag tone (300 Hz at
     *    30 m/s) rises to c0/(c0 - v) as it comes at the listener and
     *    falls to c0/(c0 + v) as it goes away, once per revolution */
    {
        aero_body s;
        const double R = 2.0, v = 30.0, w = v / R, q[4] = {1, 0, 0, 0};
        const int len = 2 * 48000;
        float *x = calloc(len, sizeof(float));
        double up, down, t_rev = 2 * PI / w, delay = 50.0 / 343.0;
        setup(&s, sphere(0), 4);
        aero_body_set_ears(&s, &(aero_ears){1, {{0, -50, 0}}});
        for (int i = 0; i < len; i += 48) {
            double t = i / SR;
            double p[3] = {R * cos(w * t), R * sin(w * t), 0};
            float *o[1] = {x + i};
            aero_body_set_pose(&s, p, q, i ? 0.001 : -1.0);
            aero_body_process(&s, NULL, o, 48);
        }
        aero_body_free(&s);
        /* towards the listener (-y) fastest at phase pi, away at 2 pi:
           1/16 revolution either side, heard `delay` later */
        up = zero_crossing_hz(x + (int)((t_rev * (0.5 - 1.0 / 16) + t_rev +
                                         delay) * SR),
                              (int)(t_rev / 8 * SR));
        down = zero_crossing_hz(x + (int)((t_rev * (1.0 - 1.0 / 16) + t_rev +
                                           delay) * SR),
                                (int)(t_rev / 8 * SR));
        UNIT_NEAR_REL(up, 300.0 * 343.0 / (343.0 - v), 0.01,
                      "whirled sphere coming at the listener: rises");
        UNIT_NEAR_REL(down, 300.0 * 343.0 / (343.0 + v), 0.01,
                      "whirled sphere going away: falls");
        UNIT_NEAR_REL(up / down, (343.0 + v) / (343.0 - v), 0.01,
                      "rise over fall per revolution");
        free(x);
    }
    free(a);
    free(b);
}

UNIT_TEST(direction_interpolation)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    /* 5. a body of revolution: directions between the sampled ones are
     *    interpolated (amplitude 1 along the axis, 2 broadside, so 1.5 at
     *    45 deg), heard along e1 */
    {
        const double angles[2] = {0.0, 90.0}, amp[2] = {1.0, 2.0};
        const double w45[3] = {7.0710678, 0, 7.0710678}, ear[3] = {5, 0, 0};
        const double w135[3] = {7.0710678, 0, -7.0710678};
        double r90, r45, r135;
        r90 = static_rms(make_texture(2, 1, angles, amp, 0, "axis", 0,
                                      "0,0,0"), w10, ear, 1.0, a, n, NULL);
        r45 = static_rms(make_texture(2, 1, angles, amp, 0, "axis", 0,
                                      "0,0,0"), w45, ear, 1.0, a, n, NULL);
        UNIT_NEAR_REL(r45 / r90, 0.75, 0.01, "flow 45 deg from the axis: "
                      "halfway between the sampled 0 and 90 deg");
        r135 = static_rms(make_texture(2, 1, angles, amp, 0, "axis", 1,
                                       "0,0,0"), w135, ear, 1.0, a, n, NULL);
        UNIT_NEAR_REL(r135 / r90, 0.75, 0.01, "mirror=1: 135 deg reads the "
                      "45 deg of the mirrored body");
        r135 = static_rms(make_texture(2, 1, angles, amp, 0, "axis", 0,
                                       "0,0,0"), w135, ear, 1.0, a, n, NULL);
        UNIT_NEAR_REL(r135 / r90, 1.0, 0.01, "mirror=0: 135 deg is beyond "
                      "the sampled 90 deg (the nearest is read)");
    }
    free(a);
    free(b);
}

UNIT_TEST(regions_centres)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    /* 6. regions are point sources at their centres: two regions 2 m
     *    apart along the axis; only region 1 sounds; a listener on the
     *    axis hears it 2 m / c0 earlier when it is the near one */
    {
        const double angle = 90.0;
        double amp = 1.0;
        aero_body s;
        const double q_flip[4] = {0, 1, 0, 0}, q0[4] = {1, 0, 0, 0};
        const double p0[3] = {0, 0, 0};
        double onset[2];
        for (int pass = 0; pass < 2; pass++) {
            aero_texture *t = make_texture(1, 2, &angle, &amp, 0, "axis", 0,
                                           "0,0,-1;0,0,1");
            /* move the sine to region 1 */
            for (int m = 0; m < t->frames; m++) {
                float *row = t->data + (size_t)m * t->channels;
                row[3] = row[0];
                row[0] = 0.0f;
            }
            setup(&s, t, 6);
            aero_body_set_wind(&s, w10);
            aero_body_set_ears(&s, &(aero_ears){1, {{0.1, 0, 20}}});
            aero_body_set_pose(&s, p0, pass ? q_flip : q0, -1.0);
            render(&s, a, 4800, 32);
            aero_body_free(&s);
            onset[pass] = -1;
            for (int i = 0; i < 4800 && onset[pass] < 0; i++)
                if (fabs(a[i]) > 1e-9)
                    onset[pass] = i;
        }
        UNIT_NEAR_REL(onset[1] - onset[0], 2.0 / 343.0 * SR, 0.05,
                      "a region is heard from its own centre (turned "
                      "upside down: 2 m farther)");
    }
    free(a);
    free(b);
}

UNIT_TEST(bad_input)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    /* 7. bad input */
    {
        aero_body s;
        char err[256];
        const double nanv[3] = {NAN, 0, 0}, p[3] = {0, 0, 0};
        const double qz[4] = {0, 0, 0, 0}, qi[4] = {1, 0, 0, 0};
        aero_texture *t = sphere(1), *bad;
        double angle = 90.0, amp = 1.0;
        float speed[64];
        aero_body_init(&s, SR, 1, 1);
        UNIT_CHECK(aero_body_set_pose(&s, nanv, qi, 0.01) == -1,
                   "a NaN position is refused");
        UNIT_CHECK(aero_body_set_pose(&s, p, qz, 0.01) == -1,
                   "a zero quaternion is refused");
        UNIT_CHECK(aero_body_set_wind(&s, nanv) == -1 &&
                       aero_body_set_scale(&s, 0) == -1 &&
                       aero_body_set_scale(&s, NAN) == -1 &&
                       aero_body_set_exponent(&s, -1) == -1,
                   "NaN wind, zero/NaN scale, negative exponent refused");
        aero_texture_set(t, "kind", "aeolian");
        UNIT_CHECK(aero_body_set_texture(&s, t, err, sizeof err) ==
                           -1 && strstr(err, "object"),
                   "an aeolian texture is refused: %s", err);
        aero_texture_free(t);
        free(t);
        bad = make_texture(1, 2, &angle, &amp, 0, "axis", 0, "0,0,1");
        UNIT_CHECK(aero_body_set_texture(&s, bad, err, sizeof err) ==
                           -1 && strstr(err, "centres"),
                   "too few centres are refused: %s", err);
        aero_texture_free(bad);
        free(bad);
        bad = make_texture(1, 1, &angle, &amp, 0, "cube", 0, "0,0,1");
        UNIT_CHECK(aero_body_set_texture(&s, bad, err, sizeof err) ==
                       -1, "an unknown symmetry is refused: %s", err);
        aero_texture_free(bad);
        free(bad);
        aero_body_set_texture(&s, sphere(1), err, sizeof err);
        for (int i = 0; i < 64; i++)
            speed[i] = i % 2 ? NAN : 1e30f;
        {
            float *o[1] = {a};
            int clamped = aero_body_process(&s, speed, o, 64);
            const double fast[3] = {500, 0, 0};
            int finite = 1;
            aero_body_set_wind(&s, fast);
            for (int k = 0; k < 20; k++)
                clamped |= aero_body_process(&s, NULL, o, 64);
            for (int i = 0; i < 64; i++)
                finite &= a[i] == a[i] && fabs(a[i]) < 1e6;
            UNIT_CHECK(finite && clamped, "NaN/huge speeds: finite output, "
                       "Mach 0.3 clamp reported");
        }
        aero_body_free(&s);
    }
    free(a);
    free(b);
}

UNIT_TEST(save_and_load)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    /* 8. an object texture survives a save and a load */
    {
        aero_texture *t = sphere(2), back;
        char err[256] = "", path[] = "build/tests/body-roundtrip.wav";
        aero_texture_setd(t, "directions", 1);
        UNIT_CHECK(aero_texture_save(path, t, err, sizeof err) == 0 &&
                       aero_texture_load(path, &back, err, sizeof err) == 0 &&
                       back.regions == 1 && back.channels == 3,
                   "object texture round trip (%s)", err);
        aero_texture_free(&back);
        aero_texture_setd(t, "regions", 2);
        aero_texture_save(path, t, err, sizeof err);
        UNIT_CHECK(aero_texture_load(path, &back, err, sizeof err) == -1 &&
                       strstr(err, "regions"),
                   "a channel count that does not match regions: %s", err);
        aero_texture_free(t);
        free(t);
    }
    free(a);
    free(b);
}

UNIT_TEST(pd_fixture)
{
    const int n = 48000;
    float *a = calloc(n, sizeof(float)), *b = calloc(n, sizeof(float));
    /* 9. a fixture for the Pd tests (tests/objects/45-body.sh): a sphere
     *    texture whose drag is a pure 100 Hz sine at v0 = 10 m/s, d = 0.1 m,
     *    so the Doppler of a whirl in real Pd can be read off one peak */
    {
        aero_texture *t = sphere(0);
        char err[256];
        aero_texture_setd(t, "directions", 1);
        UNIT_CHECK(aero_texture_save("build/tests/sine-sphere.wav", t, err,
                                     sizeof err) == 0,
                   "fixture build/tests/sine-sphere.wav written (%s)", err);
        aero_texture_free(t);
        free(t);
    }
    free(a);
    free(b);
}

/* --- two instances at once (tests/unit/multi_instance.h): a synthetic
   object texture, 2 directions x 3 regions --- */
static void *mi_make(int variant)
{
    char err[128];
    aero_body *s = calloc(1, sizeof(*s));
    aero_texture *t = calloc(1, sizeof(*t));
    double wind[3] = {variant ? 7.0 : 12.0, 1.0, 0.5};
    double pos[3] = {0.1 * variant, 0.0, 0.0}, q[4] = {0.9, 0.1, 0.2, 0.3};
    aero_texture_init_regions(t, 512, 2, 3, 16000.0);
    for (int n = 0; n < 512 * t->channels; n++)
        t->data[n] = (float)sin(0.05 * n) * (float)cos(0.0031 * n);
    aero_texture_set(t, "kind", "object");
    aero_texture_set(t, "v0", "10");
    aero_texture_set(t, "diameter", "0.05");
    aero_texture_set(t, "symmetry", "axis");
    aero_texture_set(t, "centres", "0,0,0;0,0,0.2;0,0,0.4");
    t->angles[0] = 0.0;
    t->angles[1] = 90.0;
    aero_body_init(s, 44100.0, 1, 5u + variant);
    aero_body_set_texture(s, t, err, sizeof(err));
    aero_body_set_wind(s, wind);
    aero_body_set_pose(s, pos, q, -1.0);
    return s;
}
static void mi_run(void *s, const float *speed, float *out, int n)
{
    aero_body_process(s, speed, (float *[]){out}, n);
}
static void mi_drop(void *s)
{
    aero_body_free(s);
    free(s);
}

UNIT_TEST(multi_instance)
{
    unit_multi_instance("body~", "a two-direction texture", mi_make, mi_run,
                        mi_drop);
}

/* a sphere whirled on a 2 m cord at 30 m/s, turning as it goes, posed
   every 5 ms (240 samples), into x, in calls of `block` samples within
   ticks of 64 (Pd performs a block smaller than its tick several times at
   one logical time): with each pose queued at the tick's start with its
   sample in the tick (queued), or with the calls cut at each pose's
   sample and the pose applied at once between them */
static void whirl_posed(float *x, int len, int queued, int block)
{
    aero_body s;
    int k = 0;
    setup(&s, sphere(0), 4);
    aero_body_set_ears(&s, &(aero_ears){1, {{0, -50, 0}}});
    for (int tick = 0; tick < len; tick += 64) {
        int due[8], n_due = 0; /* the tick's poses, by sample */
        for (; k * 240 < tick + 64; k++) {
            double t = k * 0.005, rv[3] = {0, 0, 30.0 * k}, q[4];
            double p[3] = {2.0 * cos(15.0 * t), 2.0 * sin(15.0 * t), 0};
            aero_body_quaternion_from_rotvec(rv, q);
            if (queued)
                aero_body_set_pose_at(&s, p, q, k ? 0.005 : -1.0,
                                      k * 240 - tick);
            else
                due[n_due++] = k;
        }
        for (int b = tick, i = 0; b < tick + 64;) {
            int end = b + block < tick + 64 ? b + block : tick + 64;
            if (i < n_due && due[i] * 240 < end) /* cut at the pose */
                end = due[i] * 240;
            if (end > b) {
                float *o[1] = {x + b};
                aero_body_process(&s, NULL, o, end - b);
                b = end;
            }
            if (i < n_due && due[i] * 240 == b) {
                double t = due[i] * 0.005, rv[3] = {0, 0, 30.0 * due[i]}, q[4];
                double p[3] = {2.0 * cos(15.0 * t), 2.0 * sin(15.0 * t), 0};
                aero_body_quaternion_from_rotvec(rv, q);
                aero_body_set_pose(&s, p, q, due[i] ? 0.005 : -1.0);
                i++;
            }
        }
    }
    aero_body_free(&s);
}

UNIT_TEST(poses_within_block)
{
    const int len = 48000;
    float *a = calloc(len, sizeof(float)), *b = calloc(len, sizeof(float));
    /* 9. a pose queued with its sample is applied there, as if the block
     *    were cut at it */
    static const int blocks[2] = {64, 16};
    for (int j = 0; j < 2; j++) {
        whirl_posed(a, len, 1, blocks[j]);
        whirl_posed(b, len, 0, blocks[j]);
        double diff = 0;
        for (int i = 0; i < len; i++)
            diff = fmax(diff, fabs(a[i] - b[i]));
        UNIT_CHECK(diff <= 1e-6 * rms(b, len) && rms(b, len) > 0,
                   "blocks of %d: poses queued at their samples = blocks "
                   "cut there: max diff %g (rms %g)", blocks[j], diff,
                   rms(b, len));
    }
    /* a full queue applies the oldest at once; offsets beyond the block,
       negative or in blocks of 1 sample: no crash, finite sound */
    {
        aero_body s;
        const double q[4] = {1, 0, 0, 0};
        int bad = 0;
        setup(&s, sphere(0), 5);
        for (int k = 0; k < 20; k++) {
            double p[3] = {0.01 * k, 0, 0};
            aero_body_set_pose_at(&s, p, q, 0.001, k % 3 ? 3 * k : -7);
        }
        double p[3] = {0.3, 0, 0};
        aero_body_set_pose_at(&s, p, q, 0.001, 1000000);
        for (int i = 0; i < 256; i++) {
            float *o[1] = {a + i};
            if (i % 50 == 0)
                aero_body_set_pose_at(&s, p, q, 0.001, 37);
            aero_body_process(&s, NULL, o, 1);
            bad += !(fabs(a[i]) < 1e3);
        }
        render(&s, a, 4800, 64);
        for (int i = 0; i < 4800; i++)
            bad += !(fabs(a[i]) < 1e3);
        double qo[4];
        aero_body_set_pose_at(&s, p, (const double[4]){0, 0, 1, 0}, 0.001, 5);
        aero_body_orientation(&s, qo);
        UNIT_CHECK(bad == 0 && s.queue.n <= AERO_GLIDE_QUEUE &&
                       fabs(qo[2] - 1.0) < 1e-12,
                   "20 poses in one block, offsets -7 to 1e6, blocks of 1: "
                   "%d bad samples, %d queued; a position alone keeps the "
                   "last queued orientation", bad, s.queue.n);
        aero_body_free(&s);
    }
    free(a);
    free(b);
}

/* The near-field policy (aero_util.h, aero_near_field; issue 49): a
 * listener passing through the sphere's source along its lift (+y: the
 * wind along x, the axis z). Curle's (1955) compact far field does not
 * hold inside the body, AERO_BODY_NEAR x its 0.1 m size = 25 mm: closer,
 * the listener is heard as at 25 mm, so the level is flat there and
 * continuous at the limit, and exactly at the source it is the same
 * (heard along the lift), neither silent nor NaN. */
static double near_rms(double y, float *buf, int n, int *hit)
{
    aero_body s;
    setup(&s, sphere(1), 5);
    aero_body_set_wind(&s, w10);
    aero_body_set_ears(&s, &(aero_ears){1, {{0.0, y, 0.0}}});
    render(&s, buf, n, 64);
    *hit = s.base.near.hit;
    aero_body_free(&s);
    double r = rms(buf + n / 4, n - n / 4);
    return isfinite(r) ? r : -1.0;
}

UNIT_TEST(listener_through_source)
{
    const int n = 12000;
    const double limit = AERO_BODY_NEAR * 0.1;
    float *a = calloc(n, sizeof(float));
    int hit, far_hit;
    double at_limit = near_rms(limit, a, n, &hit);
    double outside = near_rms(2.0 * limit, a, n, &far_hit);
    UNIT_NEAR_REL(20.0 * log10(at_limit / outside), 6.0206, 0.002,
                  "beyond the limit, 1/r: 25 mm is 6 dB above 5 cm");
    UNIT_CHECK(!far_hit, "a listener at 5 cm is not within the limit");
    UNIT_NEAR_REL(near_rms(limit * (1.0 + 1e-6), a, n, &hit), at_limit,
                  1e-4, "continuous at the limit, from outside");
    const double ys[] = {-0.02, -0.01, -0.001, -1e-13, 0.0, 1e-13, 0.001,
                         0.01, 0.02};
    for (size_t i = 0; i < sizeof(ys) / sizeof(ys[0]); i++) {
        char what[96];
        snprintf(what, sizeof what, "listener at y = %g m: heard as at the "
                 "limit, 25 mm", ys[i]);
        UNIT_NEAR_REL(near_rms(ys[i], a, n, &hit), at_limit, 1e-4, what);
        UNIT_CHECK(hit, "... and the object knows it (to warn once)");
    }
    free(a);
}

/* the object contract (CONTRIBUTING.md): init answers -1 for a sample
   rate it cannot use and the core still plays, at 44.1 kHz; set_seed
   answers 0 like every setter */
UNIT_TEST(unusable_sample_rate)
{
    aero_body s;
    char err[256];
    float out[4096];
    UNIT_CHECK(aero_body_init(&s, NAN, 1, 1) == -1,
               "init at a NaN sample rate answers -1");
    aero_texture *t = sphere(1);
    if (aero_body_set_texture(&s, t, err, sizeof err)) {
        aero_texture_free(t);
        free(t);
    }
    aero_body_set_wind(&s, w10);
    render(&s, out, 4096, 64);
    double peak = unit_finite_peak(out, 4096);
    UNIT_CHECK(peak > 0.0,
               "and the body still sounds in a 10 m/s wind: peak %g Pa",
               peak);
    UNIT_CHECK(aero_body_set_seed(&s, 0) == 0 &&
                   aero_body_set_seed(&s, 0xffffffffu) == 0,
               "set_seed answers 0 for any seed");
    aero_body_free(&s);
}

UNIT_MAIN(UNIT_CASE(listener_through_source),
          UNIT_CASE(static_sphere_laws), UNIT_CASE(block_sizes),
          UNIT_CASE(doppler_approach), UNIT_CASE(whirled_sphere),
          UNIT_CASE(direction_interpolation), UNIT_CASE(regions_centres),
          UNIT_CASE(bad_input), UNIT_CASE(save_and_load),
          UNIT_CASE(pd_fixture), UNIT_CASE(poses_within_block),
          UNIT_CASE(multi_instance), UNIT_CASE(unusable_sample_rate))
