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
 * aero_flow3d_project's bit for bit (tests/objects/80-mpi.sh). */
#ifndef AERO_FLOW3D_SLAB_H
#define AERO_FLOW3D_SLAB_H

#include <mpi.h>
#include <stddef.h>

struct aero_flow3d;

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

/* One 3D flow (flow3d.h) stepped in z slabs over the ranks: each rank
 * steps a window of the grid (aero_flow3d_set_window), its own slab of
 * planes and `halo` planes of its neighbours' either side, and projects
 * its own slab with the others (aero_flow3d_slab_project above). After
 * the projection the halo planes are copied from the ranks that own them
 * (MPI_Alltoallv: only neighbours send, more than one when a slab is
 * thinner than the halo). Advection's departure points, the confinement's
 * and diffusion's stencils and the near-body mask read at most a few
 * planes away a step, so a halo wider than that keeps every own value
 * exact: the flow equals the one-process flow bit for bit
 * (tests/objects/80-mpi.sh). The cost: each rank computes 2 halo planes
 * besides its own, and sends the halos once a step. */
typedef struct {
    aero_flow3d_slab slab;
    struct aero_flow3d *f; /* the window (allocated) */
    int halo;              /* planes each side */
    int kb, kt;            /* the window's cells in the grid: kb .. kt-1 */
    int *k0s, *nls, *kbs, *kts; /* every rank's slab and window */
    float *sbuf, *rbuf;
    int *scount, *sdispl, *rcount, *rdispl;
    int exchange;          /* 1: copy the halos; 0: not (negative control) */
    int own_f;             /* f allocated here */
    double bytes_sent;     /* of the halos, summed over steps */
} aero_flow3d_slabs;

/* params: the whole grid's aero_flow3d_params; window: the solver to
   initialise as this rank's window (NULL: one allocated); 0, or -1 with a
   message (on every rank) */
int aero_flow3d_slabs_init(aero_flow3d_slabs *w, MPI_Comm comm,
                           const void *params, int halo,
                           struct aero_flow3d *window, char *err,
                           size_t errlen);
void aero_flow3d_slabs_free(aero_flow3d_slabs *w);

/* the halo aerotex-mpi's object --slabs uses: a step's advection reads
   up to 2 (cfl |u| / v0 + 1) planes away in its two MacCormack passes,
   the confinement 3, the diffusion 1; 10 covers cfl 1.5 at |u| 2 v0
   (tests/objects/80-mpi.sh: 6 is exact at cfl 1.8, 4 is not) */
#ifndef AERO_FLOW3D_SLAB_HALO
#define AERO_FLOW3D_SLAB_HALO 10
#endif
/* aero_body_flow_params' window_open / window_close over MPI_COMM_WORLD
   (whole: the grid's aero_flow3d_params) */
void *aero_flow3d_slabs_open(const void *whole, struct aero_flow3d *s,
                             char *err, size_t errlen);
void aero_flow3d_slabs_close(void *handle);

/* index in u or v of cell (i, j) of local plane k (-1 .. nl), and in w or
   a cell-centred field of local plane k (0 .. nl) */
#define AERO_SLAB_UV(s, i, j, k) \
    ((size_t)((k) + 1) * (s)->plane + (size_t)(j) * (s)->nx + (size_t)(i))
#define AERO_SLAB_C(s, i, j, k) \
    ((size_t)(k) * (s)->plane + (size_t)(j) * (s)->nx + (size_t)(i))

#endif
