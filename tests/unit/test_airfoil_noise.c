/* aero: the airfoil self-noise model of Brooks, Pope and Marcolini (1989)
 * against its own report's figures (NASA RP-1218, as digitized by
 * AcousticAnalogies.jl: tests/unit/bpm_figures.h). Each curve is one
 * mechanism's predicted one-third-octave spectrum of a NACA 0012 section
 * (span 45.72 cm, 30.48 cm for the tip) heard at r_e = 1.22 m,
 * theta_e = phi_e = 90 deg, with the report's nu = 1.4529e-5 m^2/s and
 * c0 = 340.46 m/s. The figures plot band levels at the band centres;
 * each digitized point is compared with the model at the centre of the
 * band it was read at (read back 1-4 % off in frequency: interpolating
 * between points at the exact centres instead would move a level by up
 * to 0.8 dB on a flank falling 6 dB a band): within 1.5 dB, about
 * half a division of the figures' 10 dB grid, the reading accuracy of a
 * digitized figure. */
#include "airfoil_noise.h"
#include "bpm_figures.h"
#include "unit.h"

#define FIGURE_TOLERANCE_DB 1.5
/* the tip's angle over the section's in the report's tip test (its
   rounded-tip model at alpha* 10.8 deg, figure 91): the tip's lift
   slope over the reference, the loading correction of alpha'_tip */
#define REPORT_TIP_LOADING 0.71f
#define CURVE(name) name, (int)(sizeof name / sizeof name[0])

typedef struct {
    const char *what;
    const float (*curve)[2];
    int points;
    float chord, speed, alpha_deg;
    int tripped;
    float h, psi_deg; /* trailing edge: thickness (m), angle (deg) */
    int mechanism;
    int below_peak; /* compare the bands below the curve's peak only */
} figure;

/* the report's test conditions (the conditions of each CSV,
   ../shared/reference/bpm/README.md) */
static float report_span(int mechanism)
{
    return mechanism == AERO_BPM_TIP ? 0.3048f : 0.4572f;
}

/* the band a digitized point was read at: the figures plot band levels
   at the band centres, read back 1-4 % off in frequency; a point more
   than 0.3 of a band (7 %) from a centre is not a band reading (none
   is). 0, or -1 */
static int band_of(double f_khz, float *hz)
{
    double b = 10 * log10(1000 * f_khz), nearest = floor(b + 0.5);
    if (!(fabs(b - nearest) < 0.3))
        return -1;
    *hz = (float)pow(10, nearest / 10);
    return 0;
}

/* the worst band's difference, model minus figure, over the curve's
   points; the number of bands compared in *bands */
static double worst_difference(const figure *fg, int *bands)
{
    aero_airfoil a = {fg->chord, report_span(fg->mechanism), fg->h,
                      fg->psi_deg, fg->tripped,
                      fg->mechanism == AERO_BPM_TIP ? AERO_AIRFOIL_TIP_ROUNDED
                                                    : AERO_AIRFOIL_NO_TIP,
                      REPORT_TIP_LOADING * fg->alpha_deg};
    aero_airfoil_flow f = {fg->speed, fg->alpha_deg, AERO_BPM_REPORT_C0,
                           AERO_BPM_REPORT_NU};
    aero_airfoil_observer o = {1.22f, 90, 90};
    double worst = 0, peak_khz = 0, peak_db = -1e9;
    *bands = 0;
    for (int i = 0; i < fg->points; i++)
        if (fg->curve[i][1] > peak_db) {
            peak_db = fg->curve[i][1];
            peak_khz = fg->curve[i][0];
        }
    for (int i = 0; i < fg->points; i++) {
        float hz, spl[AERO_BPM_MECHANISMS];
        double got, want = fg->curve[i][1];
        if (band_of(fg->curve[i][0], &hz) != 0 ||
            aero_airfoil_noise_spectrum(&a, &f, &o, &hz, 1, spl) != 0)
            return 1e9;
        got = spl[fg->mechanism];
        if (fg->below_peak && fg->curve[i][0] >= peak_khz)
            continue;
        (*bands)++;
        if (fabs(got - want) > fabs(worst))
            worst = got - want;
        if (getenv("AERO_TEST_VERBOSE"))
            printf("        %s %8.0f Hz: model %6.1f, figure %6.1f\n",
                   fg->what, hz, got, want);
    }
    return worst;
}

