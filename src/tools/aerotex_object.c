/* aerotex object: 3D object textures (Dobashi et al. 2003, the 3D case): the
 * sound source function of each region of a body, per sampled flow direction,
 * the directions simulated in parallel. The physics is in
 * src/core/solve/body_flow.c, the shapes in src/core/common/body_shape.c. */
#include "aerotex.h"
#include "aero_air.h"
#include "aero_util.h"
#include "body_flow.h"
#include "strip_body.h"
#include "strouhal.h"
#include "texture.h"
#ifdef AEROTEX_MPI
#include "flow3d_slab.h"
#endif

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_DIRECTIONS 91
#define PNG_ZOOM 3

enum { SHAPE_NONE = -1, SHAPE_SPHERE, SHAPE_CAPSULE, SHAPE_CLUB };
enum { METHOD_FLOW3D, METHOD_STRIP };
/* --calibrate: the published body whose St the time axis is scaled to */
enum { CAL_BY_BODY = -1, CAL_SPHERE, CAL_CYLINDER, CAL_NONE };

/* The subcritical sphere's large-scale wake sheds at St ~0.2, independent
   of Re over 800 < Re < 2e5 (Kim and Durbin 1988; Sakamoto and Haniu 1990,
   J. Fluids Eng. 112, 386-392); Achenbach (1974, J. Fluid Mech. 62,
   209-221) found strong periodic wake fluctuations from Re 6e3 to 3e5.
   A 3D flow this machine can afford does not reach it (textures/README.md),
   so the sphere's force history is kept and its time axis scaled. */
#define SPHERE_ST 0.2
#define SPHERE_RE_MIN 800.0
#define SPHERE_RE_MAX 3e5

typedef struct {
    aerotex_job job;
    int shape;            /* SHAPE_*, or a --mesh */
    const char *mesh;
    double radius, length, handle, tip; /* 0: the shape's default */
    int sources, directions, mirror;   /* 0, 0, -1: by the body */
    double speed, grid, settle, cfl, confinement;
    int limiter;
    int method;           /* METHOD_* */
    const char *section;  /* METHOD_STRIP: the section's texture */
    int calibrate;        /* CAL_* */
    uint32_t seed;
    int checkpoint;       /* steps between solver checkpoints (0: 1/16 of
                             a direction's) */
    int slabs;            /* aerotex-mpi: each direction's flow in z slabs
                             over all the ranks (flow3d_slab.h) */
} object_job;

/* one direction: the first member is its task */
typedef struct {
    aerotex_task task;
    const object_job *oj;
    float *slice, *solid;
    aero_body_flow_stats st;
} direction_task;

/* progress, and the vorticity slices of --png (the mid-plane y, which
   holds the body's axis and the flow) */
static void hook(void *ctx, const aero_flow3d *s, long step, int recording)
{
    direction_task *c = ctx;
    char path[4096];
    int j = s->ny / 2, w = s->nx * PNG_ZOOM, h = s->nz * PNG_ZOOM;
    float scale = (float)(c->oj->grid * s->p.h / c->oj->speed);
    (void)recording;
    aerotex_task_progress(&c->task, step);
    if (!aerotex_task_snapshot_due(&c->task, step))
        return;
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
    snprintf(path, sizeof path, "%s/dir%02d_%05ld.png", c->oj->job.png_dir,
             c->task.index, step);
    if (aerotex_png_vorticity(path, c->slice, c->solid, w, h, 8.0f))
        snprintf(c->task.err, sizeof c->task.err, "can't write %.200s", path);
}

