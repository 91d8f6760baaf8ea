/* aero: incompressible 2D flow past a body (see flow2d.h): the grid and
 * its fields, the time step (its size and its phases) and the measures
 * of the flow. The phases live by role in flow2d_momentum.c (advection
 * and diffusion), flow2d_body.c (the immersed body and its force) and
 * flow2d_pressure.c (the pressure solve); flow2d_internal.h holds the
 * grid's layout they share.
 * Grid: cell (i, j), 0 <= i < nx, 0 <= j < ny, centre (xmin + (i + 1/2) h,
 * ymin + (j + 1/2) h). u[i][j] sits on the left face of cell (i, j)
 * (0 <= i <= nx), v[i][j] on its bottom face (0 <= j <= ny). Velocity
 * arrays carry two ghost layers on every side, indexed by AT(i, j). */
#include "flow2d_internal.h"
#include "turbulence2d.h"
#include "aero_clones.h"
#include "aero_fftw.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void aero_flow2d_defaults(aero_flow2d_params *p, double re)
{
    p->re = re;
    p->grid = 16.0;
    p->xmin = -10.0;
    p->xmax = 20.0;
    p->ymin = -10.0;
    p->ymax = 10.0;
    p->cfl = 0.6;
    p->spin = 0.25;
    p->spin_time = 3.0;
    p->inlet_theta = 0.0;
    p->ycore = 0.0;
    p->stretch = 1.0;
    p->turbulence = AERO_FLOW2D_LAMINAR;
    p->turbulence_intensity = 0.01;
    p->turbulence_ratio = 1.0;
}

/* FFT sizes with small prime factors only */
static int good_size(int n)
{
    for (;; n++) {
        int m = n;
        while (m % 2 == 0) m /= 2;
        while (m % 3 == 0) m /= 3;
        while (m % 5 == 0) m /= 5;
        if (m == 1) return n;
    }
}

static int check_params(const aero_flow2d_params *p, char *err,
                        size_t errlen)
{
    double lx = p->xmax - p->xmin, ly = p->ymax - p->ymin;
    if (!(p->re > 0.0 && p->re < 1e7)) {
        snprintf(err, errlen, "Reynolds number %g out of range (0, 1e7)", p->re);
        return -1;
    }
    if (!(p->grid >= 4.0 && p->grid <= 400.0)) {
        snprintf(err, errlen, "grid of %g cells per diameter out of range 4..400",
                 p->grid);
        return -1;
    }
    if (!(lx > 2.0 && ly > 2.0) || !(p->xmin < 0.0 && p->xmax > 0.0)) {
        snprintf(err, errlen, "flow domain too small");
        return -1;
    }
    if (!(p->cfl > 0.0 && p->cfl <= 1.0)) {
        snprintf(err, errlen, "CFL number %g out of range (0, 1]", p->cfl);
        return -1;
    }
    if (!(p->ycore >= 0.0 && p->ycore < 1e3) ||
        !(p->stretch >= 1.0 && p->stretch <= 1.2)) {
        snprintf(err, errlen, "stretched rows: band %g or growth %g out of "
                 "range (0..1e3 d, 1..1.2)", p->ycore, p->stretch);
        return -1;
    }
    if (p->ycore > 0.0 && p->stretch > 1.0 &&
        !(p->ycore < p->ymax && -p->ycore > p->ymin)) {
        snprintf(err, errlen, "the uniform band |y| < %g does not fit the "
                 "flow domain", p->ycore);
        return -1;
    }
    if (!(p->inlet_theta >= 0.0 && p->inlet_theta <= AERO_FLOW2D_THETA_MAX)) {
        snprintf(err, errlen, "inflow boundary layer's momentum thickness "
                 "%g out of range 0..%g (in units of d)", p->inlet_theta,
                 AERO_FLOW2D_THETA_MAX);
        return -1;
    }
    if (p->turbulence < AERO_FLOW2D_LAMINAR ||
        p->turbulence > AERO_FLOW2D_KOMEGA_KL ||
        (p->turbulence != AERO_FLOW2D_LAMINAR &&
         (!(p->turbulence_intensity >= 1e-4 &&
            p->turbulence_intensity <= 0.2) ||
          !(p->turbulence_ratio >= 0.01 && p->turbulence_ratio <= 1e3)))) {
        snprintf(err, errlen, "turbulence model %d with Tu %g and nu_t/nu "
                 "%g out of range (0..2, 1e-4..0.2, 0.01..1e3)",
                 p->turbulence, p->turbulence_intensity,
                 p->turbulence_ratio);
        return -1;
    }
    return 0;
}

