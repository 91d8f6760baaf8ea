/* aero: the explicit half of the 2D flow's step (see flow2d.h): the
 * ghost layers of the boundaries, advection in flux form with
 * third-order upwind-biased faces and diffusion by the 5-point Laplacian,
 * stepped by Adams-Bashforth 2; the convective outflow and the sponge
 * before it. */
#include "flow2d_internal.h"
#include "aero_clones.h"
#include <math.h>

/* ghost layers: uniform inflow, free-slip sides, zero-gradient outflow */
AERO_CLONES
void flow2d_fill_ghosts(aero_flow2d *s)
{
    const int nx = s->nx, ny = s->ny;
    float *u = s->u, *v = s->v;
    for (int j = 0; j < ny; j++) {
        u[AT(0, j)] = u[AT(-1, j)] = u[AT(-2, j)] = s->uin[j];
        u[AT(nx + 1, j)] = u[AT(nx + 2, j)] = u[AT(nx, j)];
    }
    for (int i = -G; i <= nx + G; i++) {
        u[AT(i, -1)] = u[AT(i, 0)];
        u[AT(i, -2)] = u[AT(i, 1)];
        u[AT(i, ny)] = u[AT(i, ny - 1)];
        u[AT(i, ny + 1)] = u[AT(i, ny - 2)];
    }
    for (int j = 0; j <= ny; j++) {
        v[AT(-1, j)] = -v[AT(0, j)];
        v[AT(-2, j)] = -v[AT(1, j)];
        v[AT(nx, j)] = v[AT(nx + 1, j)] = v[AT(nx - 1, j)];
    }
    for (int i = -G; i < nx + G; i++) {
        v[AT(i, 0)] = v[AT(i, ny)] = 0.0f;
        v[AT(i, -1)] = -v[AT(i, 1)];
        v[AT(i, -2)] = -v[AT(i, 2)];
        v[AT(i, ny + 1)] = -v[AT(i, ny - 1)];
        v[AT(i, ny + 2)] = -v[AT(i, ny - 2)];
    }
}

/* flux a * q at a face, q interpolated third-order upwind-biased from
   m, p0 | p1, q1: q = (-m + 7 p0 + 7 p1 - q1)/12
                       + sign(a) (-m + 3 p0 - 3 p1 + q1)/12 */
static inline float upwind_flux(float a, float m, float p0, float p1, float q1)
{
    return (a * (-m + 7.0f * (p0 + p1) - q1) +
            fabsf(a) * (-m + 3.0f * (p0 - p1) + q1)) *
           (1.0f / 12.0f);
}

/* fluxes of u momentum through the faces of the u control volumes of row
   j: x faces at the cell centres (i + 1/2, j), fx[i] for -1 <= i < nx, and
   y faces at the corners (i, j + 1), fy[i] for 0 <= i <= nx */
AERO_CLONES
static void flux_u_x(const aero_flow2d *s, int j, float *restrict fx)
{
    const float *restrict u = s->u + AT(0, j);
    for (int i = -1; i < s->nx; i++)
        fx[i] = upwind_flux(0.5f * (u[i] + u[i + 1]), u[i - 1], u[i],
                            u[i + 1], u[i + 2]);
}

AERO_CLONES
static void flux_u_y(const aero_flow2d *s, int j, float *restrict fy)
{
    const int sx = s->sx;
    const float *restrict u = s->u + AT(0, j), *restrict v = s->v + AT(0, j);
    for (int i = 0; i <= s->nx; i++)
        fy[i] = upwind_flux(0.5f * (v[i - 1 + sx] + v[i + sx]), u[i - sx],
                            u[i], u[i + sx], u[i + 2 * sx]);
}

/* fluxes of v momentum of row j: x faces at the corners (i + 1, j),
   fx[i] for -1 <= i < nx, y faces at the cell centres (i, j + 1/2) */
AERO_CLONES
static void flux_v_x(const aero_flow2d *s, int j, float *restrict fx)
{
    const int sx = s->sx;
    const float *restrict u = s->u + AT(0, j), *restrict v = s->v + AT(0, j);
    for (int i = -1; i < s->nx; i++)
        fx[i] = upwind_flux(0.5f * (u[i + 1 - sx] + u[i + 1]), v[i - 1], v[i],
                            v[i + 1], v[i + 2]);
}

AERO_CLONES
static void flux_v_y(const aero_flow2d *s, int j, float *restrict fy)
{
    const int sx = s->sx;
    const float *restrict v = s->v + AT(0, j);
    for (int i = 0; i < s->nx; i++)
        fy[i] = upwind_flux(0.5f * (v[i] + v[i + sx]), v[i - sx], v[i],
                            v[i + sx], v[i + 2 * sx]);
}

typedef void flux_row(const aero_flow2d *s, int j, float *restrict f);

/* H = -d(uq)/dx - d(vq)/dy + nu lap q at the interior nodes i >= i0 of
   the rows j >= j0 of one velocity component q (u: rows from 0, nodes
   from 1; v: rows from 1, nodes from 0), each row's y fluxes through its
   bottom faces being those of the row below. On a stretched grid, iy, an
   and as are the rows' y metrics (fill_rows), else NULL. */
