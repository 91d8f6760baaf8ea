/* aerotex vortex: vortex-sound textures Q(u, t) of a turbulent box of air
 * (paper 004), one channel per average flow speed, the speeds simulated in
 * parallel. The physics is in src/core/vortex_sound.c. */
#include "aerotex.h"
#include "aero_air.h"
#include "texture.h"
#include "bandwidth_extension.h"
#include "vortex_sound.h"

#include <errno.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define MAX_SPEEDS 64
#define PNG_ZOOM 4

typedef struct {
    aero_vortex_params vp;
    double speeds[MAX_SPEEDS];
    int nspeeds;
    double duration, rate;
    double extend;        /* f_top of the bandwidth extension, Hz (0: off) */
    int threads, quiet;
    const char *out, *png_dir;
} vjob_t;

typedef struct {
    const vjob_t *job;
    aerotex_progress *prog;
    int index;            /* speed index */
    long last_step, snap_every, snap;
    float *slice, *zero;
    char err[256];
} vctx_t;

static void plan_lock(void *ctx, int on)
{
    vctx_t *c = ctx;
    if (on)
        omp_set_lock(&c->prog->plan);
    else
        omp_unset_lock(&c->prog->plan);
}

/* progress, and the vorticity slices of --png */
static void hook(void *ctx, const aero_flow3d *s, long step, int recording)
{
    vctx_t *c = ctx;
    long add = step - c->last_step;
    (void)recording;
    c->last_step = step;
#pragma omp atomic
    c->prog->done += add;
    if (c->prog->show) {
#pragma omp critical(aerotex_vortex_progress)
        aerotex_progress_show(c->prog, 0);
    }
    if (c->job->png_dir && c->slice && step >= c->snap * c->snap_every) {
        /* the vertical mid-plane y = box/2: |omega| in units of U/box */
        char path[4096];
        int j = s->ny / 2;
        float scale = (float)(c->job->vp.box / c->job->speeds[c->index]);
        c->snap = step / c->snap_every + 1;
        /* PNG_ZOOM x PNG_ZOOM pixels per cell, so a 32-cell box is
           visible */
        for (int k = 0; k < s->nz * PNG_ZOOM; k++)
            for (int i = 0; i < s->nx * PNG_ZOOM; i++)
                c->slice[(size_t)k * s->nx * PNG_ZOOM + i] =
                    s->omag[AERO_F3_C(s, i / PNG_ZOOM, j, k / PNG_ZOOM)] * scale;
        snprintf(path, sizeof path, "%s/u%02d_%04ld.png", c->job->png_dir,
                 c->index, step);
        if (aerotex_png_vorticity(path, c->slice, c->zero, s->nx * PNG_ZOOM,
                                  s->nz * PNG_ZOOM, 60.0f))
            snprintf(c->err, sizeof c->err, "can't write %.200s", path);
    }
}

static int parse_speeds(vjob_t *j, const char *list)
{
    const char *p = list;
    j->nspeeds = 0;
    while (*p) {
        char *end;
        double u = strtod(p, &end);
        if (end == p || !isfinite(u) || !(u > 0.0)) {
            aerotex_error("--speeds: '%s' is not a list of positive speeds",
                          list);
            return -1;
        }
        if (j->nspeeds && !(u > j->speeds[j->nspeeds - 1])) {
            aerotex_error("--speeds must increase (%g after %g)", u,
                          j->speeds[j->nspeeds - 1]);
            return -1;
        }
        if (u / AERO_C0 > AERO_MACH_LIMIT) {
            aerotex_error("--speeds: %g m/s is above Mach %g: the "
                          "incompressible model does not hold", u,
                          AERO_MACH_LIMIT);
            return -1;
        }
        if (j->nspeeds == MAX_SPEEDS) {
            aerotex_error("--speeds: at most %d speeds", MAX_SPEEDS);
            return -1;
        }
        j->speeds[j->nspeeds++] = u;
        p = end;
        if (*p == ',') p++;
        else if (*p) {
            aerotex_error("--speeds: '%s' is not a comma-separated list", list);
            return -1;
        }
    }
    return j->nspeeds ? 0 : -1;
}

