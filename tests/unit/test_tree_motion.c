/* unit tests of src/core/play/tree_motion.c: the cantilever springs of
 * Matsuyama et al. 2005 (eqs. 1-4), accumulation from the root, independence
 * from the caller's step size, determinism from the seed. */
#include "../../src/core/common/tree.h"
#include "../../src/core/play/tree_motion.h"
#include "unit.h"

#include <fftw3.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

static double dist(const double a[3], const double b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1])
                + (a[2] - b[2]) * (a[2] - b[2]));
}

/* one vertical rod, 1 m long, 1 cm thick */
static void rod_tree(aero_tree *t)
{
    char err[128];
    aero_tree_parse("branch 0 -1 0 0 0 0 0 1 0.01 0.01\n", t, NULL, NULL, err,
                    sizeof err);
}

UNIT_TEST(still_air)
{
    aero_tree t;
    aero_tree_motion m;
    aero_tree_shape shape = {4, 500, 2.0, 0.15, 0.08, 0.05, 3};
    double pos[3], vel[3], worst = 0.0, vmax = 0.0;
    int i, s;
    aero_tree_generate(&t, &shape);
    UNIT_CHECK(aero_tree_motion_init(&m, &t, 1) == 0, "init on %d branches",
               t.nbranches);
    for (s = 0; s < 100; s++) {
        aero_tree_motion_advance(&m, 0.02);
        for (i = 0; i < t.nbranches; i++) {
            aero_tree_motion_point(&m, i, 1.0, pos, vel);
            if (dist(pos, t.branches[i].b) > worst)
                worst = dist(pos, t.branches[i].b);
            if (sqrt(vel[0] * vel[0] + vel[1] * vel[1] + vel[2] * vel[2])
                > vmax)
                vmax = sqrt(vel[0] * vel[0] + vel[1] * vel[1]
                            + vel[2] * vel[2]);
        }
    }
    UNIT_CHECK(worst < 1e-12 && vmax < 1e-12,
               "no wind: every tip stays at rest (moved %g m, %g m/s)", worst,
               vmax);
    aero_tree_motion_point(&m, -1, 0.5, pos, vel);
    UNIT_CHECK(pos[0] == 0.0 && vel[2] == 0.0, "a bad index gives zeros");
    aero_tree_motion_free(&m);
    aero_tree_free(&t);
}

/* eq. 1: the mean deflection is the load over the spring constant:
   theta = F l^2 / (2 E I), F = 0.5 rho Cd d l U^2, soft-limited by
   0.3 tanh(theta / 0.3) */
UNIT_TEST(static_deflection)
{
    aero_tree t;
    aero_tree_motion m;
    double wind[3] = {10.0, 0.0, 0.0}, pos[3], vel[3], sumx = 0.0, sumy = 0.0;
    double force = 0.5 * 1.225 * 1.2 * 0.01 * 1.0 * 100.0;
    double inertia = PI * 1e-8 / 64.0;
    double theta = force * 1.0 / (2.0 * 1e10 * inertia);
    double want = sin(0.3 * tanh(theta / 0.3));
    int s, n = 0;
    rod_tree(&t);
    aero_tree_motion_init(&m, &t, 5);
    aero_tree_motion_set_beta(&m, 0.0); /* fast noise: short average */
    aero_tree_motion_set_wind(&m, wind);
    aero_tree_motion_advance(&m, 5.0); /* the swing-out decays (zeta 0.15) */
    for (s = 0; s < 6000; s++) {
        aero_tree_motion_advance(&m, 0.01);
        aero_tree_motion_point(&m, 0, 1.0, pos, vel);
        sumx += pos[0];
        sumy += pos[1];
        n++;
    }
    /* noise rms is 30 % of the load; 60 s of noise with corners up to
       12.8 Hz averages it to ~1 %: 5 % tolerance */
    UNIT_NEAR_REL(sumx / n, want, 0.05,
                  "rod 1 m x 1 cm at 10 m/s: mean downwind tip shift, m");
    UNIT_CHECK(fabs(sumy / n) < 0.1 * want,
               "no mean shift across the wind (%g m)", sumy / n);
    aero_tree_motion_free(&m);

    /* negative control: a stiffer tree bends less (1/k) */
    aero_tree_motion_init(&m, &t, 5);
    aero_tree_motion_set_beta(&m, 0.0);
    aero_tree_motion_set_stiffness(&m, 4.0);
    aero_tree_motion_set_wind(&m, wind);
    aero_tree_motion_advance(&m, 5.0);
    sumx = 0.0;
    for (s = 0; s < 6000; s++) {
        aero_tree_motion_advance(&m, 0.01);
        aero_tree_motion_point(&m, 0, 1.0, pos, vel);
        sumx += pos[0];
    }
    UNIT_NEAR_REL(sumx / 6000, sin(0.3 * tanh(theta / 4.0 / 0.3)), 0.05,
                  "stiffness 4: a quarter of the angle");
    aero_tree_motion_free(&m);
    aero_tree_free(&t);
}

