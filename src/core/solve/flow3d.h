/* aero: a small 3D incompressible flow solver (a box of turbulent air).
 *
 * Uniform staggered (MAC) grid of nx x ny x nz cubic cells of size h,
 * periodic across x and y, an inflow face at the bottom (z = 0: the
 * velocity there is given by the caller every step, in `in_u/in_v/in_w`)
 * and an open top (z = nz h: pressure 0, zero-gradient velocity).
 * One step (Fedkiw, Stam and Jensen 2001, "Visual simulation of smoke",
 * the solver Dobashi et al. 2004 uses):
 *   1. semi-Lagrangian advection of the face velocities (stable at any
 *      step; its numerical diffusion is what step 2 compensates), or
 *      (`advection` AERO_F3_MACCORMACK) its limited MacCormack form
 *      (Selle et al. 2008), second order, for wakes that must shed, or
 *      (AERO_F3_MACCORMACK_UNLIMITED) the same without the limiter's
 *      clamp, which cuts every new extremum of the velocity and so damps
 *      a coarse wake's vortices (tests/unit/test_flow3d.c),
 *   2. vorticity confinement, a = eps (h / L) U_ref (N x omega),
 *      N = grad|omega| / |grad|omega|| (FSJ01 eq. 11-12: eps h, with a
 *      velocity scale U_ref and a length L, `confinement_length`, so that
 *      it is an acceleration; L = 0 drops h / L, the older form),
 *   3. explicit viscous diffusion nu lap(u) (when nu > 0),
 *      and an absorbing layer under the open top (`sponge`): eddies are
 *      damped before they reach it, since backflow through an open
 *      boundary feeds itself and blows up (seen at 32^3 without it),
 *   4. projection: lap(phi) = div(u), u -= grad(phi). The Poisson equation
 *      is solved exactly for the discrete operator: FFTW across x and y,
 *      a tridiagonal (Thomas) solve along z (Neumann at the inflow,
 *      Dirichlet phi = 0 at the open top). After it the discrete
 *      divergence is zero to rounding.
 *
 * Immersed body (aero_flow3d_set_body): a solid fraction chi in [0, 1]
 * per cell. After the other forces and before the projection each face
 * velocity is multiplied by (1 - chi_face), chi_face the mean of its two
 * cells: direct forcing of the body's zero velocity (Fadlun et al. 2000,
 * J. Comput. Phys. 161, with a volume-fraction weight as in Brinkman
 * penalisation). The momentum removed is what the air pushed into the
 * body, so the force on the body per unit density is
 * F / rho = SUM chi_face u* h^3 / dt over the faces, summed per region
 * into `region_force` every step (Uhlmann 2005 uses the same sum). A
 * face is solid when its two cells are half solid together (a sharp
 * wall), and vorticity confinement is off within 2 cells of the body.
 *
 * Layout: index (k * ny + j) * nx + i. u[i] lies on the face x = i h of
 * cell i, v[j] on y = j h, w[k] on z = k h (k = 0..nz, nz + 1 layers; w[0]
 * is the inflow). u and v carry one ghost layer below (k = -1, the inflow
 * tangential velocity) and one above (k = nz, a copy of nz - 1): their
 * arrays start one layer early (use AERO_F3_UV(s, i, j, k)).
 *
 * Life cycle: init, (set the inflow, step)..., free. init and free create
 * and destroy FFTW plans: call them from one thread at a time. step is
 * thread-safe for distinct solvers. No globals. */
#ifndef AERO_FLOW3D_H
#define AERO_FLOW3D_H

#include <stddef.h>

enum {
    AERO_F3_SEMI_LAGRANGIAN = 0,
    AERO_F3_MACCORMACK = 1,
    AERO_F3_MACCORMACK_UNLIMITED = 2
};

typedef struct {
    int nx, ny, nz;       /* cells (nx, ny even, >= 4; nz >= 3) */
    double h;             /* cell size, m */
    double nu;            /* kinematic viscosity, m^2/s (0: none) */
    double confinement;   /* vorticity confinement eps (0: none) */
    double u_ref;         /* velocity scale of the confinement, m/s */
    double sponge;        /* fraction of the height under the open top
                             where the velocity is relaxed towards
                             (0, 0, u_ref) (0: none) */
    int advection;        /* AERO_F3_SEMI_LAGRANGIAN (0),
                             AERO_F3_MACCORMACK or
                             AERO_F3_MACCORMACK_UNLIMITED */
    double confinement_length; /* L > 0: a = eps (h / L) U_ref (N x omega),
                             FSJ01's eps h made an acceleration by U_ref / L:
                             grid-scale eddies (omega ~ U / h) get the same
                             forcing ~ eps U^2 / L at any h, and a resolved
                             flow's forcing vanishes as h -> 0; 0: the
                             older a = eps U_ref (N x omega), whose forcing
                             of grid-scale eddies grows as 1 / h */
    int threads;          /* OpenMP threads of one step (<= 1: one; inside
                             another active parallel region: one) */
    int nz_total;         /* a window of a taller grid (aerotex-mpi's
                             slabs, aero_flow3d_set_window): its cells;
                             0: this grid is the whole grid */
    int k_origin;         /* the window's first cell in that grid */
} aero_flow3d_params;

