/* aerotex aeolian / cavity: runs the 2D flow solver for each sampled
 * direction (in parallel), turns the body force into the sound source
 * function g = dF/dt at the texture rate and writes the looped texture. */
#include "aerotex.h"
#include "aero_air.h"
#include "flow2d.h"
#include "shape2d.h"
#include "texture.h"

#include <errno.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

typedef struct {
    int cavity;
    const char *shape_name, *poly_file, *out, *png_dir;
    double d, aspect, v0, re, nu, duration, rate, grid, settle, cfl;
    double length, depth;
    int directions, symmetry, mirror, threads, quiet;
    int set_symmetry, set_mirror;
} job_t;

typedef struct {
    double alpha;         /* flow angle in the body frame, deg */
    double *t, *fx, *fy;  /* recorded times (d/v0), force / (rho v0^2 d) */
    int n;                /* recorded steps */
    double dt;            /* first solver step, d/v0 */
    aero_flowstats st;
    int nx, ny, cells_thin;
    char err[256];
} dir_t;

static int parse(job_t *j, int argc, char **argv)
{
    double x;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
#define NUM(name, lo, hi, field)                                    \
    if (!strcmp(a, name)) {                                         \
        if (aerotex_number(argc, argv, &i, lo, hi, &x)) return -1; \
        field = x;                                                  \
        continue;                                                   \
    }
        NUM("--speed", 1e-3, 1e4, j->v0)
        NUM("--re", 1.0, 1e6, j->re)
        NUM("--duration", 1e-3, 10.0, j->duration)
        NUM("--rate", 1000.0, 192000.0, j->rate)
        NUM("--grid", 4.0, 200.0, j->grid)
        NUM("--settle", 0.0, 1e4, j->settle)
        NUM("--cfl", 0.05, 0.8, j->cfl)
        NUM("--threads", 1.0, 256.0, j->threads)
        if (!j->cavity) {
            NUM("--diameter", 1e-5, 10.0, j->d)
            NUM("--aspect", 0.01, 1.0, j->aspect)
            NUM("--directions", 1.0, 360.0, j->directions)
            if (!strcmp(a, "--symmetry")) {
                if (aerotex_number(argc, argv, &i, 1.0, 64.0, &x)) return -1;
                if (x != floor(x)) {
                    aerotex_error("--symmetry takes a whole number");
                    return -1;
                }
                j->symmetry = (int)x;
                j->set_symmetry = 1;
                continue;
            }
            if (!strcmp(a, "--mirror") || !strcmp(a, "--no-mirror")) {
                j->mirror = !strcmp(a, "--mirror");
                j->set_mirror = 1;
                continue;
            }
            if (!strcmp(a, "--shape")) {
                if (i + 1 >= argc) {
                    aerotex_error("--shape needs circle, square, ellipse or "
                                  "polygon FILE");
                    return -1;
                }
                j->shape_name = argv[++i];
                if (!strcmp(j->shape_name, "polygon")) {
                    if (i + 1 >= argc) {
                        aerotex_error("--shape polygon needs a FILE");
                        return -1;
                    }
                    j->poly_file = argv[++i];
                } else if (strcmp(j->shape_name, "circle") &&
                           strcmp(j->shape_name, "square") &&
                           strcmp(j->shape_name, "ellipse")) {
                    aerotex_error("unknown shape '%s' (circle, square, "
                                  "ellipse, polygon FILE)", j->shape_name);
                    return -1;
                }
                continue;
            }
        } else {
            NUM("--length", 1e-5, 10.0, j->length)
            NUM("--depth", 1e-5, 10.0, j->depth)
        }
#undef NUM
        if (!strcmp(a, "-o")) {
            if (i + 1 >= argc) {
                aerotex_error("-o needs a file name");
                return -1;
            }
            j->out = argv[++i];
            continue;
        }
        if (!strcmp(a, "--png")) {
            if (i + 1 >= argc) {
                aerotex_error("--png needs a directory");
                return -1;
            }
            j->png_dir = argv[++i];
            continue;
        }
        if (!strcmp(a, "-q")) {
            j->quiet = 1;
            continue;
        }
        aerotex_error("unknown option '%s' for %s (see 'aerotex help')", a,
                      j->cavity ? "cavity" : "aeolian");
        return -1;
    }
    if (!j->out) {
        aerotex_error("no output file: add -o FILE.wav");
        return -1;
    }
    if (j->directions != floor(j->directions)) {
        aerotex_error("--directions takes a whole number");
        return -1;
    }
    return 0;
}

