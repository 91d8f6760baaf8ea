/* aerotex field-demo and aerotex auralize: field auralization of volume
 * data offline (Shin and Bajaj). The method is in
 * src/core/solve/field_prepare.h, the volume format in
 * src/core/common/field_volume.h. */
#include "aerotex.h"
#include "fieldsound.h"

#include <errno.h>
#include <math.h>
#include <sndfile.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* --- aerotex field-demo ------------------------------------------------ */

typedef struct {
    aero_field_demo d;
    const char *dir;
    int quiet;
} demo_job;

#define AT(field) offsetof(demo_job, field)
static const aerotex_option demo_options[] = {
    {"--size", AEROTEX_WHOLE, "N", NAN, 4.0, 512.0, AT(d.size),
     "vertices along each edge of the cube", NULL, NULL},
    {"--frames", AEROTEX_WHOLE, "N", NAN, 1.0, 100000.0, AT(d.frames),
     "frames", NULL, NULL},
    {"--spacing", AEROTEX_NUMBER, "m", NAN, 1e-5, 1e3, AT(d.spacing),
     "vertex spacing", NULL, NULL},
    {"--rate", AEROTEX_NUMBER, "fps", NAN, 1e-3, 1e6, AT(d.rate),
     "frames per second", NULL, NULL},
    {"--shell-speed", AEROTEX_NUMBER, "m/s", NAN, 0.0, 1e3,
     AT(d.shell_speed), "the burst's expansion", NULL, NULL},
    {"--velocity", AEROTEX_SWITCH, NULL, NAN, 1, 0, AT(d.velocity),
     "also the fields vx vy vz", NULL, NULL},
    {"--seed", AEROTEX_SEED, "n", NAN, 0, 0, AT(d.seed), "turbulence seed",
     NULL, NULL},
    {"-q", AEROTEX_SWITCH, NULL, NAN, 1, 0, AT(quiet), "no progress bar",
     NULL, NULL},
    {"-o", AEROTEX_TEXT, "DIR", NAN, 0, 0, AT(dir), "the volume", NULL, NULL},
    {NULL, 0, NULL, 0, 0, 0, 0, NULL, NULL, NULL}};
#undef AT

static void demo_init(void *job)
{
    aero_field_demo_default(&((demo_job *)job)->d);
}

/* the header and every frame of the volume: the exit status */
static int write_volume(const demo_job *j, const aero_volume_info *v)
{
    aerotex_progress prog;
    char err[512];
    float *data;
    if (aero_volume_write_header(v, err, sizeof err)) {
        aerotex_error("%s", err);
        return 1;
    }
    data = malloc(aero_volume_count(v) * v->fields * sizeof(float));
    if (!data) {
        aerotex_error("out of memory");
        return 1;
    }
    aerotex_progress_start(&prog, "field-demo", j->d.frames, j->quiet);
    for (int k = 0; k < j->d.frames; k++) {
        aero_field_demo_frame(&j->d, k, data);
        if (aero_volume_write_frame(v, k, data, err, sizeof err)) {
            aerotex_error("%s", err);
            free(data);
            aerotex_progress_end(&prog);
            return 1;
        }
        aerotex_progress_add(&prog, 1);
    }
    aerotex_progress_end(&prog);
    free(data);
    return 0;
}

static int field_demo_run(int argc, char **argv)
{
    demo_job j;
    aero_volume_info v;
    aerotex_defaults(&aerotex_field_demo_command, &j);
    if (aerotex_parse(&aerotex_field_demo_command, &j, argc, argv))
        return 2;
    if (!j.dir) {
        aerotex_error("field-demo: no output directory (-o DIR)");
        return 2;
    }
    if (aerotex_mkdir(j.dir) && errno != EEXIST) {
        aerotex_error("field-demo: can't make directory %s: %s", j.dir,
                      strerror(errno));
        return 1;
    }
    aero_field_demo_info(&j.d, &v);
    if (strlen(j.dir) >= sizeof v.dir) {
        aerotex_error("field-demo: directory name too long");
        return 2;
    }
    strcpy(v.dir, j.dir);
    if (write_volume(&j, &v))
        return 1;
    printf("wrote %s: %d frames of %dx%dx%d (%s), %g m spacing, %g frames/s\n",
           j.dir, j.d.frames, j.d.size, j.d.size, j.d.size,
           j.d.velocity ? "density vx vy vz" : "density", j.d.spacing,
           j.d.rate);
    return 0;
}