/* curves printed beside the checks, not judged (see the cases) */
static void show_figures(const figure *fg, int n)
{
    for (int i = 0; i < n; i++) {
        int bands;
        double worst = worst_difference(&fg[i], &bands);
        printf("  note  %s: %d bands, worst %+.2f dB (not judged)\n",
               fg[i].what, bands, worst);
    }
}

static void check_figures(const figure *fg, int n)
{
    for (int i = 0; i < n; i++) {
        int bands;
        double worst = worst_difference(&fg[i], &bands);
        UNIT_CHECK(bands >= 3 && fabs(worst) <= FIGURE_TOLERANCE_DB,
                   "%s: %d bands, worst %+.2f dB (within %.1f)", fg[i].what,
                   bands, worst, FIGURE_TOLERANCE_DB);
    }
}

enum { P = AERO_BPM_TBL_PRESSURE, S = AERO_BPM_TBL_SUCTION,
       A = AERO_BPM_SEPARATION, L = AERO_BPM_LBL_VS,
       B = AERO_BPM_BLUNTNESS, T = AERO_BPM_TIP };

/* The checks take the panels at 71.3 and 31.7 m/s (a and d) of the
 * speed series. At 55.5 and 39.6 m/s (panels b and c) the digitized
 * curves lie 0.5-2 dB above the report's own equations at every band
 * (up to 3.8 dB on the upper flank of figure 28b's separation curve),
 * where the a and d panels of the same figures agree within 0.5: a
 * smooth function of speed cannot be exact at 31.7 and 71.3 and 1 dB
 * off between, so the digitization (each panel calibrated on its own)
 * or the report's plotted conditions differ there; the independent
 * implementation AcousticAnalogies.jl checks the a and d panels only
 * for the same reason. Those panels are printed, not judged. */

/* tripped boundary layer, zero and small angle: the 30.48, 10.16 and
   2.54 cm chords (figures 11, 12, 26, 38) */
UNIT_TEST(tbl_te_tripped)
{
    static const figure fg[] = {
        {"fig 11a suction", CURVE(figure11_a_TBL_TE_suction),
         .3048f, 71.3f, 0, 1, 0, 0, S, 0},
        {"fig 11d suction", CURVE(figure11_d_TBL_TE_suction),
         .3048f, 31.7f, 0, 1, 0, 0, S, 0},
        {"fig 12a pressure", CURVE(figure12_U71_3_TBL_TE_pressure),
         .3048f, 71.3f, 1.5f, 1, 0, 0, P, 0},
        {"fig 12a suction", CURVE(figure12_U71_3_TBL_TE_suction),
         .3048f, 71.3f, 1.5f, 1, 0, 0, S, 0},
        {"fig 26a suction", CURVE(figure26_a_TBL_TE_suction),
         .1016f, 71.3f, 0, 1, 0, 0, S, 0},
        {"fig 26d suction", CURVE(figure26_d_TBL_TE_suction),
         .1016f, 31.7f, 0, 1, 0, 0, S, 0},
        {"fig 38d suction", CURVE(figure38_d_TBL_TE_suction),
         .0254f, 31.7f, 0, 1, 0, 0, S, 0},
    };
    static const figure mid[] = {
        {"fig 11b suction", CURVE(figure11_b_TBL_TE_suction),
         .3048f, 55.5f, 0, 1, 0, 0, S, 0},
        {"fig 11c suction", CURVE(figure11_c_TBL_TE_suction),
         .3048f, 39.6f, 0, 1, 0, 0, S, 0},
        {"fig 12b pressure", CURVE(figure12_b_TBL_TE_pressure),
         .3048f, 39.6f, 1.5f, 1, 0, 0, P, 0},
        {"fig 12b suction", CURVE(figure12_b_TBL_TE_suction),
         .3048f, 39.6f, 1.5f, 1, 0, 0, S, 0},
        {"fig 26b suction", CURVE(figure26_b_TBL_TE_suction),
         .1016f, 55.5f, 0, 1, 0, 0, S, 0},
        {"fig 26c suction", CURVE(figure26_c_TBL_TE_suction),
         .1016f, 39.6f, 0, 1, 0, 0, S, 0},
    };
    check_figures(fg, (int)(sizeof fg / sizeof fg[0]));
    show_figures(mid, (int)(sizeof mid / sizeof mid[0]));
}

