/* aero: incompressible 2D flow past a body, for sound textures.
 *
 * Projection method on a staggered (MAC) grid, solved in units of the
 * reference length d, the free-stream speed U and the time d/U, so the
 * only flow parameter is Re = U d / nu. The cells are square, h = d /
 * grid; optionally only in a band |y| < ycore around the body, beyond which
 * the rows grow smoothly (stretch), a mapped grid whose index space is
 * uniform, so the scheme below keeps its form row by row:
 *  - advection in flux form, third-order upwind-biased interpolation;
 *    diffusion by the 5-point Laplacian; both stepped by Adams-Bashforth 2
 *  - the body as an immersed boundary: direct forcing with the solid
 *    fraction of each velocity node (a smoothed, rotatable rasterisation of
 *    a signed distance); the force on the body is the sum of that forcing
 *  - pressure Poisson equation with Neumann walls solved exactly by a
 *    cosine transform along x (FFTW) and a tridiagonal solve along y (any
 *    row heights)
 *  - uniform inflow, free-slip sides, a sponge layer before a convective
 *    outflow corrected to conserve mass.
 * Life cycle: aero_flow2d_defaults, _init, _set_body, _step ..., _free. */
#ifndef AERO_FLOW2D_H
#define AERO_FLOW2D_H

#include <stddef.h>
#include "shape2d.h"

typedef struct {
    double re;       /* Reynolds number U d / nu */
    double grid;     /* cells per reference length d */
    double xmin, xmax, ymin, ymax; /* domain around the body origin, in d */
    double cfl;      /* time step = cfl * dx / max(|u| + |v|, 2 U) */
    double spin;     /* seeding: body surface speed / U of a brief spin */
    double spin_time;/* duration of that spin, in d/U */
    double inlet_theta; /* a cavity's wall: momentum thickness of its
                           laminar boundary layer at the inflow, in d
                           (0: uniform inflow, the layer grows from the
                           inflow edge) */
    double ycore;    /* half-height of the band |y| < ycore (in d) that
                        keeps the uniform cell size; 0: uniform everywhere */
    double stretch;  /* beyond it, each row is this much taller than the
                        one before, up to AERO_FLOW2D_STRETCH_MAX cells */
    int turbulence;  /* AERO_FLOW2D_LAMINAR, or a k-omega model
                        (turbulence2d.h) */
    double turbulence_intensity; /* the free stream's Tu (k = 3/2 (Tu U)^2) */
    double turbulence_ratio;     /* and its nu_t / nu */
} aero_flow2d_params;

enum {
    AERO_FLOW2D_LAMINAR = 0,
    AERO_FLOW2D_KOMEGA = 1,    /* Wilcox (2006) */
    AERO_FLOW2D_KOMEGA_KL = 2  /* with Kato and Launder's (1993) production */
};

/* the tallest stretched row, in cells of the uniform band */
#define AERO_FLOW2D_STRETCH_MAX 8.0

/* the full thickness of the laminar inflow layer over its momentum
   thickness: Pohlhausen's quartic profile (Schlichting & Gersten 2000) */
#define AERO_FLOW2D_DELTA_PER_THETA (315.0 / 37.0)

/* the thickest inflow boundary layer, in d: its full thickness stays
   inside a cavity's domain, which reaches 1.5 d above the wall
   (aeolian_flow.c) */
#define AERO_FLOW2D_THETA_MAX 0.1