#define AT(field) offsetof(object_job, field)
static const aerotex_option object_options[] = {
    {"--shape", AEROTEX_CHOICE, "sphere|capsule|club", SHAPE_NONE, 0, 0,
     AT(shape), "a body of revolution about z (or --mesh)", "", NULL},
    {"--mesh", AEROTEX_TEXT, "FILE", NAN, 0, 0, AT(mesh),
     "a closed triangle mesh (v/f lines, OBJ subset;\nsee "
     "textures/README.md), axis z", NULL, NULL},
    {"--radius", AEROTEX_NUMBER, "m", 0.0, 1e-4, 100.0, AT(radius),
     "sphere or capsule radius", "sphere 0.05, capsule 0.02", NULL},
    {"--length", AEROTEX_NUMBER, "m", 0.0, 1e-4, 100.0, AT(length),
     "capsule or club length", "capsule 0.3, club 0.8", NULL},
    {"--handle", AEROTEX_NUMBER, "m", 0.0, 1e-4, 100.0, AT(handle),
     "club radius at the handle", "0.0125", NULL},
    {"--tip", AEROTEX_NUMBER, "m", 0.0, 1e-4, 100.0, AT(tip),
     "club radius at the tip", "0.03", NULL},
    {"--sources", AEROTEX_WHOLE, "n", 0.0, 1.0, AERO_BODY_MAX_REGIONS,
     AT(sources), "regions: slices along the axis, sectors around\nthe "
     "flow for a sphere", "1; club 10", NULL},
    {"--directions", AEROTEX_WHOLE, "N", 0.0, 1.0, MAX_DIRECTIONS,
     AT(directions), "flow angles from the axis over 0..180 deg\n(0..90 "
     "with --mirror)", "1 for a sphere, 5 otherwise", NULL},
    {"--mirror", AEROTEX_SWITCH, NULL, -1.0, 1, 0, AT(mirror),
     "the body is symmetric under z -> -z", "yes for a capsule", NULL},
    {"--no-mirror", AEROTEX_SWITCH, NULL, NAN, 0, 0, AT(mirror), "it is not",
     NULL, NULL},
    {"--speed", AEROTEX_NUMBER, "m/s", 10.0, 0.01,
     AERO_MACH_LIMIT * AERO_C0, AT(speed), "base speed v0", NULL, NULL},
    {"--grid", AEROTEX_NUMBER, "cells", 10.0, 3.0, 64.0, AT(grid),
     "cells per reference size d", NULL, NULL},
    {"--duration", AEROTEX_NUMBER, "s", 0.5, 0.02, 10.0, AT(job.duration),
     "texture length", NULL, NULL},
    {"--rate", AEROTEX_NUMBER, "Hz", 4000.0, 500.0, 192000.0, AT(job.rate),
     "texture rate (the 3D steps resolve ~1 kHz)", NULL, NULL},
    {"--settle", AEROTEX_NUMBER, "d/v0", 25.0, 0.0, 1000.0, AT(settle),
     "start-up discarded", NULL, NULL},
    {"--cfl", AEROTEX_NUMBER, "c", 0.7, 0.05, 1.5, AT(cfl),
     "step = c h / v0", NULL, NULL},
    {"--confinement", AEROTEX_NUMBER, "eps", 1.5, 0.0, 50.0, AT(confinement),
     "vorticity confinement a = eps (h / d) v0 (N x omega)", NULL, NULL},
    {"--limiter", AEROTEX_CHOICE, "off|on", 1.0, 0, 0, AT(limiter),
     "clamp the MacCormack step to its neighbours:\noff damps a wake's "
     "vortices less (the sphere\ntexture), on suits bodies a few cells "
     "thick", NULL, NULL},
    {"--method", AEROTEX_CHOICE, "3d|strip", METHOD_FLOW3D, 0, 0, AT(method),
     "3d: a 3D flow past the body; strip: each region\nsheds as the section "
     "texture of its local\ndiameter (a slender body: club, capsule)", NULL,
     NULL},
    {"--section", AEROTEX_TEXT, "FILE", NAN, 0, 0, AT(section),
     "--method strip: a circle's aeolian texture\n(textures/cylinder.wav)",
     NULL, NULL},
    {"--calibrate", AEROTEX_CHOICE, "sphere|cylinder|none", CAL_BY_BODY, 0,
     0, AT(calibrate),
     "the published body whose St the simulated force's\ntime axis is "
     "scaled to (the force's shape, level\nand directivity kept): sphere: St 0.2 "
     "(Re 800-3e5;\nSakamoto and Haniu 1990), cylinder: Roshko's\nSt(Re) "
     "on d (a body broadside like a rod),\nnone: the flow's own St",
     "sphere for a sphere at Re 800-3e5, else none", NULL},
    {"--seed", AEROTEX_SEED, "n", 1.0, 0, 0, AT(seed),
     "start-up noise seed (strip: the regions' places)", NULL, NULL},
    {"--checkpoint", AEROTEX_WHOLE, "steps", 0.0, 0.0, 1e9, AT(checkpoint),
     "aerotex-mpi: each direction's flow kept in\nFILE.wav.ckpt every so "
     "many steps (0: 16 times\na direction), to resume a killed job from",
     NULL, NULL},
    {"--slabs", AEROTEX_SWITCH, NULL, 0.0, 1, 0, AT(slabs),
     "aerotex-mpi: each direction's flow split in\nz slabs over all the "
     "ranks (a grid larger\nthan one node)", NULL, NULL},
    AEROTEX_JOB_OPTIONS("directions",
                        "|vorticity| slices DIR/dirKK_STEP.png")};

