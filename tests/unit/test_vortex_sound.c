/* aero: tests of the vortex-sound textures (src/core/solve/vortex_sound.c):
 * the third-derivative filter and the resampler against analytic signals,
 * Howe's moment of a known vorticity field, the paper's integral cells
 * cancelling in the interior (why they are not the default), and the
 * physics of the texture on a tiny grid: the level grows as u^4 (a
 * quadrupole: Lighthill's u^8 intensity law), the spectral centroid rises
 * in proportion to u, no NaN. */
#include "unit.h"
#include "aero_air.h"
#include "aero_util.h"
#include "vortex_sound.h"

#include <fftw3.h>
#include <stdlib.h>
#include <string.h>

UNIT_TEST(d3_kernel)
{
    enum { K = 48, N = 600 };
    double h[2 * K + 1], x[N];
    printf("third-derivative filter\n");
    aero_vortex_d3_kernel(h, K, 0.2, 0.35);
    /* in the pass band: sin(2 pi nu m)''' = -(2 pi nu)^3 cos(2 pi nu m) */
    for (int q = 0; q < 3; q++) {
        const double nus[3] = {0.01, 0.05, 0.15};
        double nu = nus[q], worst = 0.0, amp = pow(2.0 * AERO_PI * nu, 3.0);
        char what[96];
        for (int m = 0; m < N; m++)
            x[m] = sin(2.0 * AERO_PI * nu * m);
        for (int m = K; m < N - K; m++) {
            double acc = 0.0, want = -amp * cos(2.0 * AERO_PI * nu * m);
            for (int n = -K; n <= K; n++)
                acc += h[K + n] * x[m - n];
            if (fabs(acc - want) > worst) worst = fabs(acc - want);
        }
        snprintf(what, sizeof what, "nu = %.2f: largest error relative to "
                 "(2 pi nu)^3", nu);
        /* 1 %: the windowed FIR's ripple */
        UNIT_CHECK(worst < 0.01 * amp, "%s: %.2g", what, worst / amp);
    }
    /* above the taper: step-to-step noise is not amplified */
    {
        double nu = 0.45, peak = 0.0;
        for (int m = 0; m < N; m++)
            x[m] = sin(2.0 * AERO_PI * nu * m);
        for (int m = K; m < N - K; m++) {
            double acc = 0.0;
            for (int n = -K; n <= K; n++)
                acc += h[K + n] * x[m - n];
            if (fabs(acc) > peak) peak = fabs(acc);
        }
        UNIT_CHECK(peak < 1e-3 * pow(2.0 * AERO_PI * nu, 3.0),
                   "nu = 0.45 suppressed: %.2g of (2 pi nu)^3",
                   peak / pow(2.0 * AERO_PI * nu, 3.0));
    }
}

UNIT_TEST(resample)
{
    enum { N = 800, M = 4000 };
    double x[N];
    float y[M];
    double worst = 0.0;
    printf("band-limited resampling\n");
    /* 60 Hz sampled at 640 Hz, read at 16 kHz */
    for (int m = 0; m < N; m++)
        x[m] = sin(2.0 * AERO_PI * 60.0 * m / 640.0);
    aero_vortex_resample(x, N, 640.0, 0.1, 16000.0, y, 1, M);
    for (int k = 0; k < M; k++) {
        double t = 0.1 + k / 16000.0;
        double d = fabs(y[k] - sin(2.0 * AERO_PI * 60.0 * t));
        if (d > worst) worst = d;
    }
    UNIT_CHECK(worst < 2e-3, "upsampling 640 Hz -> 16 kHz: largest error %.2g",
               worst);
    /* 1 kHz sampled at 10 kHz, read at 4 kHz (below the new Nyquist) */
    worst = 0.0;
    for (int m = 0; m < N; m++)
        x[m] = sin(2.0 * AERO_PI * 1000.0 * m / 10000.0);
    aero_vortex_resample(x, N, 10000.0, 0.01, 4000.0, y, 1, 200);
    for (int k = 0; k < 200; k++) {
        double t = 0.01 + k / 4000.0;
        double d = fabs(y[k] - sin(2.0 * AERO_PI * 1000.0 * t));
        if (d > worst) worst = d;
    }
    UNIT_CHECK(worst < 2e-3, "downsampling 10 kHz -> 4 kHz: largest error "
               "%.2g", worst);
}

static int make(aero_flow3d *s, int n, int nz)
{
    aero_flow3d_params p;
    char err[256];
    memset(&p, 0, sizeof p);
    p.nx = p.ny = n;
    p.nz = nz;
    p.h = 0.01;
    return aero_flow3d_init(s, &p, err, sizeof err);
}

