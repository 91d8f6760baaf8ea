/* aero: tests of the 2D-to-3D correction (src/core/span3d.c): the spectral
 * Strouhal number of a force history and the circle calibration against
 * Roshko (1954) St(Re) and Norberg (2003) C_L'(Re). */
#include "unit.h"
#include "aeolian_flow.h"
#include "shape2d.h"
#include "span3d.h"
#include "strouhal.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

UNIT_TEST(spectral_st)
{
    /* a lift at St 0.21 with its third harmonic, a stronger slow drift
       below the scan and noise, on a jittered time axis as the solver's
       adaptive step gives */
    int n = 12000;
    double *t = malloc(sizeof(double) * n), *c = malloc(sizeof(double) * n);
    uint32_t rng = 12345;
    double time = 0;
    for (int k = 0; k < n; k++) {
        rng ^= rng << 13, rng ^= rng >> 17, rng ^= rng << 5;
        double u = (double)rng / 4294967296.0;
        t[k] = time;
        c[k] = 1.0 * sin(2 * M_PI * 0.21 * time) +
               0.3 * sin(2 * M_PI * 0.63 * time) + 0.5 * (u - 0.5) + 0.4;
        time += 0.018 + 0.004 * u;
    }
    double st = aero_spectral_st(t, c, n, 0.02, 3.0);
    UNIT_NEAR_REL(st, 0.21, 0.005, "spectral St of a 0.21 tone");
    /* zero crossings would count the harmonic's extra crossings when it is
       strong: the spectral peak does not */
    for (int k = 0; k < n; k++)
        c[k] = 0.6 * sin(2 * M_PI * 0.13 * t[k]) + 0.5 * sin(2 * M_PI * 0.39 * t[k]);
    st = aero_spectral_st(t, c, n, 0.02, 3.0);
    UNIT_NEAR_REL(st, 0.13, 0.005, "spectral St with a strong 3rd harmonic");
    /* a slow drift stronger than the tone at the scan's lower edge (an
       irregular wake wandering; the square prism's 2D lift at 32 cells
       per side gave St 0.020, the scan's edge, before the peak had to be
       tonal): the tone, not the edge (the earlier scan gives 0.02 here) */
    {
        double walk = 0;
        for (int k = 0; k < n; k++) {
            rng ^= rng << 13, rng ^= rng >> 17, rng ^= rng << 5;
            walk += 0.1 * ((double)rng / 4294967296.0 - 0.5);
            c[k] = 0.3 * sin(2 * M_PI * 0.13 * t[k]) + walk;
        }
    }
    st = aero_spectral_st(t, c, n, 0.02, 3.0);
    UNIT_NEAR_REL(st, 0.13, 0.01, "spectral St of a tone over a strong drift");
    UNIT_CHECK(aero_spectral_st(t, c, 10, 0.02, 3.0) == 0.0, "too short: 0");
    for (int k = 0; k < n; k++)
        c[k] = 1.0;
    UNIT_CHECK(aero_spectral_st(t, c, n, 0.02, 3.0) == 0.0, "flat: 0");
    free(t);
    free(c);
}

UNIT_TEST(calibration)
{
    aero_span3d c;
    /* laminar wake: two-dimensional in reality, nothing changes */
    UNIT_CHECK(aero_span3d_calibrate(&c, 150, 0.18, 0.3) == 0 && !c.applied &&
                   c.frequency_scale == 1.0 && c.force_scale == 1.0,
               "Re 150: no correction (Williamson 1996: 2D wake below 190)");
    /* Re 6768: a 2D circle at St 0.25, C_L' 1.12 (the old texture) becomes
       Roshko's St and Norberg's C_L' */
    UNIT_CHECK(aero_span3d_calibrate(&c, 6768, 0.25, 1.12) == 0 && c.applied,
               "Re 6768: corrected");
    UNIT_NEAR_REL(0.25 * c.frequency_scale, 0.198 * (1 - 19.7 / 6768), 1e-9,
                  "circle St -> Roshko 1954");
    UNIT_NEAR_REL(1.12 * c.force_scale, aero_lift_rms(6768), 1e-9,
                  "circle C_L' -> Norberg 2003");
    UNIT_CHECK(aero_span3d_calibrate(&c, 6768, 0.0, 1.0) != 0 &&
                   c.frequency_scale == 1.0,
               "a circle that did not shed: error, identity");
}

/* a 2D flow that sheds slower than the real body (frequency scale > 1: the
   36-cell circle at Re 6768 sheds at St 0.192, Roshko's is 0.197) is
   squeezed in time, so its run records on until the texture is full (it
   stopped with "recording too short") */
UNIT_TEST(slow_2d_flow)
{
    enum { RATE = 16000, NOUT = 160 };
    aero_shape2d sh;
    aero_span3d c;
    aero_aeolian_flow_params p = {0};
    aero_aeolian_flow_stats st;
    static float out[2 * NOUT];
    char err[256] = "";
    double rms = 0.0;
    int finite = 1;
    aero_span3d_none(&c, 300.0);
    c.frequency_scale = 1.6;
    c.applied = 1;
    aero_shape2d_circle(&sh, 0.01);
    p.shape = &sh;
    p.size = 0.01;
    p.speed = 10.0;
    p.re = 300.0;
    p.grid = 8.0;
    p.cfl = 0.5;
    p.settle = 5.0;
    p.duration = (double)NOUT / RATE;
    p.span3d = &c;
    UNIT_CHECK(aero_aeolian_flow_simulate(&p, RATE, out, 2, NOUT, &st, NULL,
                                          0, NULL, err, sizeof err) == 0,
               "frequency scale 1.6: the texture is filled (%s)", err);
    for (int k = 0; k < 2 * NOUT; k++) {
        finite &= isfinite(out[k]) != 0;
        rms += (double)out[k] * out[k];
    }
    UNIT_CHECK(finite && rms > 0.0, "its samples are finite and not silent");
}

UNIT_MAIN(UNIT_CASE(spectral_st), UNIT_CASE(calibration), UNIT_CASE(slow_2d_flow))
