/* aero: 3D incompressible flow in a box (see flow3d.h). */
#include "flow3d.h"
#include "aero_air.h"

#include "aero_clones.h"
#include "aero_fftw.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NEAR_BODY_CELLS 2

/* the loop that follows, over z-slabs (or planes of spectral modes), on
   the solver's threads: every iteration writes its own cells, so the
   result does not depend on the number of threads */
#define F3_SLABS                                                          \
    _Pragma("omp parallel for schedule(static) num_threads(s->p.threads) \
             if (s->p.threads > 1)")

/* the cells i = 0..nx-1 of a row, with im and ip their neighbours across
   the periodic x side: CELL(i, im, ip) on the two edge cells apart, so
   that the loop between them vectorises (nx >= 4, check_params) */
#define F3_ROW(nx, CELL)                                                  \
    do {                                                                  \
        CELL(0, (nx) - 1, 1);                                             \
        for (int i_ = 1; i_ < (nx) - 1; i_++)                             \
            CELL(i_, i_ - 1, i_ + 1);                                     \
        CELL((nx) - 1, (nx) - 2, 0);                                      \
    } while (0)

/* the same, for a row that reads and writes so many arrays that the
   compiler will not check every pair for overlap at run time: omp simd
   tells it they do not overlap (each cell writes only its own cells) */
#define F3_ROW_SIMD(nx, CELL)                                             \
    do {                                                                  \
        CELL(0, (nx) - 1, 1);                                             \
        _Pragma("omp simd")                                               \
        for (int i_ = 1; i_ < (nx) - 1; i_++)                             \
            CELL(i_, i_ - 1, i_ + 1);                                     \
        CELL((nx) - 1, (nx) - 2, 0);                                      \
    } while (0)

/* i modulo n for any int (the common case is one step out of range) */
static inline int wrap(int i, int n)
{
    if (i < 0) {
        i += n;
        if (i < 0) i = ((i % n) + n) % n;
    } else if (i >= n) {
        i -= n;
        if (i >= n) i %= n;
    }
    return i;
}

/* the parameters a solver can run with: 0, or -1 with a message */
static int check_params(const aero_flow3d_params *p, char *err, size_t errlen)
{
    if (p->nx < 4 || p->ny < 4 || p->nz < 3 || (p->nx & 1) || (p->ny & 1) ||
        p->nx > 1024 || p->ny > 1024 || p->nz > 1024) {
        snprintf(err, errlen, "grid %d x %d x %d: nx, ny even and >= 4, "
                 "nz >= 3, each <= 1024", p->nx, p->ny, p->nz);
        return -1;
    }
    if (!(p->h > 0.0) || !(p->nu >= 0.0) || !(p->confinement >= 0.0) ||
        !(p->u_ref >= 0.0) || !(p->sponge >= 0.0 && p->sponge < 1.0) ||
        !(p->confinement_length >= 0.0) ||
        (p->advection != AERO_F3_SEMI_LAGRANGIAN &&
         p->advection != AERO_F3_MACCORMACK &&
         p->advection != AERO_F3_MACCORMACK_UNLIMITED)) {
        snprintf(err, errlen, "bad cell size, viscosity or confinement");
        return -1;
    }
    if (p->nz_total < 0 || (p->nz_total > 0 &&
        (p->k_origin < 0 || p->k_origin > p->nz_total - p->nz))) {
        snprintf(err, errlen, "window of %d cells from %d in %d", p->nz,
                 p->k_origin, p->nz_total);
        return -1;
    }
    return 0;
}

/* the solver's float fields allocated with calloc, with their lengths
   (0: not used with these parameters); fills up to 20 */
static int float_fields(aero_flow3d *s, float ***field, size_t *len)
{
    const size_t cells = s->plane * s->nz;
    const size_t uvn = s->plane * (s->nz + 2), wn = s->plane * (s->nz + 1);
    const size_t mc = s->p.advection != AERO_F3_SEMI_LAGRANGIAN ? 3 * uvn : 0;
    const size_t bounds = s->p.advection == AERO_F3_MACCORMACK ? mc : 0;
    float **f[] = {&s->u,  &s->v,  &s->w,    &s->u1,   &s->v1, &s->w1,
                   &s->cx, &s->cy, &s->cz,   &s->ox,   &s->oy, &s->oz,
                   &s->omag, &s->in_u, &s->in_v, &s->in_w, &s->tri_m,
                   &s->mc, &s->mc_lo, &s->mc_hi};
    const size_t n[] = {uvn,   uvn,   wn,    uvn,   uvn,      wn,
                        cells, cells, cells, cells, cells,    cells,
                        cells, s->plane, s->plane, s->plane,
                        (size_t)(s->nx / 2 + 1) * s->ny * s->nz, mc, bounds,
                        bounds};
    const int count = (int)(sizeof f / sizeof f[0]);
    for (int q = 0; q < count; q++) {
        field[q] = f[q];
        len[q] = n[q];
    }
    return count;
}

/* every field of the grid (s->nx.. set): 0, or -1 (out of memory) */
static int alloc_fields(aero_flow3d *s)
{
    const size_t cells = s->plane * s->nz;
    const size_t specn = (size_t)(s->nx / 2 + 1) * s->ny * s->nz;
    float **field[20];
    size_t len[20];
    const int count = float_fields(s, field, len);
    int ok = 1;
    for (int q = 0; q < count; q++)
        if (len[q]) {
            *field[q] = calloc(len[q], sizeof(float));
            ok = ok && *field[q];
        }
    s->phi = fftwf_malloc(sizeof(float) * cells);
    s->spec = fftwf_malloc(sizeof(fftwf_complex) * specn);
    return ok && s->phi && s->spec ? 0 : -1;
}

/* the FFTs across x and y of the pressure solve: 0 or -1 */
static int plan_fft(aero_flow3d *s)
{
    const int n[2] = {s->ny, s->nx}, nxh = s->nx / 2 + 1;
    aero_fftw_serialise(); /* one planner per process: aero_fftw.h */
    s->fwd = fftwf_plan_many_dft_r2c(2, n, s->nz, s->phi, NULL, 1,
                                     (int)s->plane, s->spec, NULL, 1,
                                     nxh * s->ny, FFTW_ESTIMATE);
    s->inv = fftwf_plan_many_dft_c2r(2, n, s->nz, s->spec, NULL, 1,
                                     nxh * s->ny, s->phi, NULL, 1,
                                     (int)s->plane, FFTW_ESTIMATE);
    return s->fwd && s->inv ? 0 : -1;
}

