/* aero: the 2D flow over a cavity (src/core/solve/flow2d.c, shape2d.c)
 * oscillates by itself at a Rossiter mode, as `aerotex cavity` relies on.
 *
 * Reference: Rossiter (1964), "Wind-tunnel experiments on the flow over
 * rectangular cavities at subsonic and transonic speeds", ARC R&M 3438:
 *     f_m = (U/L) (m - alpha) / (M + 1/kappa),  alpha = 0.25, kappa = 0.57,
 * M = U/c0. 2D incompressible simulations
 * of an open cavity at Re_L ~ 1e4 oscillate in the shear-layer mode (e.g.
 * Rowley, Colonius & Basu 2002, J. Fluid Mech. 455); at L/D = 2 the mode
 * that wins here is m = 2 (~490 Hz for L = 2 cm at 10 m/s).
 *
 * The case is the shipped texture's: L = 2 cm, D = 1 cm, U = 10 m/s
 * (Re_L 1.35e4) on the same domain and grid (48 cells per L, aerotex's
 * default; coarser grids damp the thin shear layer and stay steady). The
 * start-up (80 L/U) is discarded and 60 L/U (~60 periods) are analysed:
 * the floor's pressure force must oscillate (it was ~1e-4 when the flow
 * settled into a steady recirculation) as a tone. Its frequency against
 * mode 2 is printed, not asserted: it lies 7-12 % above it here and moves
 * with the grid (textures/README.md, "Open"), and the window of 15 %
 * around the nearest of four modes that admitted it is gone (issue 19).
 * ~10 s on one core.
 *
 * First, without running the flow: the laminar boundary layer a cavity's
 * wall can bring to the inflow (aero_flow2d_params.inlet_theta) is
 * Pohlhausen's profile with the momentum thickness asked for (integral of
 * u (1 - u) dy over the inflow column; Schlichting & Gersten 2000), and
 * an out-of-range thickness is refused. */
/* aero-test: slow */
#include "unit.h"
#include "aero_air.h"
#include "aeolian_flow.h"
#include "flow2d.h"
#include "shape2d.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SETTLE 80.0
#define RECORD 60.0
#define SAMPLE 0.02 /* L/U between recorded samples */

static double rossiter_st(int m, double mach)
{
    const double alpha = 0.25, kappa = 0.57;
    return (m - alpha) / (mach + 1.0 / kappa);
}

/* |DFT|^2 of x (mean removed) at Strouhal number st, samples SAMPLE apart */
static double power_at(const double *x, int n, double st)
{
    double c = 0.0, s = 0.0;
    for (int k = 0; k < n; k++) {
        double ph = 2.0 * AERO_PI * st * k * SAMPLE;
        c += x[k] * cos(ph);
        s += x[k] * sin(ph);
    }
    return c * c + s * s;
}

/* the inflow column of a cavity L = 1, D = 0.5 at `grid` cells per L with
   an inflow boundary layer of momentum thickness theta: its measured
   momentum thickness, or -1 if the set-up failed (err says why) */
static double inflow_theta(double grid, double theta, float *umin,
                           float *umax, char *err, size_t errlen)
{
    aero_aeolian_flow_params flow = {0};
    aero_flow2d_params p;
    aero_flow2d s;
    aero_shape2d sh;
    double th = 0.0;
    aero_shape2d_cavity(&sh, 1.0, 0.5);
    flow.shape = &sh;
    flow.cavity = 1;
    flow.size = 1.0;
    flow.depth = 0.5;
    flow.re = 13536.0;
    flow.grid = grid;
    flow.cfl = 0.5;
    flow.theta = theta;
    if (aero_aeolian_flow_domain(&flow, &p, err, errlen) ||
        aero_flow2d_init(&s, &p, err, errlen))
        return -1.0;
    if (aero_flow2d_set_body(&s, &sh, 0.0, err, errlen)) {
        aero_flow2d_free(&s);
        return -1.0;
    }
    *umin = 1.0f;
    *umax = 0.0f;
    for (int j = 0; j < s.ny; j++) {
        const double y = p.ymin + (j + 0.5) * s.h;
        if (y <= 0.0)
            continue; /* the wall */
        th += s.uin[j] * (1.0 - s.uin[j]) * s.h;
        if (s.uin[j] < *umin) *umin = s.uin[j];
        if (s.uin[j] > *umax) *umax = s.uin[j];
    }
    aero_flow2d_free(&s);
    return th;
}