typedef struct {
    aero_flow2d_params p;
    int nx, ny;          /* pressure cells */
    int sx;              /* row stride of the velocity arrays (with ghosts) */
    float h, dt, nu;     /* cell size, step of the last step (d, d/U), 1/Re */
    float dt_prev, dt_max; /* the step before it; the stability cap */
    float dt_goal, dt_rate; /* the step the CFL number asks for; the step's
                               change per step as it follows that goal */
    float *u, *v;        /* face velocities (ghost layers of 2) */
    float *hu, *hv;      /* explicit right-hand sides, this step */
    float *hu0, *hv0;    /* ... previous step (Adams-Bashforth) */
    float *uin;          /* inflow profile, ny */
    float *phi;          /* pressure (kinematic, units of U^2), nx * ny */
    float *dphi;         /* pressure increment of a step (FFT work), nx * ny */
    float *ieig;         /* Thomas factors of the y Laplacian per x mode */
    float *solid;        /* solid fraction at cell centres, nx * ny */
    float *sponge;       /* outflow sponge: rate per column (U/d), nx + 1 */
    float *work;         /* three rows of face fluxes */
    /* rows (y): cell j spans yf[j]..yf[j + 1], its centre yc[j]; stretched
       rows scale the y terms row by row (none when uniform) */
    int stretched;
    double *yf, *yc;     /* ny + 1 faces, ny centres (d) */
    float *wy;           /* cell height / h, ny */
    float *ey;           /* h / distance between centres j - 1 and j, at
                            face j (0 at the walls), ny + 1 */
    float *iy_u, *an_u, *as_u; /* u rows: 1/height, Laplacian's weights
                                  to the row above and below, ny */
    float *iy_v, *an_v, *as_v; /* v rows (faces): the same, ny + 1 */
    void *plan_fwd, *plan_inv; /* fftwf_plan */
    /* the cosine transforms through a real FFT (even nx,
       flow2d_pressure.c): rows reordered, their spectra, the
       quarter-wave twiddles */
    float *dct_rows;     /* nx * ny */
    float *dct_spec;     /* (nx / 2 + 1) * ny complex (interleaved) */
    float *dct_tw;       /* cos, sin of pi k / (2 nx), k <= nx / 2 */
    /* immersed boundary nodes: u nodes then v nodes */
    int nib, nibu;
    int *ib_idx;         /* index into u (first nibu) or v */
    float *ib_chi;       /* solid fraction */
    float *ib_x, *ib_y;  /* node position relative to the body origin (d) */
    unsigned char *ib_count; /* 1: node counts into the measured force */
    int cavity;          /* the body is a cavity: force from wall pressure */
    int cav_i0, cav_i1, cav_jd, cav_j0; /* its walls on the grid */
    double t;            /* time, d/U */
    long steps;
    double fx, fy;       /* force on the body at the last step / (rho U^2 d) */
    int diverged;
    /* k-omega (turbulence2d.c): k and omega at the cell centres with a
       ghost cell on every side, (nx + 2) * (ny + 2), the next step's, and
       the diffusivities; nu_t, the production's factor and the stress limiter
       (nx * ny); nu_t at the corners ((nx + 1) * (ny + 1)); the rows' 1 /
       height and 1 / centre distance at each row face; the largest nu_t */
    float *turb_k, *turb_omega, *turb_k_next, *turb_omega_next;
    float *turb_diff_k, *turb_diff_omega;
    float *nut, *turb_production, *turb_limiter, *nut_corner;
    float *turb_inv_height, *turb_inv_centre;
    float nut_max;
} aero_flow2d;

/* domain and numerics good for a bluff body of size d at any Re */
void aero_flow2d_defaults(aero_flow2d_params *p, double re);
/* allocates the grid; 0, or -1 with a message */
int aero_flow2d_init(aero_flow2d *s, const aero_flow2d_params *p, char *err,
                     size_t errlen);
/* rasterises the shape (size d = shape->size) rotated so that the flow
 * (+x) arrives at angle alpha (rad) in the body frame; resets the flow to
 * the uniform stream; for a cavity the force is the pressure on its walls */
int aero_flow2d_set_body(aero_flow2d *s, const aero_shape2d *shape,
                         double alpha, char *err, size_t errlen);
/* one time step; 0, or -1 when the solution diverges */
int aero_flow2d_step(aero_flow2d *s);
/* drag and lift coefficient of the last step (2 F / (rho U^2 d)) */
double aero_flow2d_cd(const aero_flow2d *s);
double aero_flow2d_cl(const aero_flow2d *s);
/* vorticity (U/d) and solid fraction at the cell centres, nx * ny each */
void aero_flow2d_vorticity(const aero_flow2d *s, float *out);
void aero_flow2d_free(aero_flow2d *s);

/* statistics of a recorded force history, coefficients at the times t
   (d/U, increasing): Strouhal number from the lift zero crossings (0 when
   the lift does not oscillate), mean drag, rms and peak lift */
typedef struct {
    double st, cd, cl_rms, cl_amp;
    int periods;
} aero_flowstats;
void aero_flow2d_stats(const double *t, const double *cd, const double *cl,
                       int n, aero_flowstats *out);

#endif
