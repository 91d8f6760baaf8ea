/* aerotex-mpi: the pressure projection of a 3D flow in z slabs over MPI
 * ranks (see flow3d_slab.h). */
#include "flow3d_slab.h"
#include "flow3d.h"

#include <fftw3-mpi.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* flow3d.c's factors, for this rank's ky rows only */
static void slab_factor(aero_flow3d_slab *s)
{
    const int nxh = s->nx / 2 + 1;
    for (ptrdiff_t yl = 0; yl < s->nyl; yl++)
        for (int kx = 0; kx < nxh; kx++)
            aero_flow3d_poisson_factors(s->nx, s->ny, s->nz, kx,
                                        (int)(s->ky0 + yl),
                                        s->tri_m + (size_t)yl * s->nz * nxh +
                                            kx,
                                        (size_t)nxh);
}

int aero_flow3d_slab_init(aero_flow3d_slab *s, MPI_Comm comm, int nx, int ny,
                          int nz, double h, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    if (nx < 4 || ny < 4 || nz < 3 || (nx & 1) || (ny & 1) || !(h > 0.0)) {
        snprintf(err, errlen, "grid %d x %d x %d: nx, ny even and >= 4, "
                 "nz >= 3", nx, ny, nz);
        return -1;
    }
    fftwf_mpi_init(); /* once per process; later calls return at once */
    s->comm = comm;
    MPI_Comm_rank(comm, &s->rank);
    MPI_Comm_size(comm, &s->size);
    s->nx = nx;
    s->ny = ny;
    s->nz = nz;
    s->h = h;
    s->halo = 1;
    s->plane = (size_t)nx * ny;
    const int nxh = nx / 2 + 1;
    const ptrdiff_t block = 2 * (ptrdiff_t)nxh; /* a row of complex */
    ptrdiff_t alloc = fftwf_mpi_local_size_many_transposed(
        2, (ptrdiff_t[]){nz, ny}, block, FFTW_MPI_DEFAULT_BLOCK,
        FFTW_MPI_DEFAULT_BLOCK, comm, &s->nl, &s->k0, &s->nyl, &s->ky0);
    int ok = s->nl > 0 && s->nyl > 0, all;
    MPI_Allreduce(&ok, &all, 1, MPI_INT, MPI_MIN, comm);
    if (!all) {
        snprintf(err, errlen, "%d ranks for %d planes and %d rows: every "
                 "rank needs a plane and a row (fewer ranks)", s->size, nz,
                 ny);
        return -1;
    }
    const size_t pl = s->plane, nl = (size_t)s->nl;
    s->u = calloc((nl + 2) * pl, sizeof(float));
    s->v = calloc((nl + 2) * pl, sizeof(float));
    s->w = calloc((nl + 1) * pl, sizeof(float));
    s->in_u = calloc(pl, sizeof(float));
    s->in_v = calloc(pl, sizeof(float));
    s->in_w = calloc(pl, sizeof(float));
    s->phi = fftwf_alloc_real((nl + 1) * pl);
    s->spec = fftwf_alloc_real((size_t)alloc);
    s->tri_m = calloc((size_t)s->nyl * nz * nxh, sizeof(float));
    ok = s->u && s->v && s->w && s->in_u && s->in_v && s->in_w && s->phi &&
         s->spec && s->tri_m;
    if (ok) {
        const int n[2] = {ny, nx};
        s->fwd = fftwf_plan_many_dft_r2c(
            2, n, (int)nl, s->phi + pl, NULL, 1, (int)pl,
            (fftwf_complex *)s->spec, NULL, 1, nxh * ny, FFTW_ESTIMATE);
        s->inv = fftwf_plan_many_dft_c2r(
            2, n, (int)nl, (fftwf_complex *)s->spec, NULL, 1, nxh * ny,
            s->phi + pl, NULL, 1, (int)pl, FFTW_ESTIMATE);
        s->there = fftwf_mpi_plan_many_transpose(
            nz, ny, block, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK,
            s->spec, s->spec, comm, FFTW_ESTIMATE);
        s->back = fftwf_mpi_plan_many_transpose(
            ny, nz, block, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK,
            s->spec, s->spec, comm, FFTW_ESTIMATE);
        ok = s->fwd && s->inv && s->there && s->back;
    }
    MPI_Allreduce(&ok, &all, 1, MPI_INT, MPI_MIN, comm);
    if (!all) {
        aero_flow3d_slab_free(s);
        snprintf(err, errlen, "out of memory or no FFTW plan for a %d x %d "
                 "x %d slab", nx, ny, nz);
        return -1;
    }
    slab_factor(s);
    return 0;
}