/* released from a deflection, the rod swings at its cantilever frequency
   omega = sqrt(3 E I / (l^3 M)) */
UNIT_TEST(sway_frequency)
{
    aero_tree t;
    aero_tree_motion m;
    double wind[3] = {10.0, 0.0, 0.0}, still[3] = {0.0, 0.0, 0.0};
    double pos[3], vel[3], prev = 0.0, first = -1.0, last = -1.0;
    double inertia = PI * 1e-8 / 64.0, mass = 800.0 * PI / 4.0 * 1e-4;
    double omega = sqrt(3.0 * 1e10 * inertia / mass);
    double zeta = 0.15, fd = omega * sqrt(1.0 - zeta * zeta) / (2.0 * PI);
    int s, crossings = 0;
    rod_tree(&t);
    aero_tree_motion_init(&m, &t, 5);
    aero_tree_motion_set_wind(&m, wind);
    aero_tree_motion_advance(&m, 10.0);
    aero_tree_motion_set_wind(&m, still);
    for (s = 0; s < 3000; s++) { /* 3 s at 1 ms */
        double tnow = m.time;
        aero_tree_motion_advance(&m, 0.001);
        aero_tree_motion_point(&m, 0, 1.0, pos, vel);
        if (s > 0 && prev > 0.0 && pos[0] <= 0.0) {
            double tc = tnow + 0.001 * prev / (prev - pos[0]);
            if (first < 0.0)
                first = tc;
            last = tc;
            crossings++;
        }
        prev = pos[0];
    }
    UNIT_CHECK(crossings >= 3, "the released rod swings (%d crossings)",
               crossings);
    if (crossings >= 3)
        /* 200 steps per second, omega dt = 0.08: the integrator's
           frequency error is ~(omega dt)^2 / 24 < 0.1 %; 2 % tolerance */
        UNIT_NEAR_REL((crossings - 1) / (last - first), fd, 0.02,
                      "damped sway frequency of the rod, Hz");
    aero_tree_motion_free(&m);
    aero_tree_free(&t);
}

/* children move with their parents: a child's start stays on its parent's
   end (the generated tree's children start at their parent's end) */
UNIT_TEST(accumulation_and_steps)
{
    aero_tree t;
    aero_tree_motion m, a, b, c;
    aero_tree_shape shape = {4, 300, 2.0, 0.15, 0.08, 0.05, 11};
    double wind[3] = {6.0, 2.0, 0.0}, p0[3], p1[3], v0[3], v1[3];
    double gap = 0.0, moved = 0.0, diff = 0.0, seeddiff = 0.0;
    int i, s;
    aero_tree_generate(&t, &shape);
    aero_tree_motion_init(&m, &t, 9);
    aero_tree_motion_set_wind(&m, wind);
    for (s = 0; s < 300; s++) {
        aero_tree_motion_advance(&m, 0.0123);
        for (i = 1; i < t.nbranches; i++) {
            int p = t.branches[i].parent;
            aero_tree_motion_point(&m, i, 0.0, p0, v0);
            aero_tree_motion_point(&m, p, 1.0, p1, v1);
            if (dist(p0, p1) > gap)
                gap = dist(p0, p1);
            if (dist(v0, v1) > gap)
                gap = dist(v0, v1);
        }
    }
    for (i = 0; i < t.nbranches; i++) {
        aero_tree_motion_point(&m, i, 1.0, p0, v0);
        moved += dist(p0, t.branches[i].b) / t.nbranches;
    }
    UNIT_CHECK(gap < 1e-9, "children stay attached to their parents "
               "(largest gap %g m or m/s)", gap);
    UNIT_CHECK(moved > 0.005, "the wind moves the tips (mean %g m)", moved);
    aero_tree_motion_free(&m);

    /* the same motion whatever the caller's step: audio blocks of
       64/44100 s against video frames of 1/30 s, compared at common
       times (every 0.1 s) */
    aero_tree_motion_init(&a, &t, 21);
    aero_tree_motion_init(&b, &t, 21);
    aero_tree_motion_init(&c, &t, 22);
    aero_tree_motion_set_wind(&a, wind);
    aero_tree_motion_set_wind(&b, wind);
    aero_tree_motion_set_wind(&c, wind);
    for (s = 1; s <= 50; s++) {
        double target = 0.1 * s;
        while (a.time + 64.0 / 44100.0 <= target)
            aero_tree_motion_advance(&a, 64.0 / 44100.0);
        aero_tree_motion_advance(&a, target - a.time);
        while (b.time + 1.0 / 30.0 <= target + 1e-12)
            aero_tree_motion_advance(&b, 1.0 / 30.0);
        aero_tree_motion_advance(&b, target - b.time);
        aero_tree_motion_advance(&c, target - c.time);
        for (i = 0; i < t.nbranches; i++) {
            aero_tree_motion_point(&a, i, 1.0, p0, v0);
            aero_tree_motion_point(&b, i, 1.0, p1, v1);
            if (dist(p0, p1) > diff)
                diff = dist(p0, p1);
            aero_tree_motion_point(&c, i, 1.0, p1, v1);
            if (dist(p0, p1) > seeddiff)
                seeddiff = dist(p0, p1);
        }
    }
    UNIT_CHECK(diff < 1e-9, "blocks of 64/44100 s and frames of 1/30 s give "
               "the same motion (%g m)", diff);
    UNIT_CHECK(seeddiff > 1e-3, "another seed moves differently (%g m, "
               "negative control)", seeddiff);
    {
        double bad[3] = {0.0 / 0.0, 1.0, 1.0};
        aero_tree_motion_set_wind(&a, bad);
        aero_tree_motion_set_stiffness(&a, -1.0);
        aero_tree_motion_set_beta(&a, 1.0 / 0.0);
        aero_tree_motion_advance(&a, 0.0 / 0.0);
        UNIT_CHECK(a.wind[0] == 6.0 && a.stiffness == 1.0
                       && a.beta > 1.6 && a.beta < 1.7,
                   "NaN wind, negative stiffness, infinite beta are ignored");
    }
    aero_tree_motion_free(&a);
    aero_tree_motion_free(&b);
    aero_tree_motion_free(&c);
    aero_tree_free(&t);
}

