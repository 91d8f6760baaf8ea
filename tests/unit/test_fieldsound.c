/* Unit tests of src/core/common/field_volume and field_sound (Shin and Bajaj):
 * the volume format and its errors, the 1/r law and the arrival delay r/c0 of
 * a pulsating point, silence until the radiation arrives, the dipole class
 * of a translating density, the chunk polynomials against the per-sample
 * sum. Files go to build/tests/field/. */
#include "fieldsound.h"
#include "unit.h"
#include "multi_instance.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define SR 48000.0
#define C0 343.0
#define DIR "build/tests/field"

static char err[512];

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
}

static void write_bytes(const char *path, size_t bytes)
{
    FILE *f = fopen(path, "wb");
    for (size_t i = 0; i < bytes; i++)
        fputc(0, f);
    fclose(f);
}

/* header text -> read it; 0 ok, else -1 with err */
static int header(const char *text, aero_volume_info *v)
{
    write_text(DIR "/hdr/volume.txt", text);
    return aero_volume_read_header(DIR "/hdr", v, err, sizeof err);
}

static void bad_header(const char *text, const char *expect)
{
    aero_volume_info v;
    int rc = header(text, &v);
    UNIT_CHECK(rc && strstr(err, expect), "bad header rejected: \"%s\"",
               err);
}

UNIT_TEST(format)
{
    aero_volume_info v, w;
    mkdir("build/tests", 0777);
    mkdir(DIR, 0777);
    mkdir(DIR "/hdr", 0777);
    const char *good = "aero-volume 1\n# a comment\ndims 4 3 2\n"
                       "spacing 0.1 0.2 0.3\norigin 1 2 3\nrate 30\n"
                       "frames 2\nfields density vx vy vz\n";
    UNIT_CHECK(header(good, &v) == 0 && v.nx == 4 && v.ny == 3 &&
                   v.nz == 2 && v.fields == 4 && v.frames == 2 &&
                   v.rate == 30 && v.spacing[2] == 0.3 && v.origin[1] == 2,
               "a good header is read (%s)", header(good, &v) ? err : "ok");
    bad_header("", "empty");
    bad_header("volume 1\ndims 4 4 4\n", "not an aero volume");
    bad_header("aero-volume 1\nspacing 1 1 1\nrate 1\nframes 1\n"
               "fields density\n", "missing 'dims'");
    bad_header("aero-volume 1\ndims 4 4\nspacing 1 1 1\n", "'dims' needs");
    bad_header("aero-volume 1\ndims 4 4 1.5\n", "'dims' needs");
    bad_header("aero-volume 1\ndims 4 4 4\nspacing 1 -1 1\n", "'spacing'");
    bad_header("aero-volume 1\ndims 4 4 4\nspacing 1 1 1\nrate fast\n",
               "'rate'");
    bad_header("aero-volume 1\ndims 4 4 4\nspacing 1 1 1\nrate 1\n"
               "frames 0\n", "'frames'");
    bad_header("aero-volume 1\ndims 4 4 4\nspacing 1 1 1\nrate 1\n"
               "frames 1\nfields pressure\n", "'fields'");
    bad_header("aero-volume 1\ndims 4 4 4\ncolour blue\n", "unknown key");
    bad_header("aero-volume 1\ndims 4 4 4\nspacing 1 1 1\nrate 1\n"
               "frames 1\nfields density\nfiles f%s.raw\n", "'files'");
    {
        int rc = aero_volume_read_header(DIR "/nowhere", &v, err,
                                         sizeof err);
        UNIT_CHECK(rc && strstr(err, "can't open"), "missing header: \"%s\"",
                   err);
    }
    /* frames: round trip, then truncated, too long, missing */
    mkdir(DIR "/vol", 0777);
    memset(&w, 0, sizeof w);
    w.nx = 4, w.ny = 3, w.nz = 2, w.frames = 3, w.fields = 1, w.rate = 10;
    w.spacing[0] = w.spacing[1] = w.spacing[2] = 0.5;
    strcpy(w.dir, DIR "/vol");
    strcpy(w.pattern, "f%03d.raw");
    float data[24], back[24];
    for (int i = 0; i < 24; i++)
        data[i] = 0.25f * i - 1;
    int rc = aero_volume_write_header(&w, err, sizeof err);
    for (int k = 0; k < 3 && !rc; k++)
        rc = aero_volume_write_frame(&w, k, data, err, sizeof err);
    rc = rc || aero_volume_read_header(DIR "/vol", &v, err, sizeof err) ||
         aero_volume_read_frame(&v, 1, back, err, sizeof err);
    UNIT_CHECK(!rc && !memcmp(data, back, sizeof data) &&
                   !strcmp(v.pattern, "f%03d.raw"),
               "header and frame written and read back");
    write_bytes(DIR "/vol/f001.raw", 95);
    rc = aero_volume_read_frame(&v, 1, back, err, sizeof err);
    UNIT_CHECK(rc && strstr(err, "truncated") && strstr(err, "f001.raw"),
               "truncated frame: \"%s\"", err);
    write_bytes(DIR "/vol/f001.raw", 97);
    rc = aero_volume_read_frame(&v, 1, back, err, sizeof err);
    UNIT_CHECK(rc && strstr(err, "too long"), "oversized frame: \"%s\"",
               err);
    remove(DIR "/vol/f002.raw");
    rc = aero_volume_read_frame(&v, 2, back, err, sizeof err);
    UNIT_CHECK(rc && strstr(err, "can't open frame 2"),
               "missing frame: \"%s\"", err);
    aero_field_sources s;
    aero_field_params par;
    aero_field_params_default(&par);
    rc = aero_field_prepare(&v, NULL, &par, &s, NULL, NULL, err, sizeof err);
    UNIT_CHECK(rc && strstr(err, "f001.raw"),
               "preparing a volume with a bad frame fails: \"%s\"", err);
}

