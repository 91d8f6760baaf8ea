/* aerotex aeolian / cavity: the texture of a 2D cross-section, one
 * channel triple per sampled flow direction, the directions simulated in
 * parallel (the run both commands share: aerotex_section.h; their
 * options: aerotex_aeolian.c, aerotex_cavity.c). The physics is in
 * src/core/solve/aeolian_flow.c, the shapes in src/core/common/shape2d.c. */
#include "aerotex_section.h"
#include "aero_air.h"
#include "band_limit.h"
#include "texture.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* --span3d urans: Wilcox's (2006) k-omega with Kato and Launder's (1993)
   production, in flow2d.h's default free stream */
#define URANS_MODEL AERO_FLOW2D_KOMEGA_KL
#define URANS_DESCRIPTION "k-omega (Wilcox 2006), Kato-Launder production"

static int urans(const aeolian_job *j)
{
    return j->span3d == SPAN3D_URANS && !j->cavity &&
           j->re > AERO_SPAN3D_RE_2D;
}

/* the flow angle's incidence to the section's x axis, 0..90 deg */
static double incidence(double alpha)
{
    double a = fmod(fabs(alpha), 180.0);
    return a < 90.0 ? a : 180.0 - a;
}

/* A thin section nearly edge-on keeps its boundary layers attached and
   sheds from a thin trailing-edge wake a few cells wide: there the
   k-omega model's eddy viscosity on the coarse grid damps the shedding
   away (a silent blade), while the laminar 2D flow sheds a weak tone.
   Stalled, the laminar shear layers roll up into under-resolved bursts
   (clicks) that the model smooths (textures/README.md, the sword). So
   with --urans-from A the directions under A deg run laminar. */
static int direction_urans(const aeolian_job *j, double alpha)
{
    return urans(j) && incidence(alpha) >= j->urans_from - 1e-9;
}

/* one sampled direction: the first member is its task */
typedef struct {
    aerotex_task task;
    double alpha;         /* flow angle in the body frame, deg */
    aero_aeolian_flow_stats st;
    float *w;             /* --png: vorticity, then (a stretched grid) its
                             rows at their true heights, and the body's */
    float wmax;           /* --png: |vorticity| at full colour, v0/d */
} direction;

/* the shape, its description and its symmetry: 0, or 2 with a message */
static int make_shape(aeolian_job *j, aero_shape2d *shape, char *desc,
                      size_t len)
{
    char err[512];
    const char *base;
    if (j->cavity) {
        if (!(j->length > 0.0) || !(j->depth > 0.0)) {
            aerotex_error("cavity needs --length and --depth (m)");
            return 2;
        }
        if (j->depth > 4.0 * j->length || j->length > 20.0 * j->depth) {
            aerotex_error("cavity %g m x %g m: keep 1/20 <= depth/length <= 4",
                          j->length, j->depth);
            return 2;
        }
        if (j->theta > AERO_FLOW2D_THETA_MAX * j->length) {
            aerotex_error("cavity: --theta %g m is thicker than %g of the "
                          "length (%g m)", j->theta, AERO_FLOW2D_THETA_MAX,
                          AERO_FLOW2D_THETA_MAX * j->length);
            return 2;
        }
        j->d = j->length;
        aero_shape2d_cavity(shape, j->length, j->depth);
        snprintf(desc, len, "cavity");
    } else if (!strcmp(j->shape_name, "circle")) {
        if (j->directions > 1) {
            aerotex_error("aeolian: a circle looks the same from every "
                          "direction: use --directions 1");
            return 2;
        }
        aero_shape2d_circle(shape, j->d);
        snprintf(desc, len, "circle");
        j->symmetry = 0;
        j->mirror = 1;
    } else if (!strcmp(j->shape_name, "square")) {
        aero_shape2d_square(shape, j->d);
        snprintf(desc, len, "square");
        if (j->symmetry < 0) j->symmetry = 4;
        if (j->mirror < 0) j->mirror = 1;
    } else if (!strcmp(j->shape_name, "ellipse")) {
        aero_shape2d_ellipse(shape, j->d, j->aspect);
        snprintf(desc, len, "ellipse aspect=%g", j->aspect);
        if (j->symmetry < 0) j->symmetry = 2;
        if (j->mirror < 0) j->mirror = 1;
    } else {
        if (aero_shape2d_load_poly(shape, j->poly_file, j->d, err,
                                   sizeof err)) {
            aerotex_error("%s", err);
            return 2;
        }
        base = strrchr(j->poly_file, '/');
        snprintf(desc, len, "polygon %s", base ? base + 1 : j->poly_file);
    }
    if (j->symmetry < 0) j->symmetry = 1;
    if (j->mirror < 0) j->mirror = 0;
    return 0;
}