/* tripped at angle: both sides and the separation term (figures 12 at
   1.5 deg, 28 at 6.7 deg, 39 at 4.8 deg) */
UNIT_TEST(tbl_te_angle)
{
    static const figure fg[] = {
        {"fig 12a separation", CURVE(figure12_U71_3_separation),
         .3048f, 71.3f, 1.5f, 1, 0, 0, A, 0},
        {"fig 28a pressure", CURVE(figure28_a_TBL_TE_pressure),
         .1016f, 71.3f, 6.7f, 1, 0, 0, P, 0},
        {"fig 28a suction", CURVE(figure28_a_TBL_TE_suction),
         .1016f, 71.3f, 6.7f, 1, 0, 0, S, 0},
        {"fig 28a separation", CURVE(figure28_a_separation),
         .1016f, 71.3f, 6.7f, 1, 0, 0, A, 0},
        {"fig 28d pressure", CURVE(figure28_d_TBL_TE_pressure),
         .1016f, 31.7f, 6.7f, 1, 0, 0, P, 0},
        {"fig 28d suction", CURVE(figure28_d_TBL_TE_suction),
         .1016f, 31.7f, 6.7f, 1, 0, 0, S, 0},
        {"fig 28d separation", CURVE(figure28_d_separation),
         .1016f, 31.7f, 6.7f, 1, 0, 0, A, 0},
        {"fig 39d pressure", CURVE(figure39_d_TBL_TE_pressure),
         .0254f, 31.7f, 4.8f, 1, 0, 0, P, 0},
        {"fig 39d suction", CURVE(figure39_d_TBL_TE_suction),
         .0254f, 31.7f, 4.8f, 1, 0, 0, S, 0},
        {"fig 39d separation", CURVE(figure39_d_separation),
         .0254f, 31.7f, 4.8f, 1, 0, 0, A, 0},
    };
    static const figure mid[] = {
        {"fig 12b separation", CURVE(figure12_b_TBL_TE_separation),
         .3048f, 39.6f, 1.5f, 1, 0, 0, A, 0},
        {"fig 28b pressure", CURVE(figure28_b_TBL_TE_pressure),
         .1016f, 55.5f, 6.7f, 1, 0, 0, P, 0},
        {"fig 28b suction", CURVE(figure28_b_TBL_TE_suction),
         .1016f, 55.5f, 6.7f, 1, 0, 0, S, 0},
        {"fig 28b separation", CURVE(figure28_b_separation),
         .1016f, 55.5f, 6.7f, 1, 0, 0, A, 0},
        {"fig 28c pressure", CURVE(figure28_c_TBL_TE_pressure),
         .1016f, 39.6f, 6.7f, 1, 0, 0, P, 0},
        {"fig 28c suction", CURVE(figure28_c_TBL_TE_suction),
         .1016f, 39.6f, 6.7f, 1, 0, 0, S, 0},
        {"fig 28c separation", CURVE(figure28_c_separation),
         .1016f, 39.6f, 6.7f, 1, 0, 0, A, 0},
    };
    check_figures(fg, (int)(sizeof fg / sizeof fg[0]));
    show_figures(mid, (int)(sizeof mid / sizeof mid[0]));
}