/* the body: 0, or -1 with a message */
static int make_body(const object_job *j, aero_body_shape *b)
{
    char err[512];
    int r;
    if (j->mesh)
        r = aero_body_mesh_load(b, j->mesh, err, sizeof err);
    else if (j->shape == SHAPE_SPHERE)
        r = aero_body_sphere(b, j->radius > 0 ? j->radius : 0.05, err,
                             sizeof err);
    else if (j->shape == SHAPE_CAPSULE)
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

/* what the runs share, the body's defaults resolved */
typedef struct {
    object_job *j;
    aero_body_shape body;
    aero_body_flow_params base;
    char desc[256];
    double d, angles[MAX_DIRECTIONS];
    int nd, nr, ch, sphere;
    aero_texture section;       /* METHOD_STRIP */
    aero_strip_layout layout;   /* METHOD_STRIP */
    double st_ref;              /* --calibrate's St at the body's Re (0:
                                   none) */
    double scale;               /* frequencies times scale (1: none) */
    double rate;                /* the texture's rate after the scaling */
    double st_loop;             /* loop_st of the broadside direction, as
                                   simulated */
} object_plan;

/* --method strip: the section texture and the regions' diameters: 0, or 2
   with a message */
static int plan_strip(object_job *j, object_plan *o)
{
    char err[512];
    if (!j->section) {
        aerotex_error("object: --method strip needs --section FILE (a "
                      "circle's aeolian texture)");
        return 2;
    }
    if (aero_texture_load(j->section, &o->section, err, sizeof err)) {
        aerotex_error("%s: %s", j->section, err);
        return 2;
    }
    if (aero_strip_check_section(&o->section, err, sizeof err) ||
        aero_strip_layout_measure(&o->body, o->nr, &o->layout, err,
                                  sizeof err)) {
        aerotex_error("object: %s", err);
        return 2;
    }
    return 0;
}

/* --calibrate: the reference St at the body's Re: 0, or -1 with a message */
static int plan_calibration(object_job *j, object_plan *o)
{
    const double re = j->speed * o->d / AERO_NU;
    o->scale = 1.0;
    o->rate = j->job.rate;
    o->st_ref = 0.0;
    /* by default a sphere in the published range is calibrated (outside
       it, and for other bodies, the flow's own St is kept) */
    if (j->calibrate == CAL_BY_BODY)
        j->calibrate = o->sphere && j->method == METHOD_FLOW3D &&
                               re >= SPHERE_RE_MIN && re <= SPHERE_RE_MAX
                           ? CAL_SPHERE
                           : CAL_NONE;
    if (j->calibrate == CAL_NONE)
        return 0;
    if (j->method == METHOD_STRIP) {
        aerotex_error("object: --method strip takes its St from the section "
                      "(--calibrate none)");
        return -1;
    }
    if (j->calibrate == CAL_SPHERE &&
        !(re >= SPHERE_RE_MIN && re <= SPHERE_RE_MAX)) {
        aerotex_error("object: --calibrate sphere: the published St %g holds "
                      "for Re %g-%g, this body's is %.3g (--calibrate none)",
                      SPHERE_ST, SPHERE_RE_MIN, SPHERE_RE_MAX, re);
        return -1;
    }
    if (j->calibrate == CAL_CYLINDER && !(re > AERO_RE_ONSET)) {
        aerotex_error("object: --calibrate cylinder: Re %.3g is below the "
                      "shedding onset", re);
        return -1;
    }
    o->st_ref = j->calibrate == CAL_SPHERE ? SPHERE_ST : aero_strouhal(re);
    return 0;
}

/* St of the loop as it is heard: the power of the lateral g (y and z,
   every region) of direction k on the loop's own lines (a seamless loop
   repeats: its spectrum is lines rate/len apart), a moving average over
   0.06 in St (a broad band's peak needs it: single lines scatter by
   several dB), its largest line over St 0.05-1. 0 if none */
static double loop_st(const object_plan *o, int k, const float *data,
                      int len, double rate)
{
    const double df = rate / len, fmax = o->j->speed / o->d;
    const int lines = (int)(fmax / df), half = (int)(0.03 * fmax / df);
    double *pw, best = 0.0, st = 0.0;
    if (lines < 2 || !(pw = calloc((size_t)lines + 1, sizeof(double))))
        return 0.0;
    for (int m = 1; m <= lines; m++)
        for (int l = 0; l < o->nr; l++)
            for (int c = 1; c < 3; c++) {
                const float *x = data + 3 * ((size_t)k * o->nr + l) + c;
                double re = 0.0, im = 0.0;
                for (int n = 0; n < len; n++) {
                    const double ph = 2.0 * AERO_PI * m * n / len;
                    re += x[(size_t)n * o->ch] * cos(ph);
                    im += x[(size_t)n * o->ch] * sin(ph);
                }
                pw[m] += re * re + im * im;
            }
    for (int m = 1; m <= lines; m++) {
        double sum = 0.0;
        int cnt = 0;
        if (m * df < 0.05 * fmax)
            continue;
        for (int i = m - half; i <= m + half; i++)
            if (i >= 1 && i <= lines) {
                sum += pw[i];
                cnt++;
            }
        if (cnt && sum / cnt > best) {
            best = sum / cnt;
            st = m * df / fmax;
        }
    }
    free(pw);
    return st;
}

/* the time axis scaled to the reference St: the samples are kept and the
   rate raised (a whole number of Hz, as a WAV holds it), so the loop stays
   seamless; g = dF/dt of the same force history grows by the same factor.
   The direction nearest broadside, which stands for the object, sets it */
static void apply_calibration(object_plan *o, double st_sim, float *data,
                              size_t n)
{
    const double rate0 = o->j->job.rate;
    if (!(o->st_ref > 0.0) || !(st_sim > 0.0))
        return;
    o->rate = floor(rate0 * o->st_ref / st_sim + 0.5);
    if (o->rate < 1.0)
        o->rate = 1.0;
    o->scale = o->rate / rate0;
    for (size_t k = 0; k < n; k++)
        data[k] = (float)(data[k] * o->scale);
}

/* the body, its directions and regions, the flow: 0, or 2 with a message */
static int plan_object(object_job *j, object_plan *o)
{
    if ((j->shape == SHAPE_NONE) == !j->mesh) {
        aerotex_error("object: give either --shape sphere|capsule|club or "
                      "--mesh FILE");
        return 2;
    }
    if (make_body(j, &o->body))
        return 2;
    o->j = j;
    o->sphere = o->body.kind == AERO_BODY_SPHERE;
    if (j->mirror < 0)
        j->mirror = o->body.kind == AERO_BODY_CAPSULE;
    if (o->sphere && j->directions > 1) {
        aerotex_error("object: a sphere looks the same from every direction: "
                      "--directions 1");
        return 2;
    }
    o->nd = j->directions ? j->directions : o->sphere ? 1 : 5;
    o->nr = j->sources ? j->sources : o->body.kind == AERO_BODY_CLUB ? 10 : 1;
    if ((long)o->nd * o->nr > AERO_TEXTURE_MAX_SOURCES) {
        aerotex_error("object: %d directions x %d regions: at most %d "
                      "together", o->nd, o->nr, AERO_TEXTURE_MAX_SOURCES);
        return 2;
    }
    o->ch = 3 * o->nd * o->nr;
    for (int k = 0; k < o->nd; k++)
        o->angles[k] = o->nd == 1 ? 90.0
                                  : (j->mirror ? 90.0 : 180.0) * k /
                                        (o->nd - 1);
    o->d = aero_body_reference_size(&o->body);
    aero_body_flow_defaults(&o->base, &o->body);
    o->base.speed = j->speed;
    o->base.cell = o->d / j->grid;
    o->base.regions = o->nr;
    o->base.cfl = j->cfl;
    o->base.confinement = j->confinement;
    o->base.limiter = j->limiter;
    o->base.settle = j->settle * o->d / j->speed;
    aero_body_describe(&o->body, o->desc, sizeof o->desc);
    if (plan_calibration(j, o))
        return 2;
    return j->method == METHOD_STRIP ? plan_strip(j, o) : 0;
}

/* --method strip: every direction from the section (strip_body.h) */
static int run_strip(object_plan *o, direction_task *ctx)
{
    object_job *j = o->j;
    const double cd = aero_texture_getd(&o->section, "cd", 0.0);
    for (int k = 0; k < o->nd; k++) {
        aero_body_flow_stats *st = &ctx[k].st;
        aero_strip_stats ss;
        const double sn = sin(o->angles[k] * AERO_PI / 180.0);
        aero_strip_render(&o->section, &o->layout, o->angles[k], j->speed,
                          j->job.rate, j->seed + 7919u * (unsigned)k,
                          j->job.raw + 3 * (size_t)k * o->nr, o->ch,
                          j->job.loop.avail, &ss);
        for (int l = 0; l < o->nr; l++)
            st->centre[3 * l + 2] = o->layout.z[l];
        st->f_peak = ss.f_peak;
        st->st = ss.f_peak * o->d / j->speed;
        st->cl_rms = ss.cl_rms;
        /* the section's mean drag on the cross-flow (none along the axis) */
        st->cd = sn * sn > 1e-12 ? cd * sn * sn : 0.0;
    }
    return 0;
}

#ifdef AEROTEX_MPI
/* --slabs: every direction in turn, each flow over all the ranks in z
   slabs (flow3d_slab.h); the forces are summed over the ranks, so each
   rank holds every direction's result and rank 0 writes it: 0 or 1 */
static int run_slabs(object_plan *o, direction_task *ctx)
{
    object_job *j = o->j;
    const int nd = o->nd, avail = j->job.loop.avail;
    int status = 0;
    aerotex_progress_start(&j->job.prog, NULL,
                           (long)nd * aero_body_flow_steps(&o->base,
                                                           j->job.rate, avail),
                           j->job.quiet || aerotex_farm_rank());
    for (int k = 0; k < nd; k++) {
        aero_body_flow_params p = o->base;
        direction_task *c = &ctx[k];
        /* a direction kept by an earlier run of the job: rank 0 has it */
        int done = !aerotex_farm_rank() &&
                   aerotex_farm_resume(&j->job, k, c, sizeof *c, 3 * o->nr);
        aerotex_farm_share(&done, sizeof done);
        if (done)
            continue;
        p.angle = o->angles[k];
        p.threads = j->job.threads;
        p.checkpoint_every =
            j->checkpoint > 0
                ? j->checkpoint
                : aero_body_flow_steps(&p, j->job.rate, avail) / 16 + 1;
        p.checkpoint_save = aerotex_farm_save_slab_state;
        p.checkpoint_load = aerotex_farm_load_slab_state;
        p.seed = aero_run_seed(j->seed, k);
        p.plan_lock = aerotex_plan_lock;
        p.window_open = aero_flow3d_slabs_open;
        p.window_close = aero_flow3d_slabs_close;
        c->task.job = &j->job;
        c->task.index = k;
        c->oj = j;
        /* rank 0 draws its own slab */
        c->task.snap_every =
            aerotex_farm_rank()
                ? LONG_MAX / 2
                : aero_body_flow_steps(&p, j->job.rate, avail) / 24 + 1;
        aero_body_flow_simulate(&p, j->job.rate,
                                j->job.raw + 3 * (size_t)k * o->nr, o->ch,
                                avail, &c->st, hook, 16, c, c->task.err,
                                sizeof c->task.err);
        free(c->slice);
        free(c->solid);
        c->slice = c->solid = NULL;
        if (!aerotex_farm_rank())
            aerotex_farm_keep(&j->job, k, c, sizeof *c, 3 * o->nr);
        aerotex_farm_drop_slab_state(&j->job, k);
    }
    aerotex_progress_end(&j->job.prog);
    if (aerotex_farm_rank())
        return 0;
    for (int k = 0; k < nd; k++)
        if (ctx[k].task.err[0]) {
            aerotex_error("direction %g deg: %s", o->angles[k],
                          ctx[k].task.err);
            status = 1;
        }
    return status;
}
#endif

/* every direction in parallel into the job's raw: 0 or 1 */
static int run_directions(void *plan, void *tasks)
{
    object_plan *o = plan;
    direction_task *ctx = tasks;
    object_job *j = o->j;
    if (j->method == METHOD_STRIP)
        return run_strip(o, ctx);
    const int nd = o->nd, avail = j->job.loop.avail;
#ifdef AEROTEX_MPI
    if (j->slabs)
        return run_slabs(o, ctx);
#endif
    /* the directions in parallel; threads left over (fewer directions
       than threads: a sphere) go inside each simulation */
    const int threads = aerotex_job_threads(&j->job,
                                            aerotex_farm_count(nd) > 0
                                                ? aerotex_farm_count(nd)
                                                : 1);
    const int inner = j->job.threads / threads > 1 ? j->job.threads / threads
                                                   : 1;
    int status = 0;
    aerotex_progress_start(&j->job.prog, NULL,
                           (long)aerotex_farm_count(nd) *
                               aero_body_flow_steps(&o->base,
                                                           j->job.rate, avail),
                           j->job.quiet);
    if (!j->job.quiet)
        fprintf(stderr, "aerotex: object %s, d %g m, v0 %g m/s (Re %.3g), "
                "%d direction%s, %d region%s, %g cells per d, %ld steps, %d "
                "thread%s\n", o->desc, o->d, j->speed,
                j->speed * o->d / AERO_NU, nd, nd > 1 ? "s" : "", o->nr,
                o->nr > 1 ? "s" : "", j->grid, j->job.prog.total, threads * inner,
                threads * inner > 1 ? "s" : "");
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int k = 0; k < nd; k++) {
        if (!aerotex_farm_mine(k) ||
            aerotex_farm_resume(&j->job, k, &ctx[k], sizeof *ctx,
                                3 * o->nr))
            continue;
        aero_body_flow_params p = o->base;
        direction_task *c = &ctx[k];
        p.angle = o->angles[k];
        p.threads = inner;
        p.seed = aero_run_seed(j->seed, k);
        p.plan_lock = aerotex_plan_lock;
        p.checkpoint_every =
            j->checkpoint > 0
                ? j->checkpoint
                : aero_body_flow_steps(&p, j->job.rate, avail) / 16 + 1;
#ifdef AEROTEX_MPI
        p.checkpoint_save = aerotex_farm_save_state;
        p.checkpoint_load = aerotex_farm_load_state;
#endif
        c->task.job = &j->job;
        c->task.index = k;
        c->oj = j;
        c->task.snap_every =
            aero_body_flow_steps(&p, j->job.rate, avail) / 24 + 1;
        aero_body_flow_simulate(&p, j->job.rate,
                                j->job.raw + 3 * (size_t)k * o->nr, o->ch,
                                avail, &c->st, hook, 16, c, c->task.err,
                                sizeof c->task.err);
        free(c->slice);
        free(c->solid);
        c->slice = c->solid = NULL;
        aerotex_farm_keep(&j->job, k, c, sizeof *c, 3 * o->nr);
    }
    aerotex_progress_end(&j->job.prog);
    if (aerotex_farm_gather(&j->job, ctx, nd, sizeof *ctx, 3 * o->nr))
        return 1;
    if (aerotex_farm_rank())
        return 0;
    for (int k = 0; k < nd; k++)
        if (ctx[k].task.err[0]) {
            aerotex_error("direction %g deg: %s", o->angles[k],
                          ctx[k].task.err);
            status = 1;
        }
    return status;
}

