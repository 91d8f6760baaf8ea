/* aero: what the parts of the 2D flow solver (flow2d.c and flow2d_*.c)
 * share: the layout of the velocity arrays and the phases of a step one
 * part calls in another. Internal: only those files (and
 * turbulence2d.c, which works on the same grid) include it. */
#ifndef AERO_FLOW2D_INTERNAL_H
#define AERO_FLOW2D_INTERNAL_H

#include "flow2d.h"

#include <stddef.h>

/* ghost layers on every side of the velocity arrays, and node (i, j) of
   one (-G <= i <= nx + G, -G <= j <= ny + G) */
#define G 2
#define AT(i, j) ((size_t)((j) + G) * (size_t)s->sx + (size_t)((i) + G))

/* flow2d_momentum.c: the explicit half of a step */
void flow2d_fill_ghosts(aero_flow2d *s);
void flow2d_momentum(aero_flow2d *s);
void flow2d_advance_explicit(aero_flow2d *s);
void flow2d_convective_outflow(aero_flow2d *s);
void flow2d_damp_outflow(aero_flow2d *s);

/* flow2d_body.c: the body's forcing and its force */
void flow2d_force_body(aero_flow2d *s);
void flow2d_force_cavity_walls(aero_flow2d *s);

/* flow2d_pressure.c: the pressure solve, set up once (plan_transforms: 0,
   or -1 with a message after freeing s) and run every step */
int flow2d_plan_transforms(aero_flow2d *s, char *err, size_t errlen);
void flow2d_factor_poisson_y(aero_flow2d *s);
void flow2d_project(aero_flow2d *s);

#endif