/* the row faces of a stretched grid, from ymin up (yf may be NULL: count
   only): rows of h across the band |y| < ycore, its edges on multiples of
   h as on the uniform grid, then each row stretch times the one before it
   (at most AERO_FLOW2D_STRETCH_MAX h) until past ymin and ymax. A smooth
   stretching keeps the scheme's order (index space is uniform). */
static double next_row(const aero_flow2d_params *p, double dy)
{
    const double top = AERO_FLOW2D_STRETCH_MAX * (1.0 / p->grid);
    return dy * p->stretch < top ? dy * p->stretch : top;
}

static int place_rows(const aero_flow2d_params *p, double *yf)
{
    const double h = 1.0 / p->grid;
    const int k = (int)ceil(p->ycore * p->grid - 1e-9);
    int below = 0, above = 0;
    double y, dy;
    for (y = -k * h, dy = h; y > p->ymin + 1e-9 * h; below++)
        y -= (dy = next_row(p, dy));
    for (y = k * h, dy = h; y < p->ymax - 1e-9 * h; above++)
        y += (dy = next_row(p, dy));
    if (yf) {
        for (int j = 0; j <= 2 * k; j++) /* the band */
            yf[below + j] = (j - k) * h;
        y = -k * h;
        dy = h;
        for (int m = 1; m <= below; m++) /* down from the band */
            yf[below - m] = (y -= (dy = next_row(p, dy)));
        y = k * h;
        dy = h;
        for (int m = 1; m <= above; m++) /* up from it */
            yf[below + 2 * k + m] = (y += (dy = next_row(p, dy)));
    }
    return below + 2 * k + above;
}

/* cell size, cell counts (FFT-friendly), viscosity and the first step */
static int size_grid(aero_flow2d *s, char *err, size_t errlen)
{
    const aero_flow2d_params *p = &s->p;
    double lx = p->xmax - p->xmin, ly = p->ymax - p->ymin;
    s->h = (float)(1.0 / p->grid);
    s->nx = good_size((int)ceil(lx * p->grid));
    s->stretched = p->ycore > 0.0 && p->stretch > 1.0;
    s->ny = s->stretched ? place_rows(p, NULL)
                         : good_size((int)ceil(ly * p->grid));
    if ((double)s->nx * s->ny > 5e7) {
        snprintf(err, errlen, "grid of %d x %d cells is too large", s->nx, s->ny);
        return -1;
    }
    s->nu = (float)(1.0 / p->re);
    /* AB2 is stable on the negative real axis down to -1: the diffusion
       (8 nu / h^2) and the upwind dissipation of the free stream (~2.7 U /
       h) share that budget (dt_max); advection is held below the CFL
       number at the measured peak speed (choose_step), starting from 2 U */
    s->dt_max = (float)(0.9 / (8.0 * s->nu / ((double)s->h * s->h) +
                               2.7 / s->h));
    s->dt = (float)(p->cfl * s->h / 2.0);
    if (s->dt > s->dt_max) s->dt = s->dt_max;
    s->dt_prev = s->dt;
    return 0;
}

static int alloc_fields(aero_flow2d *s, char *err, size_t errlen)
{
    size_t nv;
    s->sx = s->nx + 1 + 2 * G;
    nv = (size_t)s->sx * (size_t)(s->ny + 1 + 2 * G);
    s->u = aero_fftw_zalloc(nv);
    s->v = aero_fftw_zalloc(nv);
    s->hu = aero_fftw_zalloc(nv);
    s->hv = aero_fftw_zalloc(nv);
    s->hu0 = aero_fftw_zalloc(nv);
    s->hv0 = aero_fftw_zalloc(nv);
    s->uin = aero_fftw_zalloc((size_t)s->ny);
    s->phi = aero_fftw_zalloc((size_t)s->nx * s->ny);
    s->dphi = aero_fftw_zalloc((size_t)s->nx * s->ny);
    s->ieig = aero_fftw_zalloc((size_t)s->nx * s->ny);
    s->solid = aero_fftw_zalloc((size_t)s->nx * s->ny);
    s->sponge = aero_fftw_zalloc((size_t)s->nx + 1);
    s->work = aero_fftw_zalloc(3 * ((size_t)s->nx + 8));
    s->yf = calloc((size_t)s->ny + 1, sizeof(double));
    s->yc = calloc((size_t)s->ny, sizeof(double));
    if (s->stretched) {
        s->wy = aero_fftw_zalloc((size_t)s->ny);
        s->ey = aero_fftw_zalloc((size_t)s->ny + 1);
        s->iy_u = aero_fftw_zalloc((size_t)s->ny);
        s->an_u = aero_fftw_zalloc((size_t)s->ny);
        s->as_u = aero_fftw_zalloc((size_t)s->ny);
        s->iy_v = aero_fftw_zalloc((size_t)s->ny + 1);
        s->an_v = aero_fftw_zalloc((size_t)s->ny + 1);
        s->as_v = aero_fftw_zalloc((size_t)s->ny + 1);
        if (!s->wy || !s->ey || !s->iy_u || !s->an_u || !s->as_u ||
            !s->iy_v || !s->an_v || !s->as_v) {
            aero_flow2d_free(s);
            snprintf(err, errlen, "out of memory");
            return -1;
        }
    }
    if (s->p.turbulence != AERO_FLOW2D_LAMINAR &&
        aero_turbulence2d_alloc(s)) {
        aero_flow2d_free(s);
        snprintf(err, errlen, "out of memory for the turbulence fields");
        return -1;
    }
    if (!s->sponge || !s->work || !s->yf || !s->yc ||
        !s->u || !s->v || !s->hu || !s->hv || !s->hu0 || !s->hv0 || !s->uin ||
        !s->phi || !s->dphi || !s->ieig || !s->solid) {
        aero_flow2d_free(s);
        snprintf(err, errlen, "out of memory for a %d x %d grid", s->nx, s->ny);
        return -1;
    }
    return 0;
}

