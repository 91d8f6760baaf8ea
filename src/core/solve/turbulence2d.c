/* aero: Wilcox's (2006) k-omega model on the 2D flow's grid (see
 * turbulence2d.h). k and omega live at the cell centres, in arrays with
 * one ghost cell on every side (the inflow's values upstream, zero
 * gradient elsewhere); they are carried by the face velocities with
 * first-order upwind fluxes (they stay positive), diffuse explicitly and
 * lose their dissipation implicitly. Inside the body k is zero and omega
 * takes the smooth-wall value 60 nu / (beta0 h^2) that Menter (1994)
 * gives for the first cell. */
#include "turbulence2d.h"
#include "flow2d_internal.h"

#include "aero_clones.h"
#include "aero_fftw.h"
#include <math.h>
#include <string.h>

/* cell (i, j) of the padded k and omega arrays, -1 <= i <= nx */
#define PAD(i, j) ((size_t)((j) + 1) * (size_t)(s->nx + 2) + (size_t)((i) + 1))

/* Wilcox (2006) closure coefficients, 2D (f_beta = 1) */
#define BETA_STAR 0.09f
#define BETA0 0.0708f
#define ALPHA 0.52f
#define SIGMA 0.5f
#define SIGMA_STAR 0.6f
#define SIGMA_DO 0.125f
#define C_LIM 0.875f
/* production at most this many times the dissipation (Menter 1994) */
#define PRODUCTION_LIMIT 20.0f
#define K_FLOOR 1e-10f
/* max and min as selects: they vectorise (fmaxf's NaN rules call libm) */
#define MAX0(a, b) ((a) > (b) ? (a) : (b))
#define MIN0(a, b) ((a) < (b) ? (a) : (b))

int aero_turbulence2d_alloc(aero_flow2d *s)
{
    const size_t n = (size_t)s->nx * s->ny;
    const size_t np = (size_t)(s->nx + 2) * (s->ny + 2);
    s->turb_k = aero_fftw_zalloc(np);
    s->turb_omega = aero_fftw_zalloc(np);
    s->turb_k_next = aero_fftw_zalloc(np);
    s->turb_omega_next = aero_fftw_zalloc(np);
    s->turb_diff_k = aero_fftw_zalloc(np);
    s->turb_diff_omega = aero_fftw_zalloc(np);
    s->nut = aero_fftw_zalloc(n);
    s->turb_production = aero_fftw_zalloc(n);
    s->turb_limiter = aero_fftw_zalloc(n);
    s->nut_corner = aero_fftw_zalloc((size_t)(s->nx + 1) * (s->ny + 1));
    s->turb_inv_height = aero_fftw_zalloc((size_t)s->ny);
    s->turb_inv_centre = aero_fftw_zalloc((size_t)s->ny + 1);
    if (!s->turb_k || !s->turb_omega || !s->turb_k_next ||
        !s->turb_omega_next || !s->turb_diff_k || !s->turb_diff_omega ||
        !s->nut || !s->turb_production || !s->turb_limiter ||
        !s->nut_corner || !s->turb_inv_height || !s->turb_inv_centre)
        return -1;
    return 0;
}

void aero_turbulence2d_free(aero_flow2d *s)
{
    float **f[] = {&s->turb_k, &s->turb_omega, &s->turb_k_next,
                   &s->turb_omega_next, &s->turb_diff_k, &s->turb_diff_omega,
                   &s->nut, &s->turb_production, &s->turb_limiter,
                   &s->nut_corner,
                   &s->turb_inv_height, &s->turb_inv_centre};
    for (size_t m = 0; m < sizeof f / sizeof f[0]; m++) {
        fftwf_free(*f[m]);
        *f[m] = NULL;
    }
}

/* the free stream: k = 3/2 (Tu U)^2, omega = k / (ratio nu) */
static float stream_k(const aero_flow2d *s)
{
    const float tu = (float)s->p.turbulence_intensity;
    return 1.5f * tu * tu;
}

static float stream_omega(const aero_flow2d *s)
{
    return stream_k(s) / ((float)s->p.turbulence_ratio * s->nu);
}

float aero_turbulence2d_k(const aero_flow2d *s, int i, int j)
{
    return s->turb_k[PAD(i, j)];
}

