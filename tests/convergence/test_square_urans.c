/* aero: grid convergence of the square prism's texture flow (`make
 * check-convergence`; ~10 minutes on 2 cores, so not in `make check`).
 *
 * The flow of textures/square.wav at 0 deg (a 1 cm square, flow onto a
 * face, 10 m/s, Re 6768, the k-omega URANS of `--span3d urans`, the
 * texture's domain and 0.1 s record) on 16, 24 and 36 cells per side.
 * Issue 19 asks that St and the rms force change by less than 3 % from N
 * to 1.5 N cells; N is the shipped 24.
 *  - St: asserted, 24 to 36 cells within 3 %, and each grid's St inside
 *    the published 0.13 +- 10 % (Okajima 1982; Lyn et al. 1995).
 *  - The mean drag and the rms lift do not converge on these grids
 *    (textures/README.md, "Open"): they are printed, marked open, and not
 *    counted. */
#include "../unit/unit.h"
#include "../unit/square_flow.h"
#include "aeolian_flow.h"
#include "flow2d.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

typedef struct {
    double grid;
    aero_aeolian_flow_stats st;
    int failed;
    char err[256];
} grid_case;

/* the texture's record: 0.1 s at 16 kHz (textures/make.sh), 14 periods at
   St 0.14 */
static void run_square(grid_case *c)
{
    c->failed = square_flow(c->grid, 0.1, 16000.0, AERO_FLOW2D_KOMEGA_KL,
                            &c->st, c->err, sizeof c->err) != 0;
}

int main(void)
{
    /* the finest first: it takes as long as the other two together, so
       two cores finish at about the same time */
    grid_case c[3];
    memset(c, 0, sizeof c);
    c[0].grid = 36.0;
    c[1].grid = 24.0;
    c[2].grid = 16.0;
#pragma omp parallel for schedule(dynamic, 1)
    for (int k = 0; k < 3; k++)
        run_square(&c[k]);
    for (int k = 0; k < 3; k++)
        UNIT_CHECK(!c[k].failed, "the square prism's flow on %.0f cells "
                   "runs%s%s", c[k].grid, c[k].failed ? ": " : "", c[k].err);
    if (c[0].failed || c[1].failed || c[2].failed)
        return unit_summary();
    for (int k = 2; k >= 0; k--)
        printf("# %2.0f cells: St %.4f (zero crossings %.4f), Cd %.3f, "
               "Cl rms %.3f\n", c[k].grid, c[k].st.st_peak, c[k].st.flow.st,
               c[k].st.flow.cd, c[k].st.flow.cl_rms);
    for (int k = 0; k < 3; k++)
        UNIT_CHECK(fabs(c[k].st.st_peak - 0.13) <= 0.013,
                   "St %.4f on %.0f cells within 0.13 +- 10 %% (Okajima "
                   "1982; Lyn et al. 1995)", c[k].st.st_peak, c[k].grid);
    const double dst = unit_change_percent(c[0].st.st_peak, c[1].st.st_peak);
    UNIT_CHECK(fabs(dst) < 3.0, "St from 24 to 36 cells (N to 1.5 N) changes "
               "%+.2f %%, within 3 %% (issue 19)", dst);
    printf("# open, not counted: from 24 to 36 cells the mean Cd changes "
           "%+.1f %% and the rms Cl %+.1f %% (issue 19 asks < 3 %%); from "
           "16 to 24, St %+.2f %%, Cd %+.1f %%, Cl rms %+.1f %%\n",
           unit_change_percent(c[0].st.flow.cd, c[1].st.flow.cd),
           unit_change_percent(c[0].st.flow.cl_rms, c[1].st.flow.cl_rms),
           unit_change_percent(c[1].st.st_peak, c[2].st.st_peak),
           unit_change_percent(c[1].st.flow.cd, c[2].st.flow.cd),
           unit_change_percent(c[1].st.flow.cl_rms, c[2].st.flow.cl_rms));
    return unit_summary();
}
