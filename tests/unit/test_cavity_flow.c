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
 * settled into a steady recirculation) as a tone within +-15 % of a
 * Rossiter stage (it lies 7-12 % above stage 2 and moves with the grid;
 * ~10 s on one core). Then a sweep of incoming laminar layers
 * (the case rossiter_stages, below).
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
/* the incoming layers of the sweep, L/theta0 */
#define CAVITY_SWEEP 70.0, 80.0, 90.0, 100.0

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

/* the nearest Rossiter stage to st and its relative distance */
static int nearest_stage(double st, double mach, double *dist)
{
    int best = 1;
    for (int m = 2; m <= 4; m++)
        if (fabs(log(st / rossiter_st(m, mach))) <
            fabs(log(st / rossiter_st(best, mach))))
            best = m;
    *dist = st / rossiter_st(best, mach) - 1.0;
    return best;
}

typedef struct {
    double st, rms, tonal; /* peak St_L, rms Cl of the walls, the peak's
                              share of the power (+-10 %) */
    int ok;                /* it ran to the end */
} cavity_result;

/* the shipped texture's cavity (L = 2 cm, D = 1 cm, U = 10 m/s, Re_L
   1.35e4) on the domain `aerotex cavity` uses (aeolian_flow.h), with the
   solver's default step factor: grid cells per L, an inflow boundary
   layer of momentum thickness theta (m; 0: none, it grows on the wall
   from the inflow edge), SETTLE L/U discarded, `record` L/U analysed */
static cavity_result cavity_flow(double grid, double theta, double record)
{
    const double len = 0.02, depth = 0.01, u0 = 10.0;
    const double re = u0 * len / AERO_NU;
    aero_aeolian_flow_params flow = {0};
    aero_flow2d_params p;
    aero_flow2d s;
    aero_shape2d sh;
    char err[256];
    int cap = (int)(record / SAMPLE) + 8, n = 0;
    double *cl = calloc((size_t)cap, sizeof(double));
    double next = SETTLE, mean = 0.0, best = 0.0, total = 0.0, near = 0.0;
    cavity_result r = {0.0, 0.0, 0.0, 0};
    aero_shape2d_cavity(&sh, 1.0, depth / len);
    aero_flow2d_defaults(&p, re);
    flow.shape = &sh;
    flow.cavity = 1;
    flow.size = len;
    flow.depth = depth;
    flow.re = re;
    flow.grid = grid;
    flow.cfl = p.cfl;
    flow.theta = theta;
    if (!cl || aero_aeolian_flow_domain(&flow, &p, err, sizeof err) ||
        aero_flow2d_init(&s, &p, err, sizeof err) ||
        aero_flow2d_set_body(&s, &sh, 0.0, err, sizeof err)) {
        UNIT_CHECK(0, "set-up: %s", cl ? err : "out of memory");
        free(cl);
        return r;
    }
    while (s.t < SETTLE + record && n < cap) {
        if (aero_flow2d_step(&s))
            break;
        if (s.t >= next) { /* lift coefficient of the walls, 2 Fy */
            cl[n++] = 2.0 * s.fy;
            next += SAMPLE;
        }
    }
    r.ok = s.t >= SETTLE + record - 1.0 && n > (int)(0.9 * record / SAMPLE);
    aero_flow2d_free(&s);
    for (int k = 0; k < n; k++)
        mean += cl[k];
    mean /= n > 0 ? n : 1;
    for (int k = 0; k < n; k++) {
        cl[k] -= mean;
        r.rms += cl[k] * cl[k];
    }
    r.rms = sqrt(r.rms / (n > 0 ? n : 1));
    /* spectral peak over St_L 0.1-3 and its share of the power */
    for (double f = 0.1; f < 3.0; f += 0.005) {
        double pw = power_at(cl, n, f);
        total += pw;
        if (pw > best) {
            best = pw;
            r.st = f;
        }
    }
    for (double f = 0.1; f < 3.0; f += 0.005)
        if (fabs(f - r.st) <= 0.1 * r.st)
            near += power_at(cl, n, f);
    r.tonal = total > 0.0 ? near / total : 0.0;
    free(cl);
    return r;
}

