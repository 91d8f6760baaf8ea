/* aero: a 3D body in a uniform flow, forces per region (see body_flow.h). */
#include "body_flow.h"
#include "aero_air.h"
#include "aero_util.h"
#include "texture.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_CELLS (48L * 1000 * 1000)
#define SUB 3 /* solid-fraction samples per cell edge */

void aero_body_flow_defaults(aero_body_flow_params *p,
                             const aero_body_shape *body)
{
    double d = body ? aero_body_reference_size(body) : 0.1;
    memset(p, 0, sizeof *p);
    p->body = body;
    p->angle = 90.0;
    p->speed = 10.0;
    p->cell = d / 12.0;
    p->side = 2.5 * d;
    p->upstream = 3.0 * d;
    p->downstream = 8.0 * d;
    p->regions = 1;
    p->nu = AERO_NU;
    p->cfl = 0.7;
    p->settle = 25.0 * d / p->speed;
    p->noise = 0.01;
    p->sponge = 0.2;
    /* eps h / d (FSJ01): 1.5 is the former fixed 0.15 at 10 cells per d,
       the grid the sphere texture was first made on */
    p->confinement = 1.5;
    p->limiter = 1;
    p->seed = 1;
}

/* sample frame -> grid: a rotation by -angle about y (flow to +z) */
typedef struct {
    double c, s;
} turn;

static void to_grid(const turn *r, const double *p, double *g)
{
    g[0] = p[0] * r->c - p[2] * r->s;
    g[1] = p[1];
    g[2] = p[0] * r->s + p[2] * r->c;
}

static void to_sample(const turn *r, const double *g, double *p)
{
    p[0] = g[0] * r->c + g[2] * r->s;
    p[1] = g[1];
    p[2] = -g[0] * r->s + g[2] * r->c;
}

typedef struct {
    int nx, ny, nz;
    double centre_grid[3];  /* the body's box centre, grid metres */
    double centre_body[3];  /* the same point in body coordinates */
} layout;

static int make_layout(const aero_body_flow_params *p, const turn *r,
                       layout *L, char *err, size_t errlen)
{
    const aero_body_shape *b = p->body;
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
    double hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    double ext[3], n[3];
    long cells;
    for (int k = 0; k < 3; k++)
        L->centre_body[k] = 0.5 * (b->lo[k] + b->hi[k]);
    for (int q = 0; q < 8; q++) {
        double c[3] = {(q & 1 ? b->hi[0] : b->lo[0]) - L->centre_body[0],
                       (q & 2 ? b->hi[1] : b->lo[1]) - L->centre_body[1],
                       (q & 4 ? b->hi[2] : b->lo[2]) - L->centre_body[2]};
        double g[3];
        to_grid(r, c, g);
        for (int k = 0; k < 3; k++) {
            if (g[k] < lo[k]) lo[k] = g[k];
            if (g[k] > hi[k]) hi[k] = g[k];
        }
    }
    for (int k = 0; k < 3; k++)
        ext[k] = hi[k] - lo[k];
    n[0] = (ext[0] + 2.0 * p->side) / p->cell;
    n[1] = (ext[1] + 2.0 * p->side) / p->cell;
    n[2] = (p->upstream + ext[2] + p->downstream) / p->cell;
    if (!(n[0] <= 1024.0 && n[1] <= 1024.0 && n[2] <= 1024.0)) {
        snprintf(err, errlen, "the box needs %.0f x %.0f x %.0f cells (at "
                 "most 1024 each): a coarser grid or smaller margins",
                 n[0], n[1], n[2]);
        return -1;
    }
    /* even across the flow, and a multiple of 4 for FFTW */
    L->nx = 4 * (int)ceil(n[0] / 4.0);
    L->ny = 4 * (int)ceil(n[1] / 4.0);
    L->nz = (int)ceil(n[2]);
    if (L->nx < 8) L->nx = 8;
    if (L->ny < 8) L->ny = 8;
    if (L->nz < 8) L->nz = 8;
    cells = (long)L->nx * L->ny * L->nz;
    if (cells > MAX_CELLS) {
        snprintf(err, errlen, "the box needs %d x %d x %d = %ld cells (at "
                 "most %ld): a coarser grid or smaller margins", L->nx,
                 L->ny, L->nz, cells, MAX_CELLS);
        return -1;
    }
    L->centre_grid[0] = 0.5 * L->nx * p->cell;
    L->centre_grid[1] = 0.5 * L->ny * p->cell;
    L->centre_grid[2] = p->upstream - lo[2];
    return 0;
}