/* A thin polygon (thickness at most 0.3 of its extent along x) is a
 * blade: its texture carries the section as the airfoil self-noise model
 * reads it (Brooks et al. 1989; the player's band above the band limit,
 * src/core/play/blade_noise.h): the chord (the extent along x), the
 * trailing edge's thickness (the span across y of the vertices within
 * 0.5 % of the chord of the rearmost) and its angle Psi (between the two
 * edges that meet there). 1 for a blade, else 0. */
static int blade_geometry(const aero_shape2d *s, double *chord, double *h,
                          double *psi)
{
    int n = s->npts, last = 0, first, end;
    double xmin = 1e30, xmax = -1e30, ymin = 1e30, ymax = -1e30;
    if (s->kind != AERO_SHAPE_POLYGON || n < 3)
        return 0;
    for (int i = 0; i < n; i++) {
        xmin = fmin(xmin, s->px[i]);
        ymin = fmin(ymin, s->py[i]);
        ymax = fmax(ymax, s->py[i]);
        if (s->px[i] > xmax) {
            xmax = s->px[i];
            last = i;
        }
    }
    *chord = xmax - xmin;
    if (!(*chord > 0) || ymax - ymin > 0.3 * *chord)
        return 0;
    /* the trailing edge: the run of vertices around the rearmost */
    double tol = 0.005 * *chord, lo = 1e30, hi = -1e30;
    first = end = last;
    while (s->px[(first + n - 1) % n] >= xmax - tol && (first + n - 1) % n != last)
        first = (first + n - 1) % n;
    while (s->px[(end + 1) % n] >= xmax - tol && (end + 1) % n != first)
        end = (end + 1) % n;
    for (int i = first;; i = (i + 1) % n) {
        lo = fmin(lo, s->py[i]);
        hi = fmax(hi, s->py[i]);
        if (i == end)
            break;
    }
    *h = hi - lo;
    int before = (first + n - 1) % n, after = (end + 1) % n;
    double ux = s->px[before] - s->px[first], uy = s->py[before] - s->py[first];
    double vx = s->px[after] - s->px[end], vy = s->py[after] - s->py[end];
    double c = (ux * vx + uy * vy) / (hypot(ux, uy) * hypot(vx, vy));
    *psi = acos(c < -1 ? -1 : c > 1 ? 1 : c) * 180.0 / AERO_PI;
    return 1;
}

/* the core's parameters for direction alpha */
static aero_aeolian_flow_params flow_params(const aeolian_job *j,
                                            const aero_shape2d *shape,
                                            double alpha)
{
    aero_aeolian_flow_params p;
    p.shape = shape;
    p.cavity = j->cavity;
    p.size = j->d;
    p.depth = j->depth;
    p.theta = j->cavity ? j->theta : 0.0;
    p.speed = j->v0;
    p.re = j->re;
    p.grid = j->grid;
    p.cfl = j->cfl;
    p.stretch = j->stretch;
    p.settle = j->settle;
    p.duration = j->job.duration;
    p.angle = alpha;
    p.span3d = &j->correction;
    p.span3d_self = 0;
    p.turbulence = direction_urans(j, alpha) ? URANS_MODEL
                                             : AERO_FLOW2D_LAMINAR;
    return p;
}

/* Mach, Reynolds, the start-up and the grid: 0, or 2 with a message */
static int check_flow(aeolian_job *j, const aero_shape2d *shape)
{
    aero_aeolian_flow_params p;
    aero_flow2d_params fp;
    char err[512];
    if (j->v0 / AERO_C0 > AERO_MACH_LIMIT) {
        aerotex_error("%s: --speed %g m/s is above Mach %g: the "
                      "incompressible model does not hold", j->job.name,
                      j->v0, AERO_MACH_LIMIT);
        return 2;
    }
    if (j->re > 0.0) {
        j->nu = j->v0 * j->d / j->re;
    } else {
        j->nu = AERO_NU;
        j->re = j->v0 * j->d / j->nu;
    }
    if (j->re > 1e5) {
        aerotex_error("%s: Re = %.3g is beyond what a 2D laminar solver can "
                      "represent (max 1e5): lower --speed or the size, or "
                      "set --re", j->job.name, j->re);
        return 2;
    }
    if (j->settle < 0.0)
        j->settle = j->re < 300.0 ? 100.0 : 30.0;
    j->thin = j->cavity ? j->d : aero_aeolian_flow_thinnest(shape);
    p = flow_params(j, shape, 0.0);
    if (aero_aeolian_flow_domain(&p, &fp, err, sizeof err)) {
        aerotex_error("%s: %s", j->job.name, err);
        return 2;
    }
    return 0;
}