/* an in-memory volume: n^3, spacing h, rate fps, density + velocity */
typedef struct {
    aero_volume_info info;
    float *data; /* frames * 4 * count */
} memvol;

static void memvol_init(memvol *m, int n, double h, double rate, int frames)
{
    memset(&m->info, 0, sizeof m->info);
    m->info.nx = m->info.ny = m->info.nz = n;
    m->info.frames = frames;
    m->info.fields = 4;
    m->info.rate = rate;
    for (int a = 0; a < 3; a++) {
        m->info.spacing[a] = h;
        m->info.origin[a] = -(n / 2) * h; /* vertex n/2 at the origin */
    }
    m->data = calloc((size_t)frames * 4 * n * n * n, sizeof(float));
}

static float *memvol_frame(memvol *m, int k)
{
    return m->data + (size_t)k * 4 * aero_volume_count(&m->info);
}

static int memvol_sources(memvol *m, const aero_field_params *par,
                          aero_field_sources *s)
{
    aero_field_pre pre;
    int rc = aero_field_pre_init(&pre, &m->info, par, err, sizeof err);
    for (int k = 0; !rc && k < m->info.frames; k++)
        rc = aero_field_pre_push(&pre, memvol_frame(m, k), err, sizeof err);
    if (!rc)
        rc = aero_field_pre_finish(&pre, s, err, sizeof err);
    aero_field_pre_free(&pre);
    return rc;
}

/* a still field (rho 1.225, v = 0) with one vertex pulsating:
 * rho = 1.225 + a sin(2 pi f t) from frame `start` on */
static void pulsating_point(memvol *m, int x, int y, int z, double f,
                            int start)
{
    int n = m->info.nx;
    size_t count = aero_volume_count(&m->info);
    for (int k = 0; k < m->info.frames; k++) {
        float *d = memvol_frame(m, k);
        for (size_t i = 0; i < count; i++)
            d[i] = 1.225f;
        double t = (k - start) / m->info.rate;
        if (k >= start)
            d[x + n * (y + (size_t)n * z)] +=
                (float)(0.01 * sin(2 * 3.14159265358979 * f * t));
    }
}