/* the cells that may meet the body: within its reach (half its box's
   diagonal and two cells) of its box centre, on the grid; lo inclusive,
   hi exclusive */
typedef struct {
    int lo[3], hi[3];
} cell_range;

static cell_range cells_near_body(const aero_body_flow_params *p,
                                  const layout *L)
{
    const aero_body_shape *b = p->body;
    const double h = p->cell;
    const int n[3] = {L->nx, L->ny, L->nz};
    double reach = 0.0;
    cell_range c;
    for (int k = 0; k < 3; k++)
        reach += 0.25 * (b->hi[k] - b->lo[k]) * (b->hi[k] - b->lo[k]);
    reach = sqrt(reach) + 2.0 * h;
    for (int k = 0; k < 3; k++) {
        c.lo[k] = (int)floor((L->centre_grid[k] - reach) / h);
        c.hi[k] = (int)ceil((L->centre_grid[k] + reach) / h);
        if (c.lo[k] < 0) c.lo[k] = 0;
        if (c.hi[k] > n[k]) c.hi[k] = n[k];
    }
    return c;
}

/* SUB^3 samples of cell (i, j, k): how many fall inside the body, and
   the sum of their positions in body coordinates (acc) */
static int sample_cell(const aero_body_flow_params *p, const turn *r,
                       const layout *L, int i, int j, int k, double *acc)
{
    const double h = p->cell;
    int inside = 0;
    for (int q = 0; q < SUB * SUB * SUB; q++) {
        double g[3], s[3];
        g[0] = (i + (q % SUB + 0.5) / SUB) * h - L->centre_grid[0];
        g[1] = (j + (q / SUB % SUB + 0.5) / SUB) * h - L->centre_grid[1];
        g[2] = (k + (q / (SUB * SUB) + 0.5) / SUB) * h - L->centre_grid[2];
        to_sample(r, g, s);
        for (int a = 0; a < 3; a++)
            s[a] += L->centre_body[a];
        if (aero_body_inside(p->body, s)) {
            inside++;
            for (int a = 0; a < 3; a++)
                acc[a] += s[a];
        }
    }
    return inside;
}

/* frontal area: the columns along the flow that meet the body, each by
   its most solid cell */
static double frontal_area(const aero_body_flow_params *p, const layout *L,
                           const float *shadow)
{
    const double h = p->cell;
    double area = 0.0;
    for (int j = 0; j < L->ny; j++)
        for (int i = 0; i < L->nx; i++)
            area += shadow[(size_t)j * L->nx + i] * h * h;
    return area;
}

/* solid fraction and region of the cells of layers kb .. kt-1 (all of
   them for one process; a window's for aerotex-mpi's slabs), by the solid
   samples' centroid, into chi and region from layer kb; the region
   centroids, volume and frontal area of the whole body (every cell
   sampled, so the same on every rank); 0, or -1 out of memory */