void aero_flow3d_slab_free(aero_flow3d_slab *s)
{
    void *plans[] = {s->fwd, s->inv, s->there, s->back};
    for (int q = 0; q < 4; q++)
        if (plans[q]) fftwf_destroy_plan(plans[q]);
    free(s->u);
    free(s->v);
    free(s->w);
    free(s->in_u);
    free(s->in_v);
    free(s->in_w);
    free(s->tri_m);
    if (s->phi) fftwf_free(s->phi);
    if (s->spec) fftwf_free(s->spec);
    memset(s, 0, sizeof *s);
}

/* inflow on the first rank, the zero-gradient top on the last (flow3d.c's
   apply_boundaries) */
static void slab_boundaries(aero_flow3d_slab *s)
{
    const size_t pl = s->plane, nl = (size_t)s->nl;
    if (s->rank == 0) {
        memcpy(s->u, s->in_u, sizeof(float) * pl);
        memcpy(s->v, s->in_v, sizeof(float) * pl);
        memcpy(s->w, s->in_w, sizeof(float) * pl);
    }
    if (s->rank == s->size - 1) {
        memcpy(s->u + (nl + 1) * pl, s->u + nl * pl, sizeof(float) * pl);
        memcpy(s->v + (nl + 1) * pl, s->v + nl * pl, sizeof(float) * pl);
    }
}

/* one plane of floats: send to `to`, receive from `from` (MPI_PROC_NULL
   past the ends) */
static void exchange(aero_flow3d_slab *s, const float *send, int to,
                     float *recv, int from)
{
    if (!s->halo) return;
    MPI_Sendrecv(send, (int)s->plane, MPI_FLOAT, to, 53, recv,
                 (int)s->plane, MPI_FLOAT, from, 53, s->comm,
                 MPI_STATUS_IGNORE);
    if (to != MPI_PROC_NULL) s->bytes_sent += 4.0 * (double)s->plane;
}

/* the tridiagonal along z of flow3d.c's solve_modes_z, on the transposed
   spectrum [ky - ky0][k][kx] */
static void slab_solve_z(aero_flow3d_slab *s)
{
    const int nz = s->nz, nxh = s->nx / 2 + 1;
    for (ptrdiff_t yl = 0; yl < s->nyl; yl++) {
        float *d = s->spec + 2 * (size_t)yl * nz * nxh;
        const float *m = s->tri_m + (size_t)yl * nz * nxh;
        for (int kx = 0; kx < nxh; kx++) {
            d[2 * kx] *= m[kx];
            d[2 * kx + 1] *= m[kx];
        }
        for (int k = 1; k < nz; k++) {
            const float *q = m + (size_t)k * nxh;
            float *dk = d + 2 * (size_t)k * nxh, *dl = dk - 2 * nxh;
            for (int kx = 0; kx < nxh; kx++) {
                dk[2 * kx] = (dk[2 * kx] - dl[2 * kx]) * q[kx];
                dk[2 * kx + 1] = (dk[2 * kx + 1] - dl[2 * kx + 1]) * q[kx];
            }
        }
        for (int k = nz - 2; k >= 0; k--) {
            const float *q = m + (size_t)k * nxh;
            float *dk = d + 2 * (size_t)k * nxh, *du = dk + 2 * nxh;
            for (int kx = 0; kx < nxh; kx++) {
                dk[2 * kx] -= q[kx] * du[2 * kx];
                dk[2 * kx + 1] -= q[kx] * du[2 * kx + 1];
            }
        }
    }
}

