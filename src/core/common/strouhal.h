/* aero: vortex shedding from a circular cylinder as a function of the
 * Reynolds number, the laws shared by every object that sheds (Roshko
 * 1954, Williamson 1996; as Dobashi et al. 2003 and the Pd aeroacoustics
 * report use them). */
#ifndef AERO_STROUHAL_H
#define AERO_STROUHAL_H

/* Shedding onset: the wake becomes unstable at Re ~ 47 (Provansal et al.
 * 1987; Williamson 1996). Below it there is no tone. */
#define AERO_RE_ONSET 47.0

/* Re = rho U d / mu for air (aero_air.h). */
double aero_reynolds(double speed, double diameter);

/* The spanwise correlation length of a cylinder's shedding, in diameters:
 * the spacing of incoherent point sources along a stick (Dobashi et al.
 * 2003; ~3-5 d measured, Norberg 2003). */
#define AERO_CORRELATION_DIAMETERS 3.0

/* Strouhal number St(Re) of a circular cylinder:
 *   Williamson (1996) laminar fit  St = -3.3265/Re + 0.1816 + 1.6e-4 Re
 *     (valid 49 < Re < 178),
 *   Roshko's form  St = 0.198 (1 - 19.7/Re)  above (as the Pd report has it),
 * blended with a smoothstep between Re 170 and 260, where the wake turns
 * three-dimensional and St really does drop (Williamson's mode A).
 * Below onset it returns the fit's value at onset (the tone is silent there). */
double aero_strouhal(double re);

/* Relative strength of shedding, 0 below onset rising to 1: the lift
 * amplitude of a Hopf bifurcation grows as sqrt(Re - Re_c) (Provansal et al.
 * 1987); it saturates with a scale chosen so that the rms lift at Re 100 is
 * about half of the subcritical value (0.23 vs 0.45, Norberg 2003). */
double aero_shedding_strength(double re);

/* Sectional rms lift coefficient C_L'(Re) of a circular cylinder, the fits
 * of Norberg (2003, J. Fluids Struct. 17, eqs. for the four ranges):
 *   47 < Re < 190:     sqrt(e/30 + e^2/90), e = (Re - 47)/47 (laminar,
 *                      the Hopf growth of the lift from onset),
 *   260 < Re < 1600:   0.045 + 1.05 (1 - Re/1600)^4.5,
 *   1600 < Re < 5400:  0.045 + 3 x^4.6,       x = log10(Re/1600),
 *   5400 < Re < 2.25e5: 0.52 - 0.06 x^-2.6.
 * Between 190 and 260 (mode A/B transition, where the measured values
 * scatter most) it interpolates linearly; above 2.25e5, where the fits end
 * (the drag crisis), it holds the last value. 0 below onset. */
double aero_lift_rms(double re);

/* How turbulent the wake is, 0 (laminar, Re << 400) to 1 (Re >> 400): a
 * continuous logistic law in log Re centred on the wake transition range
 * (Re ~ 190..1000). Drives the width of the shedding peak. */
double aero_wake_turbulence(double re);

/* Full width at half maximum of the shedding line over its frequency:
 * nearly a pure tone in the laminar wake (0.4 %), a few percent (6 %) once
 * turbulent, following aero_wake_turbulence. */
double aero_shedding_line_width(double re);

#endif