UNIT_TEST(moment)
{
    aero_flow3d s;
    float *win;
    double sym[6], y[3], o[3] = {3.0, -2.0, 5.0}, c[3], want[6];
    uint32_t rng = 5;
    printf("Howe's moment\n");
    if (make(&s, 8, 10)) return;
    win = malloc(sizeof(float) * s.plane * s.nz);
    for (size_t k = 0; k < s.plane * s.nz; k++)
        win[k] = 1.0f;
    /* one cell (i, j, k) = (6, 1, 7) with vorticity o */
    s.ox[AERO_F3_C(&s, 6, 1, 7)] = (float)o[0];
    s.oy[AERO_F3_C(&s, 6, 1, 7)] = (float)o[1];
    s.oz[AERO_F3_C(&s, 6, 1, 7)] = (float)o[2];
    y[0] = (6.5 - 4.0) * 0.01;
    y[1] = (1.5 - 4.0) * 0.01;
    y[2] = (7.5 - 5.0) * 0.01;
    c[0] = y[1] * o[2] - y[2] * o[1];
    c[1] = y[2] * o[0] - y[0] * o[2];
    c[2] = y[0] * o[1] - y[1] * o[0];
    want[0] = y[0] * c[0];
    want[1] = y[1] * c[1];
    want[2] = y[2] * c[2];
    want[3] = 0.5 * (y[0] * c[1] + y[1] * c[0]);
    want[4] = 0.5 * (y[0] * c[2] + y[2] * c[0]);
    want[5] = 0.5 * (y[1] * c[2] + y[2] * c[1]);
    aero_vortex_moment(&s, win, sym);
    {
        double worst = 0.0;
        for (int k = 0; k < 6; k++)
            worst = fmax(worst, fabs(sym[k] - want[k] * 1e-6));
        UNIT_CHECK(worst < 1e-12, "one cell: S_ab = y_a (y x omega)_b h^3 "
                   "(largest error %.2g m^5/s)", worst);
    }
    /* y . (y x omega) = 0: the trace vanishes for any field, so the
       direction average of the pressure does too */
    for (size_t k = 0; k < s.plane * s.nz; k++) {
        s.ox[k] = (float)aero_uniform(&rng);
        s.oy[k] = (float)aero_uniform(&rng);
        s.oz[k] = (float)aero_uniform(&rng);
    }
    aero_vortex_moment(&s, win, sym);
    UNIT_CHECK(fabs(sym[0] + sym[1] + sym[2]) <
                   1e-9 * (fabs(sym[0]) + fabs(sym[1]) + fabs(sym[2])),
               "trace of S for a random field: %.2g (diagonal %.2g %.2g %.2g)",
               sym[0] + sym[1] + sym[2], sym[0], sym[1], sym[2]);
    /* the window: zero at the faces, one inside, smooth */
    UNIT_CHECK(aero_vortex_window1d(0.02, 0.05, 0.3) == 0.0 &&
                   aero_vortex_window1d(0.5, 0.05, 0.3) == 1.0 &&
                   aero_vortex_window1d(0.99, 0.05, 0.3) == 0.0 &&
                   fabs(aero_vortex_window1d(0.2, 0.05, 0.3) - 0.5) < 1e-12,
               "window: 0 at the faces, 1 in the middle, 1/2 mid-ramp");
    free(win);
    aero_flow3d_free(&s);
}

/* The paper's integral cells (eq. 3-4): a voxel whose 27-neighbourhood
 * lies inside the box adds exactly nothing, whatever the vorticity and
 * the receiver; only voxels on the faces make sound. */
UNIT_TEST(cells_cancel)
{
    aero_flow3d s;
    uint32_t rng = 11;
    double x[3] = {0.6, 0.5, 0.3}, interior, face, scale = 0.0;
    printf("paper's integral cells\n");
    if (make(&s, 8, 8)) return;
    for (int k = 1; k < 7; k++)
        for (int j = 1; j < 7; j++)
            for (int i = 1; i < 7; i++) {
                size_t c = AERO_F3_C(&s, i, j, k);
                s.ox[c] = (float)aero_uniform(&rng);
                s.oy[c] = (float)aero_uniform(&rng);
                s.oz[c] = (float)aero_uniform(&rng);
            }
    interior = aero_vortex_cells(&s, x, 3.0);
    {
        /* the size of one voxel's term: |x|^2 h^2 |omega| h^3 */
        scale = (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) * 1e-4 * 1e-6;
    }
    UNIT_CHECK(fabs(interior) < 1e-9 * scale * 216,
               "vorticity inside only: sum %.3g (one voxel's term ~%.2g)",
               interior, scale);
    /* one voxel on the face x = 0 (vorticity along y: along x the
       truncated sum still cancels by symmetry in y and z) */
    s.oy[AERO_F3_C(&s, 0, 3, 4)] = 1.0f;
    face = aero_vortex_cells(&s, x, 3.0);
    UNIT_CHECK(fabs(face) > 0.01 * scale,
               "one face voxel added: sum %.3g (the only sound)", face);
    aero_flow3d_free(&s);
}

