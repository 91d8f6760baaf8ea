/* Unit tests of src/core/play/cavity: Rossiter and quarter-wave laws
 * (written here again from their sources), lock-in, two ears, bad input. */
#include "cavity.h"
#include "multi_instance.h"
#include "unit.h"

#include <math.h>
#include <stdlib.h>

#define SR 48000.0

static double rms_of(aero_cavity *m, float speed, double seconds,
                     int *bad)
{
    float in[64], out[64];
    double sum = 0;
    long count = 0, total = (long)(seconds * SR);
    for (long done = 0; done < total; done += 64) {
        for (int i = 0; i < 64; i++)
            in[i] = speed;
        aero_cavity_process(m, in, (float *[]){out}, 64);
        for (int i = 0; i < 64; i++) {
            if (!isfinite(out[i]))
                (*bad)++;
            else if (done > total / 10)
                sum += (double)out[i] * out[i], count++;
        }
    }
    return count ? sqrt(sum / count) : 0;
}

UNIT_TEST(rossiter_and_depth_modes)
{
    /* Rossiter 1964 with Heller's Mach term: alpha 0.25, kappa 0.57 */
    double u = 30, l = 0.1, mach = u / 343.0;
    for (int k = 1; k <= 4; k++)
        UNIT_NEAR_REL(aero_cavity_rossiter_hz(u, l, k),
                      u / l * (k - 0.25) / (mach + 1 / 0.57), 1e-12,
                      "Rossiter mode");
    /* quarter wave with a flanged end correction 0.82 a */
    double a = sqrt(0.02 * 0.05 / 3.141592653589793);
    UNIT_NEAR_REL(aero_cavity_depth_hz(0.1, 0.02, 0.05, 1),
                  343.0 / (4 * (0.1 + 0.82 * a)), 1e-12, "depth mode 1");
    UNIT_NEAR_REL(aero_cavity_depth_hz(0.1, 0.02, 0.05, 2),
                  3 * 343.0 / (4 * (0.1 + 0.82 * a)), 1e-12, "depth mode 2");
}

UNIT_TEST(lock_in)
{
    double a = sqrt(0.02 * 0.05 / 3.141592653589793);
    int bad = 0;
    aero_cavity m;
    aero_cavity_init(&m, SR, 1, 1);
    double shallow = rms_of(&m, 10.0f, 1.0, &bad);
    /* tune the depth onto mode 2 at 10 m/s: it locks in and grows */
    double f2 = aero_cavity_rossiter_hz(10, 0.02, 2);
    aero_cavity_set_depth(&m, 343.0 / (4 * f2) - 0.82 * a);
    aero_cavity_set_ramp_ms(&m, 0);
    double locked = rms_of(&m, 10.0f, 1.0, &bad);
    UNIT_CHECK(20 * log10(locked / shallow) > 10,
               "lock-in: +%.1f dB when the depth mode meets mode 2",
               20 * log10(locked / shallow));
    /* the locked tone holds a frequency plateau on the depth mode while the
       speed moves +-2 % (Elder 1978: deep cavities lock onto their depth
       mode over a range of speeds); away from it, Rossiter's law */
    {
        double depth = 343.0 / (4 * f2) - 0.82 * a;
        double fd = aero_cavity_depth_hz(depth, 0.02, 0.05, 1), worst = 0;
        for (double s = 9.8; s <= 10.201; s += 0.05) {
            double f = aero_cavity_locked_hz(aero_cavity_rossiter_hz(s, 0.02, 2),
                                             depth, 0.02, 0.05);
            worst = fmax(worst, fabs(f / fd - 1));
        }
        UNIT_CHECK(worst < 0.002, "plateau: mode 2 within %.2f %% of the depth "
                   "mode over 9.8-10.2 m/s (Rossiter's law moves it 4 %%)",
                   100 * worst);
        double far = aero_cavity_rossiter_hz(7, 0.02, 2);
        UNIT_NEAR_REL(aero_cavity_locked_hz(far, depth, 0.02, 0.05), far, 0.002,
                      "unlocked at 7 m/s: Rossiter's mode 2");
    }
    aero_cavity_free(&m);
}