/* Thomas factors of (phi[k-1] + (mu - 2) phi[k] + phi[k+1]) for mode
   (kx, ky), mu = 2 cos(2 pi kx / nx) + 2 cos(2 pi ky / ny) - 4 (the
   eigenvalue of the periodic 5-point Laplacian times h^2); rows 0
   (Neumann: the inflow is prescribed) and nz-1 (phi = 0 on the top face)
   differ. In double, stored as float, m[k * stride] */
void aero_flow3d_poisson_factors(int nx, int ny, int nz, int kx, int ky,
                                 float *m, size_t stride)
{
    double mu = 2.0 * cos(2.0 * AERO_PI * kx / nx) +
                2.0 * cos(2.0 * AERO_PI * ky / ny) - 4.0;
    double cprev = 0.0;
    for (int k = 0; k < nz; k++) {
        double b = mu - 2.0;
        if (k == 0) b = mu - 1.0;
        if (k == nz - 1) b = mu - 3.0;
        double f = 1.0 / (b - (k ? cprev : 0.0));
        m[(size_t)k * stride] = (float)f;
        cprev = f;
    }
}

static void factor_poisson(aero_flow3d *s)
{
    const int nx = s->nx, ny = s->ny, nxh = nx / 2 + 1;
    for (int ky = 0; ky < ny; ky++)
        for (int kx = 0; kx < nxh; kx++)
            aero_flow3d_poisson_factors(nx, ny, s->nz, kx, ky,
                                        s->tri_m + (size_t)ky * nxh + kx,
                                        (size_t)ny * nxh);
}

int aero_flow3d_init(aero_flow3d *s, const aero_flow3d_params *p, char *err,
                     size_t errlen)
{
    memset(s, 0, sizeof *s);
    if (check_params(p, err, errlen))
        return -1;
    s->p = *p;
    if (s->p.threads < 1) s->p.threads = 1;
    if (s->p.threads > 64) s->p.threads = 64;
    s->nx = p->nx;
    s->ny = p->ny;
    s->nz = p->nz;
    s->plane = (size_t)p->nx * p->ny;
    if (alloc_fields(s)) {
        aero_flow3d_free(s);
        snprintf(err, errlen, "out of memory for a %d x %d x %d grid", p->nx,
                 p->ny, p->nz);
        return -1;
    }
    if (plan_fft(s)) {
        aero_flow3d_free(s);
        snprintf(err, errlen, "FFTW could not plan the pressure solve");
        return -1;
    }
    factor_poisson(s);
    s->own_lo = 0;
    s->own_hi = s->nz;
    s->solid = NULL;
    s->t = 0.0;
    return 0;
}

void aero_flow3d_free(aero_flow3d *s)
{
    float **field[20];
    size_t len[20];
    const int count = float_fields(s, field, len);
    aero_fftw_serialise();
    if (s->fwd) fftwf_destroy_plan(s->fwd);
    if (s->inv) fftwf_destroy_plan(s->inv);
    for (int q = 0; q < count; q++)
        free(*field[q]);
    if (s->phi) fftwf_free(s->phi);
    if (s->spec) fftwf_free(s->spec);
    free(s->near_body);
    memset(s, 0, sizeof *s);
}

/* boundary layers: inflow below (tangential u, v in the ghost layer, w on
   the bottom face), zero gradient above */
static void apply_boundaries(aero_flow3d *s)
{
    const size_t pl = s->plane;
    memcpy(s->u, s->in_u, sizeof(float) * pl);
    memcpy(s->v, s->in_v, sizeof(float) * pl);
    memcpy(s->w, s->in_w, sizeof(float) * pl);
    memcpy(s->u + (size_t)(s->nz + 1) * pl, s->u + (size_t)s->nz * pl,
           sizeof(float) * pl);
    memcpy(s->v + (size_t)(s->nz + 1) * pl, s->v + (size_t)s->nz * pl,
           sizeof(float) * pl);
}

/* the smaller and larger of two finite floats, inline (fminf and fmaxf
   are library calls without -ffast-math: a quarter of a step's time) */
static inline float min_f(float a, float b) { return b < a ? b : a; }
static inline float max_f(float a, float b) { return b > a ? b : a; }

/* floor of a float well inside the int range (the sample coordinates are
   clamped to a few grid lengths): a truncation and a correction, cheaper
   than floorf's exact rounding of any float */
static inline int floor_int(float x)
{
    int i = (int)x;
    return i - (x < (float)i);
}

/* the longest row (check_params) */
#define ROW_MAX 1024

/* the departure points of one row of faces, in grid coordinates of the
   faces' own lattice */
typedef struct {
    float fi[ROW_MAX], fj[ROW_MAX], fk[ROW_MAX];
} row_points;

/* a field's lattice as the sampler sees it: layer0 the address of its
   layer 0, first its lowest layer (-1 for u and v, which carry a ghost
   layer below; 0 for w); both reach up to layer nz; periodic in i, j */
typedef struct {
    const float *layer0;
    int first, nx, ny, nz, plane;
    int origin; /* the window's first layer in the whole grid (0: whole):
                   heights are the whole grid's, so that a departure
                   point rounds as it does in the one-process solver */
} lattice;

/* the 8 lattice values around a sample point and its weights */
typedef struct {
    float c00, c01, c10, c11, d00, d01, d10, d11; /* layers k0, k0 + 1 */
    float tx, ty, tz;
} corners;

/* the corners of departure point i: no branches, only selects and
   indexed loads, so that the loops over a row vectorise (AVX2 gathers).
   The coordinates are held within a box length of the box along x and y
   (advect_pass), so one wrap brings an index into range */
static inline corners corners_at(const lattice *L, const row_points *pt,
                                 int i)
{
    const float *f = L->layer0;
    const int nx = L->nx, ny = L->ny, nz = L->nz;
    const float x = pt->fi[i], y = pt->fj[i];
    float z = pt->fk[i];
    int i0, j0, k0, i1, j1, a, b;
    corners r;
    /* NaN (a diverging step, which aero_flow3d_step reports after it)
       goes to the lowest layer instead of an index far outside the box */
    z = z > (float)(L->first + L->origin) ? z : (float)(L->first + L->origin);
    z = z > (float)(nz + L->origin) ? (float)(nz + L->origin) : z;
    i0 = floor_int(x);
    j0 = floor_int(y);
    k0 = floor_int(z);
    r.tx = x - (float)i0;
    r.ty = y - (float)j0;
    r.tz = z - (float)k0;
    k0 -= L->origin;
    r.tz = k0 >= nz ? 1.0f : r.tz;
    k0 = k0 >= nz ? nz - 1 : k0;
    i0 += i0 < 0 ? nx : 0;
    i0 -= i0 >= nx ? nx : 0;
    j0 += j0 < 0 ? ny : 0;
    j0 -= j0 >= ny ? ny : 0;
    i1 = i0 + 1 == nx ? 0 : i0 + 1;
    j1 = j0 + 1 == ny ? 0 : j0 + 1;
    a = k0 * L->plane;
    b = a + L->plane;
    r.c00 = f[a + j0 * nx + i0];
    r.c01 = f[a + j0 * nx + i1];
    r.c10 = f[a + j1 * nx + i0];
    r.c11 = f[a + j1 * nx + i1];
    r.d00 = f[b + j0 * nx + i0];
    r.d01 = f[b + j0 * nx + i1];
    r.d10 = f[b + j1 * nx + i0];
    r.d11 = f[b + j1 * nx + i1];
    return r;
}

