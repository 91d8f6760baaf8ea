/* aero: the body in the 2D flow (see flow2d.h): an immersed boundary
 * rasterised from the shape's signed distance onto the velocity nodes,
 * the inflow it meets, the direct forcing of each step and the force the
 * body takes from it (Fadlun et al. 2000), or for a cavity the pressure
 * on its walls. */
#include "flow2d_internal.h"
#include "turbulence2d.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* solid fraction of a node from the signed distance (in cells):
   a linear ramp over one cell centred on the surface */
static float solid_fraction(const aero_shape2d *shape, double d, double alpha,
                            double x, double y, double h)
{
    double ca = cos(alpha), sa = sin(alpha);
    /* lab -> body frame: rotate by alpha */
    double xb = (x * ca - y * sa) * d, yb = (x * sa + y * ca) * d;
    double q = 0.5 - aero_shape2d_distance(shape, xb, yb) / (d * h);
    return (float)(q < 0.0 ? 0.0 : q > 1.0 ? 1.0 : q);
}

/* does a node count into the measured force? (a cavity's force is taken
   from the wall pressure instead, see force_cavity_walls) */
static int counts_into_force(const aero_shape2d *shape)
{
    return shape->kind != AERO_SHAPE_CAVITY;
}

static void free_ib_lists(aero_flow2d *s)
{
    free(s->ib_idx);
    free(s->ib_chi);
    free(s->ib_x);
    free(s->ib_y);
    free(s->ib_count);
    s->ib_idx = NULL;
    s->ib_chi = s->ib_x = s->ib_y = NULL;
    s->ib_count = NULL;
}

static int alloc_ib_lists(aero_flow2d *s, int cap, char *err, size_t errlen)
{
    s->ib_idx = malloc(sizeof(int) * (cap ? cap : 1));
    s->ib_chi = malloc(sizeof(float) * (cap ? cap : 1));
    s->ib_x = malloc(sizeof(float) * (cap ? cap : 1));
    s->ib_y = malloc(sizeof(float) * (cap ? cap : 1));
    s->ib_count = malloc(cap ? cap : 1);
    if (!s->ib_idx || !s->ib_chi || !s->ib_x || !s->ib_y || !s->ib_count) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    return 0;
}

/* the velocity nodes inside or on the body, u nodes first (nibu of them),
   then v nodes: counted only (fill = 0) or written into the lists */
static int scan_forced_nodes(aero_flow2d *s, const aero_shape2d *shape,
                             double alpha, int fill)
{
    const double h = s->h, d = shape->size;
    int n = 0;
    for (int c = 0; c < 2; c++) {
        int ni = c ? s->nx : s->nx + 1, nj = c ? s->ny + 1 : s->ny;
        if (fill && c) s->nibu = n;
        for (int j = 0; j < nj; j++)
            for (int i = 0; i < ni; i++) {
                double x = s->p.xmin + (i + (c ? 0.5 : 0.0)) * h;
                double y = c ? s->yf[j] : s->yc[j];
                float chi = solid_fraction(shape, d, alpha, x, y, h);
                if (chi <= 0.0f) continue;
                if (fill) {
                    s->ib_idx[n] = (int)AT(i, j);
                    s->ib_chi[n] = chi;
                    s->ib_x[n] = (float)x;
                    s->ib_y[n] = (float)y;
                    s->ib_count[n] = (unsigned char)counts_into_force(shape);
                }
                n++;
            }
    }
    return n;
}

/* u / U of a laminar boundary layer at height y over its wall, momentum
   thickness theta: Pohlhausen's quartic profile 2 e - 2 e^3 + e^4, e =
   y / delta, delta its full thickness (Schlichting & Gersten 2000) */
static double laminar_layer(double y, double theta)
{
    const double delta = theta * AERO_FLOW2D_DELTA_PER_THETA, e = y / delta;
    if (!(theta > 0.0) || e >= 1.0)
        return 1.0;
    if (e <= 0.0)
        return 0.0;
    return e * (2.0 - e * e * (2.0 - e));
}

