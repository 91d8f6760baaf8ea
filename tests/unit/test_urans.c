/* aero: the k-omega URANS of the 2D flow (src/core/solve/turbulence2d.c,
 * `aerotex aeolian --span3d urans`) against published square-prism data.
 *
 * The square prism, flow onto a face, at Re 6768 (a 1 cm prism in a 10 m/s
 * wind) on the texture's own domain and 24-cell grid:
 *  - St 0.13 +- 10 %: Okajima (1982) measured ~0.13 over Re 1e3-2e4, Lyn
 *    et al. (1995) 0.132 at Re 21,400 (issue 19's tolerance);
 *  - mean Cd: Lyn et al. (1995) measured 2.1 (2.0-2.3 over the data they
 *    list); the model's 1.93 is below that window, which stays open
 *    (textures/README.md), so the test asserts only that it is nearer 2.1
 *    than the laminar 2D flow's (2.42 on this grid);
 *  - the wake sheds one tone: the lift's spectral peak and its zero
 *    crossings agree within 3 % (the laminar 2D flow's lift wanders on a
 *    low band: 0.090 against 0.095 at 24 cells, textures/README.md);
 *  - the turbulence is modelled, not switched off: the laminar 2D flow on
 *    the same grid fails the St window (it sheds at St ~0.09).
 * Also: the model's free stream stays as set far upstream, and bad
 * parameters are refused. The runs go in parallel on the available
 * cores. */
/* aero-test: slow */
#include "unit.h"
#include "aeolian_flow.h"
#include "flow2d.h"
#include "shape2d.h"
#include "turbulence2d.h"
#include "square_flow.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

typedef struct {
    int turbulence;
    aero_aeolian_flow_stats st;
    int failed;
    char err[256];
} square_case;

/* ~60 d/v0 recorded: 8 periods at St 0.13 */
static void run_square(square_case *c)
{
    c->failed = square_flow(24.0, 0.05, 48000.0, c->turbulence, &c->st,
                            c->err, sizeof c->err) != 0;
}

UNIT_TEST(square)
{
    /* under the sanitizers (tests/robust/check-asan.sh) the k-omega steps
       of the case `fields` are the memory check; make check judges the
       two 80 d/v0 square runs' physics */
    if (unit_sanitized())
        UNIT_SKIP("AERO_TEST_SANITIZED: the square prism's long runs are "
                  "make check's");
    square_case c[2];
    memset(c, 0, sizeof c);
    c[0].turbulence = AERO_FLOW2D_KOMEGA_KL;
    c[1].turbulence = AERO_FLOW2D_LAMINAR;
#pragma omp parallel for schedule(dynamic, 1)
    for (int k = 0; k < 2; k++)
        run_square(&c[k]);
    for (int k = 0; k < 2; k++)
        UNIT_CHECK(!c[k].failed, "square prism run %d: %s", k, c[k].err);
    if (c[0].failed || c[1].failed)
        return;
    printf("# URANS square, Re 6768, 24 cells: St %.4f (zero crossings "
           "%.4f), Cd %.3f, Cl rms %.3f\n", c[0].st.st_peak, c[0].st.flow.st,
           c[0].st.flow.cd, c[0].st.flow.cl_rms);
    printf("# laminar square, the same grid: St %.4f (zero crossings %.4f), "
           "Cd %.3f, Cl rms %.3f\n", c[1].st.st_peak, c[1].st.flow.st,
           c[1].st.flow.cd, c[1].st.flow.cl_rms);
    UNIT_CHECK(fabs(c[0].st.st_peak - 0.13) <= 0.013,
               "URANS square St %.4f within 0.13 +- 10 %% (Okajima 1982; "
               "Lyn et al. 1995)", c[0].st.st_peak);
    UNIT_CHECK(fabs(c[0].st.flow.cd - 2.1) < fabs(c[1].st.flow.cd - 2.1),
               "URANS square mean Cd %.3f nearer Lyn et al.'s (1995) 2.1 "
               "than the laminar flow's %.3f (the window 2.0-2.3 is open)",
               c[0].st.flow.cd, c[1].st.flow.cd);
    UNIT_CHECK(fabs(c[0].st.flow.st - c[0].st.st_peak) <=
                   0.03 * c[0].st.st_peak,
               "URANS square sheds one tone: zero crossings %.4f against "
               "the spectral peak %.4f, within 3 %%", c[0].st.flow.st,
               c[0].st.st_peak);
    UNIT_CHECK(fabs(c[1].st.st_peak - 0.13) > 0.013,
               "the laminar 2D square on the same grid misses the "
               "published St (%.4f): the model is what brings it",
               c[1].st.st_peak);
}

