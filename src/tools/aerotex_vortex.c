/* aerotex vortex: vortex-sound textures Q(u, t) of a turbulent box of air
 * (Dobashi et al. 2004), one channel per average flow speed, the speeds
 * simulated in parallel. The physics is in src/core/solve/vortex_sound.c. */
#include "aerotex.h"
#include "aero_air.h"
#include "aero_util.h"
#include "texture.h"
#include "bandwidth_extension.h"
#include "vortex_sound.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SPEEDS 64
#define PNG_ZOOM 4
#define DEFAULT_SPEEDS "1,2,3,4,6,8,12,16"

typedef struct {
    aerotex_job job;
    aero_vortex_params vp;
    double speeds[MAX_SPEEDS];
    int nspeeds;
    double extend;        /* f_top of the bandwidth extension, Hz (0: off) */
    double ext_from[MAX_SPEEDS];    /* where each speed's extension starts */
    aero_bandext_info ext[MAX_SPEEDS];
} vortex_job;

/* one speed: the first member is its task */
typedef struct {
    aerotex_task task;
    const vortex_job *vj;
    float *slice, *zero;  /* --png: |vorticity| of the mid-plane, no body */
    aero_vortex_stats st;
} speed_task;

/* progress, and the vorticity slices of --png */
static void hook(void *ctx, const aero_flow3d *s, long step, int recording)
{
    speed_task *c = ctx;
    char path[4096];
    int j = s->ny / 2;
    /* the vertical mid-plane y = box/2: |omega| in units of U/box */
    float scale = (float)(c->vj->vp.box / c->vj->speeds[c->task.index]);
    (void)recording;
    aerotex_task_progress(&c->task, step);
    if (!c->slice || !aerotex_task_snapshot_due(&c->task, step))
        return;
    /* PNG_ZOOM x PNG_ZOOM pixels per cell, so a 32-cell box is visible */
    for (int k = 0; k < s->nz * PNG_ZOOM; k++)
        for (int i = 0; i < s->nx * PNG_ZOOM; i++)
            c->slice[(size_t)k * s->nx * PNG_ZOOM + i] =
                s->omag[AERO_F3_C(s, i / PNG_ZOOM, j, k / PNG_ZOOM)] * scale;
    snprintf(path, sizeof path, "%s/u%02d_%04ld.png", c->vj->job.png_dir,
             c->task.index, step);
    if (aerotex_png_vorticity(path, c->slice, c->zero, s->nx * PNG_ZOOM,
                              s->nz * PNG_ZOOM, 60.0f))
        snprintf(c->task.err, sizeof c->task.err, "can't write %.200s", path);
}

/* a comma-separated list of increasing speeds: 0 or -1 with a message */
static int read_speeds(vortex_job *j, const char *cmd, const char *list)
{
    const char *p = list;
    j->nspeeds = 0;
    while (*p) {
        char *end;
        double u = strtod(p, &end);
        if (end == p || !isfinite(u) || !(u > 0.0)) {
            aerotex_error("%s: --speeds: '%s' is not a list of positive "
                          "speeds", cmd, list);
            return -1;
        }
        if (j->nspeeds && !(u > j->speeds[j->nspeeds - 1])) {
            aerotex_error("%s: --speeds must increase (%g after %g)", cmd, u,
                          j->speeds[j->nspeeds - 1]);
            return -1;
        }
        if (u / AERO_C0 > AERO_MACH_LIMIT) {
            aerotex_error("%s: --speeds: %g m/s is above Mach %g: the "
                          "incompressible model does not hold", cmd, u,
                          AERO_MACH_LIMIT);
            return -1;
        }
        if (j->nspeeds == MAX_SPEEDS) {
            aerotex_error("%s: --speeds: at most %d speeds", cmd, MAX_SPEEDS);
            return -1;
        }
        j->speeds[j->nspeeds++] = u;
        p = end;
        if (*p == ',') p++;
        else if (*p) {
            aerotex_error("%s: --speeds: '%s' is not a comma-separated list",
                          cmd, list);
            return -1;
        }
    }
    return j->nspeeds ? 0 : -1;
}

static int parse_speeds(void *job, const char *cmd, int argc, char **argv,
                        int *i)
{
    if (*i + 1 >= argc) {
        aerotex_error("%s: --speeds needs a list, e.g. 1,2,4,8", cmd);
        return -1;
    }
    return read_speeds(job, cmd, argv[++*i]);
}