static inline float trilinear(const corners *r)
{
    const float a00 = r->c00 + r->tx * (r->c01 - r->c00);
    const float a10 = r->c10 + r->tx * (r->c11 - r->c10);
    const float b00 = r->d00 + r->tx * (r->d01 - r->d00);
    const float b10 = r->d10 + r->tx * (r->d11 - r->d10);
    const float a0 = a00 + r->ty * (a10 - a00), b0 = b00 + r->ty * (b10 - b00);
    return a0 + r->tz * (b0 - a0);
}

/* trilinear samples of a field at a row's departure points (n of them) */
AERO_CLONES
static void sample_row(const lattice *L, const row_points *pt, int n,
                       float *restrict out)
{
#pragma omp simd
    for (int i = 0; i < n; i++) {
        const corners r = corners_at(L, pt, i);
        out[i] = trilinear(&r);
    }
}

/* the same, with the smallest and largest of the 8 values around each
   point (the MacCormack limiter's bounds) */
AERO_CLONES
static void sample_row_bounds(const lattice *L, const row_points *pt, int n,
                              float *restrict out, float *restrict lo,
                              float *restrict hi)
{
#pragma omp simd
    for (int i = 0; i < n; i++) {
        const corners r = corners_at(L, pt, i);
        out[i] = trilinear(&r);
        lo[i] = min_f(min_f(min_f(min_f(min_f(min_f(min_f(
                    r.c00, r.c01), r.c10), r.c11), r.d00), r.d01), r.d10),
                    r.d11);
        hi[i] = max_f(max_f(max_f(max_f(max_f(max_f(max_f(
                    r.c00, r.c01), r.c10), r.c11), r.d00), r.d01), r.d10),
                    r.d11);
    }
}

/* a row's samples of one field, with the bounds when lo is not NULL
   (offset o into lo and hi) */
static void sample_into(const lattice *L, const row_points *pt, int n,
                        float *out, float *lo, float *hi, size_t o)
{
    if (lo)
        sample_row_bounds(L, pt, n, out, lo + o, hi + o);
    else
        sample_row(L, pt, n, out);
}

/* the fields one advection pass reads and writes */
typedef struct {
    const float *u, *v, *w; /* sampled (ghost layers valid) */
    float *du, *dv, *dw;    /* written: u, v layers 0..nz-1, w 1..nz */
    float *lo, *hi;         /* limiter bounds, 3 fields of uvn (or NULL) */
} advect_io;

/* the departure point of face i of a row, carried by the face velocity
   (U, V, W) for c = dt / h: at most a box length away along the periodic
   x and y (so that one wrap brings it back), any distance along z (the
   sampler clamps it) */
static inline void depart(row_points *pt, int i, float x0, float y0,
                          float z0, float U, float V, float W, float c,
                          float limx, float limy)
{
    const float dx = max_f(-limx, min_f(limx, U * c));
    const float dy = max_f(-limy, min_f(limy, V * c));
    pt->fi[i] = x0 - dx;
    pt->fj[i] = y0 - dy;
    pt->fk[i] = z0 - W * c;
}

/* the mean of four face values, in one order (the same sum every time) */
static inline float mean4(float a, float b, float c, float d)
{
    return 0.25f * (a + b + c + d);
}

/* semi-Lagrangian advection (Fedkiw et al. 2001, sec. 3): each face value is the field
   at the point the current velocity came from dt ago (dt < 0: forwards).
   Row by row: the departure points of a row's u, v and w faces (the
   neighbours across the periodic x side at i = 0 and nx - 1 taken apart,
   so that the rest vectorises), then their samples (sample_row) */
static void advect_pass(aero_flow3d *s, const advect_io *io, double dt)
{
    const int nx = s->nx, ny = s->ny, nz = s->nz;
    const float c = (float)(dt / s->p.h);
    const float limx = (float)nx, limy = (float)ny;
    const float *u = s->u, *v = s->v, *w = s->w;
    const size_t uvn = s->plane * (size_t)(nz + 2);
    const int kor = s->p.nz_total > 0 ? s->p.k_origin : 0;
    const lattice lu = {io->u + s->plane, -1, nx, ny, nz, (int)s->plane, kor};
    const lattice lv = {io->v + s->plane, -1, nx, ny, nz, (int)s->plane, kor};
    const lattice lw = {io->w, 0, nx, ny, nz, (int)s->plane, kor};
    F3_SLABS
    for (int k = 0; k < nz; k++) {
        row_points pt;
        for (int j = 0; j < ny; j++) {
            const int jm = j ? j - 1 : ny - 1, jp = j + 1 == ny ? 0 : j + 1;
            const float y0 = (float)j, z0 = (float)(k + kor),
                        z1 = (float)(k + kor + 1);
            /* rows of u, v (layers k, k + 1) and w (k, k + 1) */
            const float *uj = u + AERO_F3_UV(s, 0, j, k);
            const float *ujm = u + AERO_F3_UV(s, 0, jm, k);
            const float *uj1 = u + AERO_F3_UV(s, 0, j, k + 1);
            const float *vj = v + AERO_F3_UV(s, 0, j, k);
            const float *vjp = v + AERO_F3_UV(s, 0, jp, k);
            const float *vj1 = v + AERO_F3_UV(s, 0, j, k + 1);
            const float *vjp1 = v + AERO_F3_UV(s, 0, jp, k + 1);
            const float *wj = w + AERO_F3_C(s, 0, j, k);
            const float *wjm = w + AERO_F3_C(s, 0, jm, k);
            const float *wj1 = w + AERO_F3_C(s, 0, j, k + 1);
            const float *wjm1 = w + AERO_F3_C(s, 0, jm, k + 1);
            const size_t a = AERO_F3_UV(s, 0, j, k);
            const size_t aw = AERO_F3_C(s, 0, j, k + 1);
            /* u face (i, j+1/2, k+1/2): V and W from the cells either
               side, i - 1 and i */
#define U_FACE(i, im)                                                      \
    depart(&pt, i, (float)(i), y0, z0, uj[i],                              \
           mean4(vj[im], vj[i], vjp[im], vjp[i]),                          \
           mean4(wj[im], wj[i], wj1[im], wj1[i]), c, limx, limy)
            U_FACE(0, nx - 1);
            for (int i = 1; i < nx; i++)
                U_FACE(i, i - 1);
#undef U_FACE
            sample_into(&lu, &pt, nx, io->du + a, io->lo, io->hi, a);
            /* v face (i+1/2, j, k+1/2): U from faces i and i + 1 of rows
               j - 1 and j, W from rows j - 1 and j */
#define V_FACE(i, ip)                                                      \
    depart(&pt, i, (float)(i), y0, z0,                                     \
           mean4(ujm[i], ujm[ip], uj[i], uj[ip]), vj[i],                   \
           mean4(wjm[i], wj[i], wjm1[i], wj1[i]), c, limx, limy)
            for (int i = 0; i < nx - 1; i++)
                V_FACE(i, i + 1);
            V_FACE(nx - 1, 0);
#undef V_FACE
            sample_into(&lv, &pt, nx, io->dv + a, io->lo, io->hi, uvn + a);
            /* w face (i+1/2, j+1/2, k+1), k+1 = 1..nz */
#define W_FACE(i, ip)                                                      \
    depart(&pt, i, (float)(i), y0, z1,                                     \
           mean4(uj[i], uj[ip], uj1[i], uj1[ip]),                          \
           mean4(vj[i], vjp[i], vj1[i], vjp1[i]), wj1[i], c, limx, limy)
            for (int i = 0; i < nx - 1; i++)
                W_FACE(i, i + 1);
            W_FACE(nx - 1, 0);
#undef W_FACE
            sample_into(&lw, &pt, nx, io->dw + aw, io->lo, io->hi,
                        2 * uvn + aw);
        }
    }
}

