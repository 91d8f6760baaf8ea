/* aerotex airfoil: the airfoil self-noise model's one-third-octave
 * spectrum (Brooks et al. 1989; src/core/common/airfoil_noise.h) printed
 * as a table, what the sword's top is made from: the Pd test and the
 * documents compare the rendered blade with it. */
#include "aerotex.h"

#include <stddef.h>
#include <stdio.h>

#include "aero_air.h"
#include "airfoil_noise.h"

typedef struct {
    double chord, span, speed, alpha, h, psi, r, theta, phi, lo, hi;
    int untripped;
} airfoil_job;

#define AT(field) offsetof(airfoil_job, field)
static const aerotex_option options[] = {
    {"--chord", AEROTEX_POSITIVE, "m", 0.04, 0, 100, AT(chord),
     "chord (the sword's: 40 mm)", NULL, NULL},
    {"--span", AEROTEX_POSITIVE, "m", 1.0, 0, 1e3, AT(span),
     "wetted span", NULL, NULL},
    {"--speed", AEROTEX_POSITIVE, "m/s", 20.0, 0, 170, AT(speed),
     "flow speed", NULL, NULL},
    {"--alpha", AEROTEX_NUMBER, "deg", 0.0, -90, 90, AT(alpha),
     "angle of attack (the model's fits: 0-25)", NULL, NULL},
    {"--te-thickness", AEROTEX_NUMBER, "m", 0.0, 0, 1, AT(h),
     "trailing-edge thickness (0: sharp)", NULL, NULL},
    {"--te-angle", AEROTEX_NUMBER, "deg", 14.0, 0, 90, AT(psi),
     "trailing-edge angle Psi", NULL, NULL},
    {"--untripped", AEROTEX_SWITCH, NULL, 0, 1, 0, AT(untripped),
     "natural transition (LBL-VS possible); default tripped", NULL, NULL},
    {"--distance", AEROTEX_POSITIVE, "m", 1.0, 0, 1e4, AT(r),
     "observer distance r_e", NULL, NULL},
    {"--theta", AEROTEX_NUMBER, "deg", 90.0, 0, 180, AT(theta),
     "observer angle from the chord, downstream", NULL, NULL},
    {"--phi", AEROTEX_NUMBER, "deg", 90.0, 0, 180, AT(phi),
     "observer angle from the span", NULL, NULL},
    {"--from", AEROTEX_POSITIVE, "Hz", 200.0, 0, 1e5, AT(lo),
     "lowest band", NULL, NULL},
    {"--to", AEROTEX_POSITIVE, "Hz", 20000.0, 0, 1e5, AT(hi),
     "highest band", NULL, NULL},
    {NULL, 0, NULL, 0, 0, 0, 0, NULL, NULL, NULL}};
#undef AT

static int run(int argc, char **argv)
{
    airfoil_job j;
    float hz[64], spl[AERO_BPM_MECHANISMS * 64], total[64];
    aerotex_defaults(&aerotex_airfoil_command, &j);
    if (aerotex_parse(&aerotex_airfoil_command, &j, argc, argv))
        return 2;
    aero_airfoil a = {(float)j.chord, (float)j.span, (float)j.h,
                      (float)j.psi, !j.untripped, AERO_AIRFOIL_NO_TIP, 0};
    aero_airfoil_flow f = {(float)j.speed, (float)j.alpha, (float)AERO_C0,
                           (float)AERO_NU};
    aero_airfoil_observer o = {(float)j.r, (float)j.theta, (float)j.phi};
    int n = aero_third_octave_bands((float)j.lo, (float)j.hi, hz, 64);
    if (n < 1 || aero_airfoil_noise_spectrum(&a, &f, &o, hz, n, spl)) {
        aerotex_error("airfoil: no band or a value out of the model");
        return 1;
    }
    aero_airfoil_noise_total(spl, n, total);
    printf("# Brooks et al. 1989: one-third-octave SPL, dB re 20 uPa "
           "(-200: none)\n# chord %g m, span %g m, %g m/s, alpha %g deg, "
           "%s, h %g m, Psi %g deg; r %g m, theta %g, phi %g deg; Rc %.3g\n",
           j.chord, j.span, j.speed, j.alpha,
           j.untripped ? "untripped" : "tripped", j.h, j.psi, j.r, j.theta,
           j.phi, j.speed * j.chord / AERO_NU);
    printf("# hz pressure suction separation lbl-vs bluntness tip total\n");
    for (int k = 0; k < n; k++) {
        printf("%.1f", hz[k]);
        for (int m = 0; m < AERO_BPM_MECHANISMS; m++)
            printf(" %.2f", spl[m * n + k]);
        printf(" %.2f\n", total[k]);
    }
    return 0;
}

const aerotex_command aerotex_airfoil_command = {
    "airfoil", "[options]",
    "prints the airfoil self-noise model's one-third-octave spectrum\n"
    "(Brooks et al. 1989) of each mechanism and their total",
    options, sizeof(airfoil_job), NULL, run};
