/* tests/objects/80-mpi.sh: the pressure projection of a 3D flow in z slabs
 * over the MPI ranks (src/tools/flow3d_slab.c) against the one-process
 * solver's (aero_flow3d_project) on the same random field and inflow.
 * Every rank makes the whole one-process field (a small grid), projects
 * it, projects its own slab of it over the ranks, and compares u, v, w of
 * its slab. Prints the largest difference relative to the largest |u|
 * and the bytes each rank sent; exits 1 when it exceeds TOL.
 * Usage: mpirun -np N flow3d-slab NX NY NZ TOL [nohalo] */
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
    char err[200];
    aero_flow3d one;
    aero_flow3d_params p = {0};
    p.nx = nx;
    p.ny = ny;
    p.nz = nz;
    p.h = 0.01;
    p.threads = 1;
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
            worst = fmax(worst, fabs(one.u[a] - s.u[b]));
            worst = fmax(worst, fabs(one.v[a] - s.v[b]));
            worst = fmax(worst, fabs(one.w[aw] - s.w[bw]));
            big = fmax(big, fabs(one.u[a]));
        }
    if (rank == size - 1)
        for (size_t c = 0; c < pl; c++)
            worst = fmax(worst, fabs(one.w[(size_t)nz * pl + c] -
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