/* cell-centre solid fraction (pictures) and inflow profile: uniform, but
   over a cavity's wall (y < 0 solid) the boundary layer it arrives with,
   which sets the shear layer over the cavity (Gharib & Roshko 1987;
   Rowley et al. 2002) */
static void rasterise_cells(aero_flow2d *s, const aero_shape2d *shape,
                            double alpha)
{
    const double h = s->h, d = shape->size;
    const int wall = shape->kind == AERO_SHAPE_CAVITY;
    for (int j = 0; j < s->ny; j++) {
        const double y = s->yc[j];
        for (int i = 0; i < s->nx; i++)
            s->solid[j * s->nx + i] = solid_fraction(
                shape, d, alpha, s->p.xmin + (i + 0.5) * h, y, h);
        s->uin[j] = 1.0f - solid_fraction(shape, d, alpha, s->p.xmin, y, h);
        if (wall && s->p.inlet_theta > 0.0)
            s->uin[j] *= (float)laminar_layer(y, s->p.inlet_theta);
    }
}

/* does the body touch the domain's edges (other than a cavity's wall)? */
static int body_touches_edges(const aero_flow2d *s, const aero_shape2d *shape)
{
    int touch = 0;
    for (int i = 0; i < s->nx; i++)
        if (s->solid[(s->ny - 1) * s->nx + i] > 0.0f ||
            (shape->kind != AERO_SHAPE_CAVITY && s->solid[i] > 0.0f))
            touch = 1;
    for (int j = 0; j < s->ny; j++)
        if (shape->kind != AERO_SHAPE_CAVITY &&
            (s->solid[j * s->nx] > 0.0f ||
             s->solid[j * s->nx + s->nx - 1] > 0.0f))
            touch = 1;
    return touch;
}

/* cells along the cavity's walls: x from 0 to l, y from -depth to 0 */
static int locate_cavity(aero_flow2d *s, const aero_shape2d *shape,
                         char *err, size_t errlen)
{
    const double h = s->h, d = shape->size;
    s->cav_i0 = (int)lround((0.0 - s->p.xmin) / h);
    s->cav_i1 = (int)lround((shape->a / d - s->p.xmin) / h);
    if (s->stretched) {
        /* its wall pressure force sums rows of h (force_cavity_walls) */
        snprintf(err, errlen, "a cavity needs a uniform grid");
        return -1;
    }
    s->cav_jd = (int)lround((-shape->b / d - s->p.ymin) / h);
    s->cav_j0 = (int)lround((0.0 - s->p.ymin) / h);
    if (s->cav_i0 < 1 || s->cav_i1 > s->nx - 1 || s->cav_jd < 1 ||
        s->cav_i1 - s->cav_i0 < 2 || s->cav_j0 - s->cav_jd < 2) {
        snprintf(err, errlen, "the cavity does not fit the grid");
        return -1;
    }
    return 0;
}

/* the uniform stream (zero inside the body), at rest otherwise */
static void start_uniform_stream(aero_flow2d *s)
{
    memset(s->v, 0, sizeof(float) * (size_t)s->sx * (s->ny + 1 + 2 * G));
    for (int j = -G; j < s->ny + 1 + G; j++)
        for (int i = -G; i <= s->nx + G; i++) {
            int jj = j < 0 ? 0 : j >= s->ny ? s->ny - 1 : j;
            s->u[AT(i, j)] = s->uin[jj];
        }
    for (int k = 0; k < s->nibu; k++)
        s->u[s->ib_idx[k]] *= 1.0f - s->ib_chi[k];
    memset(s->phi, 0, sizeof(float) * (size_t)s->nx * s->ny);
    s->t = 0.0;
    s->steps = 0;
    s->fx = s->fy = 0.0;
    s->diverged = 0;
    if (s->turb_k)
        aero_turbulence2d_reset(s);
}

