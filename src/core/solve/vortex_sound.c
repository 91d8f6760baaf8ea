/* aero: vortex sound textures of a turbulent box (see vortex_sound.h). */
#include "vortex_sound.h"
#include "aero_air.h"
#include "aero_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void aero_vortex_defaults(aero_vortex_params *p)
{
    /* the flow and its box; the forcing and the step; the listeners */
    *p = (aero_vortex_params){
        .speed = 4.0, .box = 0.1, .n = 32, .nz = 48, .nu = AERO_NU,
        .confinement = 9.6, .turbulence = 0.3, .cfl = 0.5, .settle = 3.0,
        .receivers = 8, .elevation = 0.0, .source = AERO_VORTEX_WINDOW,
        .seed = 1};
}

/* C-infinity step from 0 (t <= 0) to 1 (t >= 1) */
static double smooth_step(double t)
{
    double a, b;
    if (t <= 0.0) return 0.0;
    if (t >= 1.0) return 1.0;
    a = exp(-1.0 / t);
    b = exp(-1.0 / (1.0 - t));
    return a / (a + b);
}

double aero_vortex_window1d(double s, double margin, double ramp)
{
    return smooth_step((s - margin) / ramp) *
           smooth_step((1.0 - margin - s) / ramp);
}

void aero_vortex_window(const aero_flow3d *s, float *win)
{
    for (int k = 0; k < s->nz; k++) {
        double z = (k + 0.5) / s->nz;
        /* the lowest 15 % is where the inflow's imposed perturbation turns
           into turbulence: not counted */
        double wz = smooth_step((z - 0.15) / 0.3) * smooth_step((0.95 - z) / 0.3);
        for (int j = 0; j < s->ny; j++) {
            double wy = aero_vortex_window1d((j + 0.5) / s->ny, 0.05, 0.3);
            for (int i = 0; i < s->nx; i++)
                win[AERO_F3_C(s, i, j, k)] = (float)(
                    wz * wy * aero_vortex_window1d((i + 0.5) / s->nx, 0.05, 0.3));
        }
    }
}

void aero_vortex_moment(const aero_flow3d *s, const float *win,
                        double sym[6])
{
    const double h = s->p.h, h3 = h * h * h;
    double xx = 0, yy = 0, zz = 0, xy = 0, xz = 0, yz = 0;
    for (int k = 0; k < s->nz; k++) {
        double yz_ = (k + 0.5 - 0.5 * s->nz) * h;
        for (int j = 0; j < s->ny; j++) {
            double yy_ = (j + 0.5 - 0.5 * s->ny) * h;
            size_t c0 = AERO_F3_C(s, 0, j, k);
            for (int i = 0; i < s->nx; i++) {
                size_t c = c0 + i;
                double W = win[c];
                if (W == 0.0) continue;
                {
                    double yx_ = (i + 0.5 - 0.5 * s->nx) * h;
                    double ox = s->ox[c], oy = s->oy[c], oz = s->oz[c];
                    /* (y x omega) */
                    double cx = W * (yy_ * oz - yz_ * oy);
                    double cy = W * (yz_ * ox - yx_ * oz);
                    double cz = W * (yx_ * oy - yy_ * ox);
                    xx += yx_ * cx;
                    yy += yy_ * cy;
                    zz += yz_ * cz;
                    xy += yx_ * cy + yy_ * cx;
                    xz += yx_ * cz + yz_ * cx;
                    yz += yy_ * cz + yz_ * cy;
                }
            }
        }
    }
    sym[0] = xx * h3;
    sym[1] = yy * h3;
    sym[2] = zz * h3;
    sym[3] = 0.5 * xy * h3;
    sym[4] = 0.5 * xz * h3;
    sym[5] = 0.5 * yz * h3;
}

double aero_vortex_contract(const double sym[6], const double xh[3])
{
    return sym[0] * xh[0] * xh[0] + sym[1] * xh[1] * xh[1] +
           sym[2] * xh[2] * xh[2] +
           2.0 * (sym[3] * xh[0] * xh[1] + sym[4] * xh[0] * xh[2] +
                  sym[5] * xh[1] * xh[2]);
}

