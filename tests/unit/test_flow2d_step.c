/* aero: the 2D solver's adaptive step (src/core/solve/flow2d.c, choose_step)
 * must not put steps into the force.
 *
 * The immersed boundary's no-slip error after each projection grows with
 * the step, so the measured force moves with the step. A step that jumps
 * shifts the force within one step, a spike in g = dF/dt that is heard as a
 * click (textures/README.md, "How the textures are computed"). Here a thin
 * plate stands broadside in the flow, where that shift is largest. Past the
 * seeding spin, the CFL number is cut from 0.5 to 0.45: the step must
 * follow smoothly and reach its new goal, and the force's largest second
 * difference from step to step must stay within 3 x what it was before the
 * cut (the flow itself changes slowly: a shedding period is hundreds of
 * steps). A step that jumps to its goal fails this: it changes by 10 % at
 * once, and the largest second difference grows 16 x (drag) and 36 x
 * (lift). */
#include "unit.h"
#include "aero_air.h"
#include "flow2d.h"
#include "shape2d.h"

#include <math.h>
#include <stdio.h>

#define BEFORE 40
#define AFTER 160

/* the largest |f[i] - 2 f[i-1] + f[i-2]| for from <= i < to (from >= 2):
   a jump of f between i - 1 and i shows at i and i + 1 */
static double max_abs_second_difference(const double *f, int from, int to)
{
    double m = 0.0;
    for (int i = from; i < to; i++) {
        double d2 = fabs(f[i] - 2.0 * f[i - 1] + f[i - 2]);
        m = d2 > m ? d2 : m;
    }
    return m;
}

UNIT_TEST(step_follows_the_forces)
{
    aero_flow2d_params p;
    aero_flow2d s;
    aero_shape2d plate;
    char err[256];
    double fx[BEFORE + AFTER], fy[BEFORE + AFTER], dt[BEFORE + AFTER];
    double worst_ratio = 0.0;
    int recorded = 0;

    printf("adaptive step: a broadside plate (ellipse 8:1, Re 27000, 20 cells "
           "per width), CFL cut from 0.5 to 0.45 mid-run\n");
    aero_flow2d_defaults(&p, 27000.0);
    p.grid = 20.0;
    p.xmin = -3.0; /* a small box: the check is on the step, not the wake */
    p.xmax = 8.0;
    p.ymin = -4.0;
    p.ymax = 4.0;
    p.cfl = 0.5;
    aero_shape2d_ellipse(&plate, 1.0, 0.125);
    if (aero_flow2d_init(&s, &p, err, sizeof err) ||
        aero_flow2d_set_body(&s, &plate, 0.5 * AERO_PI, err,
                             sizeof err)) {
        UNIT_CHECK(0, "solver set up: %s", err);
        return;
    }
    while (s.t < 5.0 && !aero_flow2d_step(&s)) /* past the seeding spin */
        ;
    for (int n = 0; n < BEFORE + AFTER; n++) {
        if (n == BEFORE)
            s.p.cfl = 0.45;
        if (aero_flow2d_step(&s))
            break;
        recorded = n + 1;
        fx[n] = s.fx;
        fy[n] = s.fy;
        dt[n] = s.dt;
        if (n > 0) {
            double r = fabs(dt[n] / dt[n - 1] - 1.0);
            worst_ratio = r > worst_ratio ? r : worst_ratio;
        }
    }
    UNIT_CHECK(!s.diverged && recorded == BEFORE + AFTER,
               "the flow stays finite (t = %.2f d/U)", s.t);
    if (recorded < BEFORE + AFTER) {
        aero_flow2d_free(&s);
        aero_shape2d_free(&plate);
        return;
    }
    UNIT_CHECK(worst_ratio < 0.02,
               "the step changes by at most %.2f %% per step (< 2 %%)",
               100.0 * worst_ratio);
    UNIT_CHECK(fabs(s.dt / s.dt_goal - 1.0) < 0.02,
               "the step reaches its new goal: %.5f against %.5f d/U",
               (double)s.dt, (double)s.dt_goal);
    UNIT_CHECK(s.dt < 0.95 * dt[BEFORE - 1],
               "the cut took effect: step %.5f -> %.5f d/U",
               dt[BEFORE - 1], (double)s.dt);
    const double *f[2] = {fx, fy};
    const char *name[2] = {"drag", "lift"};
    for (int c = 0; c < 2; c++) {
        double before = max_abs_second_difference(f[c], 2, BEFORE);
        double after = max_abs_second_difference(f[c], BEFORE, BEFORE + AFTER);
        UNIT_CHECK(after <= 3.0 * before,
                   "%s: largest second difference per step %.3g after the "
                   "cut, %.3g before (at most 3 x)", name[c], after, before);
    }
    aero_flow2d_free(&s);
    aero_shape2d_free(&plate);
}

UNIT_MAIN(UNIT_CASE(step_follows_the_forces))
