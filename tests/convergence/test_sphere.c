/* aero: grid convergence of the sphere texture's 3D flow (`make
 * check-convergence`; ~25 minutes on 2 cores, so not in `make check`).
 *
 * The flow of textures/sphere.wav (the paper's sphere, radius 5 cm, in a
 * 10 m/s flow, Re 6.8e4; the texture's domain, settling, 0.6 s record and
 * unlimited MacCormack step, textures/make.sh) on the shipped 16.8 cells
 * per diameter and on 1.4 times that. Issue 17 asks that St and Cd change
 * by less than 5 % from N to 1.4 N cells.
 *  - Asserted: the mean Cd from N to 1.4 N within 5 %, and inside the
 *    subcritical sphere's 0.4-0.55 (Achenbach 1972, 1974) on both grids.
 *  - Open, printed and not counted (textures/README.md): St. The lateral
 *    force is a broad band, and the peak of a 0.6 s record's spectrum
 *    moves across it from grid to grid; neither grid reaches the
 *    subcritical 0.17-0.22 (Achenbach 1974; Sakamoto and Haniu 1990) with
 *    that estimate. The rms side force does not converge either. */
#include "../unit/unit.h"
#include "aero_util.h"
#include "body_flow.h"
#include "body_shape.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    double grid;
    aero_body_flow_stats st;
    int failed;
    char err[256];
} grid_case;

/* `aerotex object --shape sphere --radius 0.05 --speed 10 --grid G
   --duration 0.6 --limiter off` with its default seed 1 (its one
   direction's seed is aero_run_seed(1, 0)): the record it
   simulates is its 0.6 s loop's longest length plus the cross-fade,
   2760 samples at 4000 Hz (aerotex_plan_loop) */
static void run_sphere(grid_case *c, int threads)
{
    const double rate = 4000.0;
    const int nout = 2760;
    aero_body_shape b;
    aero_body_flow_params p;
    float *out = calloc(3 * (size_t)nout, sizeof(float));
    if (!out || aero_body_sphere(&b, 0.05, c->err, sizeof c->err) != 0) {
        c->failed = 1;
        free(out);
        return;
    }
    aero_body_flow_defaults(&p, &b);
    p.cell = 0.1 / c->grid;
    p.limiter = 0;
    p.threads = threads;
    p.seed = aero_run_seed(1, 0);
    c->failed = aero_body_flow_simulate(&p, rate, out, 3, nout, &c->st, NULL,
                                        0, NULL, c->err, sizeof c->err) != 0;
    free(out);
}

int main(void)
{
    grid_case c[2];
    memset(c, 0, sizeof c);
    c[0].grid = 16.8;
    c[1].grid = 1.4 * 16.8;
    /* one after the other, each on both cores (body_flow's z slabs): the
       finer grid alone is 4 x the coarser's work */
    for (int k = 0; k < 2; k++) {
        run_sphere(&c[k], 2);
        UNIT_CHECK(!c[k].failed, "the sphere's flow on %.2f cells per d runs "
                   "(%d x %d x %d, %ld steps)%s%s", c[k].grid, c[k].st.nx,
                   c[k].st.ny, c[k].st.nz, c[k].st.steps,
                   c[k].failed ? ": " : "", c[k].err);
    }
    if (c[0].failed || c[1].failed)
        return unit_summary();
    for (int k = 0; k < 2; k++)
        printf("# %5.2f cells per d: St %.4f (f %.2f Hz), Cd %.3f, Cl rms "
               "%.4f\n", c[k].grid, c[k].st.st, c[k].st.f_peak, c[k].st.cd,
               c[k].st.cl_rms);
    const double dcd = unit_change_percent(c[1].st.cd, c[0].st.cd);
    UNIT_CHECK(fabs(dcd) < 5.0, "the mean Cd from %.2f to %.2f cells per d "
               "(N to 1.4 N) changes %+.2f %%, within 5 %% (issue 17)",
               c[0].grid, c[1].grid, dcd);
    for (int k = 0; k < 2; k++)
        UNIT_CHECK(c[k].st.cd >= 0.4 && c[k].st.cd <= 0.55,
                   "Cd %.3f on %.2f cells per d inside the subcritical "
                   "sphere's 0.4-0.55 (Achenbach 1972, 1974)", c[k].st.cd,
                   c[k].grid);
    printf("# open, not counted: St %.3f and %.3f (%+.1f %%; issue 17 asks "
           "< 5 %%) against the subcritical sphere's 0.17-0.22 (Achenbach "
           "1974; Sakamoto and Haniu 1990); the rms side force changes "
           "%+.1f %%\n", c[0].st.st, c[1].st.st,
           unit_change_percent(c[1].st.st, c[0].st.st),
           unit_change_percent(c[1].st.cl_rms, c[0].st.cl_rms));
    return unit_summary();
}
