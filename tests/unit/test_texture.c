/* aero: tests of the texture files and the signal steps that make them
 * (src/core/common/texture.c): round trip of data and metadata, rejection of
 * missing, truncated, corrupt and inconsistent files, the derivative and
 * low-pass resampling, the loop search and cross-fade. */
#include "unit.h"
#include "aero_air.h"
#include "texture.h"

#include <sndfile.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define DIR "build/tests/"

static void make_texture(aero_texture *t, int frames, int dirs)
{
    aero_texture_init(t, frames, dirs, 16000.0);
    for (int n = 0; n < frames; n++)
        for (int c = 0; c < 3 * dirs; c++)
            t->data[(size_t)n * 3 * dirs + c] =
                (float)sin(0.01 * n * (c + 1)) * (c % 3 == 2 ? 0.0f : 100.0f);
    aero_texture_set(t, "kind", "aeolian");
    aero_texture_set(t, "shape", "square");
    aero_texture_setd(t, "diameter", 0.01);
    aero_texture_setd(t, "v0", 10.0);
    aero_texture_setd(t, "directions", dirs);
    aero_texture_setd(t, "rate", 16000.0);
    aero_texture_set(t, "angles", dirs == 2 ? "0,45" : "0");
    aero_texture_set(t, "command", "aerotex aeolian --shape square -o x.wav");
}

UNIT_TEST(round_trip)
{
    aero_texture t, b;
    char err[256] = "", buf[128];
    int same = 1;
    printf("round trip\n");
    make_texture(&t, 1000, 2);
    aero_texture_setd(&t, "st", 0.125);
    aero_texture_setd(&t, "st", 0.13); /* replaces */
    UNIT_CHECK(aero_texture_save(DIR "tex_ok.wav", &t, err, sizeof err) == 0,
               "saved: %s", err);
    UNIT_CHECK(aero_texture_load(DIR "tex_ok.wav", &b, err, sizeof err) == 0,
               "loaded: %s", err);
    if (!b.data) {
        aero_texture_free(&t);
        return;
    }
    UNIT_CHECK(b.frames == 1000 && b.channels == 6 && b.directions == 2,
               "size %d frames x %d channels, %d directions", b.frames,
               b.channels, b.directions);
    for (int k = 0; k < 6000; k++)
        if (b.data[k] != t.data[k]) same = 0;
    UNIT_CHECK(same, "samples identical (float WAV)");
    UNIT_CHECK(b.rate == 16000.0, "rate %g", b.rate);
    UNIT_CHECK(b.angles[0] == 0.0 && b.angles[1] == 45.0, "angles %g, %g",
               b.angles[0], b.angles[1]);
    UNIT_CHECK(aero_texture_getd(&b, "st", 0.0) == 0.13, "st replaced: %g",
               aero_texture_getd(&b, "st", 0.0));
    UNIT_CHECK(aero_texture_get(&b, "command", buf, sizeof buf) &&
                   !strcmp(buf, "aerotex aeolian --shape square -o x.wav"),
               "command with spaces kept: '%s'", buf);
    UNIT_CHECK(aero_texture_get(&b, "nothing", buf, sizeof buf) == NULL,
               "missing key is NULL");
    UNIT_CHECK(aero_texture_getd(&b, "diameter", 0.0) == 0.01, "diameter");
    UNIT_CHECK(aero_texture_sample(&b, 1000 + 5, 1, 1) == t.data[5 * 6 + 4] &&
                   aero_texture_sample(&b, -1, 0, 0) == t.data[999 * 6],
               "sample() wraps around the loop");
    aero_texture_free(&b);
    aero_texture_free(&t);
}