/* Rowley, Colonius and Basu (2002, J. Fluid Mech. 455): a 2D cavity with
 * a laminar upstream layer oscillates in the shear-layer mode, at a
 * Rossiter stage (Rossiter 1964: alpha 0.25, kappa 0.57; here M 0.03),
 * the stage rising as the cavity gets long against the layer (L/theta0);
 * past that, the wake mode. So over a sweep of incoming layers the
 * dominant St_L lies within +-15 % of a stage (the scatter of Rossiter's
 * fit) and the stage does not fall as L/theta0 grows. 64 cells per L
 * (the layers are 5.4-7.8 cells thick, delta = 8.51 theta); the thinner
 * layers of L/theta0 120-200 fall between stages on this grid (St_L
 * 0.75-0.80; textures/README.md), and thicker ones than L/70 do not
 * oscillate. ~5 s a run on one core (the whole file ~30 s). */
UNIT_TEST(rossiter_stages)
{
    static const double l_theta[] = {CAVITY_SWEEP};
    const int runs = (int)(sizeof l_theta / sizeof l_theta[0]);
    const double mach = 10.0 / AERO_C0;
    int last = 0;
    for (int k = 0; k < runs; k++) {
        cavity_result r = cavity_flow(64.0, 0.02 / l_theta[k], 40.0);
        double dist = 0.0;
        int m = r.st > 0.0 ? nearest_stage(r.st, mach, &dist) : 0;
        UNIT_CHECK(r.ok && r.rms > 0.005 && r.tonal > 0.3,
                   "L/theta0 %.0f (64 cells per L): oscillates as a tone, "
                   "rms Cl %.4f (> 0.005), %.0f%% of the power within "
                   "+-10%% of St_L %.3f (> 30%%)", l_theta[k], r.rms,
                   100.0 * r.tonal, r.st);
        UNIT_CHECK(m > 0 && fabs(dist) <= 0.15,
                   "L/theta0 %.0f: St_L %.3f is %+.1f %% from Rossiter's "
                   "stage %d (%.3f; +-15 %%)", l_theta[k], r.st,
                   100.0 * dist, m, m > 0 ? rossiter_st(m, mach) : 0.0);
        UNIT_CHECK(m >= last, "L/theta0 %.0f: stage %d, not below the "
                   "thicker layer's %d", l_theta[k], m, last);
        if (m > last)
            last = m;
    }
}

UNIT_TEST(shear_layer_mode)
{
    const double len = 0.02, u0 = 10.0;
    const double re = u0 * len / AERO_NU, mach = u0 / AERO_C0;
    cavity_result r;
    double dist = 0.0;
    int m;

    printf("test_cavity_flow: cavity L/D = 2, Re_L %.0f, M %.3f; Rossiter "
           "stages 1..3 at St_L %.3f %.3f %.3f\n", re, mach,
           rossiter_st(1, mach), rossiter_st(2, mach), rossiter_st(3, mach));
    /* the shipped texture's flow: 48 cells per L (aerotex's default;
       coarser grids damp the thin shear layer and stay steady), no inflow
       layer; 60 L/U (~60 periods) analysed */
    r = cavity_flow(48.0, 0.0, RECORD);
    UNIT_CHECK(r.ok, "cavity flow ran to t = %.0f L/U", SETTLE + RECORD);
    UNIT_CHECK(r.rms > 0.01, "self-sustained oscillation: rms Cl of the walls "
               "%.4f (> 0.01; a steady recirculation gives ~1e-4)", r.rms);
    UNIT_CHECK(r.tonal > 0.3, "tonal: %.0f%% of the power within +-10%% of "
               "the peak St_L %.3f (> 30%%)", 100.0 * r.tonal, r.st);
    m = nearest_stage(r.st, mach, &dist);
    UNIT_CHECK(fabs(dist) <= 0.15, "the texture's flow: St_L %.3f (%.0f Hz) "
               "is %+.1f %% from Rossiter's stage %d (%.3f; +-15 %%)", r.st,
               r.st * u0 / len, 100.0 * dist, m, rossiter_st(m, mach));
}

UNIT_MAIN(UNIT_CASE(inflow_layer), UNIT_CASE(shear_layer_mode),
          UNIT_CASE(rossiter_stages))