/* the statistic at offset `at` of every direction's stats, times factor,
   joined */
static void join_stat(char *buf, size_t len, const direction_task *ctx,
                      int n, size_t at, double factor)
{
    double list[MAX_DIRECTIONS];
    for (int k = 0; k < n; k++)
        list[k] = factor * *(const double *)((const char *)&ctx[k].st + at);
    aerotex_join(buf, len, list, n, "%.4g");
}

/* the direction nearest broadside, which stands for the object */
static int broadside(const object_plan *o)
{
    int kb = 0;
    for (int k = 1; k < o->nd; k++)
        if (fabs(o->angles[k] - 90.0) < fabs(o->angles[kb] - 90.0))
            kb = k;
    return kb;
}

static const char *const calibration_names[] = {"sphere", "cylinder",
                                                "none"};

/* what --calibrate did, in the metadata (textures/README.md) */
static void describe_calibration(const object_plan *o,
                                 const direction_task *ctx, int kb,
                                 aero_texture *tex)
{
    const object_job *j = o->j;
    char buf[16384];
    aero_texture_set(tex, "calibration", calibration_names[j->calibrate]);
    if (j->calibrate == CAL_NONE)
        return;
    aero_texture_setd(tex, "calibration_st", o->st_ref);
    aero_texture_set(tex, "calibration_source",
                     j->calibrate == CAL_SPHERE
                         ? "sphere, subcritical: St 0.2 of the large-scale "
                           "wake, Re 800-2e5 (Kim and Durbin 1988; Sakamoto "
                           "and Haniu 1990, J. Fluids Eng. 112); periodic "
                           "Re 6e3-3e5 (Achenbach 1974, J. Fluid Mech. 62)"
                         : "circular cylinder St(Re) (Roshko 1954; "
                           "Williamson 1996) on the reference size");
    aero_texture_setd(tex, "frequency_scale", o->scale);
    aero_texture_setd(tex, "rate_sim", j->job.rate);
    aero_texture_setd(tex, "st_sim", o->st_loop);
    aero_texture_setd(tex, "st_sim_welch", ctx[kb].st.st);
    join_stat(buf, sizeof buf, ctx, o->nd, offsetof(aero_body_flow_stats, st),
              1.0);
    aero_texture_set(tex, "st_sim_list", buf);
}