/* the sampled flow angles, deg */
static void sample_directions(const aeolian_job *j, direction *r)
{
    for (int k = 0; k < j->directions; k++) {
        if (j->symmetry == 0 || j->cavity)
            r[k].alpha = 0.0;
        else if (j->mirror)
            r[k].alpha = j->directions > 1
                             ? k * (180.0 / j->symmetry) / (j->directions - 1)
                             : 0.0;
        else
            r[k].alpha = k * (360.0 / j->symmetry) / j->directions;
    }
}

/* the picture rows of h from the domain's bottom up: how many, and with
   out != NULL, each the flow row it falls in (a stretched grid's tall
   rows show at their true height) */
static int picture_rows(const aero_flow2d *s, const float *in, float *out)
{
    const int n = (int)lround((s->yf[s->ny] - s->yf[0]) / s->h);
    for (int k = 0, j = 0; out && k < n; k++) {
        double y = s->yf[0] + (k + 0.5) * s->h;
        while (j < s->ny - 1 && s->yf[j + 1] <= y)
            j++;
        memcpy(out + (size_t)k * s->nx, in + (size_t)j * s->nx,
               sizeof(float) * (size_t)s->nx);
    }
    return n;
}

/* progress, and the vorticity snapshots of --png */
static void hook(void *ctx, const aero_flow2d *s, long step)
{
    direction *r = ctx;
    const aerotex_job *job = r->task.job;
    char path[4096];
    if (step - r->task.last_step >= 128)
        aerotex_task_progress(&r->task, step);
    if (!aerotex_task_snapshot_due(&r->task, step))
        return;
    const int rows = s->stretched ? picture_rows(s, NULL, NULL) : s->ny;
    const size_t cells = (size_t)s->nx * s->ny, pixels = (size_t)s->nx * rows;
    float *w, *solid;
    if (!r->w)
        r->w = malloc(sizeof(float) * (cells + (s->stretched ? 2 * pixels : 0)));
    if (!r->w) {
        snprintf(r->task.err, sizeof r->task.err, "out of memory");
        return;
    }
    aero_flow2d_vorticity(s, r->w);
    w = r->w;
    solid = s->solid;
    if (s->stretched) {
        w = r->w + cells;
        solid = w + pixels;
        picture_rows(s, r->w, w);
        picture_rows(s, s->solid, solid);
    }
    snprintf(path, sizeof path, "%s/dir%02d_%04ld.png", job->png_dir,
             r->task.index, r->task.snap - 1);
    if (aerotex_png_vorticity(path, w, solid, s->nx, rows, r->wmax))
        snprintf(r->task.err, sizeof r->task.err, "can't write %.200s", path);
}

/* the calibration circle of the 2D-to-3D correction (span3d.h), on rank
   0 in c (the slot after the directions), its correction shared with
   every rank: 0, or 1 when it failed on rank 0 */
