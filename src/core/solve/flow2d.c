/* aero: incompressible 2D flow past a body (see flow2d.h).
 * Grid: cell (i, j), 0 <= i < nx, 0 <= j < ny, centre (xmin + (i + 1/2) h,
 * ymin + (j + 1/2) h). u[i][j] sits on the left face of cell (i, j)
 * (0 <= i <= nx), v[i][j] on its bottom face (0 <= j <= ny). Velocity
 * arrays carry two ghost layers on every side, indexed by AT(i, j). */
#include "flow2d.h"
#include "turbulence2d.h"
#include "aero_air.h"
#include "aero_clones.h"
#include "aero_fftw.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define G 2
#define AT(i, j) ((size_t)((j) + G) * (size_t)s->sx + (size_t)((i) + G))

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

/* cosine transforms along x, one per row (planned one at a time
   process-wide: aero_fftw.h). FFTW_ESTIMATE: the plan, and with it the
   rounding of every step, does not depend on timings, so a texture is
   the same to the last bit however loaded the machine is. For an even
   nx the pair DCT-II / DCT-III is made from one real FFT of the
   reordered row (Makhoul 1980): FFTW's real FFTs are vectorised, its
   r2r cosine kinds are not, and the transforms took 2/3 of a step. */
static int plan_transforms(aero_flow2d *s, char *err, size_t errlen)
{
    aero_fftw_serialise();
    if (s->nx % 2 == 0) {
        int n = s->nx, nc = s->nx / 2 + 1;
        s->dct_rows = aero_fftw_zalloc((size_t)s->nx * s->ny);
        s->dct_spec = aero_fftw_zalloc(2 * (size_t)nc * s->ny);
        s->dct_tw = aero_fftw_zalloc(2 * (size_t)nc);
        if (s->dct_rows && s->dct_spec && s->dct_tw) {
            for (int k = 0; k < nc; k++) {
                s->dct_tw[2 * k] = (float)cos(AERO_PI * k / (2.0 * n));
                s->dct_tw[2 * k + 1] = (float)sin(AERO_PI * k / (2.0 * n));
            }
            s->plan_fwd = fftwf_plan_many_dft_r2c(
                1, &n, s->ny, s->dct_rows, NULL, 1, n,
                (fftwf_complex *)s->dct_spec, NULL, 1, nc, FFTW_ESTIMATE);
            s->plan_inv = fftwf_plan_many_dft_c2r(
                1, &n, s->ny, (fftwf_complex *)s->dct_spec, NULL, 1, nc,
                s->dct_rows, NULL, 1, n, FFTW_ESTIMATE);
        }
    } else {
        int n = s->nx;
        fftwf_r2r_kind k10 = FFTW_REDFT10, k01 = FFTW_REDFT01;
        s->plan_fwd = fftwf_plan_many_r2r(1, &n, s->ny, s->dphi, NULL, 1,
                                          s->nx, s->dphi, NULL, 1, s->nx,
                                          &k10, FFTW_ESTIMATE);
        s->plan_inv = fftwf_plan_many_r2r(1, &n, s->ny, s->dphi, NULL, 1,
                                          s->nx, s->dphi, NULL, 1, s->nx,
                                          &k01, FFTW_ESTIMATE);
    }
    if (!s->plan_fwd || !s->plan_inv) {
        aero_flow2d_free(s);
        snprintf(err, errlen, "FFTW could not plan a %d x %d transform", s->nx,
                 s->ny);
        return -1;
    }
    return 0;
}

/* per cosine mode k along x the Neumann Laplacian along y is the
   tridiagonal x[j-1] + b x[j] + x[j+1] = h^2 r[j], b = 2 cos(pi k/nx) - 4
   (b + 1 at both ends); its Thomas factors 1 / (b_j - c_(j-1)) are also
   the eliminated upper diagonal c_j (the off-diagonals are 1). Mode 0
   is singular: its first value is pinned to 0. */