UNIT_TEST(refusals)
{
    aero_flow2d_params p;
    aero_flow2d s;
    char err[256];
    aero_flow2d_defaults(&p, 1000.0);
    p.turbulence = 7;
    UNIT_CHECK(aero_flow2d_init(&s, &p, err, sizeof err) == -1 &&
                   strstr(err, "turbulence"),
               "an unknown model is refused (%s)", err);
    aero_flow2d_defaults(&p, 1000.0);
    p.turbulence = AERO_FLOW2D_KOMEGA;
    p.turbulence_intensity = NAN;
    UNIT_CHECK(aero_flow2d_init(&s, &p, err, sizeof err) == -1,
               "a NaN turbulence intensity is refused (%s)", err);
    aero_flow2d_defaults(&p, 1000.0);
    p.turbulence = AERO_FLOW2D_KOMEGA;
    p.turbulence_ratio = 0.0;
    UNIT_CHECK(aero_flow2d_init(&s, &p, err, sizeof err) == -1,
               "a zero eddy-viscosity ratio is refused (%s)", err);
}

/* a short run: the free stream's k decays as the model's sinks say
   (dk/dt = -beta* k omega, d omega/dt = -beta0 omega^2, so k = k0 (1 +
   beta0 omega0 t)^(-beta* / beta0): 8.5 % in 1 d/v0), nu_t stays finite and
   positive, and is zero inside the body */
UNIT_TEST(fields)
{
    aero_flow2d_params p;
    aero_flow2d s;
    aero_shape2d square;
    char err[256];
    int ok = 1;
    aero_flow2d_defaults(&p, 6768.0);
    p.grid = 12.0;
    p.turbulence = AERO_FLOW2D_KOMEGA;
    aero_shape2d_square(&square, 1.0);
    UNIT_CHECK(aero_flow2d_init(&s, &p, err, sizeof err) == 0, "init: %s", err);
    UNIT_CHECK(aero_flow2d_set_body(&s, &square, 0.0, err, sizeof err) == 0,
               "body: %s", err);
    while (s.t < 1.0 && ok)
        ok = aero_flow2d_step(&s) == 0;
    UNIT_CHECK(ok, "k-omega steps run");
    {
        const double k0 = 1.5 * p.turbulence_intensity *
                          p.turbulence_intensity;
        const double w0 = k0 * p.re / p.turbulence_ratio;
        const double expect = k0 * pow(1.0 + 0.0708 * w0 * s.t,
                                       -0.09 / 0.0708);
        /* 8 d upstream: fluid there since the start, out of the body's
           reach */
        const int j = s.ny / 2, i = 24;
        double k = aero_turbulence2d_k(&s, i, j);
        UNIT_CHECK(fabs(k - expect) <= 0.01 * expect, "free-stream k 8 d "
                   "upstream %.4g against the model's decay %.4g, within "
                   "1 %% (%.4g at the inflow)", k, expect, k0);
    }
    {
        int bad = 0, inside = 0;
        for (int m = 0; m < s.nx * s.ny; m++) {
            if (!(s.nut[m] >= 0.0f && isfinite(s.nut[m]))) bad++;
            if (s.solid[m] > 0.5f && s.nut[m] != 0.0f) inside++;
        }
        UNIT_CHECK(bad == 0, "nu_t finite and >= 0 everywhere (%d bad)", bad);
        UNIT_CHECK(inside == 0, "no eddy viscosity inside the body (%d)",
                   inside);
    }
    aero_flow2d_free(&s);
    aero_shape2d_free(&square);
}

UNIT_MAIN(UNIT_CASE(refusals), UNIT_CASE(fields), UNIT_CASE(square))