static int run_calibration(aeolian_job *j, const aero_aeolian_flow_plan *plan,
                           direction *c)
{
    const int nd = j->directions;
    struct {
        int status;
        aero_span3d correction;
    } shared;
    aero_shape2d circle;
    aero_aeolian_flow_params pc;
    int status = 0;
    aero_shape2d_circle(&circle, j->d);
    pc = flow_params(j, &circle, 0.0);
    pc.span3d_self = 1;
    c->task.job = &j->job;
    c->task.index = nd;
    c->task.snap_every = (long)(plan->t_end / plan->dt) / 24 + 1;
    c->wmax = 5.0f;
    if (!j->job.quiet)
        fprintf(stderr, "aerotex: the calibration circle of the 2D-to-3D "
                "correction, Re %.4g\n", j->re);
    if (aerotex_farm_rank() == 0 &&
        !aerotex_farm_resume(&j->job, nd, c, sizeof *c, 0)) {
        if (aero_aeolian_flow_simulate(&pc, j->job.rate, NULL, 0, 0, &c->st,
                                       hook, 1, c, c->task.err,
                                       sizeof c->task.err)) {
            aerotex_error("%s", c->task.err);
            status = 1;
        }
        aerotex_farm_keep(&j->job, nd, c, sizeof *c, 0);
    }
    free(c->w);
    aero_shape2d_free(&circle);
    memset(&shared, 0, sizeof shared);
    shared.status = status;
    shared.correction = c->st.span3d;
    aerotex_farm_share(&shared, sizeof shared);
    if (!shared.status)
        j->correction = shared.correction;
    return shared.status;
}

/* every direction in parallel into the job's raw (3 channels each): 0 or 1 */
static int run_directions(aeolian_job *j, const aero_shape2d *shape,
                          const char *desc, direction *r)
{
    const int nd = j->directions,
              threads = aerotex_job_threads(&j->job, aerotex_farm_count(nd));
    aero_aeolian_flow_params p0 = flow_params(j, shape, 0.0);
    aero_aeolian_flow_plan plan;
    char err[512];
    int status = 0;
    /* the 2D-to-3D correction: a circle calibrates it on itself, any other
       shape on a circle run first at the same Re and grid (span3d.h) */
    const int corrected = j->span3d == SPAN3D_CIRCLE && !j->cavity &&
                          j->re > AERO_SPAN3D_RE_2D;
    const int self = corrected && !strcmp(desc, "circle");
    const int calibrate = corrected && !self;
    aero_span3d_none(&j->correction, j->re);
    if (aero_aeolian_flow_estimate(&p0, j->job.rate, &plan, err, sizeof err)) {
        aerotex_error("%s", err);
        return 1;
    }
    /* this rank's directions (all of them in one process), and the
       calibration circle on rank 0 */
    aerotex_progress_start(&j->job.prog, NULL,
                           (long)(aerotex_farm_count(nd) + calibrate) *
                               plan.steps, j->job.quiet);
    if (calibrate && run_calibration(j, &plan, &r[nd])) {
        aerotex_progress_end(&j->job.prog);
        return 1;
    }
    if (!j->job.quiet)
        fprintf(stderr, "aerotex: %s, Re %.4g, %d direction%s, grid %d x %d, "
                "%d thread%s\n", desc, j->re, nd, nd > 1 ? "s" : "", plan.nx,
                plan.ny, threads, threads > 1 ? "s" : "");
#pragma omp parallel for schedule(dynamic, 1) num_threads(j->job.threads)
    for (int k = 0; k < nd; k++) {
        if (!aerotex_farm_mine(k) ||
            aerotex_farm_resume(&j->job, k, &r[k], sizeof *r, 3))
            continue;
        aero_aeolian_flow_params p = flow_params(j, shape, r[k].alpha);
        p.span3d_self = self;
        r[k].task.job = &j->job;
        r[k].task.index = k;
        r[k].task.snap_every = (long)(plan.t_end / plan.dt) / 24 + 1;
        r[k].wmax = j->cavity ? 10.0f : 5.0f;
        aero_aeolian_flow_simulate(&p, j->job.rate, j->job.raw + 3 * k, 3 * nd,
                                   j->job.loop.avail, &r[k].st, hook, 1,
                                   &r[k], r[k].task.err,
                                   sizeof r[k].task.err);
        free(r[k].w);
        r[k].w = NULL;
        aerotex_farm_keep(&j->job, k, &r[k], sizeof *r, 3);
    }
    aerotex_progress_end(&j->job.prog);
    if (aerotex_farm_gather(&j->job, r, nd, sizeof *r, 3))
        return 1;
    if (aerotex_farm_rank())
        return 0;
    for (int k = 0; k < nd; k++)
        if (r[k].task.err[0]) {
            aerotex_error("direction %d (%g deg): %s", k, r[k].alpha,
                          r[k].task.err);
            status = 1;
        }
    if (self && !status)
        j->correction = r[0].st.span3d;
    return status;
}

/* the statistic `what` (0 angle, 1 St, 2 Cd, 3 Cl rms) of every direction,
   St (spectral peak) and Cl rms as the texture holds them, after the
   2D-to-3D correction c; Cd the 2D one */