double aero_vortex_cells(const aero_flow3d *s, const double x[3],
                         double alpha)
{
    const int nx = s->nx, ny = s->ny, nz = s->nz;
    const double h = s->p.h, h3 = h * h * h;
    double e[27], total = 0.0;
    for (int d = 0; d < 27; d++) {
        int dx = d % 3 - 1, dy = (d / 3) % 3 - 1, dz = d / 9 - 1;
        e[d] = exp(-alpha * sqrt((double)(dx * dx + dy * dy + dz * dz)));
    }
    for (int k = 0; k < nz; k++)
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++) {
                /* voxel k of the paper = this cell, seen from the voxels l
                   whose integral cell holds it: its neighbours in the box */
                size_t c = AERO_F3_C(s, i, j, k);
                double z = 0.0;
                double ox = s->ox[c], oy = s->oy[c], oz = s->oz[c];
                for (int d = 0; d < 27; d++) {
                    int li = i - (d % 3 - 1), lj = j - ((d / 3) % 3 - 1),
                        lk = k - (d / 9 - 1);
                    if (li >= 0 && li < nx && lj >= 0 && lj < ny && lk >= 0 &&
                        lk < nz)
                        z += e[d];
                }
                for (int d = 0; d < 27; d++) {
                    int ddx = d % 3 - 1, ddy = (d / 3) % 3 - 1, ddz = d / 9 - 1;
                    int li = i - ddx, lj = j - ddy, lk = k - ddz;
                    double X[3], D[3], cr[3];
                    if (li < 0 || li >= nx || lj < 0 || lj >= ny || lk < 0 ||
                        lk >= nz)
                        continue;
                    /* y_l from the box centre, D = y_k - y_l */
                    X[0] = x[0] - (li + 0.5 - 0.5 * nx) * h;
                    X[1] = x[1] - (lj + 0.5 - 0.5 * ny) * h;
                    X[2] = x[2] - (lk + 0.5 - 0.5 * nz) * h;
                    D[0] = ddx * h;
                    D[1] = ddy * h;
                    D[2] = ddz * h;
                    cr[0] = D[1] * oz - D[2] * oy;
                    cr[1] = D[2] * ox - D[0] * oz;
                    cr[2] = D[0] * oy - D[1] * ox;
                    total += e[d] / z *
                             (X[0] * D[0] + X[1] * D[1] + X[2] * D[2]) *
                             (cr[0] * X[0] + cr[1] * X[1] + cr[2] * X[2]);
                }
            }
    return total * h3;
}

void aero_vortex_d3_kernel(double *h, int K, double nu1, double nu2)
{
    /* h = D^3 * l: D^3 is the cube of the central difference
       (x[m+1] - x[m-1]) / 2, response -i sin^3(2 pi nu), exact in relative
       terms at low frequency; l is an even low-pass that turns it into
       (i 2 pi nu)^3 T(nu): L = T (2 pi nu / sin(2 pi nu))^3, a windowed
       cosine series (its truncation error is relative to L ~ 1, not to
       the f^3 response, so low frequencies stay accurate) */
    const int nq = 4096, L = K - 3;
    double l[2 * 512 + 1];
    static const double d3[7] = {0.125, 0.0, -0.375, 0.0, 0.375, 0.0, -0.125};
    if (L < 1 || L > 512) {
        for (int n = 0; n <= 2 * K; n++) h[n] = 0.0;
        return;
    }
    for (int n = 0; n <= 2 * L; n++)
        l[n] = 0.0;
    for (int q = 0; q < nq; q++) {
        double nu = (q + 0.5) * nu2 / nq, T, r, g;
        if (nu <= nu1)
            T = 1.0;
        else
            T = 0.5 * (1.0 + cos(AERO_PI * (nu - nu1) / (nu2 - nu1)));
        r = 2.0 * AERO_PI * nu / sin(2.0 * AERO_PI * nu);
        g = T * r * r * r * 2.0 * (nu2 / nq); /* both signs of nu */
        l[L] += g;
        for (int n = 1; n <= L; n++) {
            double v = g * cos(2.0 * AERO_PI * nu * n);
            l[L + n] += v;
            l[L - n] += v;
        }
    }
    for (int n = 1; n <= L; n++) {
        double a = AERO_PI * (double)n / (L + 1);
        double bw = 0.42 + 0.5 * cos(a) + 0.08 * cos(2.0 * a);
        l[L + n] *= bw;
        l[L - n] *= bw;
    }
    /* d3 holds taps n = -3..3 (y[m] = sum h[n] x[m - n]) */
    for (int n = 0; n <= 2 * K; n++)
        h[n] = 0.0;
    for (int a = 0; a < 7; a++)
        for (int b = 0; b <= 2 * L; b++)
            h[a + b] += d3[a] * l[b];
}

