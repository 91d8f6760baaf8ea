/* aero: Strouhal/Reynolds laws of a circular cylinder (see strouhal.h). */
#include "strouhal.h"

#include "aero_air.h"

#include <math.h>

double aero_reynolds(double speed, double diameter)
{
    if (speed < 0)
        speed = -speed;
    return AERO_RHO * speed * diameter / AERO_MU;
}

static double strouhal_williamson(double re)
{
    return -3.3265 / re + 0.1816 + 1.6e-4 * re;
}

static double strouhal_roshko(double re)
{
    return 0.198 * (1.0 - 19.7 / re);
}

double aero_strouhal(double re)
{
    const double blend_lo = 170.0, blend_hi = 260.0;
    if (!(re > AERO_RE_ONSET))
        return strouhal_williamson(AERO_RE_ONSET);
    if (re <= blend_lo)
        return strouhal_williamson(re);
    if (re >= blend_hi)
        return strouhal_roshko(re);
    double s = (re - blend_lo) / (blend_hi - blend_lo);
    s = s * s * (3.0 - 2.0 * s); /* smoothstep: continuous slope */
    return (1.0 - s) * strouhal_williamson(re) + s * strouhal_roshko(re);
}

double aero_shedding_strength(double re)
{
    const double saturation_re = 184.0;
    if (!(re > AERO_RE_ONSET))
        return 0.0;
    /* sqrt(1 - exp(-x)) ~ sqrt(x) near onset, -> 1 far above it */
    double x = (re - AERO_RE_ONSET) / saturation_re;
    if (x > 40.0)
        return 1.0;
    return sqrt(1.0 - exp(-x));
}

double aero_wake_turbulence(double re)
{
    const double transition_re = 400.0;
    if (!(re > 0.0))
        return 0.0;
    double q = transition_re / re;
    return 1.0 / (1.0 + q * q);
}

double aero_shedding_line_width(double re)
{
    const double laminar = 0.004, turbulent = 0.06;
    return laminar + (turbulent - laminar) * aero_wake_turbulence(re);
}

static double lift_rms_laminar(double re)
{
    double e = (re - AERO_RE_ONSET) / AERO_RE_ONSET;
    return sqrt(e / 30.0 + e * e / 90.0);
}

static double lift_rms_transitional(double re)
{
    return 0.045 + 1.05 * pow(1.0 - re / 1600.0, 4.5);
}

double aero_lift_rms(double re)
{
    const double laminar_end = 190.0, transitional_start = 260.0;
    const double subcritical_end = 2.25e5;
    if (!(re > AERO_RE_ONSET))
        return 0.0;
    if (re <= laminar_end)
        return lift_rms_laminar(re);
    if (re < transitional_start) {
        double s = (re - laminar_end) / (transitional_start - laminar_end);
        return (1.0 - s) * lift_rms_laminar(laminar_end) +
               s * lift_rms_transitional(transitional_start);
    }
    if (re < 1600.0)
        return lift_rms_transitional(re);
    if (re > subcritical_end)
        re = subcritical_end;
    double x = log10(re / 1600.0);
    if (re < 5400.0)
        return 0.045 + 3.0 * pow(x, 4.6);
    return 0.52 - 0.06 * pow(x, -2.6);
}