/* what it matches, for aerotex info (aerotex_matches.c): quantity, the
   texture's value, the published one, source, test, calibrated or
   independent */
static void describe_matches(const object_plan *o,
                             const aero_body_flow_stats *stb,
                             aero_texture *tex)
{
    const object_job *j = o->j;
    char buf[1024];
    int n = 0;
    if (j->method != METHOD_FLOW3D)
        return; /* strip theory: aerotex info derives its rows */
    if (j->calibrate != CAL_NONE) {
        snprintf(buf, sizeof buf, "St of the lateral force, as heard|%.3f "
                 "(the flow's %.3f, time x %.3f)|%.3f|%s|%s|calibrated",
                 o->st_loop * o->scale, o->st_loop, 1.0 / o->scale,
                 o->st_ref, j->calibrate == CAL_SPHERE
                     ? "Sakamoto and Haniu 1990; Kim and Durbin 1988"
                     : "Roshko 1954 (cylinder St(Re))",
                 o->sphere && j->calibrate == CAL_SPHERE
                     ? "46-sphere-pitch.sh (whirled in Pd, +-5 %)"
                     : "(no test for this body)");
        aero_texture_set(tex, "match1", buf);
        n = 1;
    }
    snprintf(buf, sizeof buf, "mean Cd|%.2f|%s|%s|%s|independent", stb->cd,
             o->sphere ? "0.4-0.55 (subcritical)" : "(none for this body)",
             o->sphere ? "Achenbach 1972" : "-",
             o->sphere ? "45-body.sh 1b" : "-");
    {
        char key[16];
        snprintf(key, sizeof key, "match%d", ++n);
        aero_texture_set(tex, key, buf);
        if (o->sphere) {
            snprintf(key, sizeof key, "match%d", ++n);
            aero_texture_set(tex, key, "level against speed|U^3|+18.06 dB "
                             "per doubling|Curle 1955|45-body.sh 1|"
                             "independent");
            snprintf(key, sizeof key, "match%d", ++n);
            aero_texture_set(tex, key, "whirled: coming over going|"
                             "(c0 + v k)/(c0 - v k)|the Doppler shift|"
                             "Doppler|46-sphere-pitch.sh; 45-body.sh 2b|"
                             "independent");
        }
    }
}