/* the boundary layers of any u, v, w triple (as apply_boundaries) */
static void set_ghosts(const aero_flow3d *s, float *u, float *v, float *w)
{
    const size_t pl = s->plane;
    memcpy(u, s->in_u, sizeof(float) * pl);
    memcpy(v, s->in_v, sizeof(float) * pl);
    memcpy(w, s->in_w, sizeof(float) * pl);
    memcpy(u + (size_t)(s->nz + 1) * pl, u + (size_t)s->nz * pl,
           sizeof(float) * pl);
    memcpy(v + (size_t)(s->nz + 1) * pl, v + (size_t)s->nz * pl,
           sizeof(float) * pl);
}

static void swap_advected(aero_flow3d *s)
{
    float *t = s->u;
    s->u = s->u1;
    s->u1 = t;
    t = s->v;
    s->v = s->v1;
    s->v1 = t;
    t = s->w;
    s->w = s->w1;
    s->w1 = t;
}

/* half the round trip's error added back to the forward pass (u1, v1,
   w1), from the backward pass's result (bu, bv, bw): limited, clamped to
   the values the forward pass interpolated between */
static void maccormack_correct(aero_flow3d *s, const float *bu,
                               const float *bv, const float *bw, int limited)
{
    const size_t uvn = s->plane * (size_t)(s->nz + 2);
    const size_t wn = s->plane * (size_t)(s->nz + 1);
    for (int f = 0; f < 3; f++) {
        float *dst = f == 0 ? s->u1 : f == 1 ? s->v1 : s->w1;
        const float *old = f == 0 ? s->u : f == 1 ? s->v : s->w;
        const float *rt = f == 0 ? bu : f == 1 ? bv : bw;
        /* layers 0..nz-1 of u, v and 1..nz of w: the same range */
        if (limited) {
            const float *lo = s->mc_lo + f * uvn, *hi = s->mc_hi + f * uvn;
            F3_SLABS
            for (size_t a = s->plane; a < wn; a++) {
                float x = dst[a] + 0.5f * (old[a] - rt[a]);
                dst[a] = x < lo[a] ? lo[a] : x > hi[a] ? hi[a] : x;
            }
        } else {
            F3_SLABS
            for (size_t a = s->plane; a < wn; a++)
                dst[a] += 0.5f * (old[a] - rt[a]);
        }
    }
}

/* MacCormack (Selle et al. 2008): a forward pass, a backward pass of its
   result, half the round trip's error added back; limited, no new extrema
   (second order in smooth flow) */
static void maccormack(aero_flow3d *s, double dt)
{
    const size_t uvn = s->plane * (size_t)(s->nz + 2);
    float *bu = s->mc, *bv = s->mc + uvn, *bw = s->mc + 2 * uvn;
    /* lo, hi NULL when unlimited: no bounds to keep */
    const advect_io fwd = {s->u, s->v, s->w, s->u1, s->v1, s->w1,
                           s->mc_lo, s->mc_hi};
    const advect_io back = {s->u1, s->v1, s->w1, bu, bv, bw, NULL, NULL};
    advect_pass(s, &fwd, dt);
    set_ghosts(s, s->u1, s->v1, s->w1);
    set_ghosts(s, bu, bv, bw);
    advect_pass(s, &back, -dt);
    maccormack_correct(s, bu, bv, bw, s->p.advection == AERO_F3_MACCORMACK);
    swap_advected(s);
}

static void advect(aero_flow3d *s, double dt)
{
    if (s->p.advection == AERO_F3_SEMI_LAGRANGIAN) {
        const advect_io io = {s->u, s->v, s->w, s->u1, s->v1, s->w1,
                              NULL, NULL};
        advect_pass(s, &io, dt);
        swap_advected(s); /* boundary layers are set again later */
        return;
    }
    maccormack(s, dt);
}

/* cell-centred velocity into cx, cy, cz */
static void centre_velocity(aero_flow3d *s)
{
    const int nx = s->nx, ny = s->ny;
    const size_t pl = s->plane;
    F3_SLABS
    for (int k = 0; k < s->nz; k++)
        for (int j = 0; j < ny; j++) {
            const int jp = j + 1 == ny ? 0 : j + 1;
            const size_t c = AERO_F3_C(s, 0, j, k);
            const float *u = s->u + AERO_F3_UV(s, 0, j, k);
            const float *v = s->v + AERO_F3_UV(s, 0, j, k);
            const float *vp = s->v + AERO_F3_UV(s, 0, jp, k);
            const float *w = s->w + c, *wp = w + pl;
            float *cx = s->cx + c, *cy = s->cy + c, *cz = s->cz + c;
#define CENTRE_CELL(i, im, ip)                                             \
    do {                                                                   \
        (void)(im);                                                        \
        cx[i] = 0.5f * (u[i] + u[ip]);                                     \
        cy[i] = 0.5f * (v[i] + vp[i]);                                     \
        cz[i] = 0.5f * (w[i] + wp[i]);                                     \
    } while (0)
            F3_ROW(nx, CENTRE_CELL);
#undef CENTRE_CELL
        }
}