UNIT_TEST(bad_files)
{
    aero_texture t, b;
    char err[256];
    FILE *f;
    long size;
    printf("bad files\n");
    err[0] = 0;
    UNIT_CHECK(aero_texture_load(DIR "no_such_texture.wav", &b, err,
                                 sizeof err) != 0 && err[0],
               "missing file: %s", err);

    /* truncated: half of a good file */
    make_texture(&t, 4000, 1);
    aero_texture_save(DIR "tex_trunc.wav", &t, err, sizeof err);
    f = fopen(DIR "tex_trunc.wav", "rb");
    fseek(f, 0, SEEK_END);
    size = ftell(f);
    fclose(f);
    UNIT_CHECK(truncate(DIR "tex_trunc.wav", size / 2) == 0, "truncated");
    err[0] = 0;
    UNIT_CHECK(aero_texture_load(DIR "tex_trunc.wav", &b, err, sizeof err) != 0,
               "truncated file rejected: %s", err);

    /* corrupt: random bytes */
    f = fopen(DIR "tex_junk.wav", "wb");
    for (int k = 0; k < 5000; k++) fputc((k * 7919) & 255, f);
    fclose(f);
    err[0] = 0;
    UNIT_CHECK(aero_texture_load(DIR "tex_junk.wav", &b, err, sizeof err) != 0
                   && err[0],
               "corrupt file rejected: %s", err);

    /* wrong channel count: 3 channels but directions=2 */
    aero_texture_setd(&t, "directions", 2);
    aero_texture_save(DIR "tex_chan.wav", &t, err, sizeof err);
    err[0] = 0;
    UNIT_CHECK(aero_texture_load(DIR "tex_chan.wav", &b, err, sizeof err) != 0
                   && strstr(err, "channels"),
               "wrong channel count rejected: %s", err);
    aero_texture_setd(&t, "directions", 1);

    /* a NaN sample */
    t.data[123] = NAN;
    aero_texture_save(DIR "tex_nan.wav", &t, err, sizeof err);
    err[0] = 0;
    UNIT_CHECK(aero_texture_load(DIR "tex_nan.wav", &b, err, sizeof err) != 0
                   && strstr(err, "finite"),
               "non-finite sample rejected: %s", err);
    t.data[123] = 0.0f;

    /* a plain WAV without metadata */
    {
        SF_INFO info;
        SNDFILE *s;
        float z[300] = {0};
        memset(&info, 0, sizeof info);
        info.samplerate = 16000;
        info.channels = 3;
        info.format = SF_FORMAT_WAV | SF_FORMAT_FLOAT;
        s = sf_open(DIR "tex_plain.wav", SFM_WRITE, &info);
        sf_writef_float(s, z, 100);
        sf_close(s);
        err[0] = 0;
        UNIT_CHECK(aero_texture_load(DIR "tex_plain.wav", &b, err, sizeof err)
                       != 0 && strstr(err, "metadata"),
                   "WAV without metadata rejected: %s", err);
    }
    /* a rate of 0 in the metadata */
    aero_texture_setd(&t, "rate", 0.0);
    aero_texture_save(DIR "tex_rate.wav", &t, err, sizeof err);
    err[0] = 0;
    UNIT_CHECK(aero_texture_load(DIR "tex_rate.wav", &b, err, sizeof err) != 0,
               "rate=0 rejected: %s", err);
    UNIT_CHECK(aero_texture_set(&t, "bad\nkey", "x") != 0,
               "newline in a key refused");
    aero_texture_free(&t);
    remove(DIR "tex_ok.wav");
    remove(DIR "tex_trunc.wav");
    remove(DIR "tex_junk.wav");
    remove(DIR "tex_chan.wav");
    remove(DIR "tex_nan.wav");
    remove(DIR "tex_plain.wav");
    remove(DIR "tex_rate.wav");
}

UNIT_TEST(resample)
{
    /* F = sin(2 pi f t) sampled at 64 kHz -> g = 2 pi f cos(2 pi f t) at
       16 kHz; a 10 kHz component (above the 7.2 kHz cut-off) is removed */
    const double dt = 1.0 / 64000.0, rate = 16000.0, f = 200.0, fh = 10000.0;
    const int n = 12800, nout = 2000;
    double *F = malloc(sizeof(double) * n), *Fh = malloc(sizeof(double) * n);
    double *t = malloc(sizeof(double) * n);
    float *g = malloc(sizeof(float) * nout), *gh = malloc(sizeof(float) * nout);
    double err = 0.0, peak = 0.0, hmax = 0.0;
    printf("derivative and resampling\n");
    for (int k = 0; k < n; k++) {
        /* slightly uneven steps, as the solver's */
        t[k] = k * dt + 0.2 * dt * sin(0.37 * k);
        F[k] = sin(2.0 * AERO_PI * f * t[k]);
        Fh[k] = sin(2.0 * AERO_PI * fh * t[k]);
    }
    aero_texture_resample_derivative(t, F, n, rate, 0.002, 1.0, g, 1, nout);
    aero_texture_resample_derivative(t, Fh, n, rate, 0.002, 1.0, gh, 1, nout);
    for (int k = 0; k < nout; k++) {
        double tk = 0.002 + k / rate;
        double want = 2.0 * AERO_PI * f * cos(2.0 * AERO_PI * f * tk);
        if (fabs(g[k] - want) > err) err = fabs(g[k] - want);
        if (fabs(want) > peak) peak = fabs(want);
        if (fabs(gh[k]) > hmax) hmax = fabs(gh[k]);
    }
    UNIT_CHECK(err < 2e-3 * peak, "g = dF/dt of a 200 Hz sine: error %.2g of "
               "%.4g", err, peak);
    UNIT_CHECK(hmax < 0.01 * 2.0 * AERO_PI * fh,
               "10 kHz removed by the low-pass: %.3g of %.4g (< -40 dB)", hmax,
               2.0 * AERO_PI * fh);
    free(t);
    free(F);
    free(Fh);
    free(g);
    free(gh);
}