/* the texture's metadata */
/* the body, the air and the sampled directions and regions */
static void describe_body(const object_plan *o, const direction_task *ctx,
                          aero_texture *tex)
{
    const object_job *j = o->j;
    const aero_body_flow_stats *st0 = &ctx[0].st;
    char buf[16384], shape[300];
    size_t used = 0;
    aero_texture_set(tex, "kind", "object");
    snprintf(shape, sizeof shape, "%s", o->desc);
    if (j->mesh)
        snprintf(shape, sizeof shape, "mesh %s", j->mesh);
    aero_texture_set(tex, "shape", shape);
    aero_texture_set(tex, "symmetry", o->sphere ? "sphere" : "axis");
    aero_texture_setd(tex, "mirror", j->mirror);
    aero_texture_setd(tex, "diameter", o->d);
    aero_texture_setd(tex, "v0", j->speed);
    aero_texture_setd(tex, "rho", AERO_RHO);
    aero_texture_setd(tex, "nu", AERO_NU);
    aero_texture_setd(tex, "c0", AERO_C0);
    aero_texture_setd(tex, "re", j->speed * o->d / AERO_NU);
    aero_texture_setd(tex, "directions", o->nd);
    aero_texture_setd(tex, "regions", o->nr);
    aerotex_join(buf, sizeof buf, o->angles, o->nd, "%.6g");
    aero_texture_set(tex, "angles", buf);
    buf[0] = 0;
    for (int l = 0; l < o->nr && used < sizeof buf; l++)
        used += (size_t)snprintf(buf + used, sizeof buf - used,
                                 "%s%.6g,%.6g,%.6g", l ? ";" : "",
                                 st0->centre[3 * l], st0->centre[3 * l + 1],
                                 st0->centre[3 * l + 2]);
    aero_texture_set(tex, "centres", buf);
}

