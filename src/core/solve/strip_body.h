/* aero: a slender body of revolution by strip theory, the object texture
 * of a club or a capsule from the flow past its sections.
 *
 * A body whose section changes slowly along its axis sheds from each
 * section as a cylinder of the local diameter would: a tapered cylinder
 * sheds in spanwise cells whose frequency follows the local diameter
 * (Gaster 1969, J. Fluid Mech. 38), and sections further apart than the
 * correlation length (~3-5 d, Norberg 2003) shed independently. On a 3D
 * grid a club's 25 mm handle gets 3 cells and barely sheds
 * (textures/README.md); its 2D section at 24 cells per diameter is the
 * corrected circle texture (Roshko's St, Norberg's C_L'), so each region
 * here plays that section's force history:
 *  - at the cross-flow speed U_n = v0 sin(a) (the independence principle:
 *    a yawed cylinder sheds roughly as one in the normal flow; Ramberg
 *    1983 measured how its St on U_n departs from that at large yaw),
 *  - at its own shedding frequency St(Re_l) U_n / d_l (Re_l = U_n d_l /
 *    nu; strouhal.h),
 *  - with the force per unit span scaled as rho U_n^3 St C_L'(Re_l) (g =
 *    dF/dt of a sectional force q d C_L' at f = St U / d),
 *  - over an effective span sqrt(L Lc), L the region's length and Lc the
 *    correlation length 3 d_l (the length [aeolian~]'s texture sources
 *    stand for) or the body's length if shorter: a body of length B >> Lc
 *    holds B / Lc independent cells, so its power is B Lc, shared among
 *    its regions by their lengths whether they are longer or shorter than
 *    Lc (a region shorter than Lc is partly coherent with its
 *    neighbours; played incoherently, it carries that share),
 *  - from its own place in the section's loop, its phase wandering as
 *    model mode's does (a line 0.4-6 % of f wide, strouhal.h), so that
 *    regions of one diameter add in power.
 * The section's drag (x, along the cross-flow) and lift (y) become the
 * region's x and y in the sample frame (the flow along (sin a, 0, cos a)
 * of the body axes); the axial force (skin friction) is left out. The
 * ends' own 3D flow is not modelled. No globals. */
#ifndef AERO_STRIP_BODY_H
#define AERO_STRIP_BODY_H

#include "body_shape.h"
#include "texture.h"

#include <stddef.h>
#include <stdint.h>

#define AERO_STRIP_MAX_REGIONS 64

/* the regions of a body: slices along z (aero_body_region's) */
typedef struct {
    int regions;
    double z[AERO_STRIP_MAX_REGIONS];        /* centroid on the axis, m */
    double diameter[AERO_STRIP_MAX_REGIONS]; /* mean local diameter, m */
    double span[AERO_STRIP_MAX_REGIONS];     /* the body's length in it, m */
} aero_strip_layout;

/* the local diameters of a body of revolution about z, measured along
   four radii at 32 stations per region: 0, or -1 with a message (a
   sphere, or a region the body does not reach) */
int aero_strip_layout_measure(const aero_body_shape *b, int regions,
                              aero_strip_layout *out, char *err,
                              size_t errlen);

/* what one direction's regions do */
typedef struct {
    double f_peak;  /* the strongest region's shedding frequency, Hz */
    double cl_rms;  /* rms lateral force of all regions (powers added) /
                       (rho v0^2 / 2 times the body's side area) */
} aero_strip_stats;

/* the section a texture must be: a circle (kind=aeolian, shape=circle),
   one direction, with re, v0 and diameter: 0, or -1 with a message */
int aero_strip_check_section(const aero_texture *section, char *err,
                             size_t errlen);

/* g_l (N/s) of every region for the flow at `angle` deg from the axis at
   speed v0 (air), nout samples at rate: component c of region l at
   out[n * stride + 3 l + c]; seed picks the regions' places in the
   section's loop */
void aero_strip_render(const aero_texture *section,
                       const aero_strip_layout *layout, double angle,
                       double v0, double rate, uint32_t seed, float *out,
                       int stride, int nout, aero_strip_stats *stats);

#endif