/* untripped: TBL-TE beside LBL-VS (figure 45) */
UNIT_TEST(tbl_te_untripped)
{
    static const figure fg[] = {
        {"fig 45a pressure", CURVE(figure45_a_TBL_TE_pressure),
         .3048f, 71.3f, 1.5f, 0, 0, 0, P, 0},
        {"fig 45a suction", CURVE(figure45_a_TBL_TE_suction),
         .3048f, 71.3f, 1.5f, 0, 0, 0, S, 0},
        {"fig 45a separation", CURVE(figure45_a_separation),
         .3048f, 71.3f, 1.5f, 0, 0, 0, A, 0},
    };
    check_figures(fg, (int)(sizeof fg / sizeof fg[0]));
}

/* stalled: 15.4 deg on the 5.08 cm chord (figure 69), the separation
   term alone with the wider spectrum and low-frequency directivity */
UNIT_TEST(separation_stalled)
{
    static const figure fg[] = {
        {"fig 69a separation", CURVE(figure69_a_separation),
         .0508f, 71.3f, 15.4f, 0, 0, 0, A, 0},
        {"fig 69b separation", CURVE(figure69_b_separation),
         .0508f, 39.6f, 15.4f, 0, 0, 0, A, 0},
    };
    check_figures(fg, (int)(sizeof fg / sizeof fg[0]));
}

/* laminar boundary layer vortex shedding (figures 45-66). The tone's
   flanks fall 4-10 dB a band, so a peak placed 5 % off moves them by
   2-4 dB: figures 48c, 59c, 60c and 66b lie so (the model's peak a few
   percent below the figure's, as AcousticAnalogies.jl also finds; it
   judges 45a, 54a, 60d and 65d) and are printed, not judged. */
UNIT_TEST(lbl_vs)
{
    static const figure fg[] = {
        {"fig 45a LBL-VS", CURVE(figure45_a_LBL_VS),
         .3048f, 71.3f, 1.5f, 0, 0, 0, L, 0},
        {"fig 54a LBL-VS", CURVE(figure54_a_LBL_VS),
         .1524f, 71.3f, 2.7f, 0, 0, 0, L, 0},
        {"fig 60d LBL-VS", CURVE(figure60_d_LBL_VS),
         .1016f, 31.7f, 3.3f, 0, 0, 0, L, 0},
        {"fig 65d LBL-VS", CURVE(figure65_d_LBL_VS),
         .0508f, 31.7f, 0, 0, 0, 0, L, 0},
    };
    static const figure off[] = {
        {"fig 48c LBL-VS", CURVE(figure48_c_LBL_VS),
         .2286f, 39.6f, 0, 0, 0, 0, L, 0},
        {"fig 59c LBL-VS", CURVE(figure59_c_LBL_VS),
         .1016f, 39.6f, 0, 0, 0, 0, L, 0},
        {"fig 60c LBL-VS", CURVE(figure60_c_LBL_VS),
         .1016f, 39.6f, 3.3f, 0, 0, 0, L, 0},
        {"fig 66b LBL-VS", CURVE(figure66_b_LBL_VS),
         .0508f, 39.6f, 4.2f, 0, 0, 0, L, 0},
    };
    check_figures(fg, (int)(sizeof fg / sizeof fg[0]));
    show_figures(off, (int)(sizeof off / sizeof off[0]));
}

/* trailing-edge bluntness, the 60.96 cm chord with h 1.1-2.5 mm,
   Psi 14 deg (figures 98 at 69.5 m/s, 99 at 38.6 m/s), on the rising
   side below the peak band: the spectrum falls 15.5 dB a band above its
   peak, and the printed curves put the peak up to 10 % higher than the
   report's equations do (figures 98c and 99b peak a band above the
   model), so the model is 2-6 dB under them at and just past the peak
   (AcousticAnalogies.jl finds the same on the last points) */