/* rms and spectral centroid of a signal */
static void measure(const float *x, int n, double rate, double *rms,
                    double *centroid)
{
    double *b = fftw_malloc(sizeof(double) * n), e = 0.0, sw = 0.0, sf = 0.0;
    fftw_complex *o = fftw_malloc(sizeof(fftw_complex) * (n / 2 + 1));
    fftw_plan p = fftw_plan_dft_r2c_1d(n, b, o, FFTW_ESTIMATE);
    for (int k = 0; k < n; k++) {
        e += (double)x[k] * x[k];
        b[k] = x[k] * (0.5 - 0.5 * cos(2.0 * AERO_PI * k / n));
    }
    fftw_execute(p);
    for (int k = 1; k <= n / 2; k++) {
        double P = o[k][0] * o[k][0] + o[k][1] * o[k][1];
        sw += P;
        sf += P * k * rate / n;
    }
    *rms = sqrt(e / n);
    *centroid = sw > 0.0 ? sf / sw : 0.0;
    fftw_destroy_plan(p);
    fftw_free(b);
    fftw_free(o);
}

/* The texture on a tiny grid (12 x 12 x 18, box 6 cm): four speeds, each
 * recorded for the same 40 flow-through times, independent seeds. */
UNIT_TEST(texture_physics)
{
    const double speeds[4] = {2.0, 4.0, 8.0, 16.0}, rate = 16000.0;
    double lr[4], lu[4], rms[4], cen[4];
    int finite = 1, mono = 1, rising = 1;
    printf("texture physics (12 x 12 x 18 cells, 4 speeds)\n");
    for (int k = 0; k < 4; k++) {
        aero_vortex_params p;
        aero_vortex_stats st;
        char err[256];
        int nout;
        float *out;
        aero_vortex_defaults(&p);
        p.box = 0.06;
        p.n = 12;
        p.nz = 18;
        p.speed = speeds[k];
        p.seed = 1000u + 17u * k;
        nout = (int)(40.0 * p.box * 1.5 / p.speed * rate);
        out = malloc(sizeof(float) * nout);
        if (aero_vortex_simulate(&p, rate, out, 1, nout, &st, NULL, 0, NULL,
                                 err, sizeof err)) {
            UNIT_CHECK(0, "simulation at %g m/s: %s", speeds[k], err);
            free(out);
            return;
        }
        for (int n = 0; n < nout; n++)
            if (!isfinite(out[n])) finite = 0;
        measure(out, nout, rate, &rms[k], &cen[k]);
        printf("  u %4.1f m/s: rms %.3g Pa at 1 m, centroid %.0f Hz, %ld "
               "steps\n", speeds[k], rms[k], cen[k], st.steps);
        lr[k] = log(rms[k]);
        lu[k] = log(speeds[k]);
        if (k && !(rms[k] > rms[k - 1])) mono = 0;
        if (k && !(cen[k] > cen[k - 1])) rising = 0;
        free(out);
    }
    UNIT_CHECK(finite, "no NaN or Inf in any channel");
    UNIT_CHECK(mono, "rms grows with u");
    {
        /* least-squares slope of log rms over log u. Expected 4: the
           pressure of a compact quadrupole ~ rho0 u^4 L / (c0^2 r)
           (Lighthill's u^8 intensity). Tolerance +-0.3: each record holds
           40 flow-through times of a random flow whose rms varies between
           seeds by about +-11 % (measured: 6 seeds at 4 m/s on this grid
           gave 0.89 .. 1.09 of their mean), a standard error of ~0.05 in a
           slope fitted over a factor 8 of speed; the rest of the margin is
           for the viscous (Reynolds-number) dependence, small at Re ~ 1e4.
           A dipole's u^3, or u^5 from a mis-scaled derivative, would be
           outside it. */
        double mx = 0, my = 0, sxy = 0, sxx = 0, slope;
        for (int k = 0; k < 4; k++) {
            mx += lu[k] / 4;
            my += lr[k] / 4;
        }
        for (int k = 0; k < 4; k++) {
            sxy += (lu[k] - mx) * (lr[k] - my);
            sxx += (lu[k] - mx) * (lu[k] - mx);
        }
        slope = sxy / sxx;
        UNIT_CHECK(fabs(slope - 4.0) <= 0.3,
                   "rms ~ u^%.2f (quadrupole: 4 +- 0.3)", slope);
    }
    UNIT_CHECK(rising, "spectral centroid rises with u");
    /* the flow is self-similar in u t / box, so frequencies scale with u:
       centroid(16) / centroid(2) = 8; +-15 %: the centroid of one
       record varies less than its level (a ratio of two averages) */
    UNIT_CHECK(fabs(cen[3] / cen[0] / 8.0 - 1.0) < 0.15,
               "centroid ratio 16 m/s / 2 m/s = %.2f (u ratio 8)",
               cen[3] / cen[0]);
}

UNIT_MAIN(UNIT_CASE(d3_kernel), UNIT_CASE(resample), UNIT_CASE(moment), UNIT_CASE(cells_cancel), UNIT_CASE(texture_physics))