/* the broadside direction's St, f, Cd and C_L', and every direction's */
static void describe_forces(const object_plan *o, const direction_task *ctx,
                            const aero_body_flow_stats *stb,
                            aero_texture *tex)
{
    const object_job *j = o->j;
    char buf[16384];
    /* st, f as the texture holds them: after --calibrate the loop's
       heard St (loop_st) times the scale; else the flow's own estimate */
    aero_texture_setd(tex, "st", o->scale != 1.0 ? o->st_loop * o->scale
                                                 : stb->st);
    aero_texture_setd(tex, "f", (o->scale != 1.0 ? o->st_loop * o->scale
                                                 : stb->st) *
                                    j->speed / o->d);
    aero_texture_setd(tex, "cd", stb->cd);
    aero_texture_setd(tex, "cl_rms", stb->cl_rms);
    join_stat(buf, sizeof buf, ctx, o->nd, offsetof(aero_body_flow_stats, st),
              o->scale);
    aero_texture_set(tex, "st_list", buf);
    join_stat(buf, sizeof buf, ctx, o->nd, offsetof(aero_body_flow_stats, cd),
              1.0);
    aero_texture_set(tex, "cd_list", buf);
    join_stat(buf, sizeof buf, ctx, o->nd,
              offsetof(aero_body_flow_stats, cl_rms), 1.0);
    aero_texture_set(tex, "cl_rms_list", buf);
}

/* how the forces were made: strip theory over a section texture, or the
   3D flow */
static void describe_method(const object_plan *o, const direction_task *ctx,
                            aero_texture *tex)
{
    const object_job *j = o->j;
    char buf[16384];
    size_t used = 0;
    if (j->method == METHOD_STRIP) {
        aero_texture_set(tex, "method", "strip");
        aero_texture_set(tex, "section", j->section);
        aero_texture_setd(tex, "grid",
                          aero_texture_getd(&o->section, "grid", 0.0));
        buf[0] = 0;
        for (int l = 0; l < o->nr && used < sizeof buf; l++)
            used += (size_t)snprintf(buf + used, sizeof buf - used, "%s%.4g",
                                     l ? "," : "", o->layout.diameter[l]);
        aero_texture_set(tex, "diameters", buf);
        aero_texture_set(tex, "solver", "strip theory (strip_body.h): each "
                         "region plays the section texture's 2D flow at "
                         "its local diameter's St and C_L' (Roshko 1954, "
                         "Norberg 2003) and the cross-flow speed");
        return;
    }
    aero_texture_set(tex, "method", "3d");
    aero_texture_setd(tex, "grid", j->grid);
    aero_texture_setd(tex, "cell", o->base.cell);
    aero_texture_setd(tex, "settle", o->base.settle);
    aero_texture_setd(tex, "dt", ctx[0].st.dt);
    snprintf(buf, sizeof buf, "3D incompressible, MAC grid, %sMacCormack "
             "advection, FFTW + tridiagonal projection, immersed body by "
             "direct forcing (force = removed momentum)",
             j->limiter ? "limited " : "");
    aero_texture_set(tex, "solver", buf);
}