void aero_vortex_resample(const double *x, int n, double rate_in, double t0,
                          double rate_out, float *out, int stride, int nout)
{
    const double fc = 0.45 * (rate_in < rate_out ? rate_in : rate_out);
    const double w = 8.0 / fc; /* half-width of the kernel, s */
    for (int k = 0; k < nout; k++) {
        double t = t0 + k / rate_out, acc = 0.0;
        int m0 = (int)ceil((t - w) * rate_in), m1 = (int)floor((t + w) * rate_in);
        if (m0 < 0) m0 = 0;
        if (m1 > n - 1) m1 = n - 1;
        for (int m = m0; m <= m1; m++) {
            double tau = t - m / rate_in, a = 2.0 * fc * tau, s, q;
            s = fabs(a) < 1e-12 ? 1.0 : sin(AERO_PI * a) / (AERO_PI * a);
            q = AERO_PI * (tau / w + 1.0);
            acc += x[m] * s * (0.42 - 0.5 * cos(q) + 0.08 * cos(2.0 * q));
        }
        out[(size_t)k * stride] = (float)(acc * 2.0 * fc / rate_in);
    }
}

/* --- the simulation ------------------------------------------------------ */

#define D3_HALF 48            /* taps either side of the derivative filter */
#define MODES 12              /* inflow perturbation modes (|m| <= 2) */

static double gauss(uint32_t *rng)
{
    /* sum of four uniforms: zero mean, unit variance, bounded */
    double a = aero_uniform(rng) + aero_uniform(rng) + aero_uniform(rng) +
               aero_uniform(rng);
    return a * 0.8660254037844386; /* sqrt(3/4) */
}

static void step_plan(const aero_vortex_params *p, double rate, int nout,
                      double *dt, long *settle, long *rec)
{
    double h = p->box / p->n, lz = p->nz * h;
    double rate_in, fc, reach;
    *dt = p->cfl * h / p->speed;
    rate_in = 1.0 / *dt;
    fc = 0.45 * (rate_in < rate ? rate_in : rate);
    reach = 8.0 / fc;
    *settle = (long)ceil(p->settle * lz / p->speed / *dt);
    *rec = (long)ceil((nout / rate + 2.0 * reach) * rate_in) + 2 * D3_HALF + 8;
}

long aero_vortex_steps(const aero_vortex_params *p, double rate, int nout)
{
    double dt;
    long a, b;
    step_plan(p, rate, nout, &dt, &a, &b);
    return a + b;
}

/* one simulation: the solver, the inflow's random modes, the recording */
typedef struct {
    const aero_vortex_params *p;
    aero_flow3d s;
    int solver_up, J;           /* J receivers */
    double dt;
    long settle, rec, total;    /* steps: start-up, recorded, all */
    float *win, *tab;           /* the window; the modes' cos and sin */
    double *rec_s;              /* per recorded step: S_ab (6) or, for
                                   cells, one value per receiver */
    double *series, *pj, *pbar; /* one receiver's signal; its pressure;
                                   the ring average */
    double (*xh)[3];            /* receiver directions */
    double sigma[MODES], amp[MODES][3][2], decay, kick;
    uint32_t rng;
} vortex_run;

