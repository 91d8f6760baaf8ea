/* aerotex field-demo and aerotex auralize: field auralization of volume
 * data offline (paper 002). The method is in src/core/field_sound.h, the
 * volume format in src/core/field_volume.h. */
#include "aerotex.h"
#include "field_sound.h"

#include <errno.h>
#include <math.h>
#include <sndfile.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* processor time of this process: the benchmark figures, which wall time
 * would inflate on a machine shared with other jobs */
static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

typedef struct {
    int show;
    double t0, last;
    const char *what;
} bar_t;

static void bar(bar_t *b, double frac, int final)
{
    double t = now();
    int width = 30, fill;
    if (!b->show || (!final && t - b->last < 0.2))
        return;
    b->last = t;
    if (frac > 1) frac = 1;
    fill = (int)(frac * width + 0.5);
    fprintf(stderr, "\r%-14s [%.*s%*s] %3d%%  %.1f s ", b->what, fill,
            "##############################", width - fill, "",
            (int)(100 * frac), t - b->t0);
    if (final)
        fprintf(stderr, "\n");
    fflush(stderr);
}


/* --- aerotex field-demo ---------------------------------------------------- */

int aerotex_field_demo(int argc, char **argv)
{
    aero_field_demo d;
    aero_volume_info v;
    const char *dir = NULL;
    int quiet = 0;
    double x;
    char err[512];
    aero_field_demo_default(&d);
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-o") && i + 1 < argc) {
            dir = argv[++i];
        } else if (!strcmp(a, "--size")) {
            if (aerotex_number(argc, argv, &i, 4, 512, &x)) return 2;
            d.size = (int)x;
        } else if (!strcmp(a, "--frames")) {
            if (aerotex_number(argc, argv, &i, 1, 100000, &x)) return 2;
            d.frames = (int)x;
        } else if (!strcmp(a, "--spacing")) {
            if (aerotex_number(argc, argv, &i, 1e-5, 1e3, &x)) return 2;
            d.spacing = x;
        } else if (!strcmp(a, "--rate")) {
            if (aerotex_number(argc, argv, &i, 1e-3, 1e6, &x)) return 2;
            d.rate = x;
        } else if (!strcmp(a, "--shell-speed")) {
            if (aerotex_number(argc, argv, &i, 0, 1e3, &x)) return 2;
            d.shell_speed = x;
        } else if (!strcmp(a, "--seed")) {
            if (aerotex_number(argc, argv, &i, 0, 4294967295.0, &x)) return 2;
            d.seed = (uint32_t)x;
        } else if (!strcmp(a, "--velocity")) {
            d.velocity = 1;
        } else if (!strcmp(a, "-q")) {
            quiet = 1;
        } else {
            aerotex_error("field-demo: unknown option '%s'", a);
            return 2;
        }
    }
    if (!dir) {
        aerotex_error("field-demo: no output directory (-o DIR)");
        return 2;
    }
    if (mkdir(dir, 0777) && errno != EEXIST) {
        aerotex_error("can't make directory %s: %s", dir, strerror(errno));
        return 1;
    }
    aero_field_demo_info(&d, &v);
    if (strlen(dir) >= sizeof v.dir) {
        aerotex_error("directory name too long");
        return 2;
    }
    strcpy(v.dir, dir);
    if (aero_volume_write_header(&v, err, sizeof err)) {
        aerotex_error("%s", err);
        return 1;
    }
    float *data = malloc(aero_volume_count(&v) * v.fields * sizeof(float));
    if (!data) {
        aerotex_error("out of memory");
        return 1;
    }
    bar_t b = {!quiet, now(), 0, "field-demo"};
    for (int k = 0; k < d.frames; k++) {
        aero_field_demo_frame(&d, k, data);
        if (aero_volume_write_frame(&v, k, data, err, sizeof err)) {
            aerotex_error("%s", err);
            free(data);
            return 1;
        }
        bar(&b, (k + 1.0) / d.frames, k + 1 == d.frames);
    }
    free(data);
    printf("wrote %s: %d frames of %dx%dx%d (%s), %g m spacing, %g frames/s\n",
           dir, d.frames, d.size, d.size, d.size,
           d.velocity ? "density vx vy vz" : "density", d.spacing, d.rate);
    return 0;
}

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