const aerotex_command aerotex_field_demo_command = {
    "field-demo", "-o DIR",
    "writes a synthetic volume (an expanding burst with turbulence) in the\n"
    "field volume format (src/core/common/field_volume.h)",
    demo_options, sizeof(demo_job), demo_init, field_demo_run};

/* --- aerotex auralize --------------------------------------------------- */

typedef struct {
    double t, p[3];
} path_point;

/* `t x y z` per line, '#' comments, t not decreasing */
static int read_path(const char *file, path_point **out, int *count)
{
    FILE *f = fopen(file, "r");
    char line[512];
    int n = 0, cap = 0, lineno = 0;
    path_point *pts = NULL;
    if (!f) {
        aerotex_error("can't open path file %s: %s", file, strerror(errno));
        return -1;
    }
    while (fgets(line, sizeof line, f)) {
        char *c = strchr(line, '#'), *s = line, *end;
        double x[4];
        int k;
        lineno++;
        if (c)
            *c = 0;
        while (*s == ' ' || *s == '\t')
            s++;
        if (!*s || *s == '\n' || *s == '\r')
            continue;
        for (k = 0; k < 4; k++) {
            x[k] = strtod(s, &end);
            if (end == s || !(x[k] == x[k]) || fabs(x[k]) > 1e5)
                break;
            s = end;
        }
        while (*s == ' ' || *s == '\t' || *s == '\n' || *s == '\r')
            s++;
        if (k < 4 || *s) {
            aerotex_error("%s:%d: a path line is 't x y z' (seconds, metres, "
                          "|value| <= 1e5)", file, lineno);
            goto fail;
        }
        if (n > 0 && x[0] < pts[n - 1].t) {
            aerotex_error("%s:%d: time %g goes back (previous %g)", file,
                          lineno, x[0], pts[n - 1].t);
            goto fail;
        }
        if (n == cap) {
            cap = cap ? 2 * cap : 64;
            path_point *p = realloc(pts, cap * sizeof *p);
            if (!p) {
                aerotex_error("out of memory");
                goto fail;
            }
            pts = p;
        }
        pts[n].t = x[0];
        memcpy(pts[n].p, x + 1, sizeof pts[n].p);
        n++;
    }
    fclose(f);
    if (!n) {
        aerotex_error("%s: no points", file);
        free(pts);
        return -1;
    }
    *out = pts;
    *count = n;
    return 0;
fail:
    fclose(f);
    free(pts);
    return -1;
}

/* listener at time t: linear between points, held before and after */
static void path_at(const path_point *p, int n, double t, double *x)
{
    int k = 0;
    if (t <= p[0].t) {
        memcpy(x, p[0].p, 3 * sizeof(double));
        return;
    }
    while (k + 1 < n && p[k + 1].t < t)
        k++;
    if (k + 1 >= n) {
        memcpy(x, p[n - 1].p, 3 * sizeof(double));
        return;
    }
    double span = p[k + 1].t - p[k].t, f = span > 0 ? (t - p[k].t) / span : 1;
    for (int a = 0; a < 3; a++)
        x[a] = p[k].p[a] + (p[k + 1].p[a] - p[k].p[a]) * f;
}

typedef struct {
    const char *dir, *path_file, *out_file;
    aero_field_params par;
    aero_field_demo demo;
    double rate, speed, duration, gain_db;
    int quiet, direct, use_demo;
} auralize_job;

/* the volume directory, given once */
static int parse_dir(void *job, const char *cmd, int argc, char **argv,
                     int *i)
{
    auralize_job *j = job;
    (void)argc;
    if (j->dir) {
        aerotex_error("%s: one volume directory only ('%s')", cmd, argv[*i]);
        return -1;
    }
    j->dir = argv[*i];
    return 0;
}

static int parse_threshold(void *job, const char *cmd, int argc, char **argv,
                           int *i)
{
    auralize_job *j = job;
    for (int t = 0; t < 3; t++)
        if (aerotex_number(cmd, "--threshold", argc, argv, i, 1e-30, 1e30,
                           &j->par.threshold[t]))
            return -1;
    return 0;
}