/* appends one recorded step, growing the arrays */
static int record(dir_t *r, int *cap, double t, double fx, double fy)
{
    if (r->n == *cap) {
        int nc = *cap ? 2 * *cap : 4096;
        double *a = realloc(r->t, sizeof(double) * nc);
        if (a) r->t = a;
        a = realloc(r->fx, sizeof(double) * nc);
        if (a) r->fx = a;
        a = realloc(r->fy, sizeof(double) * nc);
        if (a) r->fy = a;
        if (!r->t || !r->fx || !r->fy || !a)
            return -1;
        *cap = nc;
    }
    r->t[r->n] = t;
    r->fx[r->n] = fx;
    r->fy[r->n] = fy;
    r->n++;
    return 0;
}

/* the recorded time after the start-up, d/v0: the loop search range, the
   cross-fade and the low-pass kernel's reach on both sides (make_texture) */
static double record_time(const job_t *j)
{
    return (1.16 * j->duration + 48.0 / j->rate) * j->v0 / j->d;
}

/* one direction: settle, record the force, keep the statistics */
static void run_direction(const job_t *j, const aero_shape2d *shape,
                          const aero_flow2d_params *fp, int k, dir_t *r,
                          aerotex_progress *prog)
{
    aero_flow2d s;
    long step = 0, chunk = 0, nsnap, snap = 0;
    int cap = 0;
    float *w = NULL;
    double t_end = j->settle + record_time(j);
    if (aero_flow2d_init(&s, fp, r->err, sizeof r->err))
        return;
    if (aero_flow2d_set_body(&s, shape, r->alpha * AERO_PI / 180.0, r->err,
                             sizeof r->err)) {
        aero_flow2d_free(&s);
        return;
    }
    r->nx = s.nx;
    r->ny = s.ny;
    r->dt = s.dt;
    if (j->png_dir) {
        w = malloc(sizeof(float) * (size_t)s.nx * s.ny);
        if (!w) {
            snprintf(r->err, sizeof r->err, "out of memory");
            goto done;
        }
    }
    nsnap = (long)(t_end / s.dt) / 24 + 1;
    for (step = 0; s.t < t_end; step++) {
        if (aero_flow2d_step(&s)) {
            snprintf(r->err, sizeof r->err,
                     "the solver diverged at t = %.4g s (%.0f d/v0): try a "
                     "finer --grid or a smaller --cfl",
                     s.t * j->d / j->v0, s.t);
            goto done;
        }
        if (s.t >= j->settle && record(r, &cap, s.t, s.fx, s.fy)) {
            snprintf(r->err, sizeof r->err, "out of memory");
            goto done;
        }
        if (w && step % nsnap == 0) {
            char path[4096];
            aero_flow2d_vorticity(&s, w);
            snprintf(path, sizeof path, "%s/dir%02d_%04ld.png", j->png_dir, k,
                     snap++);
            if (aerotex_png_vorticity(path, w, s.solid, s.nx, s.ny,
                                      j->cavity ? 10.0f : 5.0f))
                snprintf(r->err, sizeof r->err, "can't write %.200s", path);
        }
        if (++chunk == 128) {
#pragma omp atomic
            prog->done += chunk;
            chunk = 0;
            if (prog->show) {
#pragma omp critical(aerotex_progress)
                aerotex_progress_show(prog, 0);
            }
        }
    }
    {
        /* statistics of the coefficients Cd = 2 Fx, Cl = 2 Fy */
        double *cd = malloc(sizeof(double) * (r->n + 1));
        double *cl = malloc(sizeof(double) * (r->n + 1));
        if (cd && cl) {
            for (int m = 0; m < r->n; m++) {
                cd[m] = 2.0 * r->fx[m];
                cl[m] = 2.0 * r->fy[m];
            }
            aero_flow2d_stats(r->t, cd, cl, r->n, &r->st);
        }
        free(cd);
        free(cl);
    }
done:
#pragma omp atomic
    prog->done += chunk;
    free(w);
    aero_flow2d_free(&s);
}