static int voxelise(const aero_body_flow_params *p, const turn *r,
                    const layout *L, int kb, int kt, float *chi, int *region,
                    aero_body_flow_stats *st)
{
    const double h = p->cell;
    const int nr = p->regions;
    double wsum[AERO_BODY_MAX_REGIONS] = {0};
    double csum[3 * AERO_BODY_MAX_REGIONS] = {0};
    const cell_range c = cells_near_body(p, L);
    const size_t pl = (size_t)L->nx * L->ny;
    /* the largest solid fraction along the flow of each column */
    float *shadow = calloc(pl, sizeof(float));
    if (!shadow)
        return -1;
    for (size_t q = 0; q < pl * (size_t)(kt - kb); q++) {
        chi[q] = 0.0f;
        region[q] = -1;
    }
    st->solid_volume = 0.0;
    for (int k = c.lo[2]; k < c.hi[2]; k++)
        for (int j = c.lo[1]; j < c.hi[1]; j++)
            for (int i = c.lo[0]; i < c.hi[0]; i++) {
                double acc[3] = {0, 0, 0};
                const int inside = sample_cell(p, r, L, i, j, k, acc);
                if (inside) {
                    size_t at = ((size_t)(k - kb) * L->ny + j) * L->nx + i;
                    double f = (double)inside / (SUB * SUB * SUB);
                    double m[3] = {acc[0] / inside, acc[1] / inside,
                                   acc[2] / inside};
                    int rg = aero_body_region(p->body, m, nr);
                    if (k >= kb && k < kt) {
                        chi[at] = (float)f;
                        region[at] = rg;
                    }
                    if ((float)f > shadow[(size_t)j * L->nx + i])
                        shadow[(size_t)j * L->nx + i] = (float)f;
                    wsum[rg] += f;
                    for (int a = 0; a < 3; a++)
                        csum[3 * rg + a] += f * m[a];
                    st->solid_volume += f * h * h * h;
                }
            }
    for (int l = 0; l < nr; l++)
        for (int a = 0; a < 3; a++)
            st->centre[3 * l + a] = wsum[l] > 0.0 ? csum[3 * l + a] / wsum[l]
                                                  : L->centre_body[a];
    st->frontal_area = frontal_area(p, L, shadow);
    free(shadow);
    return 0;
}

static double step_of(const aero_body_flow_params *p)
{
    return p->cfl * p->cell / p->speed;
}

/* the low-pass of the derivative: below the step rate's Nyquist */
static double cutoff_of(const aero_body_flow_params *p, double rate)
{
    double fc = 0.45 * rate, fs = 0.4 / step_of(p);
    return fs < fc ? fs : fc;
}

long aero_body_flow_steps(const aero_body_flow_params *p, double rate,
                          int nout)
{
    double dt = step_of(p), w = 8.0 / cutoff_of(p, rate);
    return (long)ceil((p->settle + nout / rate + 2.0 * w) / dt) + 1;
}

static int check_params(const aero_body_flow_params *p, double rate,
                        int nout, char *err, size_t errlen)
{
    if (!p->body) {
        snprintf(err, errlen, "no body");
        return -1;
    }
    if (!(p->speed > 0.0 && p->speed <= AERO_MACH_LIMIT * AERO_C0) ||
        !(p->cell > 0.0 && p->cell < 10.0) || !(p->side >= 0.0) ||
        !(p->upstream >= 0.0) || !(p->downstream >= 0.0) ||
        !(p->nu >= 0.0) ||
        !(p->confinement >= 0.0 && p->confinement <= 50.0) ||
        (p->limiter != 0 && p->limiter != 1) ||
        !(p->cfl > 0.0 && p->cfl <= 2.0) ||
        !(p->settle >= 0.0 && p->settle < 1e3) ||
        !(p->noise >= 0.0 && p->noise <= 1.0) ||
        !(p->sponge >= 0.0 && p->sponge <= 1.0) || !aero_is_finite(p->angle) ||
        p->regions < 1 || p->regions > AERO_BODY_MAX_REGIONS ||
        !(rate >= 100.0 && rate <= 192000.0) || nout < 1) {
        snprintf(err, errlen, "bad flow parameters (speed %g m/s, cell %g m, "
                 "%d regions, rate %g Hz)", p->speed, p->cell, p->regions,
                 rate);
        return -1;
    }
    if (p->nu * step_of(p) / (p->cell * p->cell) > 1.0 / 6.0) {
        snprintf(err, errlen, "viscosity %g m^2/s is too large for the "
                 "explicit step on %g m cells", p->nu, p->cell);
        return -1;
    }
    return 0;
}

/* the shedding peak of the lateral sound source: the spectrum of dF/dt
   (power times f^2, what radiates) over 0.05..1 v0/d, averaged over three
   Hann-windowed halves of the record overlapping by half (Welch 1967): a
   broad band's single periodogram peaks anywhere on it, from run to run
   and grid to grid. Below 0.05 a sphere's wake also wanders slowly
   (Constantinescu and Squires 2004, Phys. Fluids 16, a mode far below the
   shedding), which dominates the force itself but hardly radiates. Hz */