/* the solver and the buffers, the window and the receivers: 0 or -1 */
static int open_run(vortex_run *v, const aero_vortex_params *p, double rate,
                    int nout, void *ctx, char *err, size_t errlen)
{
    aero_flow3d_params fp;
    const int J = p->receivers;
    memset(v, 0, sizeof *v);
    v->p = p;
    v->J = J;
    v->rng = p->seed ? p->seed : 1;
    if (!(p->speed > 0.0) || !(p->box > 0.0) || p->n < 4 || p->nz < 3 ||
        !(p->cfl > 0.0) || J < 1 || J > 64 || nout < 1 || !(rate > 0.0)) {
        snprintf(err, errlen, "bad simulation parameters");
        return -1;
    }
    step_plan(p, rate, nout, &v->dt, &v->settle, &v->rec);
    v->total = v->settle + v->rec;
    memset(&fp, 0, sizeof fp); /* fields it does not set are off */
    fp.nx = fp.ny = p->n;
    fp.nz = p->nz;
    fp.h = p->box / p->n;
    fp.nu = p->nu;
    fp.confinement = p->confinement;
    fp.confinement_length = p->box; /* eps h / box: the same forcing at
                                       any grid (FSJ01) */
    fp.u_ref = p->speed;
    /* the top 15 %: outside the window (which ends at 95 % and ramps down
       from 65 %), so the absorbing layer is not heard */
    fp.sponge = 0.15;
    if (p->plan_lock) p->plan_lock(ctx, 1);
    v->solver_up = aero_flow3d_init(&v->s, &fp, err, errlen) == 0;
    if (p->plan_lock) p->plan_lock(ctx, 0);
    if (!v->solver_up)
        return -1;
    v->win = malloc(sizeof(float) * v->s.plane * v->s.nz);
    v->tab = malloc(sizeof(float) * v->s.plane * MODES * 2);
    v->rec_s = malloc(sizeof(double) * (size_t)v->rec *
                      (p->source == AERO_VORTEX_CELLS ? (size_t)J : 6));
    v->series = malloc(sizeof(double) * (size_t)v->rec);
    v->pj = malloc(sizeof(double) * (size_t)v->rec);
    v->pbar = calloc((size_t)v->rec, sizeof(double));
    v->xh = malloc(sizeof(*v->xh) * J);
    if (!v->win || !v->tab || !v->rec_s || !v->series || !v->pj ||
        !v->pbar || !v->xh) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    aero_vortex_window(&v->s, v->win);
    for (int j = 0; j < J; j++) {
        double e = p->elevation * AERO_PI / 180.0, a = 2.0 * AERO_PI * j / J;
        v->xh[j][0] = cos(e) * cos(a);
        v->xh[j][1] = cos(e) * sin(a);
        v->xh[j][2] = sin(e);
    }
    return 0;
}

static void close_run(vortex_run *v, void *ctx)
{
    const aero_vortex_params *p = v->p;
    AERO_FREE_ALL(v->win, v->tab, v->rec_s, v->series, v->pj, v->pbar,
                  v->xh);
    if (v->solver_up) {
        if (p->plan_lock) p->plan_lock(ctx, 1);
        aero_flow3d_free(&v->s);
        if (p->plan_lock) p->plan_lock(ctx, 0);
    }
}

/* inflow: u (0, 0, U) plus a random field of the 12 Fourier modes with
   |mx|, |my| <= 2 (wavelengths box and box/2), each amplitude an
   Ornstein-Uhlenbeck process of correlation time box / (2 U): the eddies
   of the inflow live about half a flow-through time. The box starts in
   uniform flow. */