AERO_CLONES
static void momentum(aero_flow2d *s, const float *q, float *hq,
                     flux_row *flux_x, flux_row *flux_y, int j0, int i0,
                     const float *iy, const float *an, const float *as)
{
    const int nx = s->nx, ny = s->ny, sx = s->sx;
    const float ih = 1.0f / s->h, nu_h2 = s->nu / (s->h * s->h);
    float *fx = s->work + 2, *fs = s->work + (nx + 8) + 2,
          *fn = s->work + 2 * (nx + 8) + 2;
    flux_y(s, j0 - 1, fs);
    for (int j = j0; j < ny; j++) {
        const float *restrict c = q + AT(0, j);
        float *restrict h = hq + AT(0, j);
        float *t;
        flux_x(s, j, fx);
        flux_y(s, j, fn);
        if (iy) {
            const float ky = iy[j], nn = s->nu * an[j], ns = s->nu * as[j];
            for (int i = i0; i < nx; i++) {
                float lapx = c[i + 1] + c[i - 1] - 2.0f * c[i];
                h[i] = -(fx[i] - fx[i - 1]) * ih - (fn[i] - fs[i]) * ky +
                       nu_h2 * lapx + nn * (c[i + sx] - c[i]) -
                       ns * (c[i] - c[i - sx]);
            }
        } else {
            for (int i = i0; i < nx; i++) {
                float lap = c[i + 1] + c[i - 1] + c[i + sx] + c[i - sx] - 4.0f * c[i];
                h[i] = -(fx[i] - fx[i - 1] + fn[i] - fs[i]) * ih + nu_h2 * lap;
            }
        }
        t = fs; fs = fn; fn = t;
    }
}

/* u* = u^n + dt ((1 + r/2) H^n - r/2 H^(n-1) - grad p^(n-1/2)),
   r = dt / dt_prev (Adams-Bashforth 2 with a variable step, Euler at the
   first step; incremental pressure) */
AERO_CLONES
void flow2d_advance_explicit(aero_flow2d *s)
{
    const int nx = s->nx, ny = s->ny;
    const float r = s->dt / s->dt_prev;
    const float a = s->steps ? (1.0f + 0.5f * r) * s->dt : s->dt;
    const float b = s->steps ? -0.5f * r * s->dt : 0.0f;
    const float dt_h = s->dt / s->h;
    for (int j = 0; j < ny; j++) {
        float *u = s->u + AT(0, j), *hu = s->hu + AT(0, j),
              *h0 = s->hu0 + AT(0, j);
        const float *p = s->phi + j * nx;
        for (int i = 1; i < nx; i++)
            u[i] += a * hu[i] + b * h0[i] - dt_h * (p[i] - p[i - 1]);
    }
    for (int j = 1; j < ny; j++) {
        float *v = s->v + AT(0, j), *hv = s->hv + AT(0, j),
              *h0 = s->hv0 + AT(0, j);
        const float *p = s->phi + j * nx, *pm = s->phi + (j - 1) * nx;
        const float dt_dy = s->stretched ? s->dt * s->iy_v[j] : dt_h;
        for (int i = 0; i < nx; i++)
            v[i] += a * hv[i] + b * h0[i] - dt_dy * (p[i] - pm[i]);
    }
    {
        float *t = s->hu0; s->hu0 = s->hu; s->hu = t;
        t = s->hv0; s->hv0 = s->hv; s->hv = t;
    }
}

/* du/dt + U du/dx = 0 at the outflow, then the outflow flux is made equal
   to the inflow flux so that the Poisson problem is solvable */
void flow2d_convective_outflow(aero_flow2d *s)
{
    const int nx = s->nx, ny = s->ny;
    const float c = s->dt / s->h;
    double qin = 0.0, qout = 0.0, corr;
    double height = 0.0;
    for (int j = 0; j < ny; j++) {
        float *u = s->u + AT(nx, j);
        const double w = s->stretched ? s->wy[j] : 1.0;
        u[0] -= c * (u[0] - u[-1]);
        qin += w * s->uin[j];
        qout += w * u[0];
        height += w;
    }
    corr = (qin - qout) / height;
    for (int j = 0; j < ny; j++)
        s->u[AT(nx, j)] += (float)corr;
}

/* sponge layer: u <- U + (u - U)(1 - sigma dt), v <- v (1 - sigma dt),
   so that vortices leave through the convective outflow without feedback */
AERO_CLONES
void flow2d_damp_outflow(aero_flow2d *s)
{
    const int nx = s->nx, ny = s->ny;
    int i0 = 0;
    while (i0 < nx && s->sponge[i0] == 0.0f) i0++;
    for (int j = 0; j < ny; j++) {
        float *u = s->u + AT(0, j), *v = s->v + AT(0, j);
        const float ui = s->uin[j];
        for (int i = i0; i < nx; i++) {
            float f = 1.0f - s->sponge[i] * s->dt;
            u[i] = ui + (u[i] - ui) * f;
            if (j) v[i] *= f;
        }
    }
}

/* H of both velocity components (u: rows from 0, nodes from 1; v: rows
   from 1, nodes from 0) */
void flow2d_momentum(aero_flow2d *s)
{
    momentum(s, s->u, s->hu, flux_u_x, flux_u_y, 0, 1, s->iy_u, s->an_u,
             s->as_u);
    momentum(s, s->v, s->hv, flux_v_x, flux_v_y, 1, 0, s->iy_v, s->an_v,
             s->as_v);
}