int aerotex_auralize(int argc, char **argv)
{
    const char *dir = NULL, *path_file = NULL, *out_file = NULL;
    aero_field_params par;
    aero_field_demo demo;
    aero_volume_info info;
    aero_field_sources src;
    aero_field_render r;
    double rate = 48000, speed = 0, duration = 0, gain_db = 0, x;
    int quiet = 0, direct = 0, use_demo = 0, rc = 1;
    path_point *path = NULL;
    int npath = 0;
    char err[512];
    aero_field_params_default(&par);
    aero_field_demo_default(&demo);
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-o") && i + 1 < argc)
            out_file = argv[++i];
        else if (!strcmp(a, "--path") && i + 1 < argc)
            path_file = argv[++i];
        else if (!strcmp(a, "--rate")) {
            if (aerotex_number(argc, argv, &i, 1000, 384000, &rate)) return 2;
        } else if (!strcmp(a, "--speed")) {
            if (aerotex_number(argc, argv, &i, 1e-3, 1e6, &speed)) return 2;
        } else if (!strcmp(a, "--duration")) {
            if (aerotex_number(argc, argv, &i, 1e-3, 3600, &duration)) return 2;
        } else if (!strcmp(a, "--gain")) {
            if (aerotex_number(argc, argv, &i, -200, 120, &gain_db)) return 2;
        } else if (!strcmp(a, "--threshold")) {
            for (int t = 0; t < 3; t++)
                if (aerotex_number(argc, argv, &i, 1e-30, 1e30, &par.threshold[t]))
                    return 2;
        } else if (!strcmp(a, "--zero")) {
            if (aerotex_number(argc, argv, &i, 0, 1, &par.zero)) return 2;
        } else if (!strcmp(a, "--map")) {
            if (aerotex_number(argc, argv, &i, -1e30, 1e30, &par.in_lo) ||
                aerotex_number(argc, argv, &i, -1e30, 1e30, &par.in_hi) ||
                aerotex_number(argc, argv, &i, 0, 1e6, &par.rho_lo) ||
                aerotex_number(argc, argv, &i, 0, 1e6, &par.rho_hi))
                return 2;
        } else if (!strcmp(a, "--vscale")) {
            if (aerotex_number(argc, argv, &i, -1e6, 1e6, &par.vscale)) return 2;
        } else if (!strcmp(a, "--log"))
            par.log_input = 1;
        else if (!strcmp(a, "--no-velocity"))
            par.use_velocity = 0;
        else if (!strcmp(a, "--direct"))
            direct = 1;
        else if (!strcmp(a, "--demo")) {
            /* the synthetic burst in memory, no files (benchmarks) */
            use_demo = 1;
            if (i + 1 < argc && argv[i + 1][0] != '-') {
                if (aerotex_number(argc, argv, &i, 4, 512, &x)) return 2;
                demo.size = (int)x;
            }
        } else if (!strcmp(a, "-q"))
            quiet = 1;
        else if (a[0] == '-') {
            aerotex_error("auralize: unknown option '%s'", a);
            return 2;
        } else if (!dir)
            dir = a;
        else {
            aerotex_error("auralize: one volume directory only ('%s')", a);
            return 2;
        }
    }
    if (!dir && !use_demo) {
        aerotex_error("auralize: no volume directory (aerotex auralize DIR "
                      "--path FILE -o OUT.wav)");
        return 2;
    }
    if (!path_file) {
        aerotex_error("auralize: no listener path (--path FILE, lines 't x y "
                      "z')");
        return 2;
    }
    if (!out_file) {
        aerotex_error("auralize: no output file (-o OUT.wav)");
        return 2;
    }
    if (aero_field_params_check(&par, err, sizeof err)) {
        aerotex_error("%s", err);
        return 2;
    }
    if (read_path(path_file, &path, &npath))
        return 2;
    if (use_demo)
        aero_field_demo_info(&demo, &info);
    else if (aero_volume_read_header(dir, &info, err, sizeof err)) {
        aerotex_error("%s", err);
        free(path);
        return 1;
    }

    /* preprocessing, timed with and without reading the frames */
    aero_field_pre pre;
    float *raw = malloc(aero_volume_count(&info) * info.fields *
                        sizeof(float));
    double t_start = cpu_now(), t_compute = 0;
    bar_t b = {!quiet, t_start, 0, "preprocessing"};
    if (!raw || aero_field_pre_init(&pre, &info, &par, err, sizeof err)) {
        aerotex_error("%s", raw ? err : "out of memory");
        free(raw);
        free(path);
        return 1;
    }
    for (int k = 0; k < info.frames; k++) {
        if (use_demo)
            aero_field_demo_frame(&demo, k, raw);
        else if (aero_volume_read_frame(&info, k, raw, err, sizeof err)) {
            aerotex_error("%s", err);
            aero_field_pre_free(&pre);
            free(raw);
            free(path);
            return 1;
        }
        double t0 = cpu_now();
        if (aero_field_pre_push(&pre, raw, err, sizeof err)) {
            aerotex_error("%s", err);
            aero_field_pre_free(&pre);
            free(raw);
            free(path);
            return 1;
        }
        t_compute += cpu_now() - t0;
        bar(&b, (k + 1.0) / info.frames, 0);
    }
    {
        double t0 = cpu_now();
        int bad = aero_field_pre_finish(&pre, &src, err, sizeof err);
        t_compute += cpu_now() - t0;
        aero_field_pre_free(&pre);
        free(raw);
        if (bad) {
            aerotex_error("%s", err);
            free(path);
            return 1;
        }
    }
    bar(&b, 1, 1);
    double t_pre = cpu_now() - t_start;

    /* rendering */
    aero_field_render_init(&r, rate);
    r.direct = direct;
    if (aero_field_render_set_sources(&r, &src)) {
        aerotex_error("out of memory");
        goto done;
    }
    if (speed > 0)
        aero_field_render_set_speed(&r, speed);
    aero_field_render_set_gain_db(&r, gain_db);
    {
        double far = 0;
        for (int k = 0; k < npath; k++) {
            double d = sqrt(path[k].p[0] * path[k].p[0] +
                            path[k].p[1] * path[k].p[1] +
                            path[k].p[2] * path[k].p[2]);
            if (d > far)
                far = d;
        }
        if (!(duration > 0)) {
            duration = aero_field_render_length(&src, r.speed_target, far);
            if (path[npath - 1].t > duration)
                duration = path[npath - 1].t;
        }
    }
    long total = (long)ceil(duration * rate), done_n = 0;
    float *pcm = malloc(sizeof(float) * (total > 0 ? total : 1));
    if (!pcm) {
        aerotex_error("out of memory for %ld samples", total);
        goto done;
    }
    {
        double p0[3];
        path_at(path, npath, 0, p0);
        aero_field_render_place_listener(&r, p0[0], p0[1], p0[2]);
    }
    aero_field_render_play(&r);
    bar_t rb = {!quiet, now(), 0, "rendering"};
    double t_render = 0, peak = 0;
    while (done_n < total) {
        int c = total - done_n < AERO_FIELD_CHUNK ? (int)(total - done_n)
                                                  : AERO_FIELD_CHUNK;
        double p1[3];
        /* the path, linear between its points, sampled at chunk ends */
        path_at(path, npath, (done_n + c) / rate, p1);
        memcpy(r.target, p1, sizeof p1);
        r.ramp_left = c;
        double t0 = cpu_now();
        aero_field_render_process(&r, pcm + done_n, c);
        t_render += cpu_now() - t0;
        done_n += c;
        bar(&rb, (double)done_n / total, 0);
    }
    bar(&rb, 1, 1);
    for (long i = 0; i < total; i++)
        if (fabs(pcm[i]) > peak)
            peak = fabs(pcm[i]);
    {
        SF_INFO si;
        memset(&si, 0, sizeof si);
        si.samplerate = (int)rate;
        si.channels = 1;
        si.format = SF_FORMAT_WAV | SF_FORMAT_FLOAT;
        SNDFILE *f = sf_open(out_file, SFM_WRITE, &si);
        if (!f) {
            aerotex_error("can't write %s: %s", out_file, sf_strerror(NULL));
            free(pcm);
            goto done;
        }
        sf_set_string(f, SF_STR_COMMENT, "aerotex auralize (paper 002), "
                      "sound pressure in Pa");
        sf_writef_float(f, pcm, total);
        sf_close(f);
    }
    free(pcm);
    printf("volume: %dx%dx%d, %d frames at %g frames/s, played at %g\n",
           info.nx, info.ny, info.nz, info.frames, info.rate, r.speed_target);
    printf("preprocessing: %.3f s CPU, %.2f ms per frame (%.2f ms computing, "
           "the rest reading or synthesising)\n", t_pre, 1e3 * t_pre / info.frames,
           1e3 * t_compute / info.frames);
    printf("source points over all frames: %ld monopole, %ld dipole, %ld "
           "quadrupole; %d active vertices\n", src.points[1], src.points[2],
           src.points[3], src.count);
    printf("rendering: %ld samples at %g Hz in %.3f s CPU, %.3f us per sample "
           "(%s)\n", total, rate, t_render, 1e6 * t_render / total,
           direct ? "per-sample sum" : "chunk polynomials");
    printf("wrote %s: %.3f s, peak %.4g Pa%s\n", out_file, total / rate,
           peak, r.clamped ? " (listener clamped at Mach 0.3)" : "");
    rc = 0;
done:
    aero_field_render_free(&r);
    aero_field_sources_free(&src);
    free(path);
    return rc;
}