static void seed_inflow(vortex_run *v)
{
    const aero_vortex_params *p = v->p;
    aero_flow3d *s = &v->s;
    int mode_x[MODES], mode_y[MODES], q = 0;
    double sigma_sum = 0.0, tau;
    for (int my = -2; my <= 2; my++)
        for (int mx = -2; mx <= 2; mx++)
            if (mx > 0 || (mx == 0 && my > 0)) {
                mode_x[q] = mx;
                mode_y[q] = my;
                v->sigma[q] = 1.0 / sqrt((double)(mx * mx + my * my));
                sigma_sum += v->sigma[q] * v->sigma[q];
                q++;
            }
    for (q = 0; q < MODES; q++) {
        v->sigma[q] *= p->turbulence * p->speed / sqrt(sigma_sum);
        for (int c = 0; c < 3; c++)
            for (int b = 0; b < 2; b++)
                v->amp[q][c][b] = v->sigma[q] * gauss(&v->rng);
        for (int j = 0; j < s->ny; j++)
            for (int i = 0; i < s->nx; i++) {
                double th = 2.0 * AERO_PI * (mode_x[q] * (i + 0.5) / s->nx +
                                             mode_y[q] * (j + 0.5) / s->ny);
                v->tab[(size_t)(2 * q) * s->plane + j * s->nx + i] =
                    (float)cos(th);
                v->tab[(size_t)(2 * q + 1) * s->plane + j * s->nx + i] =
                    (float)sin(th);
            }
    }
    tau = 0.5 * p->box / p->speed;
    v->decay = exp(-v->dt / tau);
    v->kick = sqrt(1.0 - v->decay * v->decay);
    for (size_t c = 0; c < s->plane * (s->nz + 1); c++)
        s->w[c] = (float)p->speed;
}

/* the inflow for the next step: the modes' amplitudes advanced */
static void step_inflow(vortex_run *v)
{
    aero_flow3d *s = &v->s;
    for (int q = 0; q < MODES; q++)
        for (int c = 0; c < 3; c++)
            for (int b = 0; b < 2; b++)
                v->amp[q][c][b] = v->decay * v->amp[q][c][b] +
                                  v->kick * v->sigma[q] * gauss(&v->rng);
    for (size_t c = 0; c < s->plane; c++) {
        double a[3] = {0.0, 0.0, v->p->speed};
        for (int q = 0; q < MODES; q++) {
            double cs = v->tab[(size_t)(2 * q) * s->plane + c],
                   sn = v->tab[(size_t)(2 * q + 1) * s->plane + c];
            for (int k = 0; k < 3; k++)
                a[k] += v->amp[q][k][0] * cs + v->amp[q][k][1] * sn;
        }
        s->in_u[c] = (float)a[0];
        s->in_v[c] = (float)a[1];
        s->in_w[c] = (float)a[2];
    }
}

/* every step; after the start-up, the moment (or the cells' sums) of
   each: 0 or -1 */
static int run_flow(vortex_run *v, aero_vortex_hook hook, long every,
                    void *ctx, char *err, size_t errlen)
{
    aero_flow3d *s = &v->s;
    const int J = v->J;
    for (long m = 0; m < v->total; m++) {
        step_inflow(v);
        if (aero_flow3d_step(s, v->dt)) {
            snprintf(err, errlen, "the flow diverged at step %ld (u = %g m/s): "
                     "try a smaller --cfl or --confinement", m, v->p->speed);
            return -1;
        }
        if (m >= v->settle) {
            long r = m - v->settle;
            aero_flow3d_vorticity(s);
            if (v->p->source == AERO_VORTEX_CELLS) {
                for (int j = 0; j < J; j++)
                    v->rec_s[(size_t)r * J + j] =
                        aero_vortex_cells(s, v->xh[j], 3.0);
            } else {
                aero_vortex_moment(s, v->win, v->rec_s + (size_t)r * 6);
            }
        }
        if (hook && every > 0 && (m % every == 0 || m == v->total - 1))
            hook(ctx, s, m, m >= v->settle);
    }
    return 0;
}