UNIT_TEST(inflow_layer)
{
    char err[256] = "";
    float umin, umax;
    const double want[] = {0.01, 1.0 / 60.0, 0.05};
    for (int k = 0; k < 3; k++) {
        double th = inflow_theta(96.0, want[k], &umin, &umax, err, sizeof err);
        UNIT_NEAR_REL(th, want[k], 0.03, "inflow boundary layer's momentum "
                      "thickness at 96 cells per L (L = 1)");
    }
    inflow_theta(96.0, 0.0, &umin, &umax, err, sizeof err);
    UNIT_CHECK(umin == 1.0f && umax == 1.0f, "no inflow layer: u/U over the "
               "wall %.3f..%.3f (uniform)", umin, umax);
    UNIT_CHECK(inflow_theta(96.0, 0.2, &umin, &umax, err, sizeof err) < 0.0 &&
                   strstr(err, "out of range"),
               "theta 0.2 L refused: %s", err);
    err[0] = '\0';
    UNIT_CHECK(inflow_theta(96.0, NAN, &umin, &umax, err, sizeof err) < 0.0 &&
                   strstr(err, "out of range"),
               "theta NaN refused: %s", err);
}

UNIT_TEST(shear_layer_mode)
{
    const double len = 0.02, depth = 0.01, u0 = 10.0;
    const double re = u0 * len / AERO_NU, mach = u0 / AERO_C0;
    aero_aeolian_flow_params flow = {0};
    aero_flow2d_params p;
    aero_flow2d s;
    aero_shape2d sh;
    char err[256];
    int cap = (int)(RECORD / SAMPLE) + 8, n = 0;
    double *cl = calloc((size_t)cap, sizeof(double));
    double next = SETTLE, mean = 0.0, rms = 0.0, best = 0.0, st = 0.0;
    double total = 0.0, near = 0.0;
    int diverged = 0;

    printf("test_cavity_flow: cavity L/D = 2, Re_L %.0f, M %.3f\n", re, mach);
    aero_shape2d_cavity(&sh, 1.0, depth / len);
    /* the domain `aerotex cavity` uses (aeolian_flow.h), the solver's
       default step factor */
    aero_flow2d_defaults(&p, re);
    flow.shape = &sh;
    flow.cavity = 1;
    flow.size = len;
    flow.depth = depth;
    flow.re = re;
    flow.grid = 48.0;
    flow.cfl = p.cfl;
    if (!cl || aero_aeolian_flow_domain(&flow, &p, err, sizeof err) ||
        aero_flow2d_init(&s, &p, err, sizeof err) ||
        aero_flow2d_set_body(&s, &sh, 0.0, err, sizeof err)) {
        UNIT_CHECK(0, "set-up: %s", cl ? err : "out of memory");
        return;
    }
    while (s.t < SETTLE + RECORD && n < cap) {
        if (aero_flow2d_step(&s)) {
            diverged = 1;
            break;
        }
        if (s.t >= next) { /* lift coefficient of the walls, 2 Fy */
            cl[n++] = 2.0 * s.fy;
            next += SAMPLE;
        }
    }
    aero_flow2d_free(&s);
    UNIT_CHECK(!diverged && n > 1000, "cavity flow ran to t = %.0f L/U "
               "(%d samples)", SETTLE + RECORD, n);

    for (int k = 0; k < n; k++)
        mean += cl[k];
    mean /= n > 0 ? n : 1;
    for (int k = 0; k < n; k++) {
        cl[k] -= mean;
        rms += cl[k] * cl[k];
    }
    rms = sqrt(rms / (n > 0 ? n : 1));
    UNIT_CHECK(rms > 0.01, "self-sustained oscillation: rms Cl of the walls "
               "%.4f (> 0.01; a steady recirculation gives ~1e-4)", rms);

    /* spectral peak over St_L 0.1-3 and its share of the power */
    for (double f = 0.1; f < 3.0; f += 0.005) {
        double pw = power_at(cl, n, f);
        total += pw;
        if (pw > best) {
            best = pw;
            st = f;
        }
    }
    for (double f = 0.1; f < 3.0; f += 0.005)
        if (fabs(f - st) <= 0.1 * st)
            near += power_at(cl, n, f);
    UNIT_CHECK(near > 0.3 * total, "tonal: %.0f%% of the power within "
               "+-10%% of the peak St_L %.3f (> 30%%)", 100.0 * near / total,
               st);
    printf("  peak St_L %.3f = %.0f Hz, %+.1f %% from Rossiter's mode 2 "
           "(not asserted: open); m=1..3: %.3f %.3f %.3f (%.0f, %.0f, %.0f "
           "Hz)\n", st, st * u0 / len,
           100.0 * (st / rossiter_st(2, mach) - 1.0), rossiter_st(1, mach),
           rossiter_st(2, mach), rossiter_st(3, mach),
           rossiter_st(1, mach) * u0 / len, rossiter_st(2, mach) * u0 / len,
           rossiter_st(3, mach) * u0 / len);
    free(cl);
}

UNIT_MAIN(UNIT_CASE(inflow_layer), UNIT_CASE(shear_layer_mode))
