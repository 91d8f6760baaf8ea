/* fuzz: the blade table parser (src/core/play/rotor.c, the .blade files of
 * [rotor~]'s `blade`). Invariants of a table that loaded: 2 to
 * AERO_ROTOR_BLADE_ROWS_MAX rows, r/R rising strictly within 0..1, every
 * chord within AERO_ROTOR_CHORD_MIN..MAX and every twist within
 * AERO_ROTOR_TWIST_MAX (what rotor.h promises); a refusal says why. A
 * table that loaded is then given to a turbine's core and rendered for a
 * few blocks: the output stays finite.
 * Seeds: abstractions/turbine.blade and propeller.blade. */
/* aero-fuzz: seeds abstractions/?*.blade */
#include "fuzz.h"

#include "rotor.h"

#define N 256

static void render(const aero_rotor_blade *b)
{
    static float out[N], rpm[N];
    float *outs[1] = {out};
    aero_rotor r;
    if (aero_rotor_init(&r, 22050.0, 1, 1u))
        return;
    aero_rotor_set_blades(&r, 3);
    aero_rotor_set_radius(&r, 47.0);
    aero_rotor_set_thrust(&r, 3e5);
    aero_rotor_set_torque(&r, 1.4e6);
    aero_rotor_set_design(&r, 16.0);
    aero_rotor_set_wind(&r, (const double[3]){0.0, 0.0, 8.0});
    aero_ears e = aero_ears_at(0.0, 200.0, -98.0);
    aero_rotor_set_ears(&r, &e);
    FUZZ_REQUIRE(aero_rotor_set_blade(&r, b) == 0,
                 "a loaded table refused by the core");
    for (int i = 0; i < N; i++)
        rpm[i] = 16.0f;
    for (int k = 0; k < 8; k++) {
        aero_rotor_process(&r, rpm, outs, N);
        FUZZ_REQUIRE(fuzz_finite(out, N), "rotor: non-finite output");
    }
    aero_rotor_free(&r);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[64], err[256];
    aero_rotor_blade b;
    int fd = fuzz_file(data, size, path, sizeof(path));
    if (fd < 0)
        return 0;
    int rc = aero_rotor_blade_load(path, &b, err, sizeof(err));
    fuzz_file_close(fd);
    if (rc) {
        FUZZ_REQUIRE(err[0] != 0, "refused without a message");
        return 0;
    }
    FUZZ_REQUIRE(b.n >= 2 && b.n <= AERO_ROTOR_BLADE_ROWS_MAX, "%d rows",
                 b.n);
    for (int i = 0; i < b.n; i++) {
        FUZZ_REQUIRE(b.r[i] >= 0.0 && b.r[i] <= 1.0 &&
                         (i == 0 || b.r[i] > b.r[i - 1]),
                     "row %d: r/R %g", i, b.r[i]);
        FUZZ_REQUIRE(b.chord[i] >= AERO_ROTOR_CHORD_MIN &&
                         b.chord[i] <= AERO_ROTOR_CHORD_MAX,
                     "row %d: chord %g", i, b.chord[i]);
        FUZZ_REQUIRE(fabs(b.twist[i]) <= AERO_ROTOR_TWIST_MAX,
                     "row %d: twist %g", i, b.twist[i]);
    }
    render(&b);
    return 0;
}