/* steps, dt, divergence and mean vorticity in the window */
static void measure(const vortex_run *v, aero_vortex_stats *st)
{
    const aero_flow3d *s = &v->s;
    double sum = 0.0, wsum = 0.0;
    st->steps = v->total;
    st->dt = v->dt;
    st->max_div = aero_flow3d_max_divergence(s);
    for (size_t c = 0; c < s->plane * s->nz; c++)
        if (v->win[c] > 0.5f) {
            sum += s->omag[c];
            wsum += 1.0;
        }
    st->mean_vort = wsum > 0.0 ? sum / wsum : 0.0;
}

/* each receiver's pressure: contracted, differentiated three times and
   averaged over the ring into pbar[lo, hi), rescaled to the receivers'
   mean square (st->gain) */
static void ring_pressure(vortex_run *v, long lo, long hi,
                          aero_vortex_stats *st)
{
    /* Howe: p r = rho0 / (12 pi c0^2) xh xh : S''' (per second^3) */
    const double scale = AERO_RHO / (12.0 * AERO_PI * AERO_C0 * AERO_C0) /
                         (v->dt * v->dt * v->dt);
    const int J = v->J;
    double dk[2 * D3_HALF + 1], msq = 0.0, bar = 0.0;
    aero_vortex_d3_kernel(dk, D3_HALF, 0.2, 0.35);
    for (int j = 0; j < J; j++) {
        double e = 0.0;
        for (long r = 0; r < v->rec; r++)
            v->series[r] = v->p->source == AERO_VORTEX_CELLS
                               ? v->rec_s[(size_t)r * J + j]
                               : aero_vortex_contract(v->rec_s + (size_t)r * 6,
                                                      v->xh[j]);
        for (long r = lo; r < hi; r++) {
            double acc = 0.0;
            for (int q = -D3_HALF; q <= D3_HALF; q++)
                acc += dk[D3_HALF + q] * v->series[r - q];
            v->pj[r] = acc * scale;
            v->pbar[r] += v->pj[r] / J;
            e += v->pj[r] * v->pj[r];
        }
        msq += e / (double)(hi - lo) / J;
    }
    for (long r = lo; r < hi; r++)
        bar += v->pbar[r] * v->pbar[r];
    bar /= (double)(hi - lo);
    st->receiver_rms = sqrt(msq);
    st->gain = bar > 0.0 ? sqrt(msq / bar) : 1.0;
    if (!(st->gain < 1e3)) st->gain = 1e3; /* a cancelled average */
    for (long r = lo; r < hi; r++)
        v->pbar[r] *= st->gain;
}

/* the ring's pressure at the texture rate into out */
static void radiate(vortex_run *v, double rate, float *out, int stride,
                    int nout, aero_vortex_stats *st)
{
    const long lo = D3_HALF, hi = v->rec - D3_HALF; /* valid outputs */
    const double rate_in = 1.0 / v->dt;
    const double fc = 0.45 * (rate_in < rate ? rate_in : rate);
    double e = 0.0;
    ring_pressure(v, lo, hi, st);
    aero_vortex_resample(v->pbar + lo, (int)(hi - lo), rate_in, 8.0 / fc,
                         rate, out, stride, nout);
    for (int k = 0; k < nout; k++)
        e += (double)out[(size_t)k * stride] * out[(size_t)k * stride];
    st->rms = sqrt(e / nout);
}

int aero_vortex_simulate(const aero_vortex_params *p, double rate,
                         float *out, int stride, int nout,
                         aero_vortex_stats *st, aero_vortex_hook hook,
                         long every, void *ctx, char *err, size_t errlen)
{
    vortex_run v;
    int status = -1;
    memset(st, 0, sizeof *st);
    if (open_run(&v, p, rate, nout, ctx, err, errlen) == 0) {
        seed_inflow(&v);
        if (run_flow(&v, hook, every, ctx, err, errlen) == 0) {
            measure(&v, st);
            radiate(&v, rate, out, stride, nout, st);
            status = 0;
        }
    }
    close_run(&v, ctx);
    return status;
}
