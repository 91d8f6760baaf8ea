/* aerotex object: 3D object textures (paper 000, the 3D case): the sound
 * source function of each region of a body, per sampled flow direction,
 * the directions simulated in parallel. The physics is in
 * src/core/body_flow.c, the shapes in src/core/body_shape.c. */
#include "aerotex.h"
#include "aero_air.h"
#include "body_flow.h"
#include "texture.h"

#include <errno.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define MAX_DIRECTIONS 91
#define PNG_ZOOM 3

typedef struct {
    const char *shape, *mesh, *out, *png_dir;
    double radius, length, handle, tip;
    int sources, directions, mirror; /* mirror: -1 default */
    double speed, grid, duration, rate, settle, cfl;
    int threads, quiet;
    unsigned seed;
} ojob_t;

typedef struct {
    const ojob_t *job;
    aerotex_progress *prog;
    int index;
    long last_step, snap_every, snap;
    float *slice, *solid;
    char err[256];
} octx_t;

static void plan_lock(void *ctx, int on)
{
    octx_t *c = ctx;
    if (on)
        omp_set_lock(&c->prog->plan);
    else
        omp_unset_lock(&c->prog->plan);
}

/* progress, and the vorticity slices of --png (the mid-plane y, which
   holds the body's axis and the flow) */
static void hook(void *ctx, const aero_flow3d *s, long step, int recording)
{
    octx_t *c = ctx;
    long add = step - c->last_step;
    (void)recording;
    c->last_step = step;
#pragma omp atomic
    c->prog->done += add;
    if (c->prog->show) {
#pragma omp critical(aerotex_object_progress)
        aerotex_progress_show(c->prog, 0);
    }
    if (c->job->png_dir && step >= c->snap * c->snap_every) {
        char path[4096];
        int j = s->ny / 2, w = s->nx * PNG_ZOOM, h = s->nz * PNG_ZOOM;
        float scale = (float)(c->job->grid * s->p.h / c->job->speed);
        c->snap = step / c->snap_every + 1;
        if (!c->slice) {
            c->slice = malloc(sizeof(float) * (size_t)w * h);
            c->solid = malloc(sizeof(float) * (size_t)w * h);
            if (!c->slice || !c->solid)
                return;
        }
        aero_flow3d_vorticity((aero_flow3d *)s);
        for (int k = 0; k < h; k++)
            for (int i = 0; i < w; i++) {
                size_t at = AERO_F3_C(s, i / PNG_ZOOM, j, k / PNG_ZOOM);
                c->slice[(size_t)k * w + i] = s->omag[at] * scale;
                c->solid[(size_t)k * w + i] = s->solid ? s->solid[at] : 0.0f;
            }
        snprintf(path, sizeof path, "%s/dir%02d_%05ld.png",
                 c->job->png_dir, c->index, step);
        if (aerotex_png_vorticity(path, c->slice, c->solid, w, h, 8.0f))
            snprintf(c->err, sizeof c->err, "can't write %.200s", path);
    }
}