static float *render(const aero_field_sources *s, double x, double y,
                     double z, double seconds, int direct, long *len)
{
    aero_fieldsound r;
    long n = (long)(seconds * SR);
    float *out = calloc(n, sizeof(float));
    aero_fieldsound_init(&r, SR, 1, 0);
    aero_fieldsound_set_sources(&r, s);
    aero_fieldsound_place_ears(&r, &(aero_ears){1, {{x, y, z}}});
    r.direct = direct;
    aero_fieldsound_play(&r);
    aero_fieldsound_process(&r, out, (int)n);
    aero_fieldsound_free(&r);
    *len = n;
    return out;
}

static double rms(const float *x, long n)
{
    double s = 0;
    for (long i = 0; i < n; i++)
        s += (double)x[i] * x[i];
    return sqrt(s / n);
}

static long first_sound(const float *x, long n)
{
    for (long i = 0; i < n; i++)
        if (x[i] != 0)
            return i;
    return -1;
}

/* lag of b against a (b later: positive) by the cross-correlation peak */
static long lag_of(const float *a, const float *b, long n, long maxlag)
{
    long best = 0;
    double top = -1e300;
    for (long l = 0; l <= maxlag; l++) {
        double c = 0;
        for (long i = 0; i + l < n; i++)
            c += (double)a[i] * b[i + l];
        if (c > top)
            top = c, best = l;
    }
    return best;
}

UNIT_TEST(monopole)
{
    memvol m;
    aero_field_sources s;
    aero_field_params par;
    memvol_init(&m, 12, 0.1, 2000, 80);
    pulsating_point(&m, 6, 6, 6, 100, 0); /* the vertex at the origin */
    aero_field_params_default(&par);
    par.threshold[0] = 1;                 /* |d rho/dt| peaks at 6.3 */
    int rc = memvol_sources(&m, &par, &s);
    UNIT_CHECK(!rc && s.count == 1 && s.points[1] > 0 && !s.points[2] &&
                   !s.points[3],
               "pulsating point: one monopole vertex, %ld monopole frames, "
               "%ld dipole, %ld quadrupole", s.points[1], s.points[2],
               s.points[3]);
    /* 1/r: rms * r the same at 2, 4 and 8 m (a point source, so the only
     * error is float rounding and the chunk's linear 1/D: < 0.1 %; 1 %
     * keeps 1/r^2 (-50 %) and no decay (+100 %) far outside) */
    double dist[3] = {2, 4, 8}, level[3];
    float *out[3];
    long n = 0;
    for (int k = 0; k < 3; k++) {
        out[k] = render(&s, dist[k] * 0.6, dist[k] * 0.8, 0, 0.08, 0, &n);
        level[k] = rms(out[k], n);
    }
    UNIT_CHECK(level[0] > 0, "pulsating point is heard: %g Pa rms at 2 m",
               level[0]);
    for (int k = 1; k < 3; k++)
        UNIT_NEAR_REL(level[k] * dist[k], level[0] * dist[0], 0.01,
                      "rms * r (1/r decay)");
    /* arrival delay r/c0: nothing before it, sound within one frame after
     * (the first frame's cubic piece starts there) */
    for (int k = 0; k < 3; k++) {
        long on = first_sound(out[k], n);
        double expect = dist[k] / C0 * SR;
        UNIT_CHECK(on >= expect - 1 && on <= expect + SR / 2000 + 1,
                   "first sound at %.2f ms for r = %g m (r/c0 = %.2f ms)",
                   1e3 * on / SR, dist[k], 1e3 * dist[k] / C0);
    }
    /* and the waveform: the 4 m render is the 2 m one delayed by 2/c0
     * (to a sample) */
    {
        long lag = lag_of(out[0], out[1], n, (long)(0.02 * SR));
        double expect = (dist[1] - dist[0]) / C0 * SR;
        UNIT_CHECK(fabs(lag - expect) <= 1,
                   "cross-correlation lag 2 m -> 4 m: %ld samples, "
                   "(r2 - r1)/c0 = %.1f", lag, expect);
    }
    /* the chunk polynomials against the per-sample sum */
    {
        long n2;
        float *ref = render(&s, 1.2, 1.6, 0, 0.08, 1, &n2);
        double worst = 0, peak = 0;
        for (long i = 0; i < n2; i++) {
            worst = fmax(worst, fabs(ref[i] - out[0][i]));
            peak = fmax(peak, fabs(ref[i]));
        }
        UNIT_CHECK(peak > 0 && worst <= 1e-5 * peak,
                   "chunk polynomials = per-sample sum: worst %.3g of peak "
                   "%.3g", worst, peak);
        free(ref);
    }
    for (int k = 0; k < 3; k++)
        free(out[k]);
    aero_field_sources_free(&s);
    free(m.data);
}