static double lateral_peak(const double *fx, const double *fy, long n,
                           double dt, double d, double v0)
{
    const long len = n / 2, hop = len / 2;
    const double T = len * dt;
    double best = 0.0, fbest = 0.0, mx[3] = {0.0}, my[3] = {0.0};
    long start[3];
    int nseg = 0;
    if (len < 16)
        return 0.0;
    /* len = n / 2 and hop = len / 2 fit three segments, never more */
    for (long s0 = 0; s0 + len <= n && nseg < 3; s0 += hop)
        start[nseg++] = s0;
    for (int q = 0; q < nseg; q++) {
        for (long m = 0; m < len; m++) {
            mx[q] += fx[start[q] + m];
            my[q] += fy[start[q] + m];
        }
        mx[q] /= len;
        my[q] /= len;
    }
    for (double f = 0.05 * v0 / d; f <= 1.0 * v0 / d; f += 0.25 / T) {
        const double w = 2.0 * AERO_PI * f * dt;
        double ar[3] = {0.0}, ai[3] = {0.0}, br[3] = {0.0}, bi[3] = {0.0};
        double power = 0.0;
        /* the window and the phase are the same in every segment */
        for (long m = 0; m < len; m++) {
            double hann = 0.5 - 0.5 * cos(2.0 * AERO_PI * m / (len - 1));
            double c = cos(w * m), s = sin(w * m);
            for (int q = 0; q < nseg; q++) {
                ar[q] += hann * (fx[start[q] + m] - mx[q]) * c;
                ai[q] -= hann * (fx[start[q] + m] - mx[q]) * s;
                br[q] += hann * (fy[start[q] + m] - my[q]) * c;
                bi[q] -= hann * (fy[start[q] + m] - my[q]) * s;
            }
        }
        for (int q = 0; q < nseg; q++)
            power += ar[q] * ar[q] + ai[q] * ai[q] + br[q] * br[q] +
                     bi[q] * bi[q];
        if (power * f * f > best) {
            best = power * f * f;
            fbest = f;
        }
    }
    return fbest;
}

/* one simulation: the layout, the solver, the recorded forces */
typedef struct {
    const aero_body_flow_params *p;
    aero_flow3d s;
    void *window;          /* p->window_open's handle (NULL: none) */
    layout L;
    turn r;
    int solver_up, nr;
    float *chi;                 /* solid fraction per cell */
    int *region;                /* region per cell */
    double *times, *forces;     /* kept steps: time, 3 nr forces (sample
                                   frame, per rho) */
    double *series;             /* one force component, resampled */
    double force[3 * AERO_BODY_MAX_REGIONS]; /* the solver's, grid frame */
    double dt, t_keep, fc, d;   /* step; first kept time; cut-off; size */
    long steps, kept;
    uint32_t rng;
} body_run;

/* the cells' and the recording's arrays: 0 or -1 */
static int alloc_run(body_run *b, char *err, size_t errlen)
{
    /* the solver's layers (a window's, or the whole grid's) */
    const size_t cells = (size_t)b->L.nx * b->L.ny * b->s.nz;
    b->chi = malloc(sizeof(float) * cells);
    b->region = malloc(sizeof(int) * cells);
    b->times = malloc(sizeof(double) * (size_t)b->steps);
    b->forces = malloc(sizeof(double) * (size_t)b->steps * 3 * b->nr);
    b->series = malloc(sizeof(double) * (size_t)b->steps);
    if (!b->chi || !b->region || !b->times || !b->forces || !b->series) {
        snprintf(err, errlen, "out of memory for a %d x %d x %d grid",
                 b->L.nx, b->L.ny, b->L.nz);
        return -1;
    }
    return 0;
}

/* the 3D solver's parameters for this body and box */
static void solver_params(const body_run *b, aero_flow3d_params *fp)
{
    const aero_body_flow_params *p = b->p;
    memset(fp, 0, sizeof *fp);
    fp->nx = b->L.nx;
    fp->ny = b->L.ny;
    fp->nz = b->L.nz;
    fp->h = p->cell;
    fp->nu = p->nu;
    fp->u_ref = p->speed;
    fp->confinement = p->confinement;
    /* eps h (Fedkiw, Stam and Jensen 2001) with the body's size as the
       length: the forcing of grid-scale eddies is the same at any grid,
       and a resolved wake's vanishes as the grid is refined */
    fp->confinement_length = b->d;
    fp->advection = p->limiter ? AERO_F3_MACCORMACK
                               : AERO_F3_MACCORMACK_UNLIMITED;
    fp->threads = p->threads;
    fp->sponge = p->downstream > 0.0
                     ? fmin(0.5, p->sponge * p->downstream /
                                     (b->L.nz * p->cell))
                     : 0.0;
}