static int parse_map(void *job, const char *cmd, int argc, char **argv,
                     int *i)
{
    auralize_job *j = job;
    return aerotex_number(cmd, "--map", argc, argv, i, -1e30, 1e30,
                          &j->par.in_lo) ||
           aerotex_number(cmd, "--map", argc, argv, i, -1e30, 1e30,
                          &j->par.in_hi) ||
           aerotex_number(cmd, "--map", argc, argv, i, 0, 1e6,
                          &j->par.rho_lo) ||
           aerotex_number(cmd, "--map", argc, argv, i, 0, 1e6,
                          &j->par.rho_hi)
               ? -1 : 0;
}

/* --demo [N]: the synthetic burst in memory, no files (benchmarks) */
static int parse_demo(void *job, const char *cmd, int argc, char **argv,
                      int *i)
{
    auralize_job *j = job;
    double x;
    j->use_demo = 1;
    if (*i + 1 < argc && argv[*i + 1][0] != '-') {
        if (aerotex_number(cmd, "--demo", argc, argv, i, 4, 512, &x))
            return -1;
        j->demo.size = (int)x;
    }
    return 0;
}

#define AT(field) offsetof(auralize_job, field)
static const aerotex_option auralize_options[] = {
    {"", AEROTEX_CUSTOM, "DIR", NAN, 0, 0, 0, NULL, NULL, parse_dir},
    {"--path", AEROTEX_TEXT, "FILE", NAN, 0, 0, AT(path_file),
     "the listener: lines 't x y z', seconds and metres,\nlinear in "
     "between", NULL, NULL},
    {"--rate", AEROTEX_NUMBER, "Hz", 48000.0, 1000.0, 384000.0, AT(rate),
     "sample rate", NULL, NULL},
    {"--speed", AEROTEX_NUMBER, "fps", 0.0, 1e-3, 1e6, AT(speed),
     "playback speed", "the data's rate", NULL},
    {"--threshold", AEROTEX_CUSTOM, "M D Q", NAN, 0, 0, 0,
     "monopole, dipole and quadrupole thresholds", "40 2e5 2e5",
     parse_threshold},
    {"--zero", AEROTEX_NUMBER, "f", NAN, 0.0, 1.0, AT(par.zero),
     "\"~0\" = below f * threshold", NULL, NULL},
    {"--map", AEROTEX_CUSTOM, "IN_LO IN_HI RHO_LO RHO_HI", NAN, 0, 0, 0,
     "the data's range onto air density", "0 1 0 1", parse_map},
    {"--log", AEROTEX_SWITCH, NULL, NAN, 1, 0, AT(par.log_input),
     "the data hold log10 of the value", NULL, NULL},
    {"--vscale", AEROTEX_NUMBER, "k", NAN, -1e6, 1e6, AT(par.vscale),
     "gradient mapping, m/s per kg/m^4", NULL, NULL},
    {"--no-velocity", AEROTEX_SWITCH, NULL, NAN, 0, 0, AT(par.use_velocity),
     "ignore the volume's velocity fields", NULL, NULL},
    {"--gain", AEROTEX_NUMBER, "dB", 0.0, -200.0, 120.0, AT(gain_db), "gain",
     NULL, NULL},
    {"--duration", AEROTEX_NUMBER, "s", 0.0, 1e-3, 3600.0, AT(duration),
     "length of the sound", "until the last sound arrives", NULL},
    {"--direct", AEROTEX_SWITCH, NULL, NAN, 1, 0, AT(direct),
     "per-sample reference sum", NULL, NULL},
    {"--demo", AEROTEX_CUSTOM, "N", NAN, 0, 0, 0,
     "the synthetic burst of N^3 in memory instead of DIR", "", parse_demo},
    {"-q", AEROTEX_SWITCH, NULL, NAN, 1, 0, AT(quiet), "no progress bar",
     NULL, NULL},
    {"-o", AEROTEX_TEXT, "OUT.wav", NAN, 0, 0, AT(out_file), "the sound",
     NULL, NULL},
    {NULL, 0, NULL, 0, 0, 0, 0, NULL, NULL, NULL}};
#undef AT

static void auralize_init(void *job)
{
    auralize_job *j = job;
    aero_field_params_default(&j->par);
    aero_field_demo_default(&j->demo);
}