UNIT_TEST(loop)
{
    /* period of 97 frames: the best loop in [900, 1100] is 970 or 1067 */
    const int period = 97, xf = 120, n = 1100 + xf;
    float *x = malloc(sizeof(float) * 2 * n);
    int len;
    double jump, step = 0.0;
    printf("loop search and cross-fade\n");
    for (int k = 0; k < n; k++) {
        x[2 * k] = (float)sin(2.0 * AERO_PI * k / period);
        x[2 * k + 1] = (float)(0.3 * sin(4.0 * AERO_PI * k / period + 1.0));
    }
    len = aero_texture_best_loop(x, 2, 900, 1100, xf);
    UNIT_CHECK(len % period == 0, "loop of %d frames = whole periods of %d",
               len, period);
    aero_texture_crossfade(x, 2, len, xf);
    for (int k = 1; k < len; k++)
        if (fabs(x[2 * k] - x[2 * k - 2]) > step)
            step = fabs(x[2 * k] - x[2 * k - 2]);
    jump = fabs(x[0] - x[2 * (len - 1)]);
    UNIT_CHECK(jump <= 1.01 * step, "wrap-around step %.3g <= largest step "
               "inside %.3g", jump, step);
    free(x);
}

/* The physical ceiling (texture.c): every shipped texture loads, its
   largest sample at least 100 times below its channel's bound (the bound
   is generous, not tuned to admit them), and a finite but impossible
   sample (3e38, a corrupt file) is refused naming its file and channel. */
UNIT_TEST(ceiling)
{
    static const char *shipped[] = {"cavity", "club", "cylinder", "fire",
                                    "sphere", "square", "sword"};
    char path[256], err[512];
    printf("physical ceiling\n");
    for (int i = 0; i < (int)(sizeof shipped / sizeof *shipped); i++) {
        aero_texture t;
        double worst = 0.0;
        snprintf(path, sizeof path, "textures/%s.wav", shipped[i]);
        err[0] = 0;
        if (aero_texture_load(path, &t, err, sizeof err)) {
            UNIT_CHECK(0, "%s loads: %s", path, err);
            continue;
        }
        for (int c = 0; c < t.channels; c++) {
            double lim = aero_texture_ceiling(&t, c), peak = 0.0;
            for (long n = 0; n < t.frames; n++) {
                double y = fabs(t.data[(size_t)n * t.channels + c]);
                peak = y > peak ? y : peak;
            }
            worst = peak / lim > worst ? peak / lim : worst;
        }
        printf("  %-9s largest sample / ceiling %.2e\n", shipped[i], worst);
        UNIT_CHECK(worst < 0.01, "%s: largest sample / ceiling %g < 0.01",
                   path, worst);
        /* the same file with one impossible sample in channel 2 */
        int two = t.channels > 1;
        t.data[(size_t)5 * t.channels + two] = 3e38f;
        snprintf(path, sizeof path, DIR "tex_ceiling_%s.wav", shipped[i]);
        UNIT_CHECK(aero_texture_save(path, &t, err, sizeof err) == 0,
                   "saved %s", path);
        aero_texture_free(&t);
        err[0] = 0;
        UNIT_CHECK(aero_texture_load(path, &t, err, sizeof err) != 0 &&
                       strstr(err, path) &&
                       strstr(err, two ? "channel 2" : "channel 1"),
                   "3e38 refused naming the file and channel: %s", err);
        remove(path);
    }
}

UNIT_MAIN(UNIT_CASE(round_trip), UNIT_CASE(bad_files), UNIT_CASE(resample),
          UNIT_CASE(loop), UNIT_CASE(ceiling))