/* the solver, planned under the caller's lock (FFTW's planner), with the
   body on its grid: 0 or -1 */
static int start_solver(body_run *b, aero_body_flow_stats *st, void *ctx,
                        char *err, size_t errlen)
{
    const aero_body_flow_params *p = b->p;
    aero_flow3d_params fp;
    solver_params(b, &fp);
    if (p->plan_lock) p->plan_lock(ctx, 1);
    if (p->window_open) {
        b->window = p->window_open(&fp, &b->s, err, errlen);
        b->solver_up = b->window != NULL;
    } else {
        b->solver_up = aero_flow3d_init(&b->s, &fp, err, errlen) == 0;
    }
    if (p->plan_lock) p->plan_lock(ctx, 0);
    if (!b->solver_up)
        return -1;
    st->nx = b->L.nx;
    st->ny = b->L.ny;
    st->nz = b->L.nz;
    st->dt = b->dt;
    return 0;
}

/* the grid, the body on it, the solver: 0 or -1 */
static int open_run(body_run *b, const aero_body_flow_params *p, double rate,
                    int nout, aero_body_flow_stats *st, void *ctx, char *err,
                    size_t errlen)
{
    memset(b, 0, sizeof *b);
    b->p = p;
    b->nr = p->regions;
    if (check_params(p, rate, nout, err, errlen))
        return -1;
    b->r.c = cos(p->angle * AERO_PI / 180.0);
    b->r.s = sin(p->angle * AERO_PI / 180.0);
    if (make_layout(p, &b->r, &b->L, err, errlen))
        return -1;
    b->d = aero_body_reference_size(p->body);
    b->dt = step_of(p);
    b->fc = cutoff_of(p, rate);
    b->steps = aero_body_flow_steps(p, rate, nout);
    b->t_keep = p->settle - 8.0 / b->fc - b->dt;
    /* the solver first: a window's layers are the body's to voxelise */
    if (start_solver(b, st, ctx, err, errlen) || alloc_run(b, err, errlen))
        return -1;
    {
        const int kb = b->s.p.nz_total > 0 ? b->s.p.k_origin : 0;
        if (voxelise(p, &b->r, &b->L, kb, kb + b->s.nz, b->chi, b->region,
                     st)) {
            snprintf(err, errlen, "out of memory");
            return -1;
        }
    }
    if (!(st->solid_volume > 0.0)) {
        snprintf(err, errlen, "the body fills no cell: a finer grid "
                 "(cell %g m)", p->cell);
        return -1;
    }
    aero_flow3d_set_body(&b->s, b->chi, b->region, b->nr, b->force);
    return 0;
}

static void close_run(body_run *b, void *ctx)
{
    if (b->solver_up) {
        if (b->p->plan_lock) b->p->plan_lock(ctx, 1);
        if (b->window)
            b->p->window_close(b->window);
        else
            aero_flow3d_free(&b->s);
        if (b->p->plan_lock) b->p->plan_lock(ctx, 0);
    }
    free(b->chi);
    free(b->region);
    free(b->times);
    free(b->forces);
    free(b->series);
}

/* the uniform flow everywhere, made divergence-free around the body */
static void start_flow(body_run *b)
{
    aero_flow3d *s = &b->s;
    for (size_t c = 0; c < s->plane * (size_t)(s->nz + 1); c++)
        s->w[c] = (float)b->p->speed;
    for (size_t c = 0; c < s->plane; c++)
        s->in_w[c] = (float)b->p->speed;
    if (s->project_hook) /* a window: projected with the others */
        s->project_hook(s->project_ctx, s);
    else
        aero_flow3d_project(s);
    b->rng = b->p->seed ? b->p->seed : 1;
}

/* the inflow at time t: a lateral gust (one sine period) during the
   first quarter of the settling time, breaking the start-up flow's
   symmetry, then a little seeded noise */
