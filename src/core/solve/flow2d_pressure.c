/* aero: the 2D flow's pressure solve (see flow2d.h): the Poisson
 * equation with Neumann walls, solved exactly by a cosine transform along
 * x (FFTW; the pair made from one real FFT, Makhoul 1980) and a
 * tridiagonal solve along y per cosine mode; the projection that makes
 * each step's velocity divergence-free with it. */
#include "flow2d_internal.h"
#include "aero_air.h"
#include "aero_clones.h"
#include "aero_fftw.h"
#include <math.h>
#include <stdio.h>

/* cosine transforms along x, one per row (planned one at a time
   process-wide: aero_fftw.h). FFTW_ESTIMATE: the plan, and with it the
   rounding of every step, does not depend on timings, so a texture is
   the same to the last bit however loaded the machine is. For an even
   nx the pair DCT-II / DCT-III is made from one real FFT of the
   reordered row (Makhoul 1980): FFTW's real FFTs are vectorised, its
   r2r cosine kinds are not, and the transforms took 2/3 of a step. */
int flow2d_plan_transforms(aero_flow2d *s, char *err, size_t errlen)
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
void flow2d_factor_poisson_y(aero_flow2d *s)
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
void flow2d_project(aero_flow2d *s)
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

