/* aero: the sound source function of a 2D cross-section in a uniform flow
 * (Dobashi et al. 2003: g = dF/dt of the force per unit span),
 * the offline half of the aeolian and cavity textures.
 *
 * One flow direction per call: the 2D solver of flow2d.h runs past the
 * shape (a stick's cross-section, or a cavity in a wall), the start-up is
 * discarded, the force is recorded, and its derivative is low-passed and
 * resampled at the texture rate (texture.c). The 3D counterpart is
 * body_flow.h. No globals. */
#ifndef AERO_AEOLIAN_FLOW_H
#define AERO_AEOLIAN_FLOW_H

#include "flow2d.h"
#include "shape2d.h"
#include "span3d.h"

#include <stddef.h>

typedef struct {
    const aero_shape2d *shape; /* aero_shape2d_cavity() for a cavity */
    int cavity;          /* the shape is a cavity in a wall */
    double size;         /* reference size d, m (a cavity: its length) */
    double depth;        /* a cavity's depth, m */
    double theta;        /* a cavity: momentum thickness of the wall's
                            laminar boundary layer at the inflow, m (0:
                            none, it grows from the inflow edge) */
    double speed;        /* v0, m/s */
    double re;           /* Reynolds number v0 d / nu */
    double grid;         /* cells per d */
    double cfl;          /* flow2d.h's step factor */
    double stretch;      /* rows' growth beyond a uniform band around a
                            body (flow2d.h); 1 or less: a uniform grid */
    double settle;       /* start-up discarded, d/v0 */
    double duration;     /* the texture's length, s: the recording covers
                            it with the loop search, cross-fade and the
                            resampling kernel's reach */
    double angle;        /* flow direction in the shape's frame, deg */
    /* the 2D-to-3D correction of the recorded force (span3d.h): NULL for
       none; with span3d_self the run itself (a circle) calibrates it at
       re, otherwise *span3d is applied as it is */
    const aero_span3d *span3d;
    int span3d_self;
    int turbulence;      /* flow2d.h's model of the 2D flow (not for a
                            cavity): AERO_FLOW2D_LAMINAR or k-omega */
} aero_aeolian_flow_params;

/* the shape's thinnest frontal width over all directions, m */
double aero_aeolian_flow_thinnest(const aero_shape2d *shape);

/* the solver's domain for p (units of d): room around tall shapes, the
   space over a cavity's wall; -1 with a message when the shape is under
   1.5 cells thin on this grid */
int aero_aeolian_flow_domain(const aero_aeolian_flow_params *p,
                             aero_flow2d_params *fp, char *err,
                             size_t errlen);

/* what a run will take, from a trial grid: its size, the first step and
   the end time (d/v0), and about how many steps */
typedef struct {
    int nx, ny;
    double dt, t_end;
    long steps;
} aero_aeolian_flow_plan;
int aero_aeolian_flow_estimate(const aero_aeolian_flow_params *p, double rate,
                               aero_aeolian_flow_plan *plan, char *err,
                               size_t errlen);

/* what a run measured: the 2D force statistics (flow2d.h), the St of the
   lift's spectral peak, the first step, and the 2D-to-3D correction the
   output carries (the identity without one) */
typedef struct {
    aero_flowstats flow;
    double st_peak;      /* 2D, before the correction */
    double dt;           /* d/v0 */
    aero_span3d span3d;
} aero_aeolian_flow_stats;

/* called every `every` steps (may be NULL): progress and snapshots */
typedef void (*aero_aeolian_flow_hook)(void *ctx, const aero_flow2d *s,
                                       long step);

/* Runs one direction and writes nout samples of g = dF/dt (N/(m s)) at
   `rate` Hz: the x component (along the flow) to out[k * stride], y to
   out[k * stride + 1], after the 2D-to-3D correction of p->span3d (time
   stretched by 1 / frequency_scale, force times force_scale). 0, or -1
   with a message in err. out NULL: the statistics only. */
int aero_aeolian_flow_simulate(const aero_aeolian_flow_params *p,
                               double rate, float *out, int stride, int nout,
                               aero_aeolian_flow_stats *st,
                               aero_aeolian_flow_hook hook, long every,
                               void *ctx, char *err, size_t errlen);

#endif