static void set_inflow(body_run *b, double t)
{
    const aero_body_flow_params *p = b->p;
    aero_flow3d *s = &b->s;
    double gust = t < 0.25 * p->settle
                      ? 0.1 * sin(2.0 * AERO_PI * t / (0.25 * p->settle))
                      : 0.0;
    float gu = (float)(p->speed * (gust + p->noise * aero_uniform(&b->rng)));
    float gv = (float)(p->speed * (0.5 * gust +
                                   p->noise * aero_uniform(&b->rng)));
    /* a window above the inflow: its bottom edge is its neighbour's */
    if (s->p.nz_total > 0 && s->p.k_origin > 0)
        return;
    for (size_t c = 0; c < s->plane; c++) {
        s->in_u[c] = gu;
        s->in_v[c] = gv;
    }
}

/* the forces of the step that ended at t, into the sample frame */
static void keep_forces(body_run *b, double t)
{
    b->times[b->kept] = t;
    for (int l = 0; l < b->nr; l++)
        to_sample(&b->r, b->force + 3 * l,
                  b->forces + ((size_t)b->kept * b->nr + l) * 3);
    b->kept++;
}

/* A run's state between steps: the next step, the forces kept, the
   generator, then the forces' times and values (all `steps` of them, so
   the size is fixed) and the solver's state. */
typedef struct {
    int64_t next, kept;
    uint64_t rng;
} run_header;

static size_t state_size(const body_run *b)
{
    return sizeof(run_header) +
           sizeof(double) * (size_t)b->steps * (1 + 3 * (size_t)b->nr) +
           aero_flow3d_state_size(&b->s);
}

/* the state after step next - 1 to p->checkpoint_save (out of memory:
   none this time) */
static void save_state(body_run *b, long next, void *ctx)
{
    const size_t ns = (size_t)b->steps, nf = ns * 3 * b->nr;
    char *buf = malloc(state_size(b)), *p = buf;
    run_header h;
    if (!buf)
        return;
    h.next = next;
    h.kept = b->kept;
    h.rng = b->rng;
    memcpy(p, &h, sizeof h);
    p += sizeof h;
    memcpy(p, b->times, sizeof(double) * ns);
    p += sizeof(double) * ns;
    memcpy(p, b->forces, sizeof(double) * nf);
    p += sizeof(double) * nf;
    aero_flow3d_state_save(&b->s, p);
    b->p->checkpoint_save(ctx, buf, state_size(b));
    free(buf);
}

/* the step to start from: a checkpoint's (its state loaded), or 0 */
static long load_state(body_run *b, void *ctx)
{
    const size_t ns = (size_t)b->steps, nf = ns * 3 * b->nr;
    char *buf, *p;
    run_header h;
    long next = 0;
    if (!b->p->checkpoint_load || !(buf = malloc(state_size(b))))
        return 0;
    p = buf;
    if (b->p->checkpoint_load(ctx, buf, state_size(b))) {
        memcpy(&h, p, sizeof h);
        p += sizeof h;
        if (h.next > 0 && h.next <= b->steps && h.kept >= 0 &&
            h.kept <= b->steps) {
            next = (long)h.next;
            b->kept = (long)h.kept;
            b->rng = (uint32_t)h.rng;
            memcpy(b->times, p, sizeof(double) * ns);
            p += sizeof(double) * ns;
            memcpy(b->forces, p, sizeof(double) * nf);
            p += sizeof(double) * nf;
            aero_flow3d_state_load(&b->s, p);
        }
    }
    free(buf);
    return next;
}

/* every step from n0 on, the forces from t_keep on, a checkpoint every
   p->checkpoint_every steps: 0 or -1 */
static int run_flow(body_run *b, long n0,
                    void (*hook)(void *ctx, const aero_flow3d *s, long step,
                                 int recording),
                    long hook_every, void *ctx, char *err, size_t errlen)
{
    const double dt = b->dt;
    const long every = b->p->checkpoint_save ? b->p->checkpoint_every : 0;
    for (long n = n0; n < b->steps; n++) {
        double t = n * dt;
        set_inflow(b, t);
        if (aero_flow3d_step(&b->s, dt)) {
            snprintf(err, errlen, "the flow blew up at t = %.4g s (step %ld): "
                     "a smaller --cfl", t, n);
            return -1;
        }
        if (t + dt >= b->t_keep)
            keep_forces(b, t + dt);
        if (hook && hook_every > 0 &&
            (n % hook_every == 0 || n == b->steps - 1))
            hook(ctx, &b->s, n, t >= b->p->settle);
        if (every > 0 && (n + 1) % every == 0 && n + 1 < b->steps)
            save_state(b, n + 1, ctx);
    }
    return 0;
}