/* rms of each ear over `blocks` blocks of 64 at a steady speed, from the
   fourth block on */
static void ears_rms(aero_cavity *m, float speed, int blocks, double rms[2])
{
    float in[64], left[64], right[64];
    double sum[2] = {0, 0};
    for (int b = 0; b < blocks; b++) {
        for (int i = 0; i < 64; i++)
            in[i] = speed;
        aero_cavity_process(m, in, (float *[]){left, right}, 64);
        for (int i = 0; b >= 4 && i < 64; i++)
            sum[0] += (double)left[i] * left[i],
            sum[1] += (double)right[i] * right[i];
    }
    for (int e = 0; e < 2; e++)
        rms[e] = sqrt(sum[e] / (64.0 * (blocks - 4)));
}

/* Two ears, the cavity to the listener's left (its centre 0.5 m to the
 * right of the opening, 1 m out): the left ear is nearer and hears it
 * louder. Model mode: the field falls as 1/r (a compact source's far
 * field, Curle 1955), so the ears' levels stand as r_right / r_left, and
 * the left ear hears what a mono listener there hears, sample for sample.
 * Texture mode: a force across the opening (along y) is a dipole,
 * p = (x . g) W / (4 pi c0 r^2) with x the ear's position (Curle 1955),
 * so p ~ y / r^2 and, y the same, they stand as (r_right / r_left)^2. */
UNIT_TEST(stereo_ears)
{
    const aero_ears ears = {2, {{0.4, 1.0, 0.0}, {0.6, 1.0, 0.0}}};
    const double r_left = sqrt(0.4 * 0.4 + 1.0), r_right = sqrt(0.6 * 0.6 + 1.0);
    aero_cavity st, mono;
    UNIT_CHECK(aero_cavity_init(&st, SR, 2, 7) == 0 &&
                   aero_cavity_set_ears(&st, &ears) == 0 &&
                   aero_cavity_init(&mono, SR, 1, 7) == 0 &&
                   aero_cavity_set_ears(&mono, &(aero_ears){1, {{0.4, 1.0, 0.0}}}) == 0,
               "two ears made and placed");
    UNIT_CHECK(aero_cavity_set_ears(&mono, &ears) < 0,
               "a mono cavity refuses two ears");
    float in[64], left[64], right[64], alone[64];
    int same = 1;
    for (int b = 0; b < 50; b++) {
        for (int i = 0; i < 64; i++)
            in[i] = 12.0f;
        aero_cavity_process(&st, in, (float *[]){left, right}, 64);
        aero_cavity_process(&mono, in, (float *[]){alone}, 64);
        for (int i = 0; i < 64; i++)
            same &= left[i] == alone[i];
    }
    UNIT_CHECK(same, "the left ear hears what one listener there hears");
    double rms[2];
    ears_rms(&st, 12.0f, 400, rms);
    UNIT_CHECK(rms[0] > rms[1], "model: the left ear louder (%g > %g Pa)",
               rms[0], rms[1]);
    UNIT_NEAR_REL(rms[0] / rms[1], r_right / r_left, 1e-5,
                  "model: the ears' levels as 1/r");
    aero_cavity_free(&mono);

    /* a texture whose force is across the opening only (g_x 0, g_y a
       tone) */
    aero_texture *t = calloc(1, sizeof(*t));
    char err[128] = "";
    aero_texture_init(t, 4096, 1, 16000.0); /* zeros, 3 channels */
    for (int i = 0; i < 4096; i++)
        t->data[t->channels * i + 1] =
            (float)sin(2.0 * 3.141592653589793 * 64 * i / 4096);
    aero_texture_set(t, "kind", "cavity");
    aero_texture_set(t, "v0", "10");
    UNIT_CHECK(aero_cavity_set_texture(&st, t, err, sizeof(err)) == 0,
               "a cavity texture taken: %s", err);
    ears_rms(&st, 10.0f, 400, rms);
    UNIT_CHECK(rms[0] > rms[1], "texture: the left ear louder (%g > %g Pa)",
               rms[0], rms[1]);
    UNIT_NEAR_REL(rms[0] / rms[1], pow(r_right / r_left, 2), 1e-5,
                  "texture: the ears' levels as a dipole's y / r^2");
    aero_cavity_free(&st);
}