static void factor_poisson_y(aero_flow2d *s)
{
    if (s->stretched) {
        /* row j times h dy_j: ey_j p_(j-1) - (ey_j + ey_(j+1) + wy_j mu_k)
           p_j + ey_(j+1) p_(j+1) = h^2 wy_j R_j, mu_k = 2 - 2 cos(pi k /
           nx); m_j = 1 / (diagonal - ey_j c_(j-1)), c_j = ey_(j+1) m_j */
        for (int k = 0; k < s->nx; k++) {
            double mu = 2.0 - 2.0 * cos(AERO_PI * k / s->nx), c = 0.0;
            for (int j = 0; j < s->ny; j++) {
                double bj = -(s->ey[j] + s->ey[j + 1] + s->wy[j] * mu), m;
                float *mm = s->ieig + (size_t)j * s->nx + k;
                if (k == 0 && j == 0) {
                    *mm = 0.0f;
                    c = 0.0;
                    continue;
                }
                m = 1.0 / (bj - s->ey[j] * c);
                c = s->ey[j + 1] * m;
                *mm = (float)m;
            }
        }
        return;
    }
    for (int k = 0; k < s->nx; k++) {
        double b = 2.0 * cos(AERO_PI * k / s->nx) - 4.0, c = 0.0;
        for (int j = 0; j < s->ny; j++) {
            double bj = b + ((j == 0 || j == s->ny - 1) ? 1.0 : 0.0);
            float *m = s->ieig + (size_t)j * s->nx + k;
            if (k == 0 && j == 0) {
                *m = 0.0f;
                c = 0.0;
                continue;
            }
            c = 1.0 / (bj - c);
            *m = (float)c;
        }
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
    if (plan_transforms(s, err, errlen)) return -1;
    factor_poisson_y(s);
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

/* ghost layers: uniform inflow, free-slip sides, zero-gradient outflow */
AERO_CLONES
static void fill_ghosts(aero_flow2d *s)
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
static void advance_explicit(aero_flow2d *s)
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
static void convective_outflow(aero_flow2d *s)
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
static void damp_outflow(aero_flow2d *s)
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

/* direct forcing u* <- (1 - chi) u* + chi u_body; the body takes the
   opposite of the momentum removed: F = sum chi (u* - u_body) h^2 / dt */
static void force_body(aero_flow2d *s)
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

/* the y direction of the Poisson problem, all x modes at once (Thomas);
   the cosine transform pair along x scales by 2 nx */
AERO_CLONES
static void solve_tridiagonal(aero_flow2d *s)
{
    const int nx = s->nx, ny = s->ny;
    const float sc = s->h * s->h / (2.0f * nx);
    float *x = s->dphi;
    const float *m = s->ieig;
    if (s->stretched) {
        const float *wy = s->wy, *ey = s->ey;
        for (int i = 0; i < nx; i++)
            x[i] = sc * wy[0] * x[i] * m[i];
        for (int j = 1; j < ny; j++) {
            float *r = x + (size_t)j * nx;
            const float *p = r - nx, *mj = m + (size_t)j * nx;
            const float w = sc * wy[j], e = ey[j];
            for (int i = 0; i < nx; i++)
                r[i] = (w * r[i] - e * p[i]) * mj[i];
        }
        for (int j = ny - 2; j >= 0; j--) {
            float *r = x + (size_t)j * nx;
            const float *q = r + nx, *mj = m + (size_t)j * nx;
            const float e = ey[j + 1];
            for (int i = 0; i < nx; i++)
                r[i] -= e * mj[i] * q[i];
        }
        return;
    }
    for (int i = 0; i < nx; i++)
        x[i] = sc * x[i] * m[i];
    for (int j = 1; j < ny; j++) {
        float *r = x + (size_t)j * nx;
        const float *p = r - nx, *mj = m + (size_t)j * nx;
        for (int i = 0; i < nx; i++)
            r[i] = (sc * r[i] - p[i]) * mj[i];
    }
    for (int j = ny - 2; j >= 0; j--) {
        float *r = x + (size_t)j * nx;
        const float *q = r + nx, *mj = m + (size_t)j * nx;
        for (int i = 0; i < nx; i++)
            r[i] -= mj[i] * q[i];
    }
}

/* pressure force on a cavity's walls (the fluid pushes each wall along
   its inward normal): Fx = sum (p_back - p_front) h, Fy = -sum (p_floor -
   p_ref) h, p_ref the free-stream pressure at the inflow's top corner */
static void force_cavity_walls(aero_flow2d *s)
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

/* dphi <- its DCT-II along x as FFTW_REDFT10 defines it, Y[k] = 2 sum_j
   x[j] cos(pi k (j + 1/2) / n): with v the row reordered (x[0], x[2],
   ..., x[3], x[1]) and V its DFT, Y[k] = 2 Re(W_k V[k]) and Y[n - k] =
   -2 Im(W_k V[k]), W_k = exp(-i pi k / (2 n)) (Makhoul 1980) */
AERO_CLONES
static void cosine_forward(aero_flow2d *s)
{
    const int n = s->nx, h = n / 2, nc = h + 1;
    if (!s->dct_rows) {
        fftwf_execute((fftwf_plan)s->plan_fwd);
        return;
    }
    for (int j = 0; j < s->ny; j++) {
        const float *restrict x = s->dphi + (size_t)j * n;
        float *restrict v = s->dct_rows + (size_t)j * n;
        for (int k = 0; k < h; k++) {
            v[k] = x[2 * k];
            v[n - 1 - k] = x[2 * k + 1];
        }
    }
    fftwf_execute((fftwf_plan)s->plan_fwd);
    for (int j = 0; j < s->ny; j++) {
        const float *restrict c = s->dct_spec + 2 * (size_t)j * nc;
        const float *restrict tw = s->dct_tw;
        float *restrict y = s->dphi + (size_t)j * n;
        y[0] = 2.0f * c[0];
        y[h] = 2.0f * tw[2 * h] * c[2 * h];
        for (int k = 1; k < h; k++) {
            float cr = c[2 * k], ci = c[2 * k + 1];
            float co = tw[2 * k], si = tw[2 * k + 1];
            y[k] = 2.0f * (co * cr + si * ci);
            y[n - k] = -2.0f * (co * ci - si * cr);
        }
    }
}

/* dphi <- its DCT-III along x as FFTW_REDFT01 defines it, x[j] = Y[0] +
   2 sum_k Y[k] cos(pi k (j + 1/2) / n) = 2 n times the inverse of
   cosine_forward: V[k] = conj(W_k) (Y[k] - i Y[n - k]) (V[0] = Y[0],
   V[n/2] = sqrt(2) Y[n/2]), its real inverse DFT unordered */
AERO_CLONES
static void cosine_inverse(aero_flow2d *s)
{
    const int n = s->nx, h = n / 2, nc = h + 1;
    if (!s->dct_rows) {
        fftwf_execute((fftwf_plan)s->plan_inv);
        return;
    }
    for (int j = 0; j < s->ny; j++) {
        const float *restrict y = s->dphi + (size_t)j * n;
        const float *restrict tw = s->dct_tw;
        float *restrict c = s->dct_spec + 2 * (size_t)j * nc;
        c[0] = y[0];
        c[1] = 0.0f;
        c[2 * h] = y[h] * (float)1.41421356237309505;
        c[2 * h + 1] = 0.0f;
        for (int k = 1; k < h; k++) {
            float a = y[k], b = y[n - k];
            float co = tw[2 * k], si = tw[2 * k + 1];
            c[2 * k] = co * a + si * b;
            c[2 * k + 1] = si * a - co * b;
        }
    }
    fftwf_execute((fftwf_plan)s->plan_inv);
    for (int j = 0; j < s->ny; j++) {
        const float *restrict v = s->dct_rows + (size_t)j * n;
        float *restrict x = s->dphi + (size_t)j * n;
        for (int k = 0; k < h; k++) {
            x[2 * k] = v[k];
            x[2 * k + 1] = v[n - 1 - k];
        }
    }
}

/* lap(dp) = div(u*) / dt, u = u* - dt grad(dp), p += dp */
AERO_CLONES
static void project(aero_flow2d *s)
{
    const int nx = s->nx, ny = s->ny;
    const float idt_h = 1.0f / (s->dt * s->h), dt_h = s->dt / s->h;
    float *phi = s->dphi;
    for (int j = 0; j < ny; j++) {
        const float *u = s->u + AT(0, j), *v = s->v + AT(0, j);
        const int sx = s->sx;
        if (s->stretched) {
            const float ax = 1.0f / (s->dt * s->h),
                        ay = s->iy_u[j] / s->dt;
            for (int i = 0; i < nx; i++)
                phi[j * nx + i] = (u[i + 1] - u[i]) * ax + (v[i + sx] - v[i]) * ay;
        } else {
            for (int i = 0; i < nx; i++)
                phi[j * nx + i] = (u[i + 1] - u[i] + v[i + sx] - v[i]) * idt_h;
        }
    }
    cosine_forward(s);
    solve_tridiagonal(s);
    cosine_inverse(s);
    for (int j = 0; j < ny; j++) {
        float *u = s->u + AT(0, j);
        const float *p = phi + j * nx;
        for (int i = 1; i < nx; i++)
            u[i] -= dt_h * (p[i] - p[i - 1]);
    }
    for (int j = 1; j < ny; j++) {
        float *v = s->v + AT(0, j);
        const float *p = phi + j * nx, *pm = phi + (j - 1) * nx;
        const float dt_dy = s->stretched ? s->dt * s->iy_v[j] : dt_h;
        for (int i = 0; i < nx; i++)
            v[i] -= dt_dy * (p[i] - pm[i]);
    }
    for (int k = 0; k < nx * ny; k++)
        s->phi[k] += phi[k];
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

int aero_flow2d_step(aero_flow2d *s)
{
    if (s->diverged)
        return -1;
    choose_step(s);
    fill_ghosts(s);
    if (s->turb_k)
        aero_turbulence2d_step(s);
    momentum(s, s->u, s->hu, flux_u_x, flux_u_y, 0, 1, s->iy_u, s->an_u,
             s->as_u);
    momentum(s, s->v, s->hv, flux_v_x, flux_v_y, 1, 0, s->iy_v, s->an_v,
             s->as_v);
    if (s->turb_k)
        aero_turbulence2d_stress(s);
    convective_outflow(s);
    advance_explicit(s);
    damp_outflow(s);
    force_body(s);
    project(s);
    if (s->cavity)
        force_cavity_walls(s);
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
