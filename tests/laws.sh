# aero: published laws of a cylinder's wake, written here independently of
# src/core (sourced by tests/run.sh and tests/platform/run.sh).
# Re = rho U d / mu (rho 1.225, mu 1.81e-5); St: Williamson (1996)
# -3.3265/Re + 0.1816 + 1.6e-4 Re for Re < 178, Roshko 0.198 (1 - 19.7/Re)
# for Re > 260 (Roshko 1954); f = St U / d.
tone_hz() {
    awk -v u="$1" -v d="$2" 'BEGIN {
        re = 1.225 * u * d / 1.81e-5
        st = (re < 178) ? -3.3265 / re + 0.1816 + 1.6e-4 * re \
                        : 0.198 * (1 - 19.7 / re)
        printf "%.6g\n", st * u / d }'
}

# Sectional rms lift coefficient C_L'(Re) of a circular cylinder, Norberg's
# (2003, J. Fluids Struct. 17) fits for 1600 < Re < 2.25e5
norberg_lift_rms() {
    awk -v re="$1" 'BEGIN { x = log(re / 1600) / log(10)
        if (re < 5400) c = 0.045 + 3 * x^4.6; else c = 0.52 - 0.06 * x^-2.6
        printf "%.5f", c }'
}
speed_re() { awk -v u="$1" -v d="$2" 'BEGIN { printf "%.1f", 1.225 * u * d / 1.81e-5 }'; }

# level step from speed U1 to U2 (diameter D), dB: p ~ U^3 C_L'(Re) St(Re),
# +18 dB per doubling of speed at a constant C_L', plus the rise of the
# sectional lift with Re (Norberg 2003: 0.11 at Re 3400, 0.32 at 6800, 0.44
# at 13500) and Roshko's St(Re)
level_step_db() {
    awk -v c1="$(norberg_lift_rms "$(speed_re "$1" "$3")")" \
        -v c2="$(norberg_lift_rms "$(speed_re "$2" "$3")")" \
        -v r1="$(speed_re "$1" "$3")" -v r2="$(speed_re "$2" "$3")" \
        -v u1="$1" -v u2="$2" \
        'BEGIN { s1 = 1 - 19.7 / r1; s2 = 1 - 19.7 / r2
                 printf "%.2f", 20 * log((u2 / u1)^3 * c2 * s2 / (c1 * s1)) / log(10) }'
}