void aero_flow3d_slab_project(aero_flow3d_slab *s)
{
    const int nx = s->nx, ny = s->ny, nxh = nx / 2 + 1;
    const size_t pl = s->plane, nl = (size_t)s->nl;
    const int up = s->rank + 1 < s->size ? s->rank + 1 : MPI_PROC_NULL;
    const int down = s->rank > 0 ? s->rank - 1 : MPI_PROC_NULL;
    const float h = (float)s->h, ih = 1.0f / h;
    const float g = 1.0f / (float)(nx * ny) * ih;
    slab_boundaries(s);
    /* the face above the slab: the next rank's first face */
    exchange(s, s->w, down, s->w + nl * pl, up);
    for (size_t k = 0; k < nl; k++)
        for (int j = 0; j < ny; j++) {
            const int jp = j + 1 == ny ? 0 : j + 1;
            const float *u = s->u + AERO_SLAB_UV(s, 0, j, (ptrdiff_t)k);
            const float *v = s->v + AERO_SLAB_UV(s, 0, j, (ptrdiff_t)k);
            const float *vp = s->v + AERO_SLAB_UV(s, 0, jp, (ptrdiff_t)k);
            const float *w = s->w + AERO_SLAB_C(s, 0, j, k), *wp = w + pl;
            float *phi = s->phi + pl + AERO_SLAB_C(s, 0, j, k);
            for (int i = 0; i < nx; i++) {
                const int ip = i + 1 == nx ? 0 : i + 1;
                phi[i] = h * (u[ip] - u[i] + vp[i] - v[i] + wp[i] - w[i]);
            }
        }
    fftwf_execute(s->fwd);
    fftwf_execute(s->there);
    slab_solve_z(s);
    fftwf_execute(s->back);
    fftwf_execute(s->inv);
    /* both transposes: this rank's blocks for the other ranks */
    s->bytes_sent += 4.0 * 2.0 * nxh *
                     ((double)nl * (ny - (double)s->nyl) +
                      (double)s->nyl * (s->nz - (double)nl));
    /* the potential of the plane below the slab: the previous rank's last */
    exchange(s, s->phi + nl * pl, up, s->phi, down);
    for (size_t k = 0; k < nl; k++)
        for (int j = 0; j < ny; j++) {
            const int jm = j ? j - 1 : ny - 1;
            const float *p = s->phi + pl + AERO_SLAB_C(s, 0, j, k);
            const float *pm = s->phi + pl + AERO_SLAB_C(s, 0, jm, k);
            float *u = s->u + AERO_SLAB_UV(s, 0, j, (ptrdiff_t)k);
            float *v = s->v + AERO_SLAB_UV(s, 0, j, (ptrdiff_t)k);
            float *w = s->w + AERO_SLAB_C(s, 0, j, k);
            for (int i = 0; i < nx; i++) {
                const int im = i ? i - 1 : nx - 1;
                u[i] -= g * (p[i] - p[im]);
                v[i] -= g * (p[i] - pm[i]);
            }
            if (s->k0 + (ptrdiff_t)k > 0)
                for (int i = 0; i < nx; i++)
                    w[i] -= g * (p[i] - p[i - (ptrdiff_t)pl]);
        }
    if (up == MPI_PROC_NULL) /* the open top: phi = 0 on the face */
        for (size_t c = 0; c < pl; c++)
            s->w[nl * pl + c] += 2.0f * g * s->phi[nl * pl + c];
    slab_boundaries(s);
}

/* ---- the whole step over slabs: windows with halos ---- */

/* the layers of u and v and the faces of w rank r owns, [a, b] */
static void owned(const aero_flow3d_slabs *w, int r, int *a, int *b,
                  int *wb)
{
    *a = w->k0s[r];
    *b = w->k0s[r] + w->nls[r] - 1;
    *wb = r == w->slab.size - 1 ? w->slab.nz : *b;
}

/* the counts of the halo exchange from rank r to q: u and v layers
   [*ua, *ub], w faces [*wa, *wbb] (empty when b < a) */
static void overlap(const aero_flow3d_slabs *w, int r, int q, int *ua,
                    int *ub, int *wa, int *wbb)
{
    int a, b, wb;
    owned(w, r, &a, &b, &wb);
    const int lo = w->kbs[q] - 1 < 0 ? 0 : w->kbs[q] - 1;
    const int hi = w->kts[q] > w->slab.nz - 1 ? w->slab.nz - 1 : w->kts[q];
    *ua = lo > a ? lo : a;
    *ub = hi < b ? hi : b;
    *wa = w->kbs[q] > a ? w->kbs[q] : a;
    *wbb = w->kts[q] < wb ? w->kts[q] : wb;
    if (r == q) { /* nothing to oneself */
        *ub = *ua - 1;
        *wbb = *wa - 1;
    }
}

static int span(int a, int b) { return b >= a ? b - a + 1 : 0; }