int aero_flow2d_set_body(aero_flow2d *s, const aero_shape2d *shape,
                         double alpha, char *err, size_t errlen)
{
    if (!(shape->size > 0.0)) {
        snprintf(err, errlen, "body size must be positive");
        return -1;
    }
    free_ib_lists(s);
    /* two passes: count the forced nodes, then fill the lists */
    if (alloc_ib_lists(s, scan_forced_nodes(s, shape, alpha, 0), err,
                       errlen))
        return -1;
    s->nib = scan_forced_nodes(s, shape, alpha, 1);
    if (s->nib == 0) {
        snprintf(err, errlen,
                 "the body is smaller than the grid: use a finer --grid");
        return -1;
    }
    if (s->stretched) {
        /* the forcing and the force sum cells of h^2 (force_body), and the
           flow next to the body wants the fine rows: two rows of margin */
        const double band = ceil(s->p.ycore * s->p.grid - 1e-9) * s->h -
                            2.0 * s->h;
        for (int n = 0; n < s->nib; n++)
            if (fabs(s->ib_y[n]) > band) {
                snprintf(err, errlen, "the body reaches the stretched rows: "
                         "the uniform band |y| < %g d is too narrow",
                         s->p.ycore);
                return -1;
            }
    }
    rasterise_cells(s, shape, alpha);
    if (body_touches_edges(s, shape)) {
        snprintf(err, errlen, "the body does not fit in the flow domain");
        return -1;
    }
    s->cavity = shape->kind == AERO_SHAPE_CAVITY;
    if (s->cavity && locate_cavity(s, shape, err, errlen)) return -1;
    start_uniform_stream(s);
    return 0;
}

/* direct forcing u* <- (1 - chi) u* + chi u_body; the body takes the
   opposite of the momentum removed: F = sum chi (u* - u_body) h^2 / dt */
void flow2d_force_body(aero_flow2d *s)
{
    const float k = s->h * s->h / s->dt;
    const double w = s->t < s->p.spin_time ? 2.0 * s->p.spin : 0.0;
    double fx = 0.0, fy = 0.0;
    for (int n = 0; n < s->nib; n++) {
        int isu = n < s->nibu;
        float *q = isu ? s->u + s->ib_idx[n] : s->v + s->ib_idx[n];
        /* rigid rotation u_body = w x r (seeding only) */
        float ub = isu ? (float)(-w * s->ib_y[n]) : (float)(w * s->ib_x[n]);
        if (s->ib_x[n] * s->ib_x[n] + s->ib_y[n] * s->ib_y[n] > 1.0f)
            ub = 0.0f; /* a wall (cavity) spins only within d of its origin */
        float chi = s->ib_chi[n], df = chi * (*q - ub);
        *q -= df;
        if (s->ib_count[n]) {
            if (isu) fx += df; else fy += df;
        }
    }
    s->fx = fx * k;
    s->fy = fy * k;
}

/* pressure force on a cavity's walls (the fluid pushes each wall along
   its inward normal): Fx = sum (p_back - p_front) h, Fy = -sum (p_floor -
   p_ref) h, p_ref the free-stream pressure at the inflow's top corner */
void flow2d_force_cavity_walls(aero_flow2d *s)
{
    const int nx = s->nx;
    const float *p = s->phi;
    const double pref = p[(size_t)(s->ny - 1) * nx];
    double fx = 0.0, fy = 0.0;
    for (int j = s->cav_jd; j < s->cav_j0; j++)
        fx += p[(size_t)j * nx + s->cav_i1 - 1] - p[(size_t)j * nx + s->cav_i0];
    for (int i = s->cav_i0; i < s->cav_i1; i++)
        fy -= p[(size_t)s->cav_jd * nx + i] - pref;
    s->fx = fx * s->h;
    s->fy = fy * s->h;
}