void aero_turbulence2d_reset(aero_flow2d *s)
{
    const size_t np = (size_t)(s->nx + 2) * (s->ny + 2);
    const float k0 = stream_k(s), w0 = stream_omega(s);
    /* the rows' metrics (the rows are placed after the allocation) */
    for (int j = 0; j < s->ny; j++)
        s->turb_inv_height[j] = (float)(1.0 / (s->yf[j + 1] - s->yf[j]));
    /* between the centres either side of a row face; at the domain's
       edges the edge row's height */
    for (int j = 0; j <= s->ny; j++) {
        double dc = j == 0 ? s->yf[1] - s->yf[0]
                  : j == s->ny ? s->yf[s->ny] - s->yf[s->ny - 1]
                  : s->yc[j] - s->yc[j - 1];
        s->turb_inv_centre[j] = (float)(1.0 / dc);
    }
    for (size_t m = 0; m < np; m++) {
        s->turb_k[m] = k0;
        s->turb_omega[m] = w0;
    }
    memset(s->nut, 0, sizeof(float) * (size_t)s->nx * s->ny);
    memset(s->nut_corner, 0, sizeof(float) * (size_t)(s->nx + 1) * (s->ny + 1));
    s->nut_max = 0.0f;
}

/* ghost cells: the inflow's k and omega upstream, zero gradient on the
   other sides */
static void fill_ghost_cells(aero_flow2d *s, float *q, float inflow)
{
    const int nx = s->nx, ny = s->ny;
    for (int j = 0; j < ny; j++) {
        q[PAD(-1, j)] = inflow;
        q[PAD(nx, j)] = q[PAD(nx - 1, j)];
    }
    for (int i = -1; i <= nx; i++) {
        q[PAD(i, -1)] = q[PAD(i, 0)];
        q[PAD(i, ny)] = q[PAD(i, ny - 1)];
    }
}

/* per cell: the stress limiter's C_lim sqrt(2 S_ij S_ij / beta*) (its
   square roots here, out of the loops that vectorise), the production's factor
   (Kato and Launder: strain times vorticity, none at a stagnation point),
   and the diffusivities nu + sigma* k / omega, nu + sigma k / omega */
AERO_CLONES
static void cell_terms(aero_flow2d *s)
{
    const int nx = s->nx, ny = s->ny, sx = s->sx;
    const float ih = 1.0f / s->h, nu = s->nu;
    const int kato_launder = s->p.turbulence == AERO_FLOW2D_KOMEGA_KL;
    for (int j = 0; j < ny; j++) {
        const double lo = j > 0 ? s->yc[j - 1] : 2.0 * s->yf[0] - s->yc[0];
        const double hi = j < ny - 1 ? s->yc[j + 1]
                                     : 2.0 * s->yf[ny] - s->yc[ny - 1];
        const float idy = s->turb_inv_height[j], k2 = (float)(0.5 / (hi - lo));
        const float *u = s->u + AT(0, j), *v = s->v + AT(0, j);
        float *s2 = s->turb_limiter + (size_t)j * nx;
        float *pr = s->turb_production + (size_t)j * nx;
        for (int i = 0; i < nx; i++) {
            float dudx = (u[i + 1] - u[i]) * ih;
            float dvdy = (v[i + sx] - v[i]) * idy;
            float dudy = ((u[i + sx] + u[i + sx + 1]) -
                          (u[i - sx] + u[i - sx + 1])) * k2;
            float dvdx = ((v[i + 1] + v[i + 1 + sx]) -
                          (v[i - 1] + v[i - 1 + sx])) * 0.25f * ih;
            float st = 2.0f * (dudx * dudx + dvdy * dvdy) +
                       (dudy + dvdx) * (dudy + dvdx);
            float w2 = (dvdx - dudy) * (dvdx - dudy);
            s2[i] = C_LIM * sqrtf(st * (1.0f / BETA_STAR));
            pr[i] = kato_launder ? sqrtf(st * w2) : st;
        }
    }
    for (int j = -1; j <= ny; j++) {
        const float *k = s->turb_k + PAD(0, j), *w = s->turb_omega + PAD(0, j);
        float *gk = s->turb_diff_k + PAD(0, j);
        float *gw = s->turb_diff_omega + PAD(0, j);
        for (int i = -1; i <= nx; i++) {
            float r = k[i] / w[i];
            gk[i] = nu + SIGMA_STAR * r;
            gw[i] = nu + SIGMA * r;
        }
    }
}

/* nu_t = k / max(omega, C_lim sqrt(2 S_ij S_ij / beta*)) (Wilcox 2006's
   stress limiter; wl, that limit, from cell_terms) */
static inline float eddy_viscosity(float k, float w, float wl)
{
    return k / (w > wl ? w : wl);
}

/* what advection and diffusion add to the cell quantity q[0] per unit
   time: first-order upwind fluxes through the four faces (ue, uw, vn, vs
   the face velocities) plus q div, the divergence the projection leaves
   inside the body; and diffusion with g the cells' diffusivities, a
   face's the mean of its two cells'. pw is the padded row's length, in
   and is the inverse centre distances north and south. */