/* row j of layer k of the cell-centred fields: its first cell c, the
   offsets to the same cell in the rows either side across the periodic y
   side (ym, yp) and in the layers above and below (up, down), and the
   weight of their difference: d/dz is centred inside, one-sided in the
   first and last layer */
typedef struct {
    size_t c;
    ptrdiff_t ym, yp, up, down;
    float half;
} row_stencil;

static inline row_stencil stencil_at(const aero_flow3d *s, int j, int k)
{
    const int ny = s->ny, nz = s->nz;
    const int jm = j ? j - 1 : ny - 1, jp = j + 1 == ny ? 0 : j + 1;
    row_stencil r;
    r.c = AERO_F3_C(s, 0, j, k);
    r.ym = ((ptrdiff_t)jm - j) * s->nx;
    r.yp = ((ptrdiff_t)jp - j) * s->nx;
    r.up = k + 1 < nz ? (ptrdiff_t)s->plane : 0;
    r.down = k > 0 ? (ptrdiff_t)s->plane : 0;
    r.half = k > 0 && k + 1 < nz ? 0.5f : 1.0f;
    return r;
}

/* the vorticity of one row (its cells from r.c on) and its magnitude */
AERO_CLONES
static void vorticity_row(const aero_flow3d *s, row_stencil r, float ih)
{
    const int nx = s->nx;
    const size_t c = r.c;
    const ptrdiff_t ym = r.ym, yp = r.yp, up = r.up, down = r.down;
    const float half = r.half;
    const float *cx = s->cx + c, *cy = s->cy + c, *cz = s->cz + c;
    float *ox = s->ox + c, *oy = s->oy + c, *oz = s->oz + c;
    float *om = s->omag + c;
#define VORTICITY_CELL(i, im, ip)                                          \
    do {                                                                   \
        const float dwdy = 0.5f * (cz[yp + i] - cz[ym + i]);               \
        const float dvdz = half * (cy[up + i] - cy[i - down]);             \
        const float dudz = half * (cx[up + i] - cx[i - down]);             \
        const float dwdx = 0.5f * (cz[ip] - cz[im]);                       \
        const float dvdx = 0.5f * (cy[ip] - cy[im]);                       \
        const float dudy = 0.5f * (cx[yp + i] - cx[ym + i]);               \
        const float wx = (dwdy - dvdz) * ih, wy = (dudz - dwdx) * ih,      \
                    wz = (dvdx - dudy) * ih;                               \
        ox[i] = wx;                                                        \
        oy[i] = wy;                                                        \
        oz[i] = wz;                                                        \
        om[i] = sqrtf(wx * wx + wy * wy + wz * wz);                        \
    } while (0)
    F3_ROW_SIMD(nx, VORTICITY_CELL);
#undef VORTICITY_CELL
}

void aero_flow3d_vorticity(aero_flow3d *s)
{
    const int ny = s->ny, nz = s->nz;
    const float ih = (float)(1.0 / s->p.h);
    centre_velocity(s);
    F3_SLABS
    for (int k = 0; k < nz; k++)
        for (int j = 0; j < ny; j++)
            vorticity_row(s, stencil_at(s, j, k), ih);
}

/* the confinement force of one row (its cells from r.c on) into cx, cy,
   cz; none in the cells next to the body (near_body) */
AERO_CLONES
static void confine_row(const aero_flow3d *s, row_stencil r, float a)
{
    const int nx = s->nx;
    const size_t c = r.c;
    const ptrdiff_t ym = r.ym, yp = r.yp, up = r.up, down = r.down;
    const float half = r.half;
    const float *om = s->omag + c;
    const float *ox = s->ox + c, *oy = s->oy + c, *oz = s->oz + c;
    const unsigned char *nb = s->near_body ? s->near_body + c : NULL;
    float *fx = s->cx + c, *fy = s->cy + c, *fz = s->cz + c;
#define CONFINE_CELL(i, im, ip, MASK)                                      \
    do {                                                                   \
        const float gx = 0.5f * (om[ip] - om[im]);                         \
        const float gy = 0.5f * (om[yp + i] - om[ym + i]);                 \
        const float gz = half * (om[up + i] - om[i - down]);               \
        const float g = sqrtf(gx * gx + gy * gy + gz * gz);                \
        float inv = g > 1e-20f ? a / g : 0.0f;                             \
        MASK(i);                                                           \
        fx[i] = (gy * inv) * oz[i] - (gz * inv) * oy[i];                   \
        fy[i] = (gz * inv) * ox[i] - (gx * inv) * oz[i];                   \
        fz[i] = (gx * inv) * oy[i] - (gy * inv) * ox[i];                   \
    } while (0)
#define NEAR_BODY_MASK(i) (inv = nb[i] ? 0.0f : inv)
#define NO_MASK(i) ((void)0)
#define CONFINE_NEAR_BODY(i, im, ip) CONFINE_CELL(i, im, ip, NEAR_BODY_MASK)
#define CONFINE_FREE(i, im, ip) CONFINE_CELL(i, im, ip, NO_MASK)
    /* two loops, so that neither tests for the mask in every cell */
    if (nb)
        F3_ROW_SIMD(nx, CONFINE_NEAR_BODY);
    else
        F3_ROW_SIMD(nx, CONFINE_FREE);
#undef CONFINE_FREE
#undef CONFINE_NEAR_BODY
#undef NO_MASK
#undef NEAR_BODY_MASK
#undef CONFINE_CELL
}

/* vorticity confinement (Fedkiw et al. 2001, eq. 11-12): a = eps (h / L) U_ref
   (N x omega) at the cell centres, averaged onto the faces */
static void confine(aero_flow3d *s, double dt)
{
    const int nx = s->nx, ny = s->ny, nz = s->nz;
    const double h_over_l = s->p.confinement_length > 0.0
                                ? s->p.h / s->p.confinement_length
                                : 1.0;
    const float a = (float)(s->p.confinement * h_over_l * s->p.u_ref * dt);
    const size_t pl = s->plane;
    aero_flow3d_vorticity(s);
    /* the force goes into cx, cy, cz (the centred velocity is not needed
       any more) */
    F3_SLABS
    for (int k = 0; k < nz; k++)
        for (int j = 0; j < ny; j++)
            confine_row(s, stencil_at(s, j, k), a);
    F3_SLABS
    for (int k = 0; k < nz; k++)
        for (int j = 0; j < ny; j++) {
            const int jm = j ? j - 1 : ny - 1;
            const size_t c = AERO_F3_C(s, 0, j, k);
            const float *fx = s->cx + c, *fy = s->cy + c, *fz = s->cz + c;
            const float *fym = s->cy + AERO_F3_C(s, 0, jm, k);
            float *u = s->u + AERO_F3_UV(s, 0, j, k);
            float *v = s->v + AERO_F3_UV(s, 0, j, k);
            float *w = s->w + c;
#define FACE_FORCE(i, im, ip)                                              \
    do {                                                                   \
        (void)(ip);                                                        \
        u[i] += 0.5f * (fx[i] + fx[im]);                                   \
        v[i] += 0.5f * (fy[i] + fym[i]);                                   \
    } while (0)
            F3_ROW(nx, FACE_FORCE);
#undef FACE_FORCE
            if (k > 0)
                for (int i = 0; i < nx; i++)
                    w[i] += 0.5f * (fz[i] + fz[i - (ptrdiff_t)pl]);
        }
    for (size_t c = 0; c < pl; c++) /* the top face: its one cell */
        s->w[(size_t)nz * pl + c] += s->cz[(size_t)(nz - 1) * pl + c];
}