static void join_stat(char *buf, size_t len, const direction *r, int n,
                      int what, const aero_span3d *c)
{
    double x[360];
    for (int k = 0; k < n; k++)
        x[k] = what == 0 ? r[k].alpha
               : what == 1 ? r[k].st.st_peak * c->frequency_scale
               : what == 2 ? r[k].st.flow.cd
                           : r[k].st.flow.cl_rms * c->force_scale;
    aerotex_join(buf, len, x, n, "%.6g");
}

/* cells across the section's smallest dimension: a cavity's shorter side,
   a stick's thinnest frontal width */
static double cells(const aeolian_job *j)
{
    if (j->cavity)
        return j->grid * fmin(j->length, j->depth) / j->length;
    return j->grid * j->thin / j->d;
}

/* the texture's metadata: what it is, its body and directions */
static void describe_section(const aeolian_job *j, const direction *r,
                             const char *desc, aero_texture *tex)
{
    const int nd = j->directions;
    const aero_span3d *c = &j->correction;
    char buf[8192];
    aero_texture_set(tex, "kind", j->cavity ? "cavity" : "aeolian");
    aero_texture_set(tex, "shape", desc);
    if (j->cavity) {
        aero_texture_setd(tex, "length", j->length);
        aero_texture_setd(tex, "depth", j->depth);
        aero_texture_setd(tex, "theta", j->theta);
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
    join_stat(buf, sizeof buf, r, nd, 0, c);
    aero_texture_set(tex, "angles", buf);
    aero_texture_setd(tex, "angle_start", r[0].alpha);
    aero_texture_setd(tex, "angle_step",
                      nd > 1 ? r[1].alpha - r[0].alpha : 0.0);
    aerotex_job_loop_meta(&j->job, tex);
    aero_texture_set(tex, "frame", "x=flow,y=across,z=axis");
    aero_texture_set(tex, "units", "N/(m s)");
}

/* what the flow measured */
static void describe_flow(const aeolian_job *j, const direction *r,
                          aero_texture *tex)
{
    const int nd = j->directions;
    const aero_span3d *c = &j->correction;
    char buf[8192];
    /* St of the lift's spectral peak and the rms lift as the texture holds
       them (after the 2D-to-3D correction), the 2D solver's own beside
       them; the mean drag is the 2D one */
    aero_texture_setd(tex, "st", r[0].st.st_peak * c->frequency_scale);
    aero_texture_setd(tex, "st_2d", r[0].st.st_peak);
    aero_texture_setd(tex, "st_2d_crossings", r[0].st.flow.st);
    aero_texture_setd(tex, "cd", r[0].st.flow.cd);
    aero_texture_setd(tex, "cl_rms", r[0].st.flow.cl_rms * c->force_scale);
    aero_texture_setd(tex, "cl_rms_2d", r[0].st.flow.cl_rms);
    aero_texture_setd(tex, "f",
                      r[0].st.st_peak * c->frequency_scale * j->v0 / j->d);
    if (nd > 1) {
        join_stat(buf, sizeof buf, r, nd, 1, c);
        aero_texture_set(tex, "st_list", buf);
        join_stat(buf, sizeof buf, r, nd, 2, c);
        aero_texture_set(tex, "cd_list", buf);
        join_stat(buf, sizeof buf, r, nd, 3, c);
        aero_texture_set(tex, "cl_rms_list", buf);
    }
}

/* how it was made: the 2D-to-3D correction, the turbulence model, the
   band limit and the solver's grid and steps */
static void describe_solver(const aeolian_job *j, const direction *r,
                            aero_texture *tex)
{
    const double tunit = j->d / j->v0; /* s per d/v0 */
    const aero_span3d *c = &j->correction;
    aero_texture_set(tex, "span3d", c->applied ? "circle-calibrated"
                                    : urans(j) ? "urans" : "none");
    if (urans(j)) {
        aero_flow2d_params fp;
        aero_flow2d_defaults(&fp, j->re);
        aero_texture_set(tex, "turbulence", URANS_DESCRIPTION);
        aero_texture_setd(tex, "turbulence_intensity",
                          fp.turbulence_intensity);
        aero_texture_setd(tex, "turbulence_ratio", fp.turbulence_ratio);
        if (j->urans_from > 0.0)
            aero_texture_setd(tex, "urans_from", j->urans_from);
    }
    if (j->band_stop > 0.0) {
        aero_texture_set(tex, "band_limit", "grid: raised cosine from "
                         "v0/(16 h) to v0/(8 h), zero phase, over the loop");
        aero_texture_setd(tex, "band_limit_pass", j->band_pass);
        aero_texture_setd(tex, "band_limit_stop", j->band_stop);
    }
    aero_texture_setd(tex, "span3d_frequency_scale", c->frequency_scale);
    aero_texture_setd(tex, "span3d_force_scale", c->force_scale);
    if (c->applied) {
        aero_texture_setd(tex, "span3d_circle_st_2d", c->st_2d);
        aero_texture_setd(tex, "span3d_circle_cl_rms_2d", c->cl_rms_2d);
    }
    aero_texture_setd(tex, "cells", cells(j));
    aero_texture_setd(tex, "grid", j->grid);
    /* rows of 1/grid over the body and 2 d around it, then growing */
    aero_texture_setd(tex, "stretch", j->stretch);
    aero_texture_setd(tex, "settle", j->settle * tunit);
    aero_texture_setd(tex, "dt", r[0].st.dt * tunit);
    aero_texture_set(tex, "solver", "2D incompressible projection, MAC grid, "
                                    "immersed boundary");
}

/* the texture's metadata */
static void describe(const aeolian_job *j, const direction *r,
                     const char *desc, aero_texture *tex)
{
    describe_section(j, r, desc, tex);
    describe_flow(j, r, tex);
    describe_solver(j, r, tex);
}

/* what the texture measured, on stdout */
static void report(const aeolian_job *j, const direction *r, const char *desc,
                   int frames)
{
    const aero_flowstats *s0 = &r[0].st.flow;
    const aero_span3d *c = &j->correction;
    printf("%s: %s, Re %.4g, %d direction%s, %d frames (%.3f s at %g Hz)\n",
           j->job.out, desc, j->re, j->directions,
           j->directions > 1 ? "s" : "", frames, frames / j->job.rate,
           j->job.rate);
    if (urans(j)) {
        aero_flow2d_params fp;
        aero_flow2d_defaults(&fp, j->re);
        printf("  2D-to-3D (urans): %s, free stream Tu %g %%, nu_t/nu %g\n",
               URANS_DESCRIPTION, 100.0 * fp.turbulence_intensity,
               fp.turbulence_ratio);
        if (j->urans_from > 0.0)
            printf("  laminar below %g deg of incidence\n", j->urans_from);
    }
    if (j->band_stop > 0.0)
        printf("  band limit of the grid: %.0f Hz passed, %.0f Hz and above "
               "removed (v0 / 16 and v0 / 8 cells)\n", j->band_pass,
               j->band_stop);
    if (c->applied)
        printf("  2D-to-3D (circle-calibrated): the 2D circle at Re %.4g "
               "sheds at St %.4f with Cl rms %.3f; Roshko St %.4f, Norberg "
               "Cl' %.3f: frequencies x %.3f, force x %.3f\n", j->re,
               c->st_2d, c->cl_rms_2d, c->st_ref, c->cl_rms_ref,
               c->frequency_scale, c->force_scale);
    printf("  %.1f cells across the smallest dimension\n", cells(j));
    if (j->cavity && j->theta > 0.0)
        printf("  inflow boundary layer: momentum thickness %g m (L/theta "
               "%.1f), %.1f cells thick\n", j->theta, j->length / j->theta,
               j->theta * AERO_FLOW2D_DELTA_PER_THETA * j->grid / j->length);
    for (int k = 0; k < j->directions; k++)
        printf("  %6.2f deg: St %.4f (f = %.1f Hz; 2D %.4f, zero crossings "
               "%.4f)  Cd(2D) %.3f  Cl rms %.3f (2D %.3f)\n", r[k].alpha,
               r[k].st.st_peak * c->frequency_scale,
               r[k].st.st_peak * c->frequency_scale * j->v0 / j->d,
               r[k].st.st_peak, r[k].st.flow.st, r[k].st.flow.cd,
               r[k].st.flow.cl_rms * c->force_scale, r[k].st.flow.cl_rms);
    if (s0->st == 0.0 && !j->cavity && s0->cl_rms < 0.01)
        printf("  no vortex shedding at Re %.3g: the tone is silent\n", j->re);
    else if (s0->st == 0.0 && !j->cavity)
        printf("  the lift is too short or too irregular for a Strouhal "
               "number (st=0 in the metadata)\n");
    if (s0->st == 0.0 && j->cavity) {
        printf("  no self-sustained oscillation of the cavity flow: the "
               "texture holds only its weak broadband wall-pressure force ");
        if (j->theta > 0.0)
            printf("(the shear layer from an inflow layer at L/theta %.0f "
                   "does not oscillate at --grid %g: a thinner --theta, or a "
                   "finer grid near L/theta 60)\n", j->length / j->theta,
                   j->grid);
        else
            printf("(a --grid under 48 damps the shear layer)\n");
    }
    printf("  %.1f s\n", aerotex_now() - j->job.t_start);
}

/* --span3d urans: every channel of the loop (len frames) low-passed at
   the band the grid resolves (band_limit.h; the laminar directions too:
   the grid is the same); 0, or 1 with a message */
static int band_limit(aeolian_job *j, int len)
{
    const int ch = j->job.channels;
    j->band_pass = j->band_stop = 0.0;
    if (!urans(j) || j->band_limit != BAND_LIMIT_GRID)
        return 0;
    aero_band_limit_grid(j->v0, j->d / j->grid, &j->band_pass, &j->band_stop);
    for (int c = 0; c < ch; c++)
        if (aero_band_limit_apply(j->job.raw + c, len, ch, j->job.rate,
                                  j->band_pass, j->band_stop))
            return aerotex_job_fail(&j->job, "out of memory");
    return 0;
}

/* the looped texture, saved and reported: the exit status */
static int write_texture(aeolian_job *j, const direction *r, const char *desc)
{
    const int nd = j->directions, len = aerotex_job_loop(&j->job);
    aero_texture tex;
    int status;
    if (band_limit(j, len))
        return 1;
    if (aero_texture_init(&tex, len, nd, j->job.rate))
        return aerotex_job_fail(&j->job, "out of memory");
    aerotex_job_fill(&j->job, &tex, len);
    for (int k = 0; k < nd; k++)
        tex.angles[k] = r[k].alpha;
    describe(j, r, desc, &tex);
    if (j->blade) {
        aero_texture_setd(&tex, "blade_chord", j->blade_chord);
        aero_texture_setd(&tex, "blade_te_thickness", j->blade_te);
        aero_texture_setd(&tex, "blade_te_angle", j->blade_psi);
        /* the model's turbulent boundary layer: the laminar edge-on wake
           is the texture's own (textures/README.md, sword.wav) */
        aero_texture_set(&tex, "blade_boundary_layer", "tripped");
    }
    status = aerotex_job_save(&j->job, &tex);
    if (!status)
        report(j, r, desc, tex.frames);
    aero_texture_free(&tex);
    return status;
}

/* what the stages under aerotex_job_run share */
typedef struct {
    aeolian_job *j;
    const aero_shape2d *shape;
    const char *desc;
} aeolian_plan;

static int run_stage(void *plan, void *tasks)
{
    aeolian_plan *p = plan;
    sample_directions(p->j, tasks);
    return run_directions(p->j, p->shape, p->desc, tasks);
}

static int write_stage(void *plan, void *tasks)
{
    aeolian_plan *p = plan;
    return write_texture(p->j, tasks, p->desc);
}

int aerotex_section_run(const aerotex_command *cmd, int argc, char **argv)
{
    aeolian_job j;
    aero_shape2d shape;
    char desc[512];
    int status;
    if (aerotex_job_parse(cmd, &j, argc, argv))
        return 2;
    memset(&shape, 0, sizeof shape);
    status = make_shape(&j, &shape, desc, sizeof desc);
    if (!status && !j.cavity)
        j.blade = blade_geometry(&shape, &j.blade_chord, &j.blade_te,
                                 &j.blade_psi);
    if (!status)
        status = check_flow(&j, &shape);
    if (!status) {
        aeolian_plan plan = {&j, &shape, desc};
        /* one task more for the calibration circle of the 2D-to-3D
           correction (run_directions) */
        status = aerotex_job_run(&j.job, argc, argv, 3 * j.directions,
                                 j.directions + 1, sizeof(direction), &plan,
                                 run_stage, write_stage);
    }
    aero_shape2d_free(&shape);
    return status;
}