static inline float transport(const float *q, const float *g, int pw,
                              float ue, float uw, float vn, float vs,
                              float div, float ih, float idy,
                              float in, float is)
{
    const float qc = q[0], qe = q[1], qw = q[-1], qn = q[pw], qs = q[-pw];
    const float adv =
        -((MAX0(ue, 0.0f) * qc + MIN0(ue, 0.0f) * qe) -
          (MAX0(uw, 0.0f) * qw + MIN0(uw, 0.0f) * qc)) * ih -
        ((MAX0(vn, 0.0f) * qc + MIN0(vn, 0.0f) * qn) -
         (MAX0(vs, 0.0f) * qs + MIN0(vs, 0.0f) * qc)) * idy +
        qc * div;
    const float dif =
        0.5f * (((g[0] + g[1]) * (qe - qc) - (g[0] + g[-1]) * (qc - qw)) *
                    (ih * ih) +
                ((g[0] + g[pw]) * (qn - qc) * in -
                 (g[0] + g[-pw]) * (qc - qs) * is) * idy);
    return adv + dif;
}

/* the new k and omega of row j */
AERO_CLONES
static void transport_row(aero_flow2d *s, int j)
{
    const int nx = s->nx, ny = s->ny, pw = nx + 2;
    const float h = s->h, ih = 1.0f / h, ih2 = ih * ih, dt = s->dt;
    const float w0 = stream_omega(s);
    const float w_wall = 60.0f * s->nu / (BETA0 * h * h);
    const float idy = s->turb_inv_height[j];
    /* 1 / centre distances north and south; at the domain's edges the
       ghost cell repeats the edge cell, so the distance does not matter */
    const float in = j + 1 < ny ? s->turb_inv_centre[j + 1] : idy;
    const float is = j > 0 ? s->turb_inv_centre[j] : idy;
    const float icross = j > 0 && j + 1 < ny ? 1.0f / (1.0f / in + 1.0f / is)
                                             : 0.5f * idy;
    const float *restrict k = s->turb_k + PAD(0, j);
    const float *restrict w = s->turb_omega + PAD(0, j);
    const float *restrict gk = s->turb_diff_k + PAD(0, j);
    const float *restrict gw = s->turb_diff_omega + PAD(0, j);
    const float *restrict u = s->u + AT(0, j), *restrict v = s->v + AT(0, j);
    const float *restrict s2 = s->turb_limiter + (size_t)j * nx;
    const float *restrict pr = s->turb_production + (size_t)j * nx;
    const float *restrict solid = s->solid + (size_t)j * nx;
    float *restrict kn = s->turb_k_next + PAD(0, j);
    float *restrict wn = s->turb_omega_next + PAD(0, j);
    const int sx = s->sx;
    /* the loads at i +- 1 and +- a row hold GCC's vectoriser back without
       this (it sees no dependence it can disprove through PAD) */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC ivdep
#endif
    for (int i = 0; i < nx; i++) {
        const float kc = k[i], wc = w[i];
        const float ke = k[i + 1], kw = k[i - 1], kN = k[i + pw], kS = k[i - pw];
        const float we = w[i + 1], ww = w[i - 1], wN = w[i + pw], wS = w[i - pw];
        const float ue = u[i + 1], uw = u[i], vn = v[i + sx], vs = v[i];
        const float div = (ue - uw) * ih + (vn - vs) * idy;
        const float trans_k = transport(k + i, gk + i, pw, ue, uw, vn, vs,
                                        div, ih, idy, in, is);
        const float trans_w = transport(w + i, gw + i, pw, ue, uw, vn, vs,
                                        div, ih, idy, in, is);
        /* production, held below 20 beta* k omega; cross diffusion
           sigma_d / omega grad k . grad omega where positive */
        const float prod = MIN0(eddy_viscosity(kc, wc, s2[i]) * pr[i],
                                 PRODUCTION_LIMIT * BETA_STAR * kc * wc);
        const float cross = (ke - kw) * (we - ww) * (0.25f * ih2) +
                            (kN - kS) * (wN - wS) * (icross * icross);
        const float cd = MAX0(cross, 0.0f) * (SIGMA_DO / wc);
        float knew = (kc + dt * (trans_k + prod)) /
                     (1.0f + dt * BETA_STAR * wc);
        float wnew = (wc + dt * (trans_w + cd +
                                 ALPHA * prod * wc / MAX0(kc, 1e-12f))) /
                     (1.0f + dt * BETA0 * wc);
        knew = knew > K_FLOOR ? knew : K_FLOOR; /* also a NaN */
        wnew = wnew > 0.01f * w0 ? wnew : 0.01f * w0;
        kn[i] = solid[i] > 0.5f ? K_FLOOR : knew;
        wn[i] = solid[i] > 0.5f ? w_wall : wnew;
    }
}

/* nu_t at the cell centres (zero inside the body), its maximum, and at
   the corners where column face i meets row face j, the mean of the
   (up to) four cells around it */