static void halo_exchange(aero_flow3d_slabs *w)
{
    aero_flow3d *f = w->f;
    const size_t pl = f->plane;
    const int me = w->slab.rank, n = w->slab.size;
    int so = 0, ro = 0;
    for (int q = 0; q < n; q++) {
        int ua, ub, wa, wb;
        overlap(w, me, q, &ua, &ub, &wa, &wb);
        w->sdispl[q] = so;
        for (int g = ua; g <= ub; g++) {
            memcpy(w->sbuf + so, f->u + AERO_F3_UV(f, 0, 0, g - w->kb),
                   sizeof(float) * pl);
            memcpy(w->sbuf + so + pl, f->v + AERO_F3_UV(f, 0, 0, g - w->kb),
                   sizeof(float) * pl);
            so += 2 * (int)pl;
        }
        for (int g = wa; g <= wb; g++) {
            memcpy(w->sbuf + so, f->w + AERO_F3_C(f, 0, 0, g - w->kb),
                   sizeof(float) * pl);
            so += (int)pl;
        }
        w->scount[q] = so - w->sdispl[q];
        overlap(w, q, me, &ua, &ub, &wa, &wb);
        w->rdispl[q] = ro;
        w->rcount[q] = (2 * span(ua, ub) + span(wa, wb)) * (int)pl;
        ro += w->rcount[q];
    }
    if (!w->exchange) return;
    MPI_Alltoallv(w->sbuf, w->scount, w->sdispl, MPI_FLOAT, w->rbuf,
                  w->rcount, w->rdispl, MPI_FLOAT, w->slab.comm);
    w->bytes_sent += 4.0 * so;
    for (int q = 0; q < n; q++) {
        int ua, ub, wa, wb, o = w->rdispl[q];
        overlap(w, q, me, &ua, &ub, &wa, &wb);
        for (int g = ua; g <= ub; g++) {
            memcpy(f->u + AERO_F3_UV(f, 0, 0, g - w->kb), w->rbuf + o,
                   sizeof(float) * pl);
            memcpy(f->v + AERO_F3_UV(f, 0, 0, g - w->kb), w->rbuf + o + pl,
                   sizeof(float) * pl);
            o += 2 * (int)pl;
        }
        for (int g = wa; g <= wb; g++) {
            memcpy(f->w + AERO_F3_C(f, 0, 0, g - w->kb), w->rbuf + o,
                   sizeof(float) * pl);
            o += (int)pl;
        }
    }
}

/* the window's projection hook (aero_flow3d_set_window) */
static void slabs_project(void *ctx, aero_flow3d *f)
{
    aero_flow3d_slabs *w = ctx;
    aero_flow3d_slab *s = &w->slab;
    const size_t pl = f->plane, nl = (size_t)s->nl;
    const int off = (int)s->k0 - w->kb;
    s->halo = w->exchange;
    memcpy(s->u, f->u + AERO_F3_UV(f, 0, 0, off - 1),
           sizeof(float) * (nl + 2) * pl);
    memcpy(s->v, f->v + AERO_F3_UV(f, 0, 0, off - 1),
           sizeof(float) * (nl + 2) * pl);
    memcpy(s->w, f->w + AERO_F3_C(f, 0, 0, off),
           sizeof(float) * (nl + 1) * pl);
    memcpy(s->in_u, f->in_u, sizeof(float) * pl);
    memcpy(s->in_v, f->in_v, sizeof(float) * pl);
    memcpy(s->in_w, f->in_w, sizeof(float) * pl);
    aero_flow3d_slab_project(s);
    memcpy(f->u + AERO_F3_UV(f, 0, 0, off), s->u + pl,
           sizeof(float) * nl * pl);
    memcpy(f->v + AERO_F3_UV(f, 0, 0, off), s->v + pl,
           sizeof(float) * nl * pl);
    memcpy(f->w + AERO_F3_C(f, 0, 0, off), s->w,
           sizeof(float) * (nl + (s->rank == s->size - 1)) * pl);
    halo_exchange(w);
    if (w->kb > 0) { /* the window's bottom edge stands for the inflow */
        memcpy(f->in_u, f->u, sizeof(float) * pl);
        memcpy(f->in_v, f->v, sizeof(float) * pl);
        memcpy(f->in_w, f->w, sizeof(float) * pl);
    }
    if (f->region_force && f->n_regions > 0)
        MPI_Allreduce(MPI_IN_PLACE, f->region_force, 3 * f->n_regions,
                      MPI_DOUBLE, MPI_SUM, s->comm);
    /* the step's finite check (flow3d.c: one layer's sum) on every rank:
       a flow that blew up in one slab fails the step on all of them */
    float *mid = f->w + (size_t)(f->nz / 2) * pl;
    float acc = 0.0f;
    for (size_t c = 0; c < pl; c++)
        acc += mid[c];
    int bad = !(acc == acc) || fabsf(acc) > 1e30f, any;
    MPI_Allreduce(&bad, &any, 1, MPI_INT, MPI_MAX, s->comm);
    if (any)
        mid[0] = NAN;
}

/* aero_body_flow_params' window_open and window_close over
   MPI_COMM_WORLD */