static int oparse(ojob_t *j, int argc, char **argv)
{
    double x;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
#define ONUM(name, lo, hi, field)                                  \
    if (!strcmp(a, name)) {                                        \
        if (aerotex_number(argc, argv, &i, lo, hi, &x)) return -1; \
        field = x;                                                 \
        continue;                                                  \
    }
        ONUM("--radius", 1e-4, 100.0, j->radius)
        ONUM("--length", 1e-4, 100.0, j->length)
        ONUM("--handle", 1e-4, 100.0, j->handle)
        ONUM("--tip", 1e-4, 100.0, j->tip)
        ONUM("--speed", 0.01, AERO_MACH_LIMIT * AERO_C0, j->speed)
        ONUM("--grid", 3.0, 64.0, j->grid)
        ONUM("--duration", 0.02, 10.0, j->duration)
        ONUM("--rate", 500.0, 192000.0, j->rate)
        ONUM("--settle", 0.0, 1000.0, j->settle)
        ONUM("--cfl", 0.05, 1.5, j->cfl)
#undef ONUM
        if (!strcmp(a, "--sources") || !strcmp(a, "--directions") ||
            !strcmp(a, "--threads") || !strcmp(a, "--seed")) {
            double hi = !strcmp(a, "--sources") ? AERO_BODY_MAX_REGIONS
                        : !strcmp(a, "--directions") ? MAX_DIRECTIONS
                        : !strcmp(a, "--threads") ? 256 : 4294967295.0;
            if (aerotex_number(argc, argv, &i, !strcmp(a, "--seed") ? 0 : 1, hi,
                        &x))
                return -1;
            if (x != floor(x)) {
                aerotex_error("%s takes a whole number", a);
                return -1;
            }
            if (!strcmp(a, "--sources")) j->sources = (int)x;
            else if (!strcmp(a, "--directions")) j->directions = (int)x;
            else if (!strcmp(a, "--threads")) j->threads = (int)x;
            else j->seed = (unsigned)x;
            continue;
        }
        if (!strcmp(a, "--mirror") || !strcmp(a, "--no-mirror")) {
            j->mirror = !strcmp(a, "--mirror");
            continue;
        }
        if (!strcmp(a, "--shape") || !strcmp(a, "--mesh") ||
            !strcmp(a, "-o") || !strcmp(a, "--png")) {
            if (i + 1 >= argc) {
                aerotex_error("%s needs a value", a);
                return -1;
            }
            if (!strcmp(a, "--shape")) j->shape = argv[++i];
            else if (!strcmp(a, "--mesh")) j->mesh = argv[++i];
            else if (!strcmp(a, "-o")) j->out = argv[++i];
            else j->png_dir = argv[++i];
            continue;
        }
        if (!strcmp(a, "-q")) {
            j->quiet = 1;
            continue;
        }
        aerotex_error("unknown option '%s' for object (see 'aerotex help')",
                      a);
        return -1;
    }
    if (!j->out) {
        aerotex_error("no output file: add -o FILE.wav");
        return -1;
    }
    if (!!j->shape == !!j->mesh) {
        aerotex_error("give either --shape sphere|capsule|club or --mesh "
                      "FILE");
        return -1;
    }
    if (j->shape && strcmp(j->shape, "sphere") && strcmp(j->shape, "capsule")
        && strcmp(j->shape, "club")) {
        aerotex_error("--shape takes sphere, capsule or club (or use --mesh "
                      "FILE), not '%s'", j->shape);
        return -1;
    }
    return 0;
}

static int make_body(ojob_t *j, aero_body_shape *b)
{
    char err[512];
    int r;
    if (j->mesh)
        r = aero_body_mesh_load(b, j->mesh, err, sizeof err);
    else if (!strcmp(j->shape, "sphere"))
        r = aero_body_sphere(b, j->radius > 0 ? j->radius : 0.05, err,
                             sizeof err);
    else if (!strcmp(j->shape, "capsule"))
        r = aero_body_capsule(b, j->radius > 0 ? j->radius : 0.02,
                              j->length > 0 ? j->length : 0.3, err,
                              sizeof err);
    else
        r = aero_body_club(b, j->handle > 0 ? j->handle : 0.0125,
                           j->tip > 0 ? j->tip : 0.03,
                           j->length > 0 ? j->length : 0.8, err, sizeof err);
    if (r)
        aerotex_error("%s%s%s", j->mesh ? j->mesh : "", j->mesh ? ": " : "",
                      err);
    return r;
}

static void join(char *buf, size_t len, const double *x, int n,
                 const char *fmt)
{
    size_t used = 0;
    buf[0] = 0;
    for (int k = 0; k < n && used < len; k++) {
        used += (size_t)snprintf(buf + used, len - used, k ? "," : "");
        if (used < len)
            used += (size_t)snprintf(buf + used, len - used, fmt, x[k]);
    }
}