static int vparse(vjob_t *j, int argc, char **argv)
{
    double x;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
#define VNUM(name, lo, hi, field)                                  \
    if (!strcmp(a, name)) {                                        \
        if (aerotex_number(argc, argv, &i, lo, hi, &x)) return -1; \
        field = x;                                                 \
        continue;                                                  \
    }
        VNUM("--box", 1e-3, 10.0, j->vp.box)
        VNUM("--duration", 0.01, 10.0, j->duration)
        VNUM("--rate", 1000.0, 192000.0, j->rate)
        VNUM("--confinement", 0.0, 200.0, j->vp.confinement)
        VNUM("--turbulence", 0.0, 2.0, j->vp.turbulence)
        VNUM("--cfl", 0.05, 2.0, j->vp.cfl)
        VNUM("--settle", 0.0, 100.0, j->vp.settle)
        VNUM("--elevation", -90.0, 90.0, j->vp.elevation)
        VNUM("--threads", 1.0, 256.0, j->threads)
        VNUM("--extend", 0.0, 96000.0, j->extend)
#undef VNUM
        if (!strcmp(a, "--grid") || !strcmp(a, "--height") ||
            !strcmp(a, "--receivers") || !strcmp(a, "--seed")) {
            double lo = !strcmp(a, "--seed") ? 0.0 : !strcmp(a, "--receivers") ? 1.0 : 4.0;
            double hi = !strcmp(a, "--seed") ? 4294967295.0
                        : !strcmp(a, "--receivers") ? 64.0 : 256.0;
            if (aerotex_number(argc, argv, &i, lo, hi, &x)) return -1;
            if (x != floor(x)) {
                aerotex_error("%s takes a whole number", a);
                return -1;
            }
            if (!strcmp(a, "--grid")) {
                if ((int)x & 1) {
                    aerotex_error("--grid takes an even number of cells");
                    return -1;
                }
                j->vp.n = (int)x;
            } else if (!strcmp(a, "--height"))
                j->vp.nz = (int)x;
            else if (!strcmp(a, "--receivers"))
                j->vp.receivers = (int)x;
            else
                j->vp.seed = (uint32_t)x;
            continue;
        }
        if (!strcmp(a, "--speeds")) {
            if (i + 1 >= argc) {
                aerotex_error("--speeds needs a list, e.g. 1,2,4,8");
                return -1;
            }
            if (parse_speeds(j, argv[++i])) return -1;
            continue;
        }
        if (!strcmp(a, "--source")) {
            if (i + 1 >= argc || (strcmp(argv[i + 1], "window") &&
                                  strcmp(argv[i + 1], "cells"))) {
                aerotex_error("--source takes window or cells");
                return -1;
            }
            j->vp.source = !strcmp(argv[++i], "cells") ? AERO_VORTEX_CELLS
                                                       : AERO_VORTEX_WINDOW;
            continue;
        }
        if (!strcmp(a, "-o") || !strcmp(a, "--png")) {
            if (i + 1 >= argc) {
                aerotex_error("%s needs a %s", a, a[1] == 'o' ? "file name"
                                                              : "directory");
                return -1;
            }
            if (a[1] == 'o') j->out = argv[++i];
            else j->png_dir = argv[++i];
            continue;
        }
        if (!strcmp(a, "-q")) {
            j->quiet = 1;
            continue;
        }
        aerotex_error("unknown option '%s' for vortex (see 'aerotex help')", a);
        return -1;
    }
    if (!j->out) {
        aerotex_error("no output file: add -o FILE.wav");
        return -1;
    }
    return 0;
}

static void join(char *buf, size_t len, const double *x, int n)
{
    size_t used = 0;
    buf[0] = 0;
    for (int k = 0; k < n && used < len; k++)
        used += (size_t)snprintf(buf + used, len - used, "%s%.6g",
                                 k ? "," : "", x[k]);
}