/* explicit nu lap(u) on one face field (layers k0..k1 updated); src has
   valid neighbours one layer beyond */
static void diffuse_field(const aero_flow3d *s, const float *src, float *dst,
                          int k0, int k1, int uv, float r)
{
    const int nx = s->nx, ny = s->ny;
    const size_t pl = s->plane;
    F3_SLABS
    for (int k = k0; k <= k1; k++)
        for (int j = 0; j < ny; j++) {
            const int jm = j ? j - 1 : ny - 1, jp = j + 1 == ny ? 0 : j + 1;
            const size_t c = uv ? AERO_F3_UV(s, 0, j, k) : AERO_F3_C(s, 0, j, k);
            const float *row = src + c, *below = row - pl, *above = row + pl;
            const float *rm = src + c + ((ptrdiff_t)jm - j) * nx;
            const float *rp = src + c + ((ptrdiff_t)jp - j) * nx;
            float *out = dst + c;
#define DIFFUSE_CELL(i, im, ip)                                            \
    out[i] = row[i] + r * (row[im] + row[ip] + rm[i] + rp[i] + below[i] +  \
                           above[i] - 6.0f * row[i])
            F3_ROW(nx, DIFFUSE_CELL);
#undef DIFFUSE_CELL
        }
}

static void diffuse(aero_flow3d *s, double dt)
{
    const float r = (float)(s->p.nu * dt / (s->p.h * s->p.h));
    const size_t uvn = s->plane * (s->nz + 2), wn = s->plane * (s->nz + 1);
    float *t;
    apply_boundaries(s);
    memcpy(s->u1, s->u, sizeof(float) * uvn);
    memcpy(s->v1, s->v, sizeof(float) * uvn);
    memcpy(s->w1, s->w, sizeof(float) * wn);
    diffuse_field(s, s->u, s->u1, 0, s->nz - 1, 1, r);
    diffuse_field(s, s->v, s->v1, 0, s->nz - 1, 1, r);
    /* w: faces 1..nz-1 (the top face keeps its advected value) */
    diffuse_field(s, s->w, s->w1, 1, s->nz - 1, 0, r);
    t = s->u; s->u = s->u1; s->u1 = t;
    t = s->v; s->v = s->v1; s->v1 = t;
    t = s->w; s->w = s->w1; s->w1 = t;
}

/* h^2 div u into phi, the right-hand side of the pressure solve (h^2
   lap phi = h^2 div u) */
static void divergence(aero_flow3d *s)
{
    const int nx = s->nx, ny = s->ny, nz = s->nz;
    const size_t pl = s->plane;
    const float h = (float)s->p.h;
    F3_SLABS
    for (int k = 0; k < nz; k++)
        for (int j = 0; j < ny; j++) {
            const int jp = j + 1 == ny ? 0 : j + 1;
            const float *u = s->u + AERO_F3_UV(s, 0, j, k);
            const float *v = s->v + AERO_F3_UV(s, 0, j, k);
            const float *vp = s->v + AERO_F3_UV(s, 0, jp, k);
            const float *w = s->w + AERO_F3_C(s, 0, j, k), *wp = w + pl;
            float *phi = s->phi + AERO_F3_C(s, 0, j, k);
#define DIVERGENCE_CELL(i, im, ip)                                         \
    do {                                                                   \
        (void)(im);                                                        \
        phi[i] = h * (u[ip] - u[i] + vp[i] - v[i] + wp[i] - w[i]);         \
    } while (0)
            F3_ROW(nx, DIVERGENCE_CELL);
#undef DIVERGENCE_CELL
        }
}

/* the tridiagonal along z per (kx, ky) of the transformed right-hand side
   (sub- and super-diagonal 1, factors from factor_poisson): the modes in
   blocks, each swept layer by layer, so that the loops over a block's
   modes vectorise */
static void solve_modes_z(aero_flow3d *s)
{
    const int ny = s->ny, nz = s->nz, nxh = s->nx / 2 + 1;
    const size_t stride = (size_t)nxh * ny, block = 64;
    const int blocks = (int)((stride + block - 1) / block);
    float *d = (float *)s->spec; /* re, im interleaved */
    F3_SLABS
    for (int b = 0; b < blocks; b++) {
        const size_t m0 = (size_t)b * block;
        const size_t m1 = m0 + block < stride ? m0 + block : stride;
        for (size_t m = m0; m < m1; m++) {
            d[2 * m] *= s->tri_m[m];
            d[2 * m + 1] *= s->tri_m[m];
        }
        for (int k = 1; k < nz; k++) {
            const float *q = s->tri_m + (size_t)k * stride;
            float *dk = d + 2 * (size_t)k * stride, *dl = dk - 2 * stride;
            for (size_t m = m0; m < m1; m++) {
                dk[2 * m] = (dk[2 * m] - dl[2 * m]) * q[m];
                dk[2 * m + 1] = (dk[2 * m + 1] - dl[2 * m + 1]) * q[m];
            }
        }
        for (int k = nz - 2; k >= 0; k--) {
            const float *q = s->tri_m + (size_t)k * stride;
            float *dk = d + 2 * (size_t)k * stride, *du = dk + 2 * stride;
            for (size_t m = m0; m < m1; m++) {
                dk[2 * m] -= q[m] * du[2 * m];
                dk[2 * m + 1] -= q[m] * du[2 * m + 1];
            }
        }
    }
}

