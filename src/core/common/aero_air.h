/* aero: physical constants of air shared by every module (SI units).
 * The project's one set of values for air: rho = 1.225 kg/m^3, mu = 1.81e-5 Pa
 * s, c0 = 343 m/s (dry air at about 20 degC). */
#ifndef AERO_AIR_H
#define AERO_AIR_H

#define AERO_RHO 1.225          /* density of air, kg/m^3 */
#define AERO_MU 1.81e-5         /* dynamic viscosity of air, Pa s */
#define AERO_NU (AERO_MU / AERO_RHO) /* kinematic viscosity, m^2/s (~1.48e-5) */
#define AERO_C0 343.0           /* speed of sound, m/s */
#define AERO_MACH_LIMIT 0.3     /* models do not hold above this Mach number */
#define AERO_PI 3.14159265358979323846

#endif