void *aero_flow3d_slabs_open(const void *whole, struct aero_flow3d *s,
                             char *err, size_t errlen)
{
    aero_flow3d_slabs *w = calloc(1, sizeof *w);
    if (!w) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    if (aero_flow3d_slabs_init(w, MPI_COMM_WORLD, whole,
                               AERO_FLOW3D_SLAB_HALO, s, err, errlen)) {
        free(w);
        return NULL;
    }
    return w;
}

void aero_flow3d_slabs_close(void *handle)
{
    aero_flow3d_slabs_free(handle);
    free(handle);
}

int aero_flow3d_slabs_init(aero_flow3d_slabs *w, MPI_Comm comm,
                           const void *params, int halo,
                           struct aero_flow3d *window, char *err,
                           size_t errlen)
{
    const aero_flow3d_params *p = params;
    memset(w, 0, sizeof *w);
    if (aero_flow3d_slab_init(&w->slab, comm, p->nx, p->ny, p->nz, p->h, err,
                              errlen))
        return -1;
    aero_flow3d_slab *s = &w->slab;
    const int n = s->size;
    w->halo = halo < 1 ? 1 : halo;
    w->exchange = 1;
    w->kb = (int)s->k0 - w->halo < 0 ? 0 : (int)s->k0 - w->halo;
    w->kt = (int)(s->k0 + s->nl) + w->halo > p->nz
                ? p->nz : (int)(s->k0 + s->nl) + w->halo;
    w->k0s = calloc((size_t)n, sizeof(int));
    w->nls = calloc((size_t)n, sizeof(int));
    w->kbs = calloc((size_t)n, sizeof(int));
    w->kts = calloc((size_t)n, sizeof(int));
    w->scount = calloc((size_t)n, sizeof(int));
    w->sdispl = calloc((size_t)n, sizeof(int));
    w->rcount = calloc((size_t)n, sizeof(int));
    w->rdispl = calloc((size_t)n, sizeof(int));
    w->own_f = window == NULL;
    w->f = window ? window : calloc(1, sizeof(aero_flow3d));
    int ok = w->k0s && w->nls && w->kbs && w->kts && w->scount &&
             w->sdispl && w->rcount && w->rdispl && w->f, all;
    if (ok) {
        int mine[4] = {(int)s->k0, (int)s->nl, w->kb, w->kt};
        int *every = calloc(4 * (size_t)n, sizeof(int));
        ok = every != NULL;
        MPI_Allgather(mine, 4, MPI_INT, every ? every : mine, every ? 4 : 0,
                      MPI_INT, comm);
        for (int r = 0; every && r < n; r++) {
            w->k0s[r] = every[4 * r];
            w->nls[r] = every[4 * r + 1];
            w->kbs[r] = every[4 * r + 2];
            w->kts[r] = every[4 * r + 3];
        }
        free(every);
    }
    if (ok) {
        aero_flow3d_params wp = *p;
        wp.nz = w->kt - w->kb;
        wp.nz_total = p->nz;
        wp.k_origin = w->kb;
        ok = !aero_flow3d_init(w->f, &wp, err, errlen);
        if (ok) {
            /* the largest exchange: every window layer, u, v and w */
            const size_t most = 3 * w->f->plane * (size_t)(wp.nz + 2);
            w->sbuf = malloc(sizeof(float) * most);
            w->rbuf = malloc(sizeof(float) * most);
            ok = w->sbuf && w->rbuf;
            aero_flow3d_set_window(w->f, (int)s->k0 - w->kb,
                                   (int)(s->k0 + s->nl) - w->kb,
                                   slabs_project, w);
        } else {
            if (w->own_f) free(w->f);
            w->f = NULL;
        }
    }
    MPI_Allreduce(&ok, &all, 1, MPI_INT, MPI_MIN, comm);
    if (!all) {
        aero_flow3d_slabs_free(w);
        snprintf(err, errlen, "no window of %d x %d x %d over %d ranks",
                 p->nx, p->ny, p->nz, n);
        return -1;
    }
    return 0;
}

void aero_flow3d_slabs_free(aero_flow3d_slabs *w)
{
    if (w->f) {
        aero_flow3d_free(w->f);
        if (w->own_f) free(w->f);
    }
    aero_flow3d_slab_free(&w->slab);
    free(w->k0s);
    free(w->nls);
    free(w->kbs);
    free(w->kts);
    free(w->scount);
    free(w->sdispl);
    free(w->rcount);
    free(w->rdispl);
    free(w->sbuf);
    free(w->rbuf);
    memset(w, 0, sizeof *w);
}