/* sponge before the outflow: relaxation rate sigma(x) = 2 U/d ((x - x0)
   / L)^2 over the last L = 4 d (or a fifth of the wake) */
static void fill_sponge(aero_flow2d *s)
{
    const aero_flow2d_params *p = &s->p;
    double len = 0.2 * p->xmax < 4.0 ? 0.2 * p->xmax : 4.0;
    for (int i = 0; i <= s->nx; i++) {
        double x = p->xmin + i * (double)s->h, q = (x - (p->xmax - len)) / len;
        double sig = q > 0.0 ? 2.0 * q * q : 0.0;
        s->sponge[i] = (float)sig;
    }
}

/* row positions, and for a stretched grid the metric of each row: the
   y terms of a row are those of the uniform scheme in index space, with
   its flux differences over the row's height and the Laplacian's second
   difference over the distances between centres (a smooth mapping y(j)),
   so the uniform band is solved exactly as on the uniform grid */
static void fill_rows(aero_flow2d *s)
{
    const int ny = s->ny;
    const double h = s->h;
    if (s->stretched)
        place_rows(&s->p, s->yf);
    else
        for (int j = 0; j <= ny; j++)
            s->yf[j] = s->p.ymin + j * h;
    for (int j = 0; j < ny; j++)
        s->yc[j] = 0.5 * (s->yf[j] + s->yf[j + 1]);
    if (!s->stretched)
        return;
    for (int j = 0; j < ny; j++)
        s->wy[j] = (float)((s->yf[j + 1] - s->yf[j]) / h);
    for (int j = 0; j <= ny; j++) {
        /* centre distance at face j; at a wall, to the mirrored centre */
        double dc = (j == 0) ? s->yf[1] - s->yf[0]
                  : (j == ny) ? s->yf[ny] - s->yf[ny - 1]
                  : s->yc[j] - s->yc[j - 1];
        s->ey[j] = (j == 0 || j == ny) ? 0.0f : (float)(h / dc);
        s->iy_v[j] = (float)(1.0 / dc);
    }
    for (int j = 0; j < ny; j++) {
        double dy = s->yf[j + 1] - s->yf[j];
        double dn = j + 1 < ny ? s->yc[j + 1] - s->yc[j] : dy;
        double ds = j > 0 ? s->yc[j] - s->yc[j - 1] : dy;
        s->iy_u[j] = (float)(1.0 / dy);
        s->an_u[j] = (float)(1.0 / (dy * dn));
        s->as_u[j] = (float)(1.0 / (dy * ds));
    }
    for (int j = 1; j < ny; j++) {
        double dc = s->yc[j] - s->yc[j - 1];
        s->an_v[j] = (float)(1.0 / (dc * (s->yf[j + 1] - s->yf[j])));
        s->as_v[j] = (float)(1.0 / (dc * (s->yf[j] - s->yf[j - 1])));
    }
}

int aero_flow2d_init(aero_flow2d *s, const aero_flow2d_params *p, char *err,
                     size_t errlen)
{
    memset(s, 0, sizeof *s);
    s->p = *p;
    if (check_params(p, err, errlen) || size_grid(s, err, errlen) ||
        alloc_fields(s, err, errlen))
        return -1;
    fill_sponge(s);
    fill_rows(s);
    if (flow2d_plan_transforms(s, err, errlen)) return -1;
    flow2d_factor_poisson_y(s);
    return 0;
}