#define AT(field) offsetof(vortex_job, field)
static const aerotex_option vortex_options[] = {
    {"--speeds", AEROTEX_CUSTOM, "u1,...,uN", NAN, 0, 0, 0,
     "increasing average speeds, m/s", DEFAULT_SPEEDS, parse_speeds},
    {"--box", AEROTEX_NUMBER, "m", NAN, 1e-3, 10.0, AT(vp.box),
     "box width, the source volume's size", NULL, NULL},
    {"--grid", AEROTEX_WHOLE, "n", NAN, 4.0, 256.0, AT(vp.n),
     "cells across the box, even", NULL, NULL},
    {"--height", AEROTEX_WHOLE, "n", NAN, 4.0, 256.0, AT(vp.nz),
     "cells along the flow", "1.5 grid", NULL},
    {"--duration", AEROTEX_NUMBER, "s", 0.5, 0.01, 10.0, AT(job.duration),
     "texture length", NULL, NULL},
    {"--rate", AEROTEX_NUMBER, "Hz", 16000.0, 1000.0, 192000.0, AT(job.rate),
     "texture sample rate", NULL, NULL},
    {"--turbulence", AEROTEX_NUMBER, "i", NAN, 0.0, 2.0, AT(vp.turbulence),
     "rms inflow perturbation / u", NULL, NULL},
    {"--extend", AEROTEX_NUMBER, "Hz", 0.0, 0.0, 96000.0, AT(extend),
     "spectral bandwidth extension (Chadwick &\nJames 2011) from the "
     "resolved band up to\nthis (1.1 x it below rate / 2; 0: off)", NULL,
     NULL},
    {"--confinement", AEROTEX_NUMBER, "eps", NAN, 0.0, 200.0,
     AT(vp.confinement), "vorticity confinement eps h / box", NULL, NULL},
    {"--cfl", AEROTEX_NUMBER, "c", NAN, 0.05, 2.0, AT(vp.cfl),
     "step = c h / u", NULL, NULL},
    {"--settle", AEROTEX_NUMBER, "n", NAN, 0.0, 100.0, AT(vp.settle),
     "start-up discarded, flow-through times", NULL, NULL},
    {"--receivers", AEROTEX_WHOLE, "n", NAN, 1.0, 64.0, AT(vp.receivers),
     "virtual receivers on a ring", NULL, NULL},
    {"--elevation", AEROTEX_NUMBER, "deg", NAN, -90.0, 90.0,
     AT(vp.elevation), "of the ring", NULL, NULL},
    {"--source", AEROTEX_CHOICE, "window|cells", NAN, 0, 0, AT(vp.source),
     "Howe integral with a smooth window or the\npaper's integral cells "
     "(eq. 3-4)", NULL, NULL},
    {"--seed", AEROTEX_SEED, "n", NAN, 0, 0, AT(vp.seed), "turbulence seed",
     NULL, NULL},
    AEROTEX_JOB_OPTIONS("speeds", "|vorticity| slices DIR/uKK_STEP.png")};

static void vortex_init(void *job)
{
    vortex_job *j = job;
    aero_vortex_defaults(&j->vp);
    j->vp.nz = -1;
    read_speeds(j, "vortex", DEFAULT_SPEEDS);
}