/* u -= grad phi (phi scaled by the unnormalised inverse FFT) */
static void subtract_gradient(aero_flow3d *s)
{
    const int nx = s->nx, ny = s->ny, nz = s->nz;
    const size_t pl = s->plane;
    const float h = (float)s->p.h, ih = 1.0f / h;
    const float norm = 1.0f / (float)(nx * ny);
    const float g = norm * ih;
    F3_SLABS
    for (int k = 0; k < nz; k++)
        for (int j = 0; j < ny; j++) {
            const int jm = j ? j - 1 : ny - 1;
            const float *p = s->phi + AERO_F3_C(s, 0, j, k);
            const float *pm = s->phi + AERO_F3_C(s, 0, jm, k);
            float *u = s->u + AERO_F3_UV(s, 0, j, k);
            float *v = s->v + AERO_F3_UV(s, 0, j, k);
            float *w = s->w + AERO_F3_C(s, 0, j, k);
#define GRADIENT_CELL(i, im, ip)                                           \
    do {                                                                   \
        (void)(ip);                                                        \
        u[i] -= g * (p[i] - p[im]);                                        \
        v[i] -= g * (p[i] - pm[i]);                                        \
    } while (0)
            F3_ROW(nx, GRADIENT_CELL);
#undef GRADIENT_CELL
            if (k > 0)
                for (int i = 0; i < nx; i++)
                    w[i] -= g * (p[i] - p[i - (ptrdiff_t)pl]);
        }
    /* top face: phi = 0 there, so the ghost value is -phi[nz-1] */
    for (size_t c = 0; c < pl; c++)
        s->w[(size_t)nz * pl + c] += 2.0f * g * s->phi[(size_t)(nz - 1) * pl + c];
}

/* the projection of Stam 1999: lap phi = div u solved by FFTs across the
   periodic x and y and a tridiagonal along z, then u -= grad phi */
void aero_flow3d_project(aero_flow3d *s)
{
    apply_boundaries(s);
    divergence(s);
    fftwf_execute(s->fwd);
    solve_modes_z(s);
    fftwf_execute(s->inv);
    subtract_gradient(s);
    apply_boundaries(s);
}

double aero_flow3d_max_divergence(const aero_flow3d *s)
{
    const int nx = s->nx, ny = s->ny, nz = s->nz;
    double worst = 0.0;
    for (int k = 0; k < nz; k++)
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++) {
                int ip = i + 1 == nx ? 0 : i + 1, jp = j + 1 == ny ? 0 : j + 1;
                size_t c = AERO_F3_C(s, i, j, k);
                double d = (double)s->u[AERO_F3_UV(s, ip, j, k)] -
                           s->u[AERO_F3_UV(s, i, j, k)] +
                           s->v[AERO_F3_UV(s, i, jp, k)] -
                           s->v[AERO_F3_UV(s, i, j, k)] +
                           s->w[c + s->plane] - s->w[c];
                if (fabs(d) > worst) worst = fabs(d);
            }
    return worst;
}

double aero_flow3d_energy(const aero_flow3d *s)
{
    double e = 0.0, h3 = s->p.h * s->p.h * s->p.h;
    for (int k = 0; k < s->nz; k++)
        for (size_t c = 0; c < s->plane; c++) {
            double a = s->u[(size_t)(k + 1) * s->plane + c];
            double b = s->v[(size_t)(k + 1) * s->plane + c];
            double d = s->w[(size_t)k * s->plane + c];
            e += a * a + b * b + d * d;
        }
    return 0.5 * e * h3;
}

/* absorbing layer: relax towards (0, 0, u_ref) at a rate growing as the
   square of the depth into the layer, up to u_ref / h at the top */
static void sponge(aero_flow3d *s, double dt)
{
    const int nz = s->nz;
    /* heights in the whole grid (a window's from its origin) */
    const int nzt = s->p.nz_total > 0 ? s->p.nz_total : nz;
    const int kor = s->p.nz_total > 0 ? s->p.k_origin : 0;
    const double z0 = (1.0 - s->p.sponge) * nzt, rate = s->p.u_ref / s->p.h;
    const float target = (float)s->p.u_ref;
    for (int k = 0; k <= nz; k++) {
        double zc = kor + k + 0.5, zf = kor + k, qc, qf;
        float ac, af;
        qc = zc > z0 ? (zc - z0) / (nzt - z0) : 0.0;
        qf = zf > z0 ? (zf - z0) / (nzt - z0) : 0.0;
        if (qf <= 0.0 && qc <= 0.0)
            continue;
        ac = (float)exp(-dt * rate * qc * qc);
        af = (float)exp(-dt * rate * qf * qf);
        if (k < nz) {
            float *u = s->u + AERO_F3_UV(s, 0, 0, k);
            float *v = s->v + AERO_F3_UV(s, 0, 0, k);
            for (size_t c = 0; c < s->plane; c++) {
                u[c] *= ac;
                v[c] *= ac;
            }
        }
        if (k > 0) {
            float *w = s->w + AERO_F3_C(s, 0, 0, k);
            for (size_t c = 0; c < s->plane; c++)
                w[c] = target + (w[c] - target) * af;
        }
    }
}

/* the cells whose low faces the forcing must visit: a face is solid only
   when one of its two cells is, so the solid cells' box and one cell past
   its high side (the whole width across a periodic side the box touches) */
static void body_box(aero_flow3d *s, const float *solid)
{
    const int n[3] = {s->nx, s->ny, s->nz};
    int lo[3] = {n[0], n[1], n[2]}, hi[3] = {-1, -1, -1};
    for (int k = 0; k < n[2]; k++)
        for (int j = 0; j < n[1]; j++)
            for (int i = 0; i < n[0]; i++) {
                const int at[3] = {i, j, k};
                if (!(solid[AERO_F3_C(s, i, j, k)] > 0.0f))
                    continue;
                for (int d = 0; d < 3; d++) {
                    if (at[d] < lo[d]) lo[d] = at[d];
                    if (at[d] > hi[d]) hi[d] = at[d];
                }
            }
    for (int d = 0; d < 3; d++) {
        if (hi[d] < 0) { /* no solid cell: an empty range */
            s->body_lo[d] = 0;
            s->body_hi[d] = -1;
            continue;
        }
        s->body_lo[d] = lo[d];
        s->body_hi[d] = hi[d] + 1 < n[d] ? hi[d] + 1 : n[d] - 1;
        if (d < 2 && (lo[d] == 0 || hi[d] + 1 >= n[d])) {
            s->body_lo[d] = 0;
            s->body_hi[d] = n[d] - 1;
        }
    }
}

/* the cells within NEAR_BODY_CELLS of the body, where vorticity
   confinement is off: it would push the boundary layer along the wall,
   and the body would feel that push as a force (a capsule along the flow
   showed a negative drag). Left NULL when out of memory: confinement
   everywhere */