void aero_flow2d_free(aero_flow2d *s)
{
    aero_fftw_serialise();
    {
        if (s->plan_fwd) fftwf_destroy_plan((fftwf_plan)s->plan_fwd);
        if (s->plan_inv) fftwf_destroy_plan((fftwf_plan)s->plan_inv);
    }
    fftwf_free(s->u);
    fftwf_free(s->v);
    fftwf_free(s->hu);
    fftwf_free(s->hv);
    fftwf_free(s->hu0);
    fftwf_free(s->hv0);
    fftwf_free(s->uin);
    fftwf_free(s->phi);
    fftwf_free(s->dphi);
    fftwf_free(s->dct_rows);
    fftwf_free(s->dct_spec);
    fftwf_free(s->dct_tw);
    fftwf_free(s->ieig);
    fftwf_free(s->solid);
    fftwf_free(s->sponge);
    fftwf_free(s->work);
    free(s->yf);
    free(s->yc);
    fftwf_free(s->wy);
    fftwf_free(s->ey);
    fftwf_free(s->iy_u);
    fftwf_free(s->an_u);
    fftwf_free(s->as_u);
    fftwf_free(s->iy_v);
    fftwf_free(s->an_v);
    fftwf_free(s->as_v);
    free(s->ib_idx);
    free(s->ib_chi);
    free(s->ib_x);
    free(s->ib_y);
    free(s->ib_count);
    aero_turbulence2d_free(s);
    memset(s, 0, sizeof *s);
}

/* a velocity far above the stream's means the scheme has blown up */
static int check_finite(aero_flow2d *s)
{
    float m = 0.0f;
    if (!isfinite(s->fx) || !isfinite(s->fy))
        return -1;
    for (int j = 0; j < s->ny; j += 3) {
        const float *u = s->u + AT(0, j), *v = s->v + AT(0, j);
        for (int i = 0; i < s->nx; i++) {
            float a = fabsf(u[i]) + fabsf(v[i]);
            m = a > m ? a : m;
        }
    }
    return (m < 20.0f) ? 0 : -1; /* also false for NaN */
}

/* dt = cfl h / max(|u| + |v|) (at least the free stream's 2 U), capped
   by the AB2 limit of diffusion and upwinding; the peak speed is measured
   every 4 steps. The step follows that goal on a smooth path (a critically
   damped second-order follower, ~10 steps): the immersed boundary's
   no-slip error after the projection grows with the step, so a step that
   jumped would shift the force in one step, and every jump would be a
   click in g = dF/dt. A speed-up faster than the follower is held at 1.2
   times the goal's step (CFL 0.6 for the default 0.5). */
AERO_CLONES
static float peak_speed(const aero_flow2d *s)
{
    float m = 2.0f;
    for (int j = 0; j < s->ny; j++) {
        const float *u = s->u + AT(0, j), *v = s->v + AT(0, j);
        for (int i = 0; i < s->nx; i++) {
            float a = fabsf(u[i]) + fabsf(v[i]);
            m = a > m ? a : m;
        }
    }
    return m < 1e3f ? m : 1e3f; /* NaN or blown up: the check reports it */
}

/* the explicit eddy viscosity's stability bound on the step:
   8 (nu + nu_t) dt / h^2 <= 0.8 */
static float nut_step_bound(const aero_flow2d *s)
{
    return 0.1f * s->h * s->h / (s->nut_max + s->nu);
}

static void choose_step(aero_flow2d *s)
{
    const float w = 0.1f;
    s->dt_prev = s->dt;
    if ((s->steps & 3) == 0) {
        float limit = (float)(s->p.cfl * s->h / peak_speed(s));
        s->dt_goal = limit < s->dt_max ? limit : s->dt_max;
        /* the eddy viscosity's bound (below), with a margin so that the
           follower, not the hard bound, keeps the step when nu_t grows */
        if (s->turb_k && s->nut_max > 0.0f) {
            float cap = 0.95f * nut_step_bound(s);
            s->dt_goal = s->dt_goal < cap ? s->dt_goal : cap;
        }
        if (s->steps == 0) {
            s->dt = s->dt_goal;
            s->dt_rate = 0.0f;
            return;
        }
    }
    s->dt_rate += w * w * (s->dt_goal - s->dt) - 2.0f * w * s->dt_rate;
    s->dt += s->dt_rate;
    if (s->dt > 1.2f * s->dt_goal) {
        s->dt = 1.2f * s->dt_goal;
        s->dt_rate = 0.0f;
    }
    if (s->dt > s->dt_max)
        s->dt = s->dt_max;
    /* a safety bound only: nu_t outgrew the follower between goals */
    if (s->turb_k && s->nut_max > 0.0f) {
        float cap = nut_step_bound(s);
        if (s->dt > cap)
            s->dt = cap;
    }
}