static void describe(const object_plan *o, const direction_task *ctx,
                     aero_texture *tex)
{
    const int kb = broadside(o);
    describe_body(o, ctx, tex);
    aerotex_job_loop_meta(&o->j->job, tex);
    aero_texture_setd(tex, "rate", o->rate);
    aero_texture_set(tex, "frame", "sample frame: the flow arrives along "
                     "(sin a, 0, cos a) of the body axes, a = angles[k]");
    aero_texture_set(tex, "units", "N/s");
    describe_forces(o, ctx, &ctx[kb].st, tex);
    describe_calibration(o, ctx, kb, tex);
    describe_matches(o, &ctx[kb].st, tex);
    describe_method(o, ctx, tex);
}

/* the looped texture, saved and reported: the exit status */
static int write_texture(void *plan, void *tasks)
{
    object_plan *o = plan;
    const direction_task *ctx = tasks;
    object_job *j = o->j;
    const int len = aerotex_job_loop(&j->job), nd = o->nd;
    aero_texture tex;
    int status;
    if (aero_texture_init_regions(&tex, len, nd, o->nr, j->job.rate))
        return aerotex_job_fail(&j->job, "out of memory");
    aerotex_job_fill(&j->job, &tex, len);
    o->st_loop = j->method == METHOD_FLOW3D
                     ? loop_st(o, broadside(o), tex.data, len, j->job.rate)
                     : 0.0;
    apply_calibration(o, o->st_loop, tex.data, (size_t)len * o->ch);
    tex.rate = o->rate;
    memcpy(tex.angles, o->angles, sizeof(double) * nd);
    describe(o, ctx, &tex);
    status = aerotex_job_save(&j->job, &tex);
    if (!status) {
        printf("%s: object %s, d %g m, %d direction%s x %d region%s, %d "
               "frames (%.3f s at %g Hz)\n", j->job.out, o->desc, o->d, nd,
               nd > 1 ? "s" : "", o->nr, o->nr > 1 ? "s" : "", len,
               len / o->rate, o->rate);
        if (o->scale != 1.0 && j->job.rate / len * o->d / j->speed > 0.02)
            fprintf(stderr, "aerotex: the loop's lines lie %.3f apart in St: "
                    "its St is coarse (a longer --duration)\n",
                    j->job.rate / len * o->d / j->speed);
        if (o->scale != 1.0)
            printf("  --calibrate %s: St %.3f -> %.3f (the loop's lateral "
                   "force; time axis x %.4f, rate %g Hz)\n",
                   calibration_names[j->calibrate], o->st_loop,
                   o->st_loop * o->scale, 1.0 / o->scale, o->rate);
        for (int k = 0; k < nd && j->method == METHOD_STRIP; k++)
            printf("  %5.1f deg: strip theory, St %.3f (f %.1f Hz), Cl rms "
                   "%.3f\n", o->angles[k], ctx[k].st.st, ctx[k].st.f_peak,
                   ctx[k].st.cl_rms);
        for (int k = 0; k < nd && j->method == METHOD_FLOW3D; k++) {
            const aero_body_flow_stats *s = &ctx[k].st;
            printf("  %5.1f deg: grid %d x %d x %d, %ld steps of %.3g ms, "
                   "St %.3f (f %.1f Hz), Cd %.2f, Cl rms %.3f, max |div u| h "
                   "%.2g m/s\n", o->angles[k], s->nx, s->ny, s->nz, s->steps,
                   1e3 * s->dt, s->st, s->f_peak, s->cd, s->cl_rms,
                   s->max_div);
        }
        printf("  %.1f s\n", aerotex_now() - j->job.t_start);
    }
    aero_texture_free(&tex);
    return status;
}

static int object_run(int argc, char **argv)
{
    object_job j;
    object_plan o;
    int status;
    if (aerotex_job_parse(&aerotex_object_command, &j, argc, argv))
        return 2;
    memset(&o, 0, sizeof o);
    status = plan_object(&j, &o);
    if (!status)
        status = aerotex_job_run(&j.job, argc, argv, o.ch, o.nd,
                                 sizeof(direction_task), &o, run_directions,
                                 write_texture);
    aero_body_shape_free(&o.body);
    if (o.section.data)
        aero_texture_free(&o.section);
    return status;
}

const aerotex_command aerotex_object_command = {
    "object", "--shape <sphere|capsule|club> | --mesh FILE -o FILE.wav",
    "3D object texture (Dobashi et al. 2003, 3D case): 3D incompressible\n"
    "flow past a body (immersed boundary), the force on each of n regions,\n"
    "g_l = dF_l/dt per sampled direction; played by [body~]",
    object_options, sizeof(object_job), NULL, object_run};
