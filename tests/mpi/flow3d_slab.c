/* tests/objects/80-mpi.sh: the pressure projection of a 3D flow in z slabs
 * over the MPI ranks (src/tools/flow3d_slab.c) against the one-process
 * solver's (aero_flow3d_project) on the same random field and inflow.
 * Every rank makes the whole one-process field (a small grid), projects
 * it, projects its own slab of it over the ranks, and compares u, v, w of
 * its slab. Prints the largest difference relative to the largest |u|
 * and the bytes each rank sent; exits 1 when it exceeds TOL.
 * Usage: mpirun -np N flow3d-slab NX NY NZ TOL [halo|nohalo [STEPS [HW]]]
 * (STEPS > 0: the whole step, with a body, HW halo planes) */
#include "flow3d.h"
#include "flow3d_slab.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static float rnd(unsigned *x)
{
    *x = *x * 1664525u + 1013904223u;
    return (float)((*x >> 8) & 0xffff) / 32768.0f - 1.0f;
}

/* STEPS steps of the whole solver with a body (a block of two regions)
   in windows of HW halo planes, against the one-process solver */
/* the larger of a and b, NaN when either is (a blown-up field fails) */
static double worse(double a, double b)
{
    return a != a || b != b ? NAN : fmax(a, b);
}

static int step_mode(aero_flow3d *one, const aero_flow3d_params *p,
                     int steps, double tol, int halo, int hw, int rank,
                     int size)
{
    const int nx = p->nx, ny = p->ny, nz = p->nz;
    const size_t pl = one->plane, cells = pl * (size_t)nz;
    float *solid = calloc(cells, sizeof(float));
    int *region = calloc(cells, sizeof(int));
    double force1[6], forcen[6];
    char err[200];
    for (int k = 0; k < nz; k++)
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++) {
                const size_t c = AERO_F3_C(one, i, j, k);
                region[c] = k < nz / 2 ? 0 : 1;
                if (abs(2 * i - nx) < nx / 3 && abs(2 * j - ny) < ny / 4 &&
                    k > nz / 4 && k < 3 * nz / 4)
                    solid[c] = 1.0f;
            }
    aero_flow3d_set_body(one, solid, region, 2, force1);
    for (size_t c = 0; c < pl; c++) { /* a steady inflow along z */
        one->in_u[c] = 0.0f;
        one->in_v[c] = 0.0f;
        one->in_w[c] = 10.0f;
    }
    aero_flow3d_project(one);
    aero_flow3d_slabs w;
    if (aero_flow3d_slabs_init(&w, MPI_COMM_WORLD, p, hw, NULL, err,
                               sizeof err)) {
        if (!rank) fprintf(stderr, "flow3d-slab: %s\n", err);
        MPI_Finalize();
        return 2;
    }
    w.exchange = halo;
    aero_flow3d *f = w.f;
    const int kb = w.kb, nw = w.kt - w.kb;
    /* the window's part of the state, the body cut to it */
    memcpy(f->u, one->u + (size_t)kb * pl, sizeof(float) * (nw + 2) * pl);
    memcpy(f->v, one->v + (size_t)kb * pl, sizeof(float) * (nw + 2) * pl);
    memcpy(f->w, one->w + (size_t)kb * pl, sizeof(float) * (nw + 1) * pl);
    memcpy(f->in_u, kb ? f->u : one->in_u, sizeof(float) * pl);
    memcpy(f->in_v, kb ? f->v : one->in_v, sizeof(float) * pl);
    memcpy(f->in_w, kb ? f->w : one->in_w, sizeof(float) * pl);
    aero_flow3d_set_body(f, solid + (size_t)kb * pl, region + (size_t)kb * pl,
                         2, forcen);
    aero_flow3d_set_window(f, (int)w.slab.k0 - kb,
                           (int)(w.slab.k0 + w.slab.nl) - kb,
                           f->project_hook, f->project_ctx);
    double worst = 0.0, big = 0.0, fworst = 0.0, fbig = 0.0;
    for (int n = 0; n < steps; n++) {
        /* a lateral gust at the inflow (body_flow's start-up) */
        for (size_t c = 0; c < pl; c++) {
            one->in_u[c] = (float)(2.0 * sin(0.7 * n));
            if (kb == 0) f->in_u[c] = one->in_u[c];
        }
        aero_flow3d_step(one, 1e-3);
        aero_flow3d_step(f, 1e-3);
        for (int q = 0; q < 6; q++) {
            fworst = worse(fworst, fabs(force1[q] - forcen[q]));
            fbig = fmax(fbig, fabs(force1[q]));
        }
    }
    const size_t nl = (size_t)w.slab.nl, k0 = (size_t)w.slab.k0;
    const size_t off = k0 - (size_t)kb;
    for (size_t k = 0; k < nl; k++)
        for (size_t c = 0; c < pl; c++) {
            const size_t a = (k0 + k + 1) * pl + c, b = (off + k + 1) * pl + c;
            const size_t aw = (k0 + k) * pl + c, bw = (off + k) * pl + c;
            worst = worse(worst, fabs(one->u[a] - f->u[b]));
            worst = worse(worst, fabs(one->v[a] - f->v[b]));
            worst = worse(worst, fabs(one->w[aw] - f->w[bw]));
            big = fmax(big, fabs(one->w[aw]));
        }
    double gw, gb, gf, gfb, bytes = w.bytes_sent + w.slab.bytes_sent, bmax;
    MPI_Allreduce(&worst, &gw, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    MPI_Allreduce(&big, &gb, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    MPI_Allreduce(&fworst, &gf, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    MPI_Allreduce(&fbig, &gfb, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    MPI_Allreduce(&bytes, &bmax, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    const double rel = gw / gb, frel = gfb > 0.0 ? gf / gfb : 0.0;
    if (!rank)
        printf("flow3d-slab %d x %d x %d, %d steps, %d ranks, halo %d%s: "
               "largest difference %.3g of max |w| %.3g, forces %.3g of "
               "max %.3g (tolerance %g), %.0f bytes sent by a rank a step\n",
               nx, ny, nz, steps, size, hw,
               halo ? "" : " (no halo exchange)", rel, gb, frel, gfb, tol,
               bmax / steps);
    aero_flow3d_slabs_free(&w);
    aero_flow3d_free(one);
    free(solid);
    free(region);
    MPI_Finalize();
    return rel <= tol && frel <= tol ? 0 : 1;
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    int rank, size;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    const int nx = argc > 1 ? atoi(argv[1]) : 16;
    const int ny = argc > 2 ? atoi(argv[2]) : 16;
    const int nz = argc > 3 ? atoi(argv[3]) : 24;
    const double tol = argc > 4 ? atof(argv[4]) : 1e-5;
    const int halo = !(argc > 5 && !strcmp(argv[5], "nohalo"));
    const int steps = argc > 6 ? atoi(argv[6]) : 0;
    const int hw = argc > 7 ? atoi(argv[7]) : 6;
    char err[200];
    aero_flow3d one;
    aero_flow3d_params p = {0};
    p.nx = nx;
    p.ny = ny;
    p.nz = nz;
    p.h = 0.01;
    p.threads = 1;
    if (steps > 0) { /* every part of a step: body_flow's choices */
        p.advection = AERO_F3_MACCORMACK;
        p.confinement = 0.3;
        p.confinement_length = 0.04;
        p.u_ref = 10.0;
        p.nu = 1.5e-5;
        p.sponge = 0.25;
    }
    if (aero_flow3d_init(&one, &p, err, sizeof err)) {
        fprintf(stderr, "flow3d-slab: %s\n", err);
        MPI_Abort(MPI_COMM_WORLD, 2);
    }
    unsigned x = 53u;
    const size_t pl = one.plane;
    for (size_t c = 0; c < pl * (size_t)(nz + 2); c++) {
        one.u[c] = 10.0f * rnd(&x);
        one.v[c] = 10.0f * rnd(&x);
    }
    for (size_t c = 0; c < pl * (size_t)(nz + 1); c++)
        one.w[c] = 10.0f + 10.0f * rnd(&x);
    for (size_t c = 0; c < pl; c++) {
        one.in_u[c] = rnd(&x);
        one.in_v[c] = rnd(&x);
        one.in_w[c] = 10.0f + rnd(&x);
    }
    if (steps > 0)
        return step_mode(&one, &p, steps, tol, halo, hw, rank, size);
    aero_flow3d_slab s;
    if (aero_flow3d_slab_init(&s, MPI_COMM_WORLD, nx, ny, nz, p.h, err,
                              sizeof err)) {
        if (!rank) fprintf(stderr, "flow3d-slab: %s\n", err);
        MPI_Finalize();
        return 2;
    }
    s.halo = halo;
    const size_t nl = (size_t)s.nl, k0 = (size_t)s.k0;
    /* the slab's planes k0-1 .. k0+nl of u, v and faces k0 .. k0+nl of w */
    memcpy(s.u, one.u + k0 * pl, sizeof(float) * (nl + 2) * pl);
    memcpy(s.v, one.v + k0 * pl, sizeof(float) * (nl + 2) * pl);
    memcpy(s.w, one.w + k0 * pl, sizeof(float) * (nl + 1) * pl);
    if (!halo) /* what this rank does not own is not there without halos */
        if (rank + 1 < size) memset(s.w + nl * pl, 0, sizeof(float) * pl);
    memcpy(s.in_u, one.in_u, sizeof(float) * pl);
    memcpy(s.in_v, one.in_v, sizeof(float) * pl);
    memcpy(s.in_w, one.in_w, sizeof(float) * pl);
    aero_flow3d_project(&one);
    aero_flow3d_slab_project(&s);
    /* compare the planes this rank owns */
    double worst = 0.0, big = 0.0;
    for (size_t k = 0; k < nl; k++)
        for (size_t c = 0; c < pl; c++) {
            const size_t a = (k0 + k + 1) * pl + c, b = (k + 1) * pl + c;
            const size_t aw = (k0 + k) * pl + c, bw = k * pl + c;
            worst = worse(worst, fabs(one.u[a] - s.u[b]));
            worst = worse(worst, fabs(one.v[a] - s.v[b]));
            worst = worse(worst, fabs(one.w[aw] - s.w[bw]));
            big = fmax(big, fabs(one.u[a]));
        }
    if (rank == size - 1)
        for (size_t c = 0; c < pl; c++)
            worst = worse(worst, fabs(one.w[(size_t)nz * pl + c] -
                                     s.w[nl * pl + c]));
    double gw, gb, bytes = s.bytes_sent, bmax;
    MPI_Allreduce(&worst, &gw, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    MPI_Allreduce(&big, &gb, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    MPI_Allreduce(&bytes, &bmax, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    const double rel = gw / gb;
    if (!rank)
        printf("flow3d-slab %d x %d x %d, %d ranks%s: largest difference "
               "%.3g of max |u| %.3g (tolerance %g), %.0f bytes sent by a "
               "rank a projection\n", nx, ny, nz, size,
               halo ? "" : " (no halo exchange)", rel, gb, tol, bmax);
    aero_flow3d_slab_free(&s);
    aero_flow3d_free(&one);
    MPI_Finalize();
    return rel <= tol ? 0 : 1;
}