int aerotex_object(int argc, char **argv)
{
    ojob_t j;
    aero_body_shape body;
    aerotex_progress prog;
    octx_t *ctx = NULL;
    aero_body_flow_stats *st = NULL;
    aero_body_flow_params base;
    aero_texture tex;
    float *raw = NULL;
    double angles[MAX_DIRECTIONS], list[MAX_DIRECTIONS], t_start = aerotex_now();
    char err[512], command[4096], buf[16384], desc[256];
    int status = 1, nd, nr, ch, l0, xf, lmin, lmax, avail, len, sphere;
    double d;

    memset(&j, 0, sizeof j);
    j.mirror = -1;
    j.speed = 10.0;
    j.grid = 10.0;
    j.duration = 0.5;
    j.rate = 4000.0;
    j.settle = 25.0;
    j.cfl = 0.7;
    j.seed = 1;
    j.threads = omp_get_max_threads();
    if (oparse(&j, argc, argv))
        return 2;
    if (make_body(&j, &body))
        return 2;
    sphere = body.kind == AERO_BODY_SPHERE;
    if (j.mirror < 0)
        j.mirror = body.kind == AERO_BODY_CAPSULE;
    if (sphere && j.directions > 1) {
        aerotex_error("a sphere looks the same from every direction: "
                      "--directions 1");
        aero_body_free(&body);
        return 2;
    }
    nd = j.directions ? j.directions : sphere ? 1 : 5;
    nr = j.sources ? j.sources : body.kind == AERO_BODY_CLUB ? 10 : 1;
    for (int k = 0; k < nd; k++)
        angles[k] = nd == 1 ? 90.0 : (j.mirror ? 90.0 : 180.0) * k / (nd - 1);
    d = aero_body_reference_size(&body);
    aero_body_flow_defaults(&base, &body);
    base.speed = j.speed;
    base.cell = d / j.grid;
    base.regions = nr;
    base.cfl = j.cfl;
    base.settle = j.settle * d / j.speed;
    ch = 3 * nd * nr;
    l0 = (int)lround(j.duration * j.rate);
    if (l0 < 64) {
        aerotex_error("--duration %g s at --rate %g Hz is under 64 samples",
                      j.duration, j.rate);
        aero_body_free(&body);
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
        aero_body_free(&body);
        return 1;
    }
    raw = calloc((size_t)avail * ch, sizeof(float));
    ctx = calloc((size_t)nd, sizeof *ctx);
    st = calloc((size_t)nd, sizeof *st);
    if (!raw || !ctx || !st) {
        aerotex_error("out of memory");
        goto out;
    }
    prog.total = (long)nd * aero_body_flow_steps(&base, j.rate, avail);
    prog.done = 0;
    prog.t0 = prog.last = aerotex_now();
    prog.show = !j.quiet && isatty(fileno(stderr));
    omp_init_lock(&prog.plan);
    aero_body_describe(&body, desc, sizeof desc);
    if (!j.quiet)
        fprintf(stderr, "aerotex: object %s, d %g m, v0 %g m/s (Re %.3g), "
                "%d direction%s, %d region%s, %g cells per d, %ld steps, %d "
                "thread%s\n", desc, d, j.speed, j.speed * d / AERO_NU, nd,
                nd > 1 ? "s" : "", nr, nr > 1 ? "s" : "", j.grid, prog.total,
                j.threads < nd ? j.threads : nd,
                (j.threads < nd ? j.threads : nd) > 1 ? "s" : "");

#pragma omp parallel for schedule(dynamic, 1) num_threads(j.threads)
    for (int k = 0; k < nd; k++) {
        aero_body_flow_params p = base;
        octx_t *c = &ctx[k];
        p.angle = angles[k];
        p.seed = j.seed * 2654435761u + 7919u * (unsigned)(k + 1);
        p.plan_lock = plan_lock;
        c->job = &j;
        c->prog = &prog;
        c->index = k;
        c->snap_every = aero_body_flow_steps(&p, j.rate, avail) / 24 + 1;
        aero_body_flow_simulate(&p, j.rate, raw + 3 * (size_t)k * nr, ch,
                                avail, &st[k], hook, 16, c, c->err,
                                sizeof c->err);
        free(c->slice);
        free(c->solid);
    }
    aerotex_progress_show(&prog, 1);
    omp_destroy_lock(&prog.plan);
    status = 0;
    for (int k = 0; k < nd; k++)
        if (ctx[k].err[0]) {
            aerotex_error("direction %g deg: %s", angles[k], ctx[k].err);
            status = 1;
        }
    if (status)
        goto out;
    len = aero_texture_best_loop(raw, ch, lmin, lmax, xf);
    aero_texture_crossfade(raw, ch, len, xf);
    if (aero_texture_init_regions(&tex, len, nd, nr, j.rate)) {
        aerotex_error("out of memory");
        status = 1;
        goto out;
    }
    memcpy(tex.data, raw, sizeof(float) * (size_t)len * ch);
    memcpy(tex.angles, angles, sizeof(double) * nd);
    aero_texture_set(&tex, "kind", "object");
    {
        char shape[300];
        snprintf(shape, sizeof shape, "%s", desc);
        if (j.mesh)
            snprintf(shape, sizeof shape, "mesh %s", j.mesh);
        aero_texture_set(&tex, "shape", shape);
    }
    aero_texture_set(&tex, "symmetry", sphere ? "sphere" : "axis");
    aero_texture_setd(&tex, "mirror", j.mirror);
    aero_texture_setd(&tex, "diameter", d);
    aero_texture_setd(&tex, "v0", j.speed);
    aero_texture_setd(&tex, "rho", AERO_RHO);
    aero_texture_setd(&tex, "nu", AERO_NU);
    aero_texture_setd(&tex, "c0", AERO_C0);
    aero_texture_setd(&tex, "re", j.speed * d / AERO_NU);
    aero_texture_setd(&tex, "directions", nd);
    aero_texture_setd(&tex, "regions", nr);
    join(buf, sizeof buf, angles, nd, "%.6g");
    aero_texture_set(&tex, "angles", buf);
    {
        size_t used = 0;
        buf[0] = 0;
        for (int l = 0; l < nr && used < sizeof buf; l++)
            used += (size_t)snprintf(buf + used, sizeof buf - used,
                                     "%s%.6g,%.6g,%.6g", l ? ";" : "",
                                     st[0].centre[3 * l],
                                     st[0].centre[3 * l + 1],
                                     st[0].centre[3 * l + 2]);
        aero_texture_set(&tex, "centres", buf);
    }
    aero_texture_setd(&tex, "rate", j.rate);
    aero_texture_setd(&tex, "frames", len);
    aero_texture_set(&tex, "loop", "seamless");
    aero_texture_setd(&tex, "xfade", xf);
    aero_texture_set(&tex, "frame", "sample frame: the flow arrives along "
                     "(sin a, 0, cos a) of the body axes, a = angles[k]");
    aero_texture_set(&tex, "units", "N/s");
    {
        /* the direction nearest broadside stands for the object */
        int kb = 0;
        for (int k = 1; k < nd; k++)
            if (fabs(angles[k] - 90.0) < fabs(angles[kb] - 90.0))
                kb = k;
        aero_texture_setd(&tex, "st", st[kb].st);
        aero_texture_setd(&tex, "f", st[kb].f_peak);
        aero_texture_setd(&tex, "cd", st[kb].cd);
        aero_texture_setd(&tex, "cl_rms", st[kb].cl_rms);
    }
    for (int k = 0; k < nd; k++) list[k] = st[k].st;
    join(buf, sizeof buf, list, nd, "%.4g");
    aero_texture_set(&tex, "st_list", buf);
    for (int k = 0; k < nd; k++) list[k] = st[k].cd;
    join(buf, sizeof buf, list, nd, "%.4g");
    aero_texture_set(&tex, "cd_list", buf);
    for (int k = 0; k < nd; k++) list[k] = st[k].cl_rms;
    join(buf, sizeof buf, list, nd, "%.4g");
    aero_texture_set(&tex, "cl_rms_list", buf);
    aero_texture_setd(&tex, "grid", j.grid);
    aero_texture_setd(&tex, "cell", base.cell);
    aero_texture_setd(&tex, "settle", base.settle);
    aero_texture_setd(&tex, "dt", st[0].dt);
    aero_texture_set(&tex, "solver", "3D incompressible, MAC grid, MacCormack "
                     "advection, FFTW + tridiagonal projection, immersed "
                     "body by direct forcing (force = removed momentum)");
    aero_texture_set(&tex, "command", command);
    if (aero_texture_save(j.out, &tex, err, sizeof err)) {
        aerotex_error("%s", err);
        status = 1;
    } else {
        printf("%s: object %s, d %g m, %d direction%s x %d region%s, %d "
               "frames (%.3f s at %g Hz)\n", j.out, desc, d, nd,
               nd > 1 ? "s" : "", nr, nr > 1 ? "s" : "", len, len / j.rate,
               j.rate);
        for (int k = 0; k < nd; k++)
            printf("  %5.1f deg: grid %d x %d x %d, %ld steps of %.3g ms, "
                   "St %.3f (f %.1f Hz), Cd %.2f, Cl rms %.3f, max |div u| h "
                   "%.2g m/s\n", angles[k], st[k].nx, st[k].ny, st[k].nz,
                   st[k].steps, 1e3 * st[k].dt, st[k].st, st[k].f_peak,
                   st[k].cd, st[k].cl_rms, st[k].max_div);
        printf("  %.1f s\n", aerotex_now() - t_start);
    }
    aero_texture_free(&tex);
out:
    free(raw);
    free(ctx);
    free(st);
    aero_body_free(&body);
    return status;
}