/* a source 60 m away (outside the audible distance at first) is silent
 * until its radiation arrives; a near one is heard alone until then */
UNIT_TEST(reach)
{
    memvol m;
    aero_field_sources s_near, s_both;
    aero_field_params par;
    aero_field_params_default(&par);
    par.threshold[0] = 1;
    /* 16^3 at 4 m spacing: a 60 m cube (the paper's scale) */
    memvol_init(&m, 16, 4, 500, 40);
    pulsating_point(&m, 1, 8, 8, 40, 0);  /* (-28, 0, 0) */
    int rc = memvol_sources(&m, &par, &s_near);
    /* add a far point at (+28, 0, 0), 56 m from the near one */
    {
        int n = 16;
        for (int k = 0; k < m.info.frames; k++)
            memvol_frame(&m, k)[15 + n * (8 + (size_t)n * 8)] +=
                (float)(0.01 * sin(2 * 3.14159265358979 * 60 * k / 500.0));
    }
    rc = rc || memvol_sources(&m, &par, &s_both);
    UNIT_CHECK(!rc && s_near.count == 1 && s_both.count == 2,
               "near and far points detected (%d, %d)", s_near.count,
               s_both.count);
    /* listener 2 m from the near point */
    long n;
    float *a = render(&s_near, -28, 2, 0, 0.3, 0, &n);
    float *b = render(&s_both, -28, 2, 0, 0.3, 0, &n);
    double far = sqrt(56.0 * 56 + 4) / C0;
    long arrive = (long)(far * SR) - 1, differs = -1;
    for (long i = 0; i < n; i++)
        if (a[i] != b[i]) {
            differs = i;
            break;
        }
    UNIT_CHECK(differs >= arrive && differs <= arrive + SR / 500 + 2,
               "the far source is first heard at %.2f ms (arrival %.2f ms)",
               1e3 * differs / SR, 1e3 * far);
    /* negative control: the same sum with the listener in the middle is
     * not the near source alone from the start */
    {
        float *c = render(&s_near, 0, 2, 0, 0.3, 0, &n);
        float *d = render(&s_both, 0, 2, 0, 0.3, 0, &n);
        long on = first_sound(d, n);
        UNIT_CHECK(on > 0 && on < 0.09 * SR && rms(d, n) > 1.2 * rms(c, n),
                   "control: from the middle both arrive at ~82 ms (first "
                   "sound %.2f ms)", 1e3 * on / SR);
        free(c);
        free(d);
    }
    free(a);
    free(b);
    aero_field_sources_free(&s_near);
    aero_field_sources_free(&s_both);
    free(m.data);
}

/* a Gaussian blob of density carried by a uniform flow u: no mass is
 * made (the continuity residual is only the discretisation error), the
 * momentum changes: a dipole */
static void translating_blob(memvol *m, const double *u, double sigma,
                             int pulsate)
{
    int n = m->info.nx;
    double h = m->info.spacing[0];
    for (int k = 0; k < m->info.frames; k++) {
        float *d = memvol_frame(m, k);
        size_t count = aero_volume_count(&m->info);
        double t = k / m->info.rate;
        for (int z = 0; z < n; z++)
            for (int y = 0; y < n; y++)
                for (int x = 0; x < n; x++) {
                    size_t i = x + n * (y + (size_t)n * z);
                    double p[3] = {m->info.origin[0] + x * h,
                                   m->info.origin[1] + y * h,
                                   m->info.origin[2] + z * h};
                    double r2 = 0;
                    for (int a = 0; a < 3; a++) {
                        double e = p[a] - (pulsate ? 0 : u[a] * t);
                        r2 += e * e;
                    }
                    double amp = pulsate ? 0.5 * (1 + sin(2 * 3.14159265 *
                                                          100 * t))
                                         : 1;
                    d[i] = (float)(1.225 + 0.2 * amp *
                                              exp(-r2 / (2 * sigma * sigma)));
                    for (int a = 0; a < 3; a++)
                        d[i + (size_t)(a + 1) * count] =
                            pulsate ? 0.0f : (float)u[a];
                }
    }
}

