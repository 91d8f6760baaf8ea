/* tests for src/core/solve/strip_body.c: a slender body by strip theory.
 * The section is a synthetic circle texture (a pure lift tone of known
 * amplitude), so what each region plays can be checked against Roshko's
 * (1954) St and Norberg's (2003) C_L' at its own Reynolds number and the
 * cross-flow speed, not against the texture's metadata. */
/* aero-test: slow */
#include "strip_body.h"
#include "aero_air.h"
#include "strouhal.h"
#include "unit.h"

#include <stdlib.h>
#include <string.h>

#define SECTION_RATE 16000.0
#define SECTION_FRAMES 16000
#define SECTION_F 200.0   /* Hz: St 0.2 at 10 m/s on 1 cm */
#define SECTION_G 3.0     /* N/(m s), amplitude of the lift's g */

/* a circle's texture whose lift g is a pure tone: 0 or -1 */
static int make_section(aero_texture *t, const char *shape)
{
    if (aero_texture_init(t, SECTION_FRAMES, 1, SECTION_RATE))
        return -1;
    for (int n = 0; n < SECTION_FRAMES; n++) {
        double ph = 2.0 * AERO_PI * SECTION_F * n / SECTION_RATE;
        t->data[3 * n] = (float)(0.1 * SECTION_G * cos(2.0 * ph));
        t->data[3 * n + 1] = (float)(SECTION_G * sin(ph));
    }
    aero_texture_set(t, "kind", "aeolian");
    aero_texture_set(t, "shape", shape);
    aero_texture_setd(t, "v0", 10.0);
    aero_texture_setd(t, "diameter", 0.01);
    aero_texture_setd(t, "st", SECTION_F * 0.01 / 10.0);
    aero_texture_setd(t, "cl_rms", 0.3);
    return 0;
}

/* the centre of x's line between lo and hi: the mean frequency weighted
   by the Hann-windowed Fourier power, scanned in 0.05 Hz steps (n samples
   at rate, every stride-th) */
static double line_centre(const float *x, int stride, int n, double rate,
                          double lo, double hi)
{
    double sum = 0.0, moment = 0.0;
    for (double f = lo; f <= hi; f += 0.05) {
        double re = 0.0, im = 0.0, p;
        for (int k = 0; k < n; k++) {
            double w = 0.5 - 0.5 * cos(2.0 * AERO_PI * k / (n - 1));
            re += w * x[(size_t)k * stride] * cos(2.0 * AERO_PI * f * k / rate);
            im += w * x[(size_t)k * stride] * sin(2.0 * AERO_PI * f * k / rate);
        }
        p = re * re + im * im;
        sum += p;
        moment += p * f;
    }
    return sum > 0.0 ? moment / sum : 0.0;
}

static double rms(const float *x, int stride, int n)
{
    double s = 0.0;
    for (int k = 0; k < n; k++)
        s += (double)x[(size_t)k * stride] * x[(size_t)k * stride];
    return sqrt(s / n);
}

UNIT_TEST(layout)
{
    aero_body_shape club, capsule, sphere;
    aero_strip_layout L;
    char err[256];
    int rising = 1;
    printf("local diameters along a club and a capsule\n");
    aero_body_club(&club, 0.0125, 0.03, 0.8, err, sizeof err);
    UNIT_CHECK(aero_strip_layout_measure(&club, 10, &L, err, sizeof err) == 0,
               "a club's 10 slices measured");
    UNIT_NEAR_REL(L.diameter[0], 0.025, 0.005, "handle slice diameter (m)");
    UNIT_NEAR_REL(L.span[4], 0.08, 1e-9, "a middle slice's span (m)");
    for (int l = 1; l < 9; l++)
        rising = rising && L.diameter[l] >= L.diameter[l - 1];
    UNIT_CHECK(rising && L.diameter[8] > 0.055 && L.diameter[8] < 0.06,
               "the diameter grows to the tip's 60 mm: slice 8 %.4g m",
               L.diameter[8]);
    UNIT_CHECK(L.z[0] > 0.0 && L.z[0] < 0.08 && L.z[9] > 0.72 && L.z[9] < 0.8,
               "centroids inside their slices: %.3g, %.3g m", L.z[0], L.z[9]);
    aero_body_capsule(&capsule, 0.02, 0.3, err, sizeof err);
    aero_strip_layout_measure(&capsule, 5, &L, err, sizeof err);
    UNIT_NEAR_REL(L.diameter[2], 0.04, 0.005, "a capsule's middle diameter");
    aero_body_sphere(&sphere, 0.05, err, sizeof err);
    UNIT_CHECK(aero_strip_layout_measure(&sphere, 1, &L, err, sizeof err) &&
                   strstr(err, "sphere"),
               "a sphere is refused: %s", err);
    UNIT_CHECK(aero_strip_layout_measure(&club, 0, &L, err, sizeof err),
               "0 regions are refused: %s", err);
    aero_body_shape_free(&club);
    aero_body_shape_free(&capsule);
    aero_body_shape_free(&sphere);
}