/* one step of the projection method: the explicit half (Adams-Bashforth
   2 of advection and diffusion, the eddy viscosity's stress with a
   turbulence model), the outflow, the body's direct forcing (Fadlun et
   al. 2000), the pressure's projection onto a divergence-free field */
int aero_flow2d_step(aero_flow2d *s)
{
    if (s->diverged)
        return -1;
    choose_step(s);
    flow2d_fill_ghosts(s);
    if (s->turb_k)
        aero_turbulence2d_step(s);
    flow2d_momentum(s);
    if (s->turb_k)
        aero_turbulence2d_stress(s);
    flow2d_convective_outflow(s);
    flow2d_advance_explicit(s);
    flow2d_damp_outflow(s);
    flow2d_force_body(s);
    flow2d_project(s);
    if (s->cavity)
        flow2d_force_cavity_walls(s);
    s->t += s->dt;
    s->steps++;
    if ((s->steps & 31) == 0 || !isfinite(s->fx + s->fy))
        if (check_finite(s)) {
            s->diverged = 1;
            return -1;
        }
    return 0;
}

double aero_flow2d_cd(const aero_flow2d *s)
{
    return 2.0 * s->fx;
}

double aero_flow2d_cl(const aero_flow2d *s)
{
    return 2.0 * s->fy;
}

void aero_flow2d_vorticity(const aero_flow2d *s, float *out)
{
    const float k = 0.25f / s->h;
    const int sx = s->sx, ny = s->ny;
    for (int j = 0; j < ny; j++) {
        const float *u = s->u + AT(0, j), *v = s->v + AT(0, j);
        float ky = 1.0f;
        if (s->stretched) {
            /* du/dy spans the centres of rows j - 1 and j + 1 (at a wall,
               the ghost row mirrored about it) */
            double lo = j > 0 ? s->yc[j - 1] : 2.0 * s->yf[0] - s->yc[0];
            double hi = j < ny - 1 ? s->yc[j + 1]
                                   : 2.0 * s->yf[ny] - s->yc[ny - 1];
            ky = (float)(2.0 * s->h / (hi - lo));
        }
        for (int i = 0; i < s->nx; i++) {
            /* w = dv/dx - du/dy at the cell centre */
            float dvdx = (v[i + 1] + v[i + 1 + sx]) - (v[i - 1] + v[i - 1 + sx]);
            float dudy = (u[i + sx] + u[i + 1 + sx]) - (u[i - sx] + u[i + 1 - sx]);
            out[j * s->nx + i] = k * (dvdx - ky * dudy);
        }
    }
}

void aero_flow2d_stats(const double *t, const double *cd, const double *cl,
                       int n, aero_flowstats *out)
{
    double mcd = 0.0, mcl = 0.0, var = 0.0, t0 = 0.0, t1 = 0.0, amp = 0.0;
    int ncross = 0;
    memset(out, 0, sizeof *out);
    if (n < 2)
        return;
    for (int k = 0; k < n; k++) {
        mcd += cd[k];
        mcl += cl[k];
    }
    mcd /= n;
    mcl /= n;
    for (int k = 0; k < n; k++) {
        double a = cl[k] - mcl;
        var += a * a;
        if (fabs(a) > amp) amp = fabs(a);
    }
    out->cd = mcd;
    out->cl_rms = sqrt(var / n);
    out->cl_amp = amp;
    /* upward zero crossings of the lift, linearly interpolated, each after
       a dip below -rms/2 (hysteresis: noise makes no extra crossings) */
    {
        double thr = 0.5 * out->cl_rms;
        int armed = 0;
        for (int k = 1; k < n; k++) {
            double a = cl[k - 1] - mcl, b = cl[k] - mcl;
            if (a < -thr) armed = 1;
            if (armed && a < 0.0 && b >= 0.0) {
                double tc = t[k - 1] + (t[k] - t[k - 1]) * a / (a - b);
                if (!ncross) t0 = tc;
                t1 = tc;
                ncross++;
                armed = 0;
            }
        }
    }
    if (ncross >= 3 && out->cl_rms > 1e-3) {
        out->periods = ncross - 1;
        out->st = (ncross - 1) / (t1 - t0);
    }
}