UNIT_TEST(classification)
{
    memvol m;
    aero_field_sources s;
    aero_field_params par;
    const double h = 0.01, rate = 1000, sigma = 3 * h;
    /* half a cell per frame, along x and y */
    const double u[3] = {4, 3, 0}, speed = 5;
    memvol_init(&m, 24, h, rate, 12);
    translating_blob(&m, u, sigma, 0);
    aero_field_params_default(&par);
    /* thresholds at 10 % of the analytic peaks: |d rho/dt| <= A |u| /
     * sigma e^-1/2 (the monopole strength if the flow were ignored) and
     * |(u.grad)^2 rho| <= A |u|^2 / sigma^2 (dipole and quadrupole) */
    par.threshold[0] = 0.1 * 0.2 * speed / sigma * exp(-0.5);
    par.threshold[1] = par.threshold[2] = 0.1 * 0.2 * speed * speed /
                                          (sigma * sigma);
    int rc = memvol_sources(&m, &par, &s);
    long total = s.points[1] + s.points[2] + s.points[3];
    UNIT_CHECK(!rc && s.points[2] > 100 && s.points[1] == 0 &&
                   s.points[2] >= 0.95 * total,
               "translating density: %ld dipole, %ld monopole, %ld "
               "quadrupole source points", s.points[2], s.points[1],
               s.points[3]);
    aero_field_sources_free(&s);
    /* negative control: the paper's monopole |d rho/dt| (flow ignored,
     * velocity from the gradient) calls the same data monopoles */
    par.use_velocity = 0;
    rc = memvol_sources(&m, &par, &s);
    UNIT_CHECK(!rc && s.points[1] > 100,
               "control: ignoring the flow, %ld monopole points",
               s.points[1]);
    aero_field_sources_free(&s);
    /* positive control: a blob pulsating in place is a monopole */
    par.use_velocity = 1;
    translating_blob(&m, u, sigma, 1);
    rc = memvol_sources(&m, &par, &s);
    UNIT_CHECK(!rc && s.points[1] > 100 && s.points[2] == 0,
               "pulsating blob: %ld monopole, %ld dipole points", s.points[1],
               s.points[2]);
    aero_field_sources_free(&s);
    free(m.data);
}

/* the demo burst: sources of every type, finite output, chunk polynomials
 * = per-sample sum with a moving listener; hostile data stay finite */