typedef struct aero_flow3d {
    aero_flow3d_params p;
    int nx, ny, nz;
    size_t plane;         /* nx * ny */
    float *u, *v, *w;     /* face velocities (u, v from ghost layer -1) */
    float *u1, *v1, *w1;  /* advection targets */
    float *mc, *mc_lo, *mc_hi; /* MacCormack: the backward pass and the
                                  limiter's bounds (3 fields each) */
    float *cx, *cy, *cz;  /* cell-centred velocity, then force scratch */
    float *ox, *oy, *oz, *omag; /* cell-centred vorticity and |omega| */
    float *phi;           /* pressure-like potential, nx*ny*nz */
    float *in_u, *in_v, *in_w; /* inflow at the bottom face, nx*ny each */
    const float *solid;   /* body: solid fraction per cell (NULL: none) */
    const int *region;    /* body: region of each cell (< 0: none) */
    int n_regions;
    double *region_force; /* body: 3 per region, F / rho of the last step
                             (m^4/s^2), in grid axes */
    unsigned char *near_body; /* cells near the body: no confinement */
    int body_lo[3], body_hi[3]; /* cells (i, j, k) whose faces the body
                             can touch: its box and one cell above */
    /* Poisson solver */
    void *fwd, *inv;      /* fftwf plans */
    void *spec;           /* fftwf_complex, nz * ny * (nx/2+1) */
    float *tri_c, *tri_m; /* Thomas coefficients per (kx, ky, k) */
    double t;             /* simulated time, s */
    /* a window of a grid split over processes (aero_flow3d_set_window) */
    int own_lo, own_hi;   /* the cells whose faces' forces this one sums */
    void (*project_hook)(void *ctx, struct aero_flow3d *s);
    void *project_ctx;
} aero_flow3d;

/* 0, or -1 with a message in err */
int aero_flow3d_init(aero_flow3d *s, const aero_flow3d_params *p, char *err,
                     size_t errlen);
void aero_flow3d_free(aero_flow3d *s);

/* index of u or v (including the ghost layers k = -1 and k = nz) */
#define AERO_F3_UV(s, i, j, k) \
    ((size_t)((k) + 1) * (s)->plane + (size_t)(j) * (s)->nx + (size_t)(i))
/* index of w (k = 0..nz) or of a cell-centred value (k = 0..nz-1) */
#define AERO_F3_C(s, i, j, k) \
    ((size_t)(k) * (s)->plane + (size_t)(j) * (s)->nx + (size_t)(i))

/* an immersed body (see above): chi and region per cell (nx*ny*nz, kept
   by pointer, not copied), the forces of each step written to force
   (3 * n_regions); solid NULL removes it */
void aero_flow3d_set_body(aero_flow3d *s, const float *solid,
                          const int *region, int n_regions, double *force);

/* This solver as a window of a taller grid (p.nz_total cells, this one
   from p.k_origin) that other processes step with it: the window's layers
   own_lo .. own_hi-1 are its own, the others are halos, copies of its
   neighbours' layers. A step does everything but the projection on the
   whole window (a halo value computed wrongly from the window's edge
   reaches inward no further than the halo's width), sums the body's
   forces over its own layers only, and calls project(ctx, s) instead of
   the projection: it projects the own layers with the other windows and
   refreshes the halos and the bottom edge's in_u, in_v, in_w (the
   inflow's place in a window that does not start at the inflow). The
   hook holds the host's communication (src/tools/flow3d_slab.c); this
   file has none. project NULL: a whole grid again. */
void aero_flow3d_set_window(aero_flow3d *s, int own_lo, int own_hi,
                            void (*project)(void *ctx, aero_flow3d *s),
                            void *ctx);

/* one step of dt seconds (the inflow arrays are read at its start);
   returns -1 if a velocity became non-finite */
int aero_flow3d_step(aero_flow3d *s, double dt);
/* the Thomas factors of the pressure solve's tridiagonal system along z
   for the Fourier mode (kx, ky) of an nx x ny x nz grid, m[k * stride]
   for k = 0..nz-1 (the slab solver of aerotex-mpi shares them) */
void aero_flow3d_poisson_factors(int nx, int ny, int nz, int kx, int ky,
                                 float *m, size_t stride);
/* the projection alone (makes the current field divergence-free) */
void aero_flow3d_project(aero_flow3d *s);
/* largest |div u| h over the cells, m/s (0 after a projection) */
double aero_flow3d_max_divergence(const aero_flow3d *s);

/* The solver's state between two steps, for a checkpoint: the velocity
   (u, v, w with their ghost layers), the inflow, the potential and the
   time. A solver initialised with the same parameters and body that
   loads it steps on exactly as the one that saved it (the other fields
   are scratch, filled anew each step). The size in bytes; save writes
   that many bytes to buf, load reads them. */
size_t aero_flow3d_state_size(const aero_flow3d *s);
void aero_flow3d_state_save(const aero_flow3d *s, void *buf);
void aero_flow3d_state_load(aero_flow3d *s, const void *buf);
/* cell-centred vorticity into s->ox, oy, oz and |omega| into s->omag
   (central differences of the cell-centred velocity), 1/s */
void aero_flow3d_vorticity(aero_flow3d *s);
/* kinetic energy per unit density, 0.5 sum |u|^2 h^3, m^5/s^2 */
double aero_flow3d_energy(const aero_flow3d *s);

#endif