UNIT_TEST(bluntness)
{
    static const figure fg[] = {
        {"fig 98a suction", CURVE(figure98_a_TBL_TE_suction),
         .6096f, 69.5f, 0, 1, 2.5e-3f, 14, S, 0},
        {"fig 98b bluntness", CURVE(figure98_b_bluntness),
         .6096f, 69.5f, 0, 1, 1.1e-3f, 14, B, 1},
        {"fig 98c bluntness", CURVE(figure98_c_bluntness),
         .6096f, 69.5f, 0, 1, 1.9e-3f, 14, B, 1},
        {"fig 98d bluntness", CURVE(figure98_d_bluntness),
         .6096f, 69.5f, 0, 1, 2.5e-3f, 14, B, 1},
        {"fig 99b bluntness", CURVE(figure99_b_bluntness),
         .6096f, 38.6f, 0, 1, 1.1e-3f, 14, B, 1},
        {"fig 99c bluntness", CURVE(figure99_c_bluntness),
         .6096f, 38.6f, 0, 1, 1.9e-3f, 14, B, 1},
        {"fig 99d bluntness", CURVE(figure99_d_bluntness),
         .6096f, 38.6f, 0, 1, 2.5e-3f, 14, B, 1},
    };
    static const figure rest[] = {
        {"fig 99b suction", CURVE(figure99_b_TBL_TE_suction),
         .6096f, 38.6f, 0, 1, 2.5e-3f, 14, S, 0},
        {"fig 98b bluntness, whole", CURVE(figure98_b_bluntness),
         .6096f, 69.5f, 0, 1, 1.1e-3f, 14, B, 0},
        {"fig 99d bluntness, whole", CURVE(figure99_d_bluntness),
         .6096f, 38.6f, 0, 1, 2.5e-3f, 14, B, 0},
    };
    check_figures(fg, (int)(sizeof fg / sizeof fg[0]));
    show_figures(rest, (int)(sizeof rest / sizeof rest[0]));
}

/* tip vortex noise of the rounded tip, 15.24 cm chord at 71.3 m/s
   (figure 91) */
UNIT_TEST(tip)
{
    static const figure fg[] = {
        {"fig 91 tip", CURVE(figure91_tip),
         .1524f, 71.3f, 10.8f, 0, 0, 0, T, 0},
    };
    check_figures(fg, (int)(sizeof fg / sizeof fg[0]));
}

/* the boundary layer at zero angle against the report's figure 6 (its
   correlations drawn over the measured points, a log-log plot): within
   8 %, a thirtieth of a decade, the reading accuracy of a point on a
   log axis of that figure's size */
static double worst_thickness(const float (*curve)[2], int n, int tripped,
                              int displacement)
{
    double worst = 0;
    for (int i = 0; i < n; i++) {
        /* chord 1 m: the speed sets Rc */
        aero_airfoil a = {1, 1, 0, 14, tripped, AERO_AIRFOIL_NO_TIP, 0};
        aero_airfoil_flow f = {1e6f * curve[i][0] * AERO_BPM_REPORT_NU, 0,
                               1e9f, AERO_BPM_REPORT_NU};
        aero_boundary_layer bl;
        double got, err;
        if (aero_airfoil_boundary_layer(&a, &f, &bl) != 0)
            return 1e9;
        got = displacement ? bl.delta_star0 : bl.delta0;
        err = got / curve[i][1] - 1;
        if (fabs(err) > fabs(worst))
            worst = err;
    }
    return worst;
}

UNIT_TEST(boundary_layer)
{
    static const struct {
        const char *what;
        const float (*curve)[2];
        int n, tripped, displacement;
    } fg[] = {
        {"fig 6 delta0, tripped", CURVE(figure06_bl_thickness_tripped), 1, 0},
        {"fig 6 delta0, untripped", CURVE(figure06_bl_thickness_untripped),
         0, 0},
        {"fig 6 delta*0, tripped", CURVE(figure06_disp_thickness_tripped),
         1, 1},
        {"fig 6 delta*0, untripped", CURVE(figure06_disp_thickness_untripped),
         0, 1},
    };
    for (int i = 0; i < (int)(sizeof fg / sizeof fg[0]); i++) {
        double worst = worst_thickness(fg[i].curve, fg[i].n, fg[i].tripped,
                                       fg[i].displacement);
        UNIT_CHECK(fabs(worst) <= 0.08, "%s: %d points, worst %+.1f %%",
                   fg[i].what, fg[i].n, 100 * worst);
    }
}

