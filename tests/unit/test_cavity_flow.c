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
 * settled into a steady recirculation) with a spectral peak within 15 % of
 * a Rossiter mode. ~10 s on one core. */
#include "unit.h"
#include "aero_air.h"
#include "aeolian_flow.h"
#include "flow2d.h"
#include "shape2d.h"

#include <stdio.h>
#include <stdlib.h>

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

int main(void)
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
        return unit_summary();
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
    {
        int m = 1;
        double d = fabs(st - rossiter_st(1, mach));
        for (int k = 2; k <= 4; k++)
            if (fabs(st - rossiter_st(k, mach)) < d) {
                d = fabs(st - rossiter_st(k, mach));
                m = k;
            }
        printf("  peak St_L %.3f = %.0f Hz; Rossiter m=1..3: %.3f %.3f %.3f "
               "(%.0f, %.0f, %.0f Hz)\n", st, st * u0 / len,
               rossiter_st(1, mach), rossiter_st(2, mach),
               rossiter_st(3, mach), rossiter_st(1, mach) * u0 / len,
               rossiter_st(2, mach) * u0 / len, rossiter_st(3, mach) * u0 / len);
        UNIT_NEAR_REL(st, rossiter_st(m, mach), 0.15,
                      "dominant St_L vs the nearest Rossiter mode");
    }
    free(cl);
    return unit_summary();
}