static void join_list(char *buf, size_t len, const dir_t *r, int n, int what)
{
    size_t used = 0;
    buf[0] = 0;
    for (int k = 0; k < n && used < len; k++) {
        double x = what == 0 ? r[k].alpha : what == 1 ? r[k].st.st
                   : what == 2 ? r[k].st.cd : r[k].st.cl_rms;
        used += (size_t)snprintf(buf + used, len - used, "%s%.6g",
                                 k ? "," : "", x);
    }
}

/* g = dF/dt of every direction at the texture rate, looped, with metadata */
static int make_texture(const job_t *j, dir_t *r, const char *shape_desc,
                        const char *command, aero_texture *tex)
{
    const int nd = j->directions, ch = 3 * nd;
    const int l0 = (int)lround(j->duration * j->rate);
    const aerotex_loop_plan lp = aerotex_plan_loop(l0);
    const int xf = lp.xfade, lmin = lp.lmin, lmax = lp.lmax, avail = lp.avail;
    const double tunit = j->d / j->v0;               /* s per d/v0 */
    const double scale = AERO_RHO * j->v0 * j->v0 * j->d; /* F in N/m */
    const double t0 = 20.0 / j->rate;                /* kernel reach */
    float *raw = calloc((size_t)avail * ch, sizeof(float));
    char buf[8192];
    int len;
    if (!raw) {
        aerotex_error("out of memory");
        return -1;
    }
    for (int k = 0; k < nd; k++) {
        double *ts = malloc(sizeof(double) * (r[k].n + 1)), start;
        if (!ts) {
            aerotex_error("out of memory");
            free(raw);
            return -1;
        }
        for (int m = 0; m < r[k].n; m++)
            ts[m] = r[k].t[m] * tunit;
        start = ts[0] + t0;
        if (r[k].n < 2 ||
            ts[r[k].n - 1] < start + avail / j->rate + 18.0 / j->rate) {
            aerotex_error("internal: recording too short");
            free(ts);
            free(raw);
            return -1;
        }
        aero_texture_resample_derivative(ts, r[k].fx, r[k].n, j->rate, start,
                                         scale, raw + 3 * k, ch, avail);
        aero_texture_resample_derivative(ts, r[k].fy, r[k].n, j->rate, start,
                                         scale, raw + 3 * k + 1, ch, avail);
        free(ts);
    }
    len = aero_texture_best_loop(raw, ch, lmin, lmax, xf);
    aero_texture_crossfade(raw, ch, len, xf);
    if (aero_texture_init(tex, len, nd, j->rate)) {
        free(raw);
        aerotex_error("out of memory");
        return -1;
    }
    memcpy(tex->data, raw, sizeof(float) * (size_t)len * ch);
    free(raw);
    for (int k = 0; k < nd; k++)
        tex->angles[k] = r[k].alpha;

    aero_texture_set(tex, "kind", j->cavity ? "cavity" : "aeolian");
    aero_texture_set(tex, "shape", shape_desc);
    if (j->cavity) {
        aero_texture_setd(tex, "length", j->length);
        aero_texture_setd(tex, "depth", j->depth);
    } else {
        aero_texture_setd(tex, "diameter", j->d);
    }
    aero_texture_setd(tex, "v0", j->v0);
    aero_texture_setd(tex, "rho", AERO_RHO);
    aero_texture_setd(tex, "nu", j->nu);
    aero_texture_setd(tex, "c0", AERO_C0);
    aero_texture_setd(tex, "re", j->re);
    aero_texture_setd(tex, "directions", nd);
    aero_texture_setd(tex, "symmetry", j->symmetry);
    aero_texture_setd(tex, "mirror", j->mirror);
    join_list(buf, sizeof buf, r, nd, 0);
    aero_texture_set(tex, "angles", buf);
    aero_texture_setd(tex, "angle_start", r[0].alpha);
    aero_texture_setd(tex, "angle_step", nd > 1 ? r[1].alpha - r[0].alpha : 0.0);
    aero_texture_setd(tex, "rate", j->rate);
    aero_texture_setd(tex, "frames", len);
    aero_texture_set(tex, "loop", "seamless");
    aero_texture_setd(tex, "xfade", xf);
    aero_texture_set(tex, "frame", "x=flow,y=across,z=axis");
    aero_texture_set(tex, "units", "N/(m s)");
    aero_texture_setd(tex, "st", r[0].st.st);
    aero_texture_setd(tex, "cd", r[0].st.cd);
    aero_texture_setd(tex, "cl_rms", r[0].st.cl_rms);
    aero_texture_setd(tex, "f", r[0].st.st * j->v0 / j->d);
    if (nd > 1) {
        join_list(buf, sizeof buf, r, nd, 1);
        aero_texture_set(tex, "st_list", buf);
        join_list(buf, sizeof buf, r, nd, 2);
        aero_texture_set(tex, "cd_list", buf);
        join_list(buf, sizeof buf, r, nd, 3);
        aero_texture_set(tex, "cl_rms_list", buf);
    }
    aero_texture_setd(tex, "grid", j->grid);
    aero_texture_setd(tex, "settle", j->settle * tunit);
    aero_texture_setd(tex, "dt", r[0].dt * tunit);
    aero_texture_set(tex, "solver", "2D incompressible projection, MAC grid, "
                                    "immersed boundary");
    aero_texture_set(tex, "command", command);
    return 0;
}