/* what a caller relies on besides the physics */
UNIT_TEST(api)
{
    aero_airfoil a = {0.1f, 0.5f, 0, 14, 1, AERO_AIRFOIL_NO_TIP, 0};
    aero_airfoil_flow f = {30, 2, 343, 1.48e-5f};
    aero_airfoil_observer o = {1, 90, 90};
    float hz[40], spl[AERO_BPM_MECHANISMS * 40], total[40];
    int n = aero_third_octave_bands(20, 20000, hz, 40), bad = 0, clean = 1;
    UNIT_CHECK(n == 31 && fabsf(hz[0] - 19.95f) < 0.01f &&
                   fabsf(hz[17] - 1000) < 0.01f,
               "third octaves 20 Hz-20 kHz: %d bands, %.2f .. %.0f Hz", n,
               hz[0], hz[n - 1]);
    UNIT_CHECK(fabs(aero_airfoil_directivity_high(0, 90, 90) - 1) < 1e-9 &&
                   fabs(aero_airfoil_directivity_low(0, 90, 90) - 1) < 1e-9 &&
                   aero_airfoil_directivity_high(0.1, 0, 90) < 1e-12,
               "directivity: 1 broadside, 0 upstream along the chord");
    aero_airfoil_noise_spectrum(&a, &f, &o, hz, n, spl);
    aero_airfoil_noise_total(spl, n, total);
    for (int k = 0; k < n; k++) {
        double e = 0;
        for (int m = 0; m < AERO_BPM_MECHANISMS; m++)
            if (spl[m * n + k] > AERO_BPM_SILENT_DB)
                e += pow(10, spl[m * n + k] / 10);
        if (e == 0 && total[k] != AERO_BPM_SILENT_DB)
            bad++;
        if (e > 0 && fabs(10 * log10(e) - total[k]) > 0.01)
            bad++;
    }
    UNIT_CHECK(bad == 0, "the total is the energy sum in every band");
    UNIT_CHECK(spl[AERO_BPM_LBL_VS * n + 17] == AERO_BPM_SILENT_DB &&
                   spl[AERO_BPM_BLUNTNESS * n + 17] == AERO_BPM_SILENT_DB &&
                   spl[AERO_BPM_TIP * n + 17] == AERO_BPM_SILENT_DB,
               "tripped, sharp, no tip: no LBL-VS, bluntness or tip noise");
    f.speed = NAN;
    UNIT_CHECK(aero_airfoil_noise_spectrum(&a, &f, &o, hz, n, spl) == -1,
               "a NaN speed is refused");
    for (int k = 0; k < AERO_BPM_MECHANISMS * n; k++)
        clean = clean && spl[k] == AERO_BPM_SILENT_DB;
    UNIT_CHECK(clean, "and every level is silent, none NaN");
    f.speed = 30;
    a.chord = -1;
    UNIT_CHECK(aero_airfoil_noise_spectrum(&a, &f, &o, hz, n, spl) == -1,
               "a negative chord is refused");
    a.chord = 0.1f;
    f.alpha_deg = 1e30f;
    clean = aero_airfoil_noise_spectrum(&a, &f, &o, hz, n, spl) == 0;
    for (int k = 0; k < AERO_BPM_MECHANISMS * n; k++)
        clean = clean && isfinite(spl[k]);
    UNIT_CHECK(clean, "an angle of 1e30 deg is clamped to the fitted 25");
}

UNIT_MAIN(UNIT_CASE(tbl_te_tripped), UNIT_CASE(tbl_te_angle),
          UNIT_CASE(tbl_te_untripped), UNIT_CASE(separation_stalled),
          UNIT_CASE(lbl_vs), UNIT_CASE(bluntness), UNIT_CASE(tip),
          UNIT_CASE(boundary_layer), UNIT_CASE(api))