/* the options, checked: 0, or 2 with a message */
static int auralize_args(auralize_job *j, int argc, char **argv)
{
    char err[512];
    aerotex_defaults(&aerotex_auralize_command, j);
    if (aerotex_parse(&aerotex_auralize_command, j, argc, argv))
        return 2;
    if (!j->dir && !j->use_demo) {
        aerotex_error("auralize: no volume directory (aerotex auralize DIR "
                      "--path FILE -o OUT.wav)");
        return 2;
    }
    if (!j->path_file) {
        aerotex_error("auralize: no listener path (--path FILE, lines 't x y "
                      "z')");
        return 2;
    }
    if (!j->out_file) {
        aerotex_error("auralize: no output file (-o OUT.wav)");
        return 2;
    }
    if (aero_field_params_check(&j->par, err, sizeof err)) {
        aerotex_error("auralize: %s", err);
        return 2;
    }
    return 0;
}

/* processor seconds: preprocessing (with reading or synthesising the
   frames), its computing alone, rendering */
typedef struct {
    double pre, compute, render;
} timing;

/* every frame read (or synthesised) and preprocessed into src: 0 or 1 */
static int preprocess(const auralize_job *j, const aero_volume_info *info,
                      aero_field_sources *src, timing *tm)
{
    aero_field_pre pre;
    aerotex_progress prog;
    char err[512];
    float *raw = malloc(aero_volume_count(info) * info->fields *
                        sizeof(float));
    double t_start = aerotex_cpu_now(), t0;
    int bad = 0;
    if (!raw || aero_field_pre_init(&pre, info, &j->par, err, sizeof err)) {
        aerotex_error("%s", raw ? err : "out of memory");
        free(raw);
        return 1;
    }
    aerotex_progress_start(&prog, "preprocessing", info->frames, j->quiet);
    for (int k = 0; k < info->frames && !bad; k++) {
        if (j->use_demo)
            aero_field_demo_frame(&j->demo, k, raw);
        else if (aero_volume_read_frame(info, k, raw, err, sizeof err)) {
            bad = 1;
            break;
        }
        t0 = aerotex_cpu_now();
        bad = aero_field_pre_push(&pre, raw, err, sizeof err);
        tm->compute += aerotex_cpu_now() - t0;
        aerotex_progress_add(&prog, 1);
    }
    if (!bad) {
        t0 = aerotex_cpu_now();
        bad = aero_field_pre_finish(&pre, src, err, sizeof err);
        tm->compute += aerotex_cpu_now() - t0;
    }
    aero_field_pre_free(&pre);
    free(raw);
    aerotex_progress_end(&prog);
    if (bad) {
        aerotex_error("%s", err);
        return 1;
    }
    tm->pre = aerotex_cpu_now() - t_start;
    return 0;
}

/* the sound's length: given, or until the last source is heard from the
   farthest point of the path */
static double sound_length(const auralize_job *j,
                           const aero_field_sources *src, double speed,
                           const path_point *path, int npath)
{
    double far = 0, duration = j->duration;
    if (duration > 0)
        return duration;
    for (int k = 0; k < npath; k++) {
        double d = sqrt(path[k].p[0] * path[k].p[0] +
                        path[k].p[1] * path[k].p[1] +
                        path[k].p[2] * path[k].p[2]);
        if (d > far)
            far = d;
    }
    duration = aero_fieldsound_length(src, speed, far);
    return path[npath - 1].t > duration ? path[npath - 1].t : duration;
}

/* total samples heard along the path into pcm */
static void render(const auralize_job *j, aero_fieldsound *r,
                   const path_point *path, int npath, float *pcm, long total,
                   timing *tm)
{
    aerotex_progress prog;
    double p[3];
    long done = 0;
    path_at(path, npath, 0, p);
    aero_ears start = aero_ears_at(p[0], p[1], p[2]);
    aero_fieldsound_place_ears(r, &start);
    aero_fieldsound_play(r);
    aerotex_progress_start(&prog, "rendering", total, j->quiet);
    while (done < total) {
        int c = total - done < AERO_FIELD_CHUNK ? (int)(total - done)
                                                : AERO_FIELD_CHUNK;
        double t0;
        /* the path, linear between its points, sampled at chunk ends */
        path_at(path, npath, (done + c) / j->rate, p);
        memcpy(r->target, p, sizeof p);
        r->ramp_left = c;
        t0 = aerotex_cpu_now();
        aero_fieldsound_process(r, pcm + done, c);
        tm->render += aerotex_cpu_now() - t0;
        done += c;
        aerotex_progress_add(&prog, c);
    }
    aerotex_progress_end(&prog);
}