int aerotex_aeolian(int argc, char **argv, int cavity)
{
    job_t j;
    aero_shape2d shape;
    aero_flow2d_params fp;
    dir_t *r;
    aerotex_progress prog;
    aero_texture tex;
    char err[512], shape_desc[512], command[4096];
    int status = 1;
    double t_start = aerotex_now(), thin = 1e300;

    memset(&j, 0, sizeof j);
    j.cavity = cavity;
    j.shape_name = "circle";
    j.d = 0.01;
    j.aspect = 0.5;
    j.v0 = 10.0;
    j.duration = 0.2;
    j.rate = 16000.0;
    /* a cavity's shear layer starts as the wall's boundary layer, a cell
       or two thick: below ~48 cells per length the grid damps it and the
       flow stays steady (no Rossiter tone) */
    j.grid = cavity ? 48.0 : 16.0;
    j.settle = -1.0;
    j.cfl = 0.5;
    j.directions = 1;
    j.symmetry = 1;
    j.threads = omp_get_max_threads();
    if (parse(&j, argc, argv))
        return 2;
    memset(&shape, 0, sizeof shape);

    /* the shape and its symmetry */
    if (cavity) {
        if (!(j.length > 0.0) || !(j.depth > 0.0)) {
            aerotex_error("cavity needs --length and --depth (m)");
            return 2;
        }
        if (j.depth > 4.0 * j.length || j.length > 20.0 * j.depth) {
            aerotex_error("cavity %g m x %g m: keep 1/20 <= depth/length <= 4",
                          j.length, j.depth);
            return 2;
        }
        j.d = j.length;
        aero_shape2d_cavity(&shape, j.length, j.depth);
        snprintf(shape_desc, sizeof shape_desc, "cavity");
    } else if (!strcmp(j.shape_name, "circle")) {
        aero_shape2d_circle(&shape, j.d);
        snprintf(shape_desc, sizeof shape_desc, "circle");
        if (j.directions > 1) {
            aerotex_error("a circle looks the same from every direction: use "
                          "--directions 1");
            return 2;
        }
        j.symmetry = 0;
        j.mirror = 1;
    } else if (!strcmp(j.shape_name, "square")) {
        aero_shape2d_square(&shape, j.d);
        snprintf(shape_desc, sizeof shape_desc, "square");
        if (!j.set_symmetry) j.symmetry = 4;
        if (!j.set_mirror) j.mirror = 1;
    } else if (!strcmp(j.shape_name, "ellipse")) {
        aero_shape2d_ellipse(&shape, j.d, j.aspect);
        snprintf(shape_desc, sizeof shape_desc, "ellipse aspect=%g", j.aspect);
        if (!j.set_symmetry) j.symmetry = 2;
        if (!j.set_mirror) j.mirror = 1;
    } else {
        if (aero_shape2d_load_poly(&shape, j.poly_file, j.d, err, sizeof err)) {
            aerotex_error("%s", err);
            return 2;
        }
        {
            const char *base = strrchr(j.poly_file, '/');
            snprintf(shape_desc, sizeof shape_desc, "polygon %s",
                     base ? base + 1 : j.poly_file);
        }
    }
    if (j.v0 / AERO_C0 > AERO_MACH_LIMIT) {
        aerotex_error("--speed %g m/s is above Mach %g: the incompressible "
                      "model does not hold", j.v0, AERO_MACH_LIMIT);
        goto out;
    }
    if (j.re > 0.0) {
        j.nu = j.v0 * j.d / j.re;
    } else {
        j.nu = AERO_NU;
        j.re = j.v0 * j.d / j.nu;
    }
    if (j.re > 1e5) {
        aerotex_error("Re = %.3g is beyond what a 2D laminar solver can "
                      "represent (max 1e5): lower --speed or the size, or "
                      "set --re", j.re);
        goto out;
    }
    if (j.settle < 0.0)
        /* the cavity's oscillation takes ~50-80 L/v0 to grow from the
           seeding to its saturated level: discard that */
        j.settle = cavity ? 80.0 : (j.re < 300.0 ? 100.0 : 30.0);
    if (j.duration * j.rate < 64) {
        aerotex_error("--duration %g s at --rate %g Hz is under 64 samples",
                      j.duration, j.rate);
        goto out;
    }

    /* the flow domain (units of d) */
    aero_flow2d_defaults(&fp, j.re);
    fp.grid = j.grid;
    fp.cfl = j.cfl;
    if (cavity) {
        fp.xmin = -0.3;
        fp.xmax = 3.5;
        fp.ymin = -(j.depth / j.length) - 0.25;
        fp.ymax = 1.5;
        fp.spin = 0.15;
        fp.spin_time = 2.0;
    } else {
        double ext = 2.0 * aero_shape2d_radius(&shape) / j.d;
        if (ext > 1.5) { /* tall polygons: room around them */
            fp.xmin *= ext;
            fp.xmax *= ext;
            fp.ymin *= ext;
            fp.ymax *= ext;
        }
        for (int a = 0; a < 180; a++) {
            double w = aero_shape2d_frontal(&shape, a * AERO_PI / 180.0);
            if (w < thin) thin = w;
        }
        if (thin * j.grid / j.d < 1.5) {
            aerotex_error("the shape is %.3g cells thin at --grid %g: use a "
                          "finer --grid (at least %.0f)", thin * j.grid / j.d,
                          j.grid, ceil(1.5 * j.d / thin));
            goto out;
        }
    }

    /* the sampled directions */
    r = calloc((size_t)j.directions, sizeof *r);
    if (!r) {
        aerotex_error("out of memory");
        goto out;
    }
    for (int k = 0; k < j.directions; k++) {
        double range;
        if (j.symmetry == 0 || cavity)
            r[k].alpha = 0.0;
        else if (j.mirror) {
            range = 180.0 / j.symmetry;
            r[k].alpha = j.directions > 1 ? k * range / (j.directions - 1) : 0.0;
        } else {
            range = 360.0 / j.symmetry;
            r[k].alpha = k * range / j.directions;
        }
    }
    aerotex_command_line(command, sizeof command, argc, argv);
    if (j.png_dir && mkdir(j.png_dir, 0777) && errno != EEXIST) {
        aerotex_error("can't create %s: %s", j.png_dir, strerror(errno));
        free(r);
        goto out;
    }

    {
        /* a trial grid for the step count of the progress bar */
        aero_flow2d probe;
        if (aero_flow2d_init(&probe, &fp, err, sizeof err)) {
            aerotex_error("%s", err);
            free(r);
            goto out;
        }
        /* the steps run at about 1.2 times the first step's size */
        prog.total = (long)j.directions *
                     (long)((j.settle + record_time(&j)) / (0.85 * probe.dt));
        if (!j.quiet)
            fprintf(stderr, "aerotex: %s, Re %.4g, %d direction%s, grid %d x "
                    "%d, %d thread%s\n", shape_desc, j.re, j.directions,
                    j.directions > 1 ? "s" : "", probe.nx, probe.ny,
                    j.threads < j.directions ? j.threads : j.directions,
                    (j.threads < j.directions ? j.threads : j.directions) > 1
                        ? "s" : "");
        aero_flow2d_free(&probe);
    }
    prog.done = 0;
    prog.t0 = prog.last = aerotex_now();
    prog.show = !j.quiet && isatty(fileno(stderr));

#pragma omp parallel for schedule(dynamic, 1) num_threads(j.threads)
    for (int k = 0; k < j.directions; k++)
        run_direction(&j, &shape, &fp, k, &r[k], &prog);
    aerotex_progress_show(&prog, 1);

    status = 0;
    for (int k = 0; k < j.directions; k++)
        if (r[k].err[0]) {
            aerotex_error("direction %d (%g deg): %s", k, r[k].alpha, r[k].err);
            status = 1;
        }
    if (!status) {
        if (make_texture(&j, r, shape_desc, command, &tex)) {
            status = 1;
        } else {
            if (aero_texture_save(j.out, &tex, err, sizeof err)) {
                aerotex_error("%s", err);
                status = 1;
            } else {
                printf("%s: %s, Re %.4g, %d direction%s, %d frames (%.3f s "
                       "at %g Hz)\n", j.out, shape_desc, j.re, j.directions,
                       j.directions > 1 ? "s" : "", tex.frames,
                       tex.frames / j.rate, j.rate);
                for (int k = 0; k < j.directions; k++)
                    printf("  %6.2f deg: St %.4f (f = %.1f Hz)  Cd %.3f  Cl "
                           "rms %.3f\n", r[k].alpha, r[k].st.st,
                           r[k].st.st * j.v0 / j.d, r[k].st.cd,
                           r[k].st.cl_rms);
                if (r[0].st.st == 0.0 && !cavity && r[0].st.cl_rms < 0.01)
                    printf("  no vortex shedding at Re %.3g: the tone is "
                           "silent\n", j.re);
                else if (r[0].st.st == 0.0 && !cavity)
                    printf("  the lift is too short or too irregular for a "
                           "Strouhal number (st=0 in the metadata)\n");
                if (r[0].st.st == 0.0 && cavity)
                    printf("  no self-sustained oscillation of the cavity "
                           "flow: the texture holds only its weak broadband "
                           "wall-pressure force (a --grid under 48 damps "
                           "the shear layer)\n");
                printf("  %.1f s\n", aerotex_now() - t_start);
            }
            aero_texture_free(&tex);
        }
    }
    for (int k = 0; k < j.directions; k++) {
        free(r[k].t);
        free(r[k].fx);
        free(r[k].fy);
    }
    free(r);
out:
    aero_shape2d_free(&shape);
    return status;
}
