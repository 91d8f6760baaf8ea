/* aero: the sound source functions of a 3D body in a uniform flow
 * (Dobashi et al. 2003, sec. 5.2.1, the 3D case: w(l, s, u) per region l), the
 * offline half of the 3D object textures.
 *
 * One flow direction per call. The body (body_shape.h) is turned so that
 * the flow, which arrives in its x-z plane at `angle` deg from +z towards
 * +x (the "sample frame": flow direction (sin a, 0, cos a)), runs along
 * the solver's +z: the box of flow3d.h (uniform inflow at the bottom,
 * periodic sides, open top with an absorbing layer), the body an immersed
 * boundary (direct forcing of each cell's solid fraction, sampled 3 x 3 x 3
 * per cell). The force on each region l of the body is the momentum the
 * forcing removes (flow3d.h); g_l = dF_l/dt is its derivative, low-passed
 * below the solver's step rate and resampled at the texture rate
 * (texture.c), rotated back into the sample frame. Regions: slices along
 * the body's z axis, or sectors around the flow for a sphere.
 *
 * Start-up: a lateral inflow gust during the first quarter of the settling
 * time breaks the symmetry (symmetric set-ups shed late); a
 * small seeded lateral noise stays on, so the wake is not locked to one
 * plane. Advection is MacCormack's, with a little vorticity confinement
 * away from the body (flow3d.h): on 8-12 cells per d the first-order step
 * alone left a sphere's wake steady (a sphere sheds only above Re ~ 270).
 * Selle et al.'s (2008) limiter (`limiter`, on by default) cuts every new
 * extremum: it damps a coarse wake's vortices (a sphere sheds faster
 * without it), but without it the club, whose handle is 3.3 cells
 * across, lost its broadside tone between its tip's and handle's. The
 * numerical viscosity still sets the effective Reynolds number: a sphere
 * on 10-16 cells per d has the drag and Strouhal number published for Re
 * ~ 300-500 (textures/README.md). No globals. */
#ifndef AERO_BODY_FLOW_H
#define AERO_BODY_FLOW_H

#include "body_shape.h"
#include "flow3d.h"

#include <stddef.h>
#include <stdint.h>

#define AERO_BODY_MAX_REGIONS 64

typedef struct {
    const aero_body_shape *body;
    double angle;        /* flow direction in the body's x-z plane, deg */
    double speed;        /* v0, m/s */
    double cell;         /* cell size h, m */
    double side;         /* clearance from the body to each side, m */
    double upstream;     /* inflow face to the body, m */
    double downstream;   /* body to the open top, m */
    double sponge;       /* the last fraction of `downstream` is an
                            absorbing layer (flow3d.h) */
    int regions;         /* 1..AERO_BODY_MAX_REGIONS */
    double nu;           /* kinematic viscosity, m^2/s (explicit term) */
    double confinement;  /* vorticity confinement eps: a = eps (h / d) v0
                            (N x omega), d the body's reference size
                            (flow3d.h, confinement_length = d) */
    int limiter;         /* 1: the MacCormack step limited (Selle et al.
                            2008; AERO_F3_MACCORMACK, the default), 0:
                            unlimited (AERO_F3_MACCORMACK_UNLIMITED) */
    double cfl;          /* step = cfl h / v0 */
    double settle;       /* start-up discarded, s */
    double noise;        /* rms lateral inflow noise / v0 */
    uint32_t seed;
    int threads;         /* OpenMP threads inside the one simulation
                            (flow3d.h; 0 or 1: one) */
    /* FFTW's planner is not thread-safe: called with on = 1 / 0 around
       the solver's init and free when directions run in parallel */
    void (*plan_lock)(void *ctx, int on);
    /* checkpoints (aerotex-mpi keeps them beside the texture): with
       checkpoint_every > 0, after every checkpoint_every steps
       checkpoint_save(ctx, state, bytes) is handed the run's state (the
       step, the forces kept, the seed's generator and the solver's,
       aero_flow3d_state_save); at the start checkpoint_load(ctx, state,
       bytes) may fill such a state and return 1, and the run continues
       from its step to exactly the result it would have had; 0: start */
    long checkpoint_every;
    /* one flow over several processes (aerotex-mpi object --slabs): with
       window_open set, the solver is opened by window_open(whole, s, err,
       errlen) as a window of the whole grid (aero_flow3d_set_window),
       which returns a handle (NULL: failed, with a message) that
       window_close(handle) closes (freeing s); the body is set on the
       window's layers, the inflow only where the window starts at it */
    void *(*window_open)(const void *whole, aero_flow3d *s, char *err,
                         size_t errlen);
    void (*window_close)(void *handle);
    void (*checkpoint_save)(void *ctx, const void *state, size_t bytes);
    int (*checkpoint_load)(void *ctx, void *state, size_t bytes);
} aero_body_flow_params;

typedef struct {
    int nx, ny, nz;
    long steps;
    double dt;
    double solid_volume;       /* m^3 (sum of solid fractions) */
    double frontal_area;       /* m^2, projected along the flow */
    double centre[3 * AERO_BODY_MAX_REGIONS]; /* region centroids, body
                                                 frame, m */
    double cd;                 /* mean drag / (rho v0^2 A / 2) */
    double cl_rms;             /* rms lateral force / (rho v0^2 A / 2) */
    double st;                 /* f d / v0 of the lateral force's peak */
    double f_peak;             /* that peak, Hz */
    double max_div;            /* largest |div u| h after the last step */
} aero_body_flow_stats;

/* defaults: angle 90, v0 10 m/s, 12 cells per reference size, sides 2.5 d,
   upstream 3 d, downstream 8 d (its last 0.2 absorbing), 1 region, air,
   confinement 1.5 (eps h / d), limiter on, cfl 0.7, settle 25 d/v0,
   noise 0.01, seed 1 (body must be set) */
void aero_body_flow_defaults(aero_body_flow_params *p,
                             const aero_body_shape *body);

/* the solver steps simulate will take for nout samples at rate */
long aero_body_flow_steps(const aero_body_flow_params *p, double rate,
                          int nout);

/* Runs the flow, writes g_l (N/s, sample frame) for nout samples at rate
 * from the end of the settling time: component c of region l at
 * out[n * stride + 3 l + c]. hook (may be NULL) is called every
 * hook_every steps. 0, or -1 with a message (bad parameters, too large a
 * grid, the flow blew up). */
int aero_body_flow_simulate(const aero_body_flow_params *p, double rate,
                            float *out, int stride, int nout,
                            aero_body_flow_stats *stats,
                            void (*hook)(void *ctx, const aero_flow3d *s,
                                         long step, int recording),
                            long hook_every, void *ctx, char *err,
                            size_t errlen);

#endif