/* a mono float WAV: 0 or 1 */
static int write_wav(const char *file, const float *pcm, long total,
                     double rate)
{
    SF_INFO si;
    SNDFILE *f;
    memset(&si, 0, sizeof si);
    si.samplerate = (int)rate;
    si.channels = 1;
    si.format = SF_FORMAT_WAV | SF_FORMAT_FLOAT;
    f = sf_open(file, SFM_WRITE, &si);
    if (!f) {
        aerotex_error("can't write %s: %s", file, sf_strerror(NULL));
        return 1;
    }
    sf_set_string(f, SF_STR_COMMENT, "aerotex auralize (Shin and Bajaj), "
                  "sound pressure in Pa");
    sf_writef_float(f, pcm, total);
    sf_close(f);
    return 0;
}

static void report(const auralize_job *j, const aero_volume_info *info,
                   const aero_field_sources *src, const aero_fieldsound *r,
                   const float *pcm, long total, const timing *tm)
{
    double peak = 0;
    for (long i = 0; i < total; i++)
        if (fabs(pcm[i]) > peak)
            peak = fabs(pcm[i]);
    printf("volume: %dx%dx%d, %d frames at %g frames/s, played at %g\n",
           info->nx, info->ny, info->nz, info->frames, info->rate,
           r->speed_target);
    printf("preprocessing: %.3f s CPU, %.2f ms per frame (%.2f ms computing, "
           "the rest reading or synthesising)\n", tm->pre,
           1e3 * tm->pre / info->frames, 1e3 * tm->compute / info->frames);
    printf("source points over all frames: %ld monopole, %ld dipole, %ld "
           "quadrupole; %d active vertices\n", src->points[1], src->points[2],
           src->points[3], src->count);
    printf("rendering: %ld samples at %g Hz in %.3f s CPU, %.3f us per sample "
           "(%s)\n", total, j->rate, tm->render, 1e6 * tm->render / total,
           j->direct ? "per-sample sum" : "chunk polynomials");
    printf("wrote %s: %.3f s, peak %.4g Pa%s\n", j->out_file, total / j->rate,
           peak, r->clamped ? " (listener clamped at Mach 0.3)" : "");
}

/* renders the sources along the path and writes the sound: 0 or 1 */
static int sound(const auralize_job *j, const aero_volume_info *info,
                 const aero_field_sources *src, const path_point *path,
                 int npath, const timing *pre)
{
    aero_fieldsound r;
    timing tm = *pre;
    float *pcm = NULL;
    long total;
    int rc = 1;
    aero_fieldsound_init(&r, j->rate, 1, 0);
    r.direct = j->direct;
    if (aero_fieldsound_set_sources(&r, src)) {
        aerotex_error("out of memory");
        goto done;
    }
    if (j->speed > 0)
        aero_fieldsound_set_speed(&r, j->speed);
    aero_fieldsound_set_gain_db(&r, j->gain_db);
    total = (long)ceil(sound_length(j, src, r.speed_target, path, npath) *
                       j->rate);
    pcm = malloc(sizeof(float) * (total > 0 ? total : 1));
    if (!pcm) {
        aerotex_error("out of memory for %ld samples", total);
        goto done;
    }
    render(j, &r, path, npath, pcm, total, &tm);
    rc = write_wav(j->out_file, pcm, total, j->rate);
    if (!rc)
        report(j, info, src, &r, pcm, total, &tm);
done:
    free(pcm);
    aero_fieldsound_free(&r);
    return rc;
}

static int auralize_run(int argc, char **argv)
{
    auralize_job j;
    aero_volume_info info;
    aero_field_sources src;
    timing tm = {0, 0, 0};
    path_point *path = NULL;
    int npath = 0, rc;
    char err[512];
    rc = auralize_args(&j, argc, argv);
    if (rc || read_path(j.path_file, &path, &npath))
        return 2;
    if (j.use_demo)
        aero_field_demo_info(&j.demo, &info);
    else if (aero_volume_read_header(j.dir, &info, err, sizeof err)) {
        aerotex_error("%s", err);
        free(path);
        return 1;
    }
    memset(&src, 0, sizeof src);
    rc = preprocess(&j, &info, &src, &tm);
    if (!rc)
        rc = sound(&j, &info, &src, path, npath, &tm);
    aero_field_sources_free(&src);
    free(path);
    return rc;
}

const aerotex_command aerotex_auralize_command = {
    "auralize", "DIR --path FILE -o OUT.wav",
    "field auralization (Shin and Bajaj): the sound of volume DIR heard along\n"
    "a listener path",
    auralize_options, sizeof(auralize_job), auralize_init, auralize_run};