UNIT_TEST(demo)
{
    aero_field_demo d;
    aero_volume_info v;
    aero_field_sources s;
    aero_field_params par;
    aero_field_demo_default(&d);
    d.size = 20;
    d.frames = 16;
    d.spacing = 0.05;
    aero_field_demo_info(&d, &v);
    aero_field_params_default(&par);
    int rc = aero_field_prepare(&v, &d, &par, &s, NULL, NULL, err,
                                sizeof err);
    UNIT_CHECK(!rc && s.points[1] > 0 && s.points[2] + s.points[3] > 0,
               "demo burst: %ld monopole, %ld dipole, %ld quadrupole points",
               s.points[1], s.points[2], s.points[3]);
    aero_fieldsound r[2];
    float out[2][4096];
    double worst = 0, peak = 0;
    int bad = 0;
    for (int k = 0; k < 2; k++) {
        aero_fieldsound_init(&r[k], SR, 1, 0);
        aero_fieldsound_set_sources(&r[k], &s);
        r[k].direct = k;
        aero_fieldsound_place_ears(&r[k], &(aero_ears){1, {{1, 0, 0}}});
        aero_fieldsound_set_ramp_ms(&r[k], 50);
        aero_fieldsound_set_ears(&r[k], &(aero_ears){1, {{-1, 0.5, 0.2}}});
        aero_fieldsound_play(&r[k]);
        aero_fieldsound_process(&r[k], out[k], 4096);
    }
    for (int i = 0; i < 4096; i++) {
        worst = fmax(worst, fabs(out[0][i] - out[1][i]));
        peak = fmax(peak, fabs(out[1][i]));
        bad += !isfinite(out[0][i]);
    }
    UNIT_CHECK(peak > 0 && !bad && worst <= 1e-4 * peak,
               "moving listener: chunk polynomials within %.2g of the "
               "per-sample sum (peak %.3g Pa)", worst, peak);
    for (int k = 0; k < 2; k++)
        aero_fieldsound_free(&r[k]);
    aero_field_sources_free(&s);
    /* NaN and Inf in the data, absurd listener, speed and ramp */
    memvol m;
    memvol_init(&m, 8, 0.1, 1000, 6);
    for (size_t i = 0; i < 6 * 4 * 512; i++)
        m.data[i] = i % 7 == 0 ? NAN : i % 11 == 0 ? INFINITY : 1.0f;
    rc = memvol_sources(&m, &par, &s);
    aero_fieldsound_init(&r[0], SR, 1, 0);
    aero_fieldsound_set_sources(&r[0], &s);
    int refused = aero_fieldsound_set_ears(&r[0],
                                             &(aero_ears){1, {{NAN, 0, 0}}}) &&
                  aero_fieldsound_set_speed(&r[0], -1) &&
                  aero_fieldsound_set_ramp_ms(&r[0], -5) &&
                  aero_fieldsound_set_gain_db(&r[0], 1e9);
    aero_fieldsound_set_ears(&r[0],
                               &(aero_ears){1, {{1e5, 0, 0}}}); /* far, fast */
    aero_fieldsound_play(&r[0]);
    aero_fieldsound_process(&r[0], out[0], 4096);
    bad = 0;
    for (int i = 0; i < 4096; i++)
        bad += !isfinite(out[0][i]);
    UNIT_CHECK(!rc && refused && !bad && r[0].clamped,
               "NaN/Inf data and bad settings: refused, output finite, "
               "listener clamped at Mach 0.3");
    aero_fieldsound_free(&r[0]);
    aero_field_sources_free(&s);
    free(m.data);
    aero_field_params_default(&par);
    par.threshold[1] = 0;
    UNIT_CHECK(aero_field_params_check(&par, err, sizeof err) &&
                   strstr(err, "dipole threshold"),
               "zero threshold refused: \"%s\"", err);
}

/* --- two instances at once (tests/unit/multi_instance.h): the demo
   burst, preprocessed, played slowly --- */
typedef struct {
    aero_field_sources src;
    aero_fieldsound r;
} mi_state;
static void *mi_make(int variant)
{
    char e[256];
    aero_field_demo d;
    aero_volume_info info;
    aero_field_params par;
    mi_state *f = calloc(1, sizeof(*f));
    aero_field_demo_default(&d);
    d.size = 12;
    d.spacing = 1.28 / d.size;
    d.seed = 1u + variant;
    aero_field_demo_info(&d, &info);
    aero_field_params_default(&par);
    aero_field_prepare(&info, &d, &par, &f->src, NULL, NULL, e, sizeof(e));
    aero_fieldsound_init(&f->r, 44100.0, 1, 0);
    aero_fieldsound_set_sources(&f->r, &f->src);
    aero_fieldsound_place_ears(&f->r,
            &(aero_ears){1, {{variant ? 0.5 : 0.8, 0.1, 0.0}}});
    aero_fieldsound_set_speed(&f->r, 100.0);
    aero_fieldsound_play(&f->r);
    return f;
}
static void mi_run(void *s, const float *speed, float *out, int n)
{
    (void)speed;
    aero_fieldsound_process(&((mi_state *)s)->r, out, n);
}
static void mi_drop(void *s)
{
    mi_state *f = s;
    aero_fieldsound_free(&f->r);
    aero_field_sources_free(&f->src);
    free(f);
}

UNIT_TEST(multi_instance)
{
    unit_multi_instance("fieldsound~", "the demo burst", mi_make, mi_run,
                        mi_drop);
}

