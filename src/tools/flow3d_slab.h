/* aerotex-mpi: the pressure projection of one 3D flow (src/core/solve/
 * flow3d.h) with its grid split along z in slabs of whole planes over the
 * ranks of an MPI communicator (docs/cluster.md). Built only into the MPI
 * tools (mpicc, -lfftw3f_mpi); src/core stays free of MPI.
 *
 * A rank holds planes k0 .. k0+nl-1 (FFTW's block distribution of nz,
 * fftwf_mpi_local_size_many_transposed): u and v with one halo plane each
 * side (AERO_F3_UV layout with nz replaced by nl), w for the faces k0 ..
 * k0+nl (the last one is the next rank's first face, a halo; on the last
 * rank it is the open top). The projection: the divergence of each plane
 * (the face above the slab received from the next rank, MPI_Sendrecv),
 * FFTW's 2D transforms per plane (local), FFTW's MPI transpose of the
 * spectrum so that each rank holds whole lines along z for some ky, the
 * same tridiagonal solve along z as flow3d.c, the transpose back, the
 * inverse transforms, and the gradient (the potential of the plane below
 * the slab received from the previous rank). The result equals
 * aero_flow3d_project's within float rounding (tests/objects/80-mpi.sh). */
#ifndef AERO_FLOW3D_SLAB_H
#define AERO_FLOW3D_SLAB_H

#include <mpi.h>
#include <stddef.h>

typedef struct {
    MPI_Comm comm;
    int rank, size;
    int nx, ny, nz;
    double h;
    ptrdiff_t nl, k0;   /* this rank's planes */
    ptrdiff_t nyl, ky0; /* this rank's ky rows of the transposed spectrum */
    size_t plane;
    float *u, *v;       /* (nl + 2) planes: k0-1 .. k0+nl */
    float *w;           /* (nl + 1) planes: faces k0 .. k0+nl */
    float *in_u, *in_v, *in_w; /* inflow (used on the first rank) */
    float *phi;         /* (nl + 1) planes: k0-1 (halo) .. k0+nl-1 */
    float *spec;        /* the spectrum, complex as float pairs */
    float *tri_m;       /* Thomas factors, [ky - ky0][k][kx] */
    void *fwd, *inv, *there, *back; /* fftwf plans */
    int halo;           /* 1: exchange halos; 0: not (a negative control) */
    double bytes_sent;  /* bytes this rank sent, summed over calls */
} aero_flow3d_slab;

/* 0, or -1 with a message (a rank without a plane or a ky row: fewer
   ranks) */
int aero_flow3d_slab_init(aero_flow3d_slab *s, MPI_Comm comm, int nx, int ny,
                          int nz, double h, char *err, size_t errlen);
void aero_flow3d_slab_free(aero_flow3d_slab *s);
/* u -= grad phi with lap phi = div u over the whole grid (collective) */
void aero_flow3d_slab_project(aero_flow3d_slab *s);

/* index in u or v of cell (i, j) of local plane k (-1 .. nl), and in w or
   a cell-centred field of local plane k (0 .. nl) */
#define AERO_SLAB_UV(s, i, j, k) \
    ((size_t)((k) + 1) * (s)->plane + (size_t)(j) * (s)->nx + (size_t)(i))
#define AERO_SLAB_C(s, i, j, k) \
    ((size_t)(k) * (s)->plane + (size_t)(j) * (s)->nx + (size_t)(i))

#endif