static void mark_near_body(aero_flow3d *s, const float *solid)
{
    const int nx = s->nx, ny = s->ny, nz = s->nz, r = NEAR_BODY_CELLS;
    s->near_body = calloc(s->plane * (size_t)nz, 1);
    if (!s->near_body)
        return;
    for (int k = 0; k < nz; k++)
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++) {
                if (!(solid[AERO_F3_C(s, i, j, k)] > 0.0f))
                    continue;
                for (int dk = -r; dk <= r; dk++) {
                    const int kk = k + dk;
                    if (kk < 0 || kk >= nz)
                        continue;
                    for (int dj = -r; dj <= r; dj++)
                        for (int di = -r; di <= r; di++)
                            s->near_body[AERO_F3_C(s, wrap(i + di, nx),
                                                   wrap(j + dj, ny), kk)] = 1;
                }
            }
}

void aero_flow3d_set_body(aero_flow3d *s, const float *solid,
                          const int *region, int n_regions, double *force)
{
    free(s->near_body);
    s->near_body = NULL;
    if (solid) {
        mark_near_body(s, solid);
        body_box(s, solid);
    }
    s->solid = solid;
    s->region = solid ? region : NULL;
    s->n_regions = solid && force ? n_regions : 0;
    s->region_force = solid ? force : NULL;
}

void aero_flow3d_set_window(aero_flow3d *s, int own_lo, int own_hi,
                            void (*project)(void *ctx, aero_flow3d *s),
                            void *ctx)
{
    s->project_hook = project;
    s->project_ctx = project ? ctx : NULL;
    s->own_lo = project ? own_lo : 0;
    s->own_hi = project ? own_hi : s->nz;
}

/* direct forcing of a body at rest: each face velocity times
   (1 - chi_face); the removed momentum, per region, is the force on the
   body (flow3d.h) */
static void force_body(aero_flow3d *s, double dt)
{
    const int nx = s->nx, ny = s->ny;
    const size_t pl = s->plane;
    const float *chi = s->solid;
    const int *reg = s->region;
    const int nr = s->n_regions;
    const double scale = s->p.h * s->p.h * s->p.h / dt;
    double *F = s->region_force;
    if (F)
        memset(F, 0, sizeof(double) * 3 * (size_t)nr);
    for (int k = s->body_lo[2]; k <= s->body_hi[2]; k++)
        for (int j = s->body_lo[1]; j <= s->body_hi[1]; j++) {
            int jm = j ? j - 1 : ny - 1;
            for (int i = s->body_lo[0]; i <= s->body_hi[0]; i++) {
                int im = i ? i - 1 : nx - 1;
                size_t c = AERO_F3_C(s, i, j, k);
                size_t n3[3] = {AERO_F3_C(s, im, j, k), AERO_F3_C(s, i, jm, k),
                                k > 0 ? c - pl : c};
                float *vel[3] = {&s->u[AERO_F3_UV(s, i, j, k)],
                                 &s->v[AERO_F3_UV(s, i, j, k)], &s->w[c]};
                float a = chi[c];
                for (int d = 0; d < 3; d++) {
                    float b = chi[n3[d]], f;
                    if (d == 2 && k == 0) /* the inflow face is given */
                        continue;
                    /* a sharp wall: a face is solid when its two cells are
                       at least half solid together (a fractional weight
                       let the boundary layer leak through the wall and
                       delayed separation: a sphere shed at St 0.11
                       instead of 0.13 on 8 cells per d) */
                    f = 0.5f * (a + b) >= 0.5f ? 1.0f : 0.0f;
                    if (f <= 0.0f)
                        continue;
                    if (F && reg && k >= s->own_lo && k < s->own_hi) {
                        int r = a >= b ? reg[c] : reg[n3[d]];
                        if (r >= 0 && r < nr)
                            F[3 * r + d] += scale * f * *vel[d];
                    }
                    *vel[d] *= 1.0f - f;
                }
            }
        }
}

/* a cheap finiteness check on one layer per step: 0, or -1 (NaN, or a
   blown-up flow) */
static int check_finite(const aero_flow3d *s)
{
    const float *w = s->w + (size_t)(s->nz / 2) * s->plane;
    float acc = 0.0f;
    for (size_t c = 0; c < s->plane; c++)
        acc += w[c];
    return !(acc == acc) || fabsf(acc) > 1e30f ? -1 : 0;
}

/* one step of the split of Stam 1999 and Fedkiw et al. 2001: advect,
   confine the vorticity, diffuse, damp in the outflow's sponge, force the
   body (Fadlun et al. 2000), project onto divergence-free fields */
int aero_flow3d_step(aero_flow3d *s, double dt)
{
    apply_boundaries(s);
    advect(s, dt);
    apply_boundaries(s);
    if (s->p.confinement > 0.0 && s->p.u_ref > 0.0) {
        confine(s, dt);
        apply_boundaries(s);
    }
    if (s->p.nu > 0.0)
        diffuse(s, dt);
    if (s->p.sponge > 0.0 && s->p.u_ref > 0.0)
        sponge(s, dt);
    if (s->solid)
        force_body(s, dt);
    if (s->project_hook)
        s->project_hook(s->project_ctx, s);
    else
        aero_flow3d_project(s);
    s->t += dt;
    return check_finite(s);
}

/* the fields of the state between steps, with their lengths (floats) */
static int state_fields(const aero_flow3d *s, float **f, size_t *n)
{
    const size_t uvn = s->plane * (s->nz + 2), wn = s->plane * (s->nz + 1);
    float *const fields[] = {s->u, s->v, s->w, s->in_u, s->in_v, s->in_w,
                             s->phi};
    const size_t lens[] = {uvn, uvn, wn, s->plane, s->plane, s->plane,
                           s->plane * s->nz};
    for (int q = 0; q < 7; q++) {
        f[q] = fields[q];
        n[q] = lens[q];
    }
    return 7;
}

size_t aero_flow3d_state_size(const aero_flow3d *s)
{
    float *f[7];
    size_t n[7], bytes = sizeof s->t;
    const int count = state_fields(s, f, n);
    for (int q = 0; q < count; q++)
        bytes += sizeof(float) * n[q];
    return bytes;
}

void aero_flow3d_state_save(const aero_flow3d *s, void *buf)
{
    float *f[7];
    size_t n[7];
    const int count = state_fields(s, f, n);
    char *p = buf;
    memcpy(p, &s->t, sizeof s->t);
    p += sizeof s->t;
    for (int q = 0; q < count; q++) {
        memcpy(p, f[q], sizeof(float) * n[q]);
        p += sizeof(float) * n[q];
    }
}

void aero_flow3d_state_load(aero_flow3d *s, const void *buf)
{
    float *f[7];
    size_t n[7];
    const int count = state_fields(s, f, n);
    const char *p = buf;
    memcpy(&s->t, p, sizeof s->t);
    p += sizeof s->t;
    for (int q = 0; q < count; q++) {
        memcpy(f[q], p, sizeof(float) * n[q]);
        p += sizeof(float) * n[q];
    }
}