/* every speed in parallel into the job's raw (one channel each): 0 or 1 */
static int run_speeds(void *job, void *tasks)
{
    vortex_job *j = job;
    speed_task *ctx = tasks;
    const int ns = j->nspeeds, avail = j->job.loop.avail;
    const int threads = aerotex_job_threads(&j->job,
                                            aerotex_farm_count(ns) > 0
                                                ? aerotex_farm_count(ns)
                                                : 1);
    long total = 0;
    int status = 0;
    for (int k = 0; k < ns; k++) {
        aero_vortex_params p = j->vp;
        p.speed = j->speeds[k];
        if (aerotex_farm_mine(k))
            total += aero_vortex_steps(&p, j->job.rate, avail);
    }
    aerotex_progress_start(&j->job.prog, NULL, total, j->job.quiet);
    if (!j->job.quiet)
        fprintf(stderr, "aerotex: vortex box %g m, grid %d x %d x %d, %d "
                "speed%s (%g..%g m/s), %.3g s, %ld steps, %d thread%s\n",
                j->vp.box, j->vp.n, j->vp.n, j->vp.nz, ns, ns > 1 ? "s" : "",
                j->speeds[0], j->speeds[ns - 1], j->job.duration, total,
                threads, threads > 1 ? "s" : "");
#pragma omp parallel for schedule(dynamic, 1) num_threads(j->job.threads)
    for (int q = 0; q < ns; q++) {
        /* the fastest speeds take the most steps: start them first */
        int k = ns - 1 - q;
        if (!aerotex_farm_mine(k) ||
            aerotex_farm_resume(&j->job, k, &ctx[k], sizeof *ctx, 1))
            continue;
        aero_vortex_params p = j->vp;
        speed_task *c = &ctx[k];
        long steps;
        p.speed = j->speeds[k];
        /* independent turbulence per speed */
        p.seed = aero_run_seed(j->vp.seed, k);
        p.plan_lock = aerotex_plan_lock;
        c->task.job = &j->job;
        c->task.index = k;
        c->vj = j;
        steps = aero_vortex_steps(&p, j->job.rate, avail);
        c->task.snap_every = steps / 24 + 1;
        if (j->job.png_dir) {
            size_t pixels = (size_t)p.n * p.nz * PNG_ZOOM * PNG_ZOOM;
            c->slice = malloc(sizeof(float) * pixels);
            c->zero = calloc(pixels, sizeof(float));
        }
        if (aero_vortex_simulate(&p, j->job.rate, j->job.raw + k, ns, avail,
                                 &c->st, hook, 64, c, c->task.err,
                                 sizeof c->task.err) == 0)
            aerotex_task_progress(&c->task, steps - 1);
        free(c->slice);
        free(c->zero);
        c->slice = c->zero = NULL;
        aerotex_farm_keep(&j->job, k, c, sizeof *c, 1);
    }
    aerotex_progress_end(&j->job.prog);
    if (aerotex_farm_gather(&j->job, ctx, ns, sizeof *ctx, 1))
        return 1;
    if (aerotex_farm_rank())
        return 0;
    for (int k = 0; k < ns; k++)
        if (ctx[k].task.err[0]) {
            aerotex_error("speed %g m/s: %s", j->speeds[k], ctx[k].task.err);
            status = 1;
        }
    return status;
}

/* Above the band each speed's grid resolves, the bandwidth extension
 * (bandwidth_extension.h) on the looped raw texture: the third
 * derivative's taper runs from 0.2 to 0.35 of the step rate
 * (vortex_sound.h), the resampling cuts at 0.45 of the lower rate. */
static void extend_band(vortex_job *j, const speed_task *ctx, int len)
{
    const int ns = j->nspeeds;
    for (int k = 0; k < ns && j->extend > 0.0; k++) {
        double steprate = 1.0 / ctx[k].st.dt;
        double f2 = fmin(0.35 * steprate, 0.45 * fmin(steprate, j->job.rate));
        double f1 = fmin(0.2 * steprate, 0.8 * f2);
        if (f2 >= j->extend)
            continue; /* resolved up to the top already */
        aero_bandext_apply(j->job.raw + k, len, ns, j->job.rate, f1, f2,
                           j->extend, j->vp.seed * 40503u + (uint32_t)k + 1u,
                           &j->ext[k]);
        j->ext_from[k] = j->ext[k].extended ? f1 : 0.0;
    }
}

/* the texture's metadata; rms: each channel's, Pa at 1 m */
static void describe(const vortex_job *j, const speed_task *ctx,
                     const double *rms, aero_texture *tex)
{
    const int ns = j->nspeeds;
    double list[MAX_SPEEDS];
    char buf[8192];
    aero_texture_set(tex, "formula", "Howe compact vortex sound: Q = rho0 / "
                     "(12 pi c0^2) xh_a xh_b d3/dt3 INT y_a (y x omega)_b dy; "
                     "p = Q(u, t - r/c0) / r");
    aero_texture_set(tex, "units", "Pa at 1 m");
    aero_texture_setd(tex, "box", j->vp.box);
    aero_texture_setd(tex, "grid", j->vp.n);
    aero_texture_setd(tex, "height", j->vp.nz);
    aero_texture_setd(tex, "rho", AERO_RHO);
    aero_texture_setd(tex, "c0", AERO_C0);
    aero_texture_setd(tex, "nu", j->vp.nu);
    aero_texture_setd(tex, "confinement", j->vp.confinement);
    aero_texture_setd(tex, "turbulence", j->vp.turbulence);
    aero_texture_setd(tex, "cfl", j->vp.cfl);
    aero_texture_setd(tex, "settle", j->vp.settle);
    aero_texture_set(tex, "source", j->vp.source == AERO_VORTEX_CELLS
                                        ? "cells (paper eq. 3-4, alpha 3)"
                                        : "window");
    aero_texture_setd(tex, "receivers", j->vp.receivers);
    aero_texture_setd(tex, "elevation", j->vp.elevation);
    aero_texture_setd(tex, "seed", j->vp.seed);
    aerotex_job_loop_meta(&j->job, tex);
    aerotex_join(buf, sizeof buf, rms, ns, "%.6g");
    aero_texture_set(tex, "rms", buf);
    for (int k = 0; k < ns; k++) list[k] = ctx[k].st.dt;
    aerotex_join(buf, sizeof buf, list, ns, "%.6g");
    aero_texture_set(tex, "dt", buf);
    for (int k = 0; k < ns; k++) list[k] = ctx[k].st.gain;
    aerotex_join(buf, sizeof buf, list, ns, "%.6g");
    aero_texture_set(tex, "receiver_gain", buf);
    if (j->extend > 0.0) {
        aero_texture_set(tex, "extension", "spectral bandwidth extension "
                         "(Chadwick & James 2011): above extend_from, noise "
                         "with the band's envelope and the power law fitted "
                         "on its top two octaves (extend_slope, |X|^2 ~ "
                         "f^s), up to extend_top; 0: not extended");
        aero_texture_setd(tex, "extend_top", j->extend);
        aerotex_join(buf, sizeof buf, j->ext_from, ns, "%.6g");
        aero_texture_set(tex, "extend_from", buf);
        for (int k = 0; k < ns; k++) list[k] = j->ext[k].slope;
        aerotex_join(buf, sizeof buf, list, ns, "%.6g");
        aero_texture_set(tex, "extend_slope", buf);
    }
    aero_texture_set(tex, "solver", "3D incompressible, MAC grid, "
                     "semi-Lagrangian advection, vorticity confinement, "
                     "FFTW + tridiagonal projection");
}