UNIT_TEST(bad_input)
{
    int bad = 0;
    aero_cavity m;
    aero_cavity_init(&m, SR, 1, 2);
    UNIT_CHECK(aero_cavity_set_length(&m, 0) < 0 &&
                   aero_cavity_set_depth(&m, NAN) < 0 &&
                   aero_cavity_set_width(&m, -1) < 0 &&
                   aero_cavity_set_exponent(&m, INFINITY) < 0 &&
                   aero_cavity_set_ears(&m,
                           &(aero_ears){1, {{0, NAN, 0}}}) < 0,
               "bad length, depth, width, exponent, listener rejected");
    double silent = rms_of(&m, 0.0f, 0.2, &bad);
    UNIT_CHECK(silent == 0.0, "no flow, no sound (%g Pa)", silent);
    rms_of(&m, NAN, 0.2, &bad);
    rms_of(&m, 1e30f, 0.2, &bad);
    rms_of(&m, -INFINITY, 0.2, &bad);
    UNIT_CHECK(bad == 0, "NaN, huge and infinite speeds: finite output");
    /* a chunk that gusts to Mach 0.3 and ends at 1e-30 m/s: the locked
       tone's pull over a vanishing Rossiter frequency made its factor
       ~1e28 and the phase overflowed the fast wrap (NaN, found by the
       libpd table fuzzer); then a glide from a tiny level */
    {
        float in[64], out[64];
        int nonfinite = 0;
        aero_cavity_set_width(&m, 2.78);
        for (int b = 0; b < 40; b++) {
            for (int i = 0; i < 64; i++)
                in[i] = (b % 3 == 1) ? (i == 63 ? 1e-30f : 102.9f) : 20.0f;
            if (b == 20)
                aero_cavity_set_ears(&m, &(aero_ears){1, {{4e9, 0, 0}}});
            if (b == 21)
                aero_cavity_set_ears(&m, &(aero_ears){1, {{1, 0, 0}}});
            aero_cavity_process(&m, in, (float *[]){out}, 64);
            for (int i = 0; i < 64; i++)
                nonfinite += !isfinite(out[i]);
        }
        UNIT_CHECK(nonfinite == 0, "a gust to Mach 0.3 ending at 1e-30 m/s, a "
                   "listener 4e9 m away and back: finite output (%d not)",
                   nonfinite);
    }
    aero_texture t;
    char err[128];
    aero_texture_init(&t, 16, 1, 16000);
    aero_texture_set(&t, "kind", "aeolian");
    UNIT_CHECK(aero_cavity_set_texture(&m, &t, err, sizeof(err)) < 0,
               "an aeolian texture is refused: %s", err);
    aero_texture_free(&t);
    aero_cavity_free(&m);
}

/* --- two instances at once (tests/unit/multi_instance.h), model and
   texture mode --- */
static void *mi_make_mode(int variant, int textured)
{
    char err[128];
    aero_cavity *m = calloc(1, sizeof(*m));
    aero_cavity_init(m, 44100.0, 1, 5u + variant);
    aero_cavity_set_length(m, variant ? 0.05 : 0.02);
    if (textured)
        aero_cavity_set_texture(m, unit_mi_texture("cavity", 1), err,
                                sizeof(err));
    return m;
}
static void *mi_make(int variant) { return mi_make_mode(variant, 0); }
static void *mi_make_texture(int variant) { return mi_make_mode(variant, 1); }
static void mi_run(void *s, const float *speed, float *out, int n)
{
    aero_cavity_process(s, speed, (float *[]){out}, n);
}
static void mi_drop(void *s)
{
    aero_cavity_free(s);
    free(s);
}

UNIT_TEST(multi_instance)
{
    unit_multi_instance("cavity~", "model mode", mi_make, mi_run, mi_drop);
    unit_multi_instance("cavity~", "texture mode", mi_make_texture, mi_run,
                        mi_drop);
}

UNIT_MAIN(UNIT_CASE(rossiter_and_depth_modes), UNIT_CASE(lock_in),
          UNIT_CASE(stereo_ears), UNIT_CASE(bad_input),
          UNIT_CASE(multi_instance))