/* g_l = rho dF_l/dt, resampled from the settling time on */
static void radiate(body_run *b, double rate, float *out, int stride,
                    int nout)
{
    const int nr = b->nr;
    for (int l = 0; l < nr; l++)
        for (int c = 0; c < 3; c++) {
            for (long m = 0; m < b->kept; m++)
                b->series[m] = b->forces[((size_t)m * nr + l) * 3 + c];
            aero_texture_resample_derivative_fc(
                b->times, b->series, (int)b->kept, rate, b->fc,
                b->p->settle, AERO_RHO, out + 3 * l + c, stride, nout);
        }
}

/* drag, lateral force and shedding peak over the recorded part, in grid
   axes (z: drag): 0 or -1 */
static int statistics(body_run *b, aero_body_flow_stats *st, char *err,
                      size_t errlen)
{
    const aero_body_flow_params *p = b->p;
    const int nr = b->nr;
    double *fx = malloc(sizeof(double) * (size_t)b->kept);
    double *fy = malloc(sizeof(double) * (size_t)b->kept);
    double drag = 0.0, lat = 0.0, q, mx = 0.0, my = 0.0;
    long m0 = 0, nrec;
    while (m0 < b->kept && b->times[m0] < p->settle)
        m0++;
    nrec = b->kept - m0;
    if (!fx || !fy || nrec < 2) {
        free(fx);
        free(fy);
        snprintf(err, errlen, nrec < 2 ? "too short a recording"
                                       : "out of memory");
        return -1;
    }
    for (long m = 0; m < nrec; m++) {
        double sx = 0.0, sy = 0.0, sz = 0.0;
        for (int l = 0; l < nr; l++) {
            double g[3];
            to_grid(&b->r, b->forces + ((size_t)(m0 + m) * nr + l) * 3, g);
            sx += g[0];
            sy += g[1];
            sz += g[2];
        }
        fx[m] = sx;
        fy[m] = sy;
        mx += sx;
        my += sy;
        drag += sz;
    }
    mx /= nrec;
    my /= nrec;
    for (long m = 0; m < nrec; m++)
        lat += (fx[m] - mx) * (fx[m] - mx) + (fy[m] - my) * (fy[m] - my);
    q = 0.5 * p->speed * p->speed * st->frontal_area; /* per rho */
    st->cd = drag / nrec / q;
    st->cl_rms = sqrt(lat / nrec) / q;
    st->f_peak = lateral_peak(fx, fy, nrec, b->dt, b->d, p->speed);
    st->st = st->f_peak * b->d / p->speed;
    free(fx);
    free(fy);
    return 0;
}

/* the body on its grid and the solver (open_run), the uniform stream
   started, every step run with its forces kept (run_flow), then each
   region's g = rho dF/dt resampled at the texture rate, the 3D case of
   Dobashi et al. 2003 (radiate), and the force statistics */
int aero_body_flow_simulate(const aero_body_flow_params *p, double rate,
                            float *out, int stride, int nout,
                            aero_body_flow_stats *st,
                            void (*hook)(void *ctx, const aero_flow3d *s,
                                         long step, int recording),
                            long hook_every, void *ctx, char *err,
                            size_t errlen)
{
    body_run b;
    int status = -1;
    memset(st, 0, sizeof *st);
    if (open_run(&b, p, rate, nout, st, ctx, err, errlen) == 0) {
        start_flow(&b);
        if (run_flow(&b, load_state(&b, ctx), hook, hook_every, ctx, err,
                     errlen) == 0) {
            st->steps = b.steps;
            st->max_div = aero_flow3d_max_divergence(&b.s);
            radiate(&b, rate, out, stride, nout);
            status = statistics(&b, st, err, errlen);
        }
    }
    close_run(&b, ctx);
    return status;
}