/* the looped texture, saved and reported: the exit status */
static int write_texture(void *job, void *tasks)
{
    vortex_job *j = job;
    const speed_task *ctx = tasks;
    const int ns = j->nspeeds, len = aerotex_job_loop(&j->job);
    double rms[MAX_SPEEDS];
    aero_texture tex;
    int status;
    extend_band(j, ctx, len);
    if (aero_texture_init_speeds(&tex, len, ns, j->speeds, j->job.rate))
        return aerotex_job_fail(&j->job, "out of memory");
    aerotex_job_fill(&j->job, &tex, len);
    for (int k = 0; k < ns; k++) {
        double e = 0.0;
        for (int n = 0; n < len; n++)
            e += (double)tex.data[(size_t)n * ns + k] *
                 tex.data[(size_t)n * ns + k];
        rms[k] = sqrt(e / len);
    }
    describe(j, ctx, rms, &tex);
    status = aerotex_job_save(&j->job, &tex);
    if (!status) {
        printf("%s: vortex sound, box %g m, grid %d x %d x %d, %d speeds, %d "
               "frames (%.3f s at %g Hz)\n", j->job.out, j->vp.box, j->vp.n,
               j->vp.n, j->vp.nz, ns, len, len / j->job.rate, j->job.rate);
        for (int k = 0; k < ns; k++)
            printf("  %6.3g m/s: rms %.3g Pa at 1 m (%.1f dB SPL), %ld steps "
                   "of %.3g ms, max |div u| h %.2g m/s\n", j->speeds[k],
                   rms[k], 20.0 * log10(rms[k] / 2e-5 + 1e-30),
                   ctx[k].st.steps, 1e3 * ctx[k].st.dt, ctx[k].st.max_div);
        printf("  %.1f s\n", aerotex_now() - j->job.t_start);
    }
    aero_texture_free(&tex);
    return status;
}

static int vortex_run(int argc, char **argv)
{
    vortex_job j;
    if (aerotex_job_parse(&aerotex_vortex_command, &j, argc, argv))
        return 2;
    if (j.vp.n & 1) {
        aerotex_error("vortex: --grid takes an even number of cells");
        return 2;
    }
    if (j.extend > 0.0 && !(j.extend * 1.1 < 0.5 * j.job.rate)) {
        aerotex_error("vortex: --extend %g Hz: 1.1 x it must stay below half "
                      "the --rate (%g Hz)", j.extend, 0.5 * j.job.rate);
        return 2;
    }
    if (j.vp.nz < 0)
        j.vp.nz = j.vp.n * 3 / 2;
    return aerotex_job_run(&j.job, argc, argv, j.nspeeds, j.nspeeds,
                           sizeof(speed_task), &j, run_speeds, write_texture);
}

const aerotex_command aerotex_vortex_command = {
    "vortex", "--speeds <u1,...,uN> -o FILE.wav",
    "vortex-sound texture Q(u, t) of a turbulent box of air (fire, jets;\n"
    "Dobashi et al. 2004): 3D incompressible flow with a randomly\n"
    "perturbed inflow at the bottom, periodic sides, open top; Howe's\n"
    "vortex sound at 1 m, one channel per speed (p = Q / r)",
    vortex_options, sizeof(vortex_job), vortex_init, vortex_run};
