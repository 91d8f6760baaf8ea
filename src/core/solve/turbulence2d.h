/* aero: the k-omega turbulence model of the 2D flow (private to the 2D
 * solver, flow2d*.c).
 *
 * A 2D flow past a bluff body at Re ~ 1e3-1e5 keeps its wake coherent
 * along an infinite span and its shear layers laminar: the square prism's
 * 2D wake sheds on a slow, irregular low band (textures/README.md). An
 * unsteady Reynolds-averaged flow carries the turbulence the third
 * dimension would make as an eddy viscosity: Wilcox's (2006) k-omega model
 * with its stress limiter, and Kato and Launder's (1993) production term,
 * which removes the spurious turbulence a stagnation point makes. */
#ifndef AERO_TURBULENCE2D_H
#define AERO_TURBULENCE2D_H

#include "flow2d.h"

/* the fields (k, omega, nu_t and two work copies): 0, or -1 */
int aero_turbulence2d_alloc(aero_flow2d *s);
void aero_turbulence2d_free(aero_flow2d *s);
/* the free stream's k and omega everywhere */
void aero_turbulence2d_reset(aero_flow2d *s);
/* one step dt of k and omega from the velocities (ghosts filled), then
   nu_t and its maximum */
void aero_turbulence2d_step(aero_flow2d *s);
/* k at the centre of cell (i, j) */
float aero_turbulence2d_k(const aero_flow2d *s, int i, int j);
/* hu, hv += div(nu_t (grad u + grad u^T)) at the velocity nodes */
void aero_turbulence2d_stress(aero_flow2d *s);

#endif