/* the loads' noise is 1/f^beta: a very stiff rod follows its load (spring
   at 32 Hz, flat below 10 Hz), so the spectrum of its tip's sway has the
   slope -beta; fitted over 0.3..3 Hz, a decade inside the noise's
   0.05..12.8 Hz band of octave-spaced relaxations (their sum ripples by a
   few percent: +-0.25 on the slope) */
static double sway_slope(double beta)
{
    aero_tree t;
    aero_tree_motion m;
    double wind[3] = {10.0, 0.0, 0.0}, pos[3], vel[3], mean = 0.0;
    const int seg = 2048, nseg = 60, n = seg * nseg;
    double *x = malloc(sizeof(double) * n), *psd = calloc(seg / 2 + 1,
                                                          sizeof(double));
    double *buf = fftw_malloc(sizeof(double) * seg);
    fftw_complex *spec = fftw_malloc(sizeof(fftw_complex) * (seg / 2 + 1));
    fftw_plan plan = fftw_plan_dft_r2c_1d(seg, buf, spec, FFTW_ESTIMATE);
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int i, k, s, cnt = 0;
    rod_tree(&t);
    aero_tree_motion_init(&m, &t, 17);
    aero_tree_motion_set_stiffness(&m, 1000.0);
    aero_tree_motion_set_beta(&m, beta);
    aero_tree_motion_set_wind(&m, wind);
    aero_tree_motion_advance(&m, 2.0);
    for (i = 0; i < n; i++) {
        aero_tree_motion_advance(&m, 1.0 / AERO_TREE_MOTION_RATE);
        aero_tree_motion_point(&m, 0, 1.0, pos, vel);
        x[i] = pos[0];
        mean += pos[0] / n;
    }
    for (s = 0; s < nseg; s++) {
        for (k = 0; k < seg; k++) { /* Hann window */
            double w = 0.5 - 0.5 * cos(2.0 * PI * k / seg);
            buf[k] = w * (x[s * seg + k] - mean);
        }
        fftw_execute(plan);
        for (k = 0; k <= seg / 2; k++)
            psd[k] += spec[k][0] * spec[k][0] + spec[k][1] * spec[k][1];
    }
    for (k = 1; k <= seg / 2; k++) {
        double f = k * AERO_TREE_MOTION_RATE / seg;
        if (f >= 0.3 && f <= 3.0) {
            double lx = log10(f), ly = log10(psd[k]);
            sx += lx;
            sy += ly;
            sxx += lx * lx;
            sxy += lx * ly;
            cnt++;
        }
    }
    fftw_destroy_plan(plan);
    fftw_free(buf);
    fftw_free(spec);
    free(x);
    free(psd);
    aero_tree_motion_free(&m);
    aero_tree_free(&t);
    return (cnt * sxy - sx * sy) / (cnt * sxx - sx * sx);
}

UNIT_TEST(noise_spectrum)
{
    double betas[3] = {0.5, 1.0, 5.0 / 3.0};
    int i;
    for (i = 0; i < 3; i++) {
        double slope = sway_slope(betas[i]);
        UNIT_CHECK(fabs(slope + betas[i]) < 0.25,
                   "beta %.3g: sway spectrum slope %.3f (want %.3f)",
                   betas[i], slope, -betas[i]);
    }
}

UNIT_MAIN(UNIT_CASE(still_air), UNIT_CASE(static_deflection), UNIT_CASE(sway_frequency), UNIT_CASE(accumulation_and_steps), UNIT_CASE(noise_spectrum))