int aerotex_vortex(int argc, char **argv)
{
    vjob_t j;
    aerotex_progress prog;
    vctx_t *ctx;
    aero_vortex_stats *st;
    aero_texture tex;
    float *raw;
    char err[512], command[4096], buf[8192];
    double t_start = aerotex_now(), list[MAX_SPEEDS], ext_from[MAX_SPEEDS];
    aero_bandext_info ext[MAX_SPEEDS];
    int status = 1, l0, xf, lmin, lmax, avail, len, ns;

    memset(&j, 0, sizeof j);
    aero_vortex_defaults(&j.vp);
    j.vp.nz = -1;
    j.duration = 0.5;
    j.rate = 16000.0;
    j.threads = omp_get_max_threads();
    parse_speeds(&j, "1,2,3,4,6,8,12,16");
    if (vparse(&j, argc, argv))
        return 2;
    if (j.extend > 0.0 && !(j.extend * 1.1 < 0.5 * j.rate)) {
        aerotex_error("--extend %g Hz: 1.1 x it must stay below half the "
                      "--rate (%g Hz)", j.extend, 0.5 * j.rate);
        return 2;
    }
    if (j.vp.nz < 0)
        j.vp.nz = j.vp.n * 3 / 2;
    ns = j.nspeeds;
    l0 = (int)lround(j.duration * j.rate);
    if (l0 < 64) {
        aerotex_error("--duration %g s at --rate %g Hz is under 64 samples",
                      j.duration, j.rate);
        return 2;
    }
    {
        aerotex_loop_plan lp = aerotex_plan_loop(l0);
        xf = lp.xfade;
        lmin = lp.lmin;
        lmax = lp.lmax;
        avail = lp.avail;
    }
    aerotex_command_line(command, sizeof command, argc, argv);
    if (j.png_dir && mkdir(j.png_dir, 0777) && errno != EEXIST) {
        aerotex_error("can't create %s: %s", j.png_dir, strerror(errno));
        return 1;
    }
    memset(ext, 0, sizeof ext);
    memset(ext_from, 0, sizeof ext_from);
    raw = calloc((size_t)avail * ns, sizeof(float));
    ctx = calloc((size_t)ns, sizeof *ctx);
    st = calloc((size_t)ns, sizeof *st);
    if (!raw || !ctx || !st) {
        aerotex_error("out of memory");
        free(raw);
        free(ctx);
        free(st);
        return 1;
    }
    prog.total = 0;
    for (int k = 0; k < ns; k++) {
        aero_vortex_params p = j.vp;
        p.speed = j.speeds[k];
        prog.total += aero_vortex_steps(&p, j.rate, avail);
    }
    prog.done = 0;
    prog.t0 = prog.last = aerotex_now();
    prog.show = !j.quiet && isatty(fileno(stderr));
    omp_init_lock(&prog.plan);
    if (!j.quiet)
        fprintf(stderr, "aerotex: vortex box %g m, grid %d x %d x %d, %d "
                "speed%s (%g..%g m/s), %.3g s, %ld steps, %d thread%s\n",
                j.vp.box, j.vp.n, j.vp.n, j.vp.nz, ns, ns > 1 ? "s" : "",
                j.speeds[0], j.speeds[ns - 1], j.duration, prog.total,
                j.threads < ns ? j.threads : ns,
                (j.threads < ns ? j.threads : ns) > 1 ? "s" : "");

#pragma omp parallel for schedule(dynamic, 1) num_threads(j.threads)
    for (int q = 0; q < ns; q++) {
        /* the fastest speeds take the most steps: start them first */
        int k = ns - 1 - q;
        aero_vortex_params p = j.vp;
        vctx_t *c = &ctx[k];
        long steps;
        p.speed = j.speeds[k];
        /* independent turbulence per speed */
        p.seed = j.vp.seed * 2654435761u + 7919u * (uint32_t)(k + 1);
        p.plan_lock = plan_lock;
        c->job = &j;
        c->prog = &prog;
        c->index = k;
        steps = aero_vortex_steps(&p, j.rate, avail);
        c->snap_every = steps / 24 + 1;
        if (j.png_dir) {
            c->slice = malloc(sizeof(float) * (size_t)p.n * p.nz * PNG_ZOOM *
                              PNG_ZOOM);
            c->zero = calloc((size_t)p.n * p.nz * PNG_ZOOM * PNG_ZOOM,
                             sizeof(float));
        }
        if (aero_vortex_simulate(&p, j.rate, raw + k, ns, avail, &st[k], hook,
                                 64, c, c->err, sizeof c->err) == 0) {
#pragma omp atomic
            prog.done += steps - 1 - c->last_step;
        }
        free(c->slice);
        free(c->zero);
    }
    aerotex_progress_show(&prog, 1);
    omp_destroy_lock(&prog.plan);

    status = 0;
    for (int k = 0; k < ns; k++)
        if (ctx[k].err[0]) {
            aerotex_error("speed %g m/s: %s", j.speeds[k], ctx[k].err);
            status = 1;
        }
    if (status)
        goto out;
    len = aero_texture_best_loop(raw, ns, lmin, lmax, xf);
    aero_texture_crossfade(raw, ns, len, xf);
    /* above the band each speed's grid resolves, the bandwidth extension
       (bandwidth_extension.h): the third derivative's taper runs from 0.2
       to 0.35 of the step rate (vortex_sound.h), the resampling cuts at
       0.45 of the lower rate */
    for (int k = 0; k < ns && j.extend > 0.0; k++) {
        double steprate = 1.0 / st[k].dt;
        double f2 = fmin(0.35 * steprate, 0.45 * fmin(steprate, j.rate));
        double f1 = fmin(0.2 * steprate, 0.8 * f2);
        if (f2 >= j.extend) {
            ext_from[k] = 0.0; /* resolved up to the top already */
            continue;
        }
        aero_bandext_apply(raw + k, len, ns, j.rate, f1, f2, j.extend,
                           j.vp.seed * 40503u + (uint32_t)k + 1u, &ext[k]);
        ext_from[k] = ext[k].extended ? f1 : 0.0;
    }
    if (aero_texture_init_speeds(&tex, len, ns, j.speeds, j.rate)) {
        aerotex_error("out of memory");
        status = 1;
        goto out;
    }
    memcpy(tex.data, raw, sizeof(float) * (size_t)len * ns);
    aero_texture_set(&tex, "formula", "Howe compact vortex sound: Q = rho0 / "
                     "(12 pi c0^2) xh_a xh_b d3/dt3 INT y_a (y x omega)_b dy; "
                     "p = Q(u, t - r/c0) / r");
    aero_texture_set(&tex, "units", "Pa at 1 m");
    aero_texture_setd(&tex, "box", j.vp.box);
    aero_texture_setd(&tex, "grid", j.vp.n);
    aero_texture_setd(&tex, "height", j.vp.nz);
    aero_texture_setd(&tex, "rho", AERO_RHO);
    aero_texture_setd(&tex, "c0", AERO_C0);
    aero_texture_setd(&tex, "nu", j.vp.nu);
    aero_texture_setd(&tex, "confinement", j.vp.confinement);
    aero_texture_setd(&tex, "turbulence", j.vp.turbulence);
    aero_texture_setd(&tex, "cfl", j.vp.cfl);
    aero_texture_setd(&tex, "settle", j.vp.settle);
    aero_texture_set(&tex, "source", j.vp.source == AERO_VORTEX_CELLS
                                         ? "cells (paper eq. 3-4, alpha 3)"
                                         : "window");
    aero_texture_setd(&tex, "receivers", j.vp.receivers);
    aero_texture_setd(&tex, "elevation", j.vp.elevation);
    aero_texture_setd(&tex, "seed", j.vp.seed);
    aero_texture_setd(&tex, "rate", j.rate);
    aero_texture_setd(&tex, "frames", len);
    aero_texture_set(&tex, "loop", "seamless");
    aero_texture_setd(&tex, "xfade", xf);
    for (int k = 0; k < ns; k++) {
        double e = 0.0;
        for (int n = 0; n < len; n++)
            e += (double)tex.data[(size_t)n * ns + k] * tex.data[(size_t)n * ns + k];
        list[k] = sqrt(e / len);
    }
    join(buf, sizeof buf, list, ns);
    aero_texture_set(&tex, "rms", buf);
    for (int k = 0; k < ns; k++) list[k] = st[k].dt;
    join(buf, sizeof buf, list, ns);
    aero_texture_set(&tex, "dt", buf);
    for (int k = 0; k < ns; k++) list[k] = st[k].gain;
    join(buf, sizeof buf, list, ns);
    aero_texture_set(&tex, "receiver_gain", buf);
    if (j.extend > 0.0) {
        aero_texture_set(&tex, "extension", "spectral bandwidth extension "
                         "(Chadwick & James 2011): above extend_from, noise "
                         "with the band's envelope and the power law fitted "
                         "on its top two octaves (extend_slope, |X|^2 ~ "
                         "f^s), up to extend_top; 0: not extended");
        aero_texture_setd(&tex, "extend_top", j.extend);
        join(buf, sizeof buf, ext_from, ns);
        aero_texture_set(&tex, "extend_from", buf);
        for (int k = 0; k < ns; k++) list[k] = ext[k].slope;
        join(buf, sizeof buf, list, ns);
        aero_texture_set(&tex, "extend_slope", buf);
    }
    aero_texture_set(&tex, "solver", "3D incompressible, MAC grid, "
                     "semi-Lagrangian advection, vorticity confinement, "
                     "FFTW + tridiagonal projection");
    aero_texture_set(&tex, "command", command);
    if (aero_texture_save(j.out, &tex, err, sizeof err)) {
        aerotex_error("%s", err);
        status = 1;
    } else {
        printf("%s: vortex sound, box %g m, grid %d x %d x %d, %d speeds, %d "
               "frames (%.3f s at %g Hz)\n", j.out, j.vp.box, j.vp.n, j.vp.n,
               j.vp.nz, ns, len, len / j.rate, j.rate);
        for (int k = 0; k < ns; k++) {
            double e = 0.0;
            for (int n = 0; n < len; n++)
                e += (double)tex.data[(size_t)n * ns + k] * tex.data[(size_t)n * ns + k];
            e = sqrt(e / len);
            printf("  %6.3g m/s: rms %.3g Pa at 1 m (%.1f dB SPL), %ld steps "
                   "of %.3g ms, max |div u| h %.2g m/s\n", j.speeds[k], e,
                   20.0 * log10(e / 2e-5 + 1e-30), st[k].steps,
                   1e3 * st[k].dt, st[k].max_div);
        }
        printf("  %.1f s\n", aerotex_now() - t_start);
    }
    aero_texture_free(&tex);
out:
    free(raw);
    free(ctx);
    free(st);
    return status;
}