/* the object contract (CONTRIBUTING.md): init(r, sr, n_ears, seed)
   answers -1 for a sample rate it cannot use or more than the one
   listener, and the player stays usable (silent without sources) */
UNIT_TEST(init_contract)
{
    aero_fieldsound r;
    float out[64];
    int silent = 1;
    UNIT_CHECK(aero_fieldsound_init(&r, SR, 2, 0) == -1,
               "init with two ears answers -1 (one listener)");
    aero_fieldsound_free(&r);
    UNIT_CHECK(aero_fieldsound_init(&r, NAN, 1, 0) == -1,
               "init at a NaN sample rate answers -1");
    aero_fieldsound_process(&r, out, 64);
    for (int i = 0; i < 64; i++)
        silent &= out[i] == 0.0f;
    UNIT_CHECK(silent, "and the player is silent without sources");
    aero_fieldsound_free(&r);
}

/* the volume parameters' setters (the object contract): 0 within the
   named ranges, -1 outside with the parameters unchanged, and what they
   accept is what aero_field_params_check accepts */
UNIT_TEST(param_setters)
{
    aero_field_params p, before;
    const double good_t[3] = {1, 2, AERO_FIELD_THRESHOLD_MAX};
    const double bad_t[3][3] = {{AERO_FIELD_THRESHOLD_MIN, 1, 1},
                                {1, NAN, 1},
                                {1, 1, AERO_FIELD_THRESHOLD_MAX * 2}};
    int kept = 1, ok;
    aero_field_params_default(&p);
    before = p;
    for (int k = 0; k < 3; k++)
        kept &= aero_field_params_set_threshold(&p, bad_t[k]) == -1;
    kept &= aero_field_params_set_map(&p, 1, 1, 0, 1) == -1;
    kept &= aero_field_params_set_map(&p, 0, INFINITY, 0, 1) == -1;
    kept &= aero_field_params_set_map(&p, 0, 1, AERO_FIELD_RHO_MIN - 1,
                                      1) == -1;
    kept &= aero_field_params_set_map(&p, 0, 1, 0,
                                      AERO_FIELD_RHO_MAX * 2) == -1;
    kept &= aero_field_params_set_zero(&p, AERO_FIELD_ZERO_MAX + 1) == -1;
    kept &= aero_field_params_set_zero(&p, NAN) == -1;
    kept &= aero_field_params_set_vscale(&p, -2 * AERO_FIELD_VSCALE_MAX)
        == -1;
    kept &= aero_field_params_set_vscale(&p, INFINITY) == -1;
    kept &= aero_field_params_set_log(&p, 2) == -1;
    kept &= aero_field_params_set_velocity(&p, -1) == -1;
    UNIT_CHECK(kept && !memcmp(&p, &before, sizeof p),
               "out-of-range values refused (-1), the parameters unchanged");
    ok = !aero_field_params_set_threshold(&p, good_t) &&
        !aero_field_params_set_map(&p, 5, -5, AERO_FIELD_RHO_MAX,
                                   AERO_FIELD_RHO_MIN) &&
        !aero_field_params_set_zero(&p, AERO_FIELD_ZERO_MIN) &&
        !aero_field_params_set_vscale(&p, -AERO_FIELD_VSCALE_MAX) &&
        !aero_field_params_set_log(&p, 1) &&
        !aero_field_params_set_velocity(&p, 0);
    UNIT_CHECK(ok && p.threshold[2] == AERO_FIELD_THRESHOLD_MAX &&
                   p.in_lo == 5 && p.rho_hi == AERO_FIELD_RHO_MIN &&
                   p.zero == AERO_FIELD_ZERO_MIN && p.log_input == 1 &&
                   p.use_velocity == 0 &&
                   !aero_field_params_check(&p, err, sizeof err),
               "values at the bounds accepted, and check agrees");
}

UNIT_MAIN(UNIT_CASE(format), UNIT_CASE(monopole), UNIT_CASE(reach), UNIT_CASE(classification), UNIT_CASE(demo), UNIT_CASE(multi_instance), UNIT_CASE(init_contract), UNIT_CASE(param_setters))