AERO_CLONES
static void eddy_viscosities(aero_flow2d *s)
{
    const int nx = s->nx, ny = s->ny;
    float m = 0.0f;
    for (int j = 0; j < ny; j++) {
        const float *k = s->turb_k + PAD(0, j), *w = s->turb_omega + PAD(0, j);
        const float *s2 = s->turb_limiter + (size_t)j * nx;
        const float *solid = s->solid + (size_t)j * nx;
        float *nt = s->nut + (size_t)j * nx;
        for (int i = 0; i < nx; i++) {
            float n = solid[i] > 0.5f ? 0.0f : eddy_viscosity(k[i], w[i], s2[i]);
            nt[i] = n;
            m = n > m ? n : m;
        }
    }
    s->nut_max = m;
    for (int j = 0; j <= ny; j++) {
        const int j0 = j > 0 ? j - 1 : 0, j1 = j < ny ? j : ny - 1;
        const float *a = s->nut + (size_t)j0 * nx, *b = s->nut + (size_t)j1 * nx;
        float *c = s->nut_corner + (size_t)j * (nx + 1);
        c[0] = 0.5f * (a[0] + b[0]);
        for (int i = 1; i < nx; i++)
            c[i] = 0.25f * (a[i - 1] + a[i] + b[i - 1] + b[i]);
        c[nx] = 0.5f * (a[nx - 1] + b[nx - 1]);
    }
}

void aero_turbulence2d_step(aero_flow2d *s)
{
    float *t;
    fill_ghost_cells(s, s->turb_k, stream_k(s));
    fill_ghost_cells(s, s->turb_omega, stream_omega(s));
    cell_terms(s);
    for (int j = 0; j < s->ny; j++)
        transport_row(s, j);
    t = s->turb_k;
    s->turb_k = s->turb_k_next;
    s->turb_k_next = t;
    t = s->turb_omega;
    s->turb_omega = s->turb_omega_next;
    s->turb_omega_next = t;
    eddy_viscosities(s);
}

AERO_CLONES
void aero_turbulence2d_stress(aero_flow2d *s)
{
    const int nx = s->nx, ny = s->ny, sx = s->sx, cw = nx + 1;
    const float ih = 1.0f / s->h;
    /* u: normal stress 2 nu_t du/dx at the cell centres on either side,
       shear stress nu_t (du/dy + dv/dx) at the corners above and below */
    for (int j = 0; j < ny; j++) {
        const float idy = s->turb_inv_height[j];
        const float in = s->turb_inv_centre[j + 1], is = s->turb_inv_centre[j];
        const float *n = s->nut + (size_t)j * nx;
        const float *cn = s->nut_corner + (size_t)(j + 1) * cw,
                    *cs = s->nut_corner + (size_t)j * cw;
        const float *u = s->u + AT(0, j), *v = s->v + AT(0, j);
        float *hu = s->hu + AT(0, j);
        for (int i = 1; i < nx; i++) {
            float txe = 2.0f * n[i] * (u[i + 1] - u[i]) * ih;
            float txw = 2.0f * n[i - 1] * (u[i] - u[i - 1]) * ih;
            float tyn = cn[i] * ((u[i + sx] - u[i]) * in +
                                 (v[i + sx] - v[i - 1 + sx]) * ih);
            float tys = cs[i] * ((u[i] - u[i - sx]) * is +
                                 (v[i] - v[i - 1]) * ih);
            hu[i] += (txe - txw) * ih + (tyn - tys) * idy;
        }
    }
    /* v: shear stress at the corners left and right, normal stress
       2 nu_t dv/dy at the cell centres above and below */
    for (int j = 1; j < ny; j++) {
        const float ic = s->turb_inv_centre[j];
        const float irn = s->turb_inv_height[j], irs = s->turb_inv_height[j - 1];
        const float *nn = s->nut + (size_t)j * nx;
        const float *ns = s->nut + (size_t)(j - 1) * nx;
        const float *c = s->nut_corner + (size_t)j * cw;
        const float *u = s->u + AT(0, j), *v = s->v + AT(0, j);
        float *hv = s->hv + AT(0, j);
        for (int i = 0; i < nx; i++) {
            float tyn = 2.0f * nn[i] * (v[i + sx] - v[i]) * irn;
            float tys = 2.0f * ns[i] * (v[i] - v[i - sx]) * irs;
            float txe = c[i + 1] * ((u[i + 1] - u[i + 1 - sx]) * ic +
                                    (v[i + 1] - v[i]) * ih);
            float txw = c[i] * ((u[i] - u[i - sx]) * ic +
                                (v[i] - v[i - 1]) * ih);
            hv[i] += (txe - txw) * ih + (tyn - tys) * ic;
        }
    }
}