/* region l's tone and level at the flow angle a against Roshko's St and
   Norberg's C_L' at its Re and the cross-flow speed */
static void check_region(const aero_texture *sec, const aero_strip_layout *L,
                         double angle, int l)
{
    const double rate = 1000.0, v0 = 10.0;
    const int n = 16000;
    float *out = calloc((size_t)n * 3 * L->regions, sizeof(float));
    aero_strip_stats st;
    double un = v0 * sin(angle * AERO_PI / 180.0), d = L->diameter[l];
    double re = un * d / AERO_NU, f = aero_strouhal(re) * un / d;
    double length = 0.0, lc, span;
    for (int k = 0; k < L->regions; k++)
        length += L->span[k];
    lc = fmin(3.0 * d, length);
    span = sqrt(L->span[l] * lc);
    double want = SECTION_G / sqrt(2.0) * pow(un / 10.0, 3.0) *
                  (aero_strouhal(re) / 0.2) * (aero_lift_rms(re) / 0.3) * span;
    char what[128];
    aero_strip_render(sec, L, angle, v0, rate, 1, out, 3 * L->regions, n, &st);
    snprintf(what, sizeof what, "%g deg, region %d (d %.3g m): tone, Hz",
             angle, l, d);
    /* the line's centre within 1.5 %: the wander makes a line 6 % of f
       wide whose estimate over 16 s scatters by about 1 % */
    UNIT_NEAR_REL(line_centre(out + 3 * l + 1, 3 * L->regions, n, rate,
                              0.8 * f, 1.2 * f), f, 0.015, what);
    snprintf(what, sizeof what, "%g deg, region %d: rms g_y, N/s", angle, l);
    UNIT_NEAR_REL(rms(out + 3 * l + 1, 3 * L->regions, n), want, 0.03, what);
    UNIT_CHECK(rms(out + 3 * l + 2, 3 * L->regions, n) == 0.0,
               "no axial force");
    free(out);
}

UNIT_TEST(render)
{
    aero_texture sec, square;
    aero_body_shape club;
    aero_strip_layout L;
    aero_strip_stats st;
    char err[256];
    float *out;
    printf("each region sheds at its own diameter and cross-flow\n");
    make_section(&sec, "circle");
    aero_body_club(&club, 0.0125, 0.03, 0.8, err, sizeof err);
    aero_strip_layout_measure(&club, 10, &L, err, sizeof err);
    UNIT_CHECK(aero_strip_check_section(&sec, err, sizeof err) == 0,
               "a circle's texture is a section");
    check_region(&sec, &L, 90.0, 0);
    check_region(&sec, &L, 90.0, 8);
    check_region(&sec, &L, 45.0, 0);
    check_region(&sec, &L, 135.0, 8);
    /* along the axis nothing sheds */
    out = calloc((size_t)400 * 30, sizeof(float));
    aero_strip_render(&sec, &L, 0.0, 10.0, 4000.0, 1, out, 30, 400, &st);
    UNIT_CHECK(rms(out, 1, 400 * 30) == 0.0 && st.cl_rms == 0.0,
               "flow along the axis: silent");
    free(out);
    make_section(&square, "square");
    UNIT_CHECK(aero_strip_check_section(&square, err, sizeof err) != 0,
               "a square's texture is refused: %s", err);
    aero_texture_free(&square);
    aero_texture_set(&sec, "st", "0");
    UNIT_CHECK(aero_strip_check_section(&sec, err, sizeof err) != 0,
               "a section without st is refused: %s", err);
    aero_texture_free(&sec);
    aero_body_shape_free(&club);
}

UNIT_MAIN(UNIT_CASE(layout), UNIT_CASE(render))
