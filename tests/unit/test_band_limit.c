/* aero: tests of the band limit of a looped texture at what its grid
 * resolves (src/core/solve/band_limit.c): below the pass band nothing
 * changes, above the stop band nothing is left, between them the raised
 * cosine; zero phase (a symmetric pulse stays symmetric about its
 * centre); cyclic (filtering commutes with rotating the loop, so the loop
 * stays seamless); the grid's ends; bad arguments refused. */
#include "unit.h"
#include "aero_air.h"
#include "band_limit.h"

#include <stdlib.h>
#include <string.h>

#define RATE 16000.0
#define N 1676 /* not a power of two, as a texture's loop */

/* a sine of whole cycles over the loop, k cycles: f = k RATE / N */
static double tone(int k, int t, double phase)
{
    return sin(2.0 * AERO_PI * k * t / N + phase);
}

UNIT_TEST(passes_stops_rolls_off)
{
    /* pass 1 kHz, stop 2 kHz: cycles 52 (496 Hz), 157 (1499 Hz, the
       roll-off's middle: gain 0.5), 262 (2502 Hz) */
    const int ch = 3;
    float *x = malloc(sizeof(float) * N * ch);
    double e_lo = 0, e_mid = 0, g = 0;
    for (int t = 0; t < N; t++)
        for (int c = 0; c < ch; c++)
            x[t * ch + c] = (float)(c == 1 ? tone(52, t, 0.3) +
                                                 tone(157, t, 1.1) +
                                                 tone(262, t, 2.0)
                                           : 0.25 * c);
    UNIT_CHECK(aero_band_limit_apply(x + 1, N, ch, RATE, 1000.0, 2000.0) == 0,
               "applied");
    g = aero_band_limit_gain(157 * RATE / N, 1000.0, 2000.0);
    for (int t = 0; t < N; t++) {
        double y = x[t * ch + 1];
        double lo = tone(52, t, 0.3), mid = g * tone(157, t, 1.1);
        e_lo += (y - lo - mid) * (y - lo - mid);
        e_mid += y * y;
    }
    UNIT_CHECK(sqrt(e_lo / N) < 1e-5,
               "496 Hz kept, 1499 Hz at the raised cosine's %.3f, 2502 Hz "
               "gone: residual rms %.2g", g, sqrt(e_lo / N));
    UNIT_CHECK(fabs(g - 0.5) < 0.01, "the roll-off's middle at half: %.3f", g);
    UNIT_CHECK(fabs(sqrt(e_mid / N) - sqrt(0.5 + 0.5 * g * g)) < 1e-4,
               "rms %.4f", sqrt(e_mid / N));
    {
        int others = 1;
        for (int t = 0; t < N; t++)
            if (x[t * ch] != 0.0f || x[t * ch + 2] != 0.5f) others = 0;
        UNIT_CHECK(others, "the other channels untouched");
    }
    free(x);
}

UNIT_TEST(zero_phase_and_cyclic)
{
    float *a = malloc(sizeof(float) * N), *b = malloc(sizeof(float) * N);
    const int c = 400, shift = 1000;
    double asym = 0.0, diff = 0.0, peak = 0.0;
    int at = 0;
    /* a force step up and back down (a burst of the grid) at c +- 3 */
    for (int t = 0; t < N; t++)
        a[t] = (t >= c - 3 && t <= c + 3) ? 1.0f : 0.0f;
    for (int t = 0; t < N; t++)
        b[t] = a[(t + N - shift) % N];
    aero_band_limit_apply(a, N, 1, RATE, 1000.0, 2000.0);
    aero_band_limit_apply(b, N, 1, RATE, 1000.0, 2000.0);
    for (int t = 0; t < N; t++) {
        if (fabs(a[t]) > peak) { peak = fabs(a[t]); at = t; }
        diff = fmax(diff, fabs(b[(t + shift) % N] - a[t]));
    }
    for (int d = 1; d < 200; d++)
        asym = fmax(asym, fabs(a[c + d] - a[c - d]));
    UNIT_CHECK(at == c && asym < 1e-5,
               "zero phase: the pulse's peak stays at %d (%d), symmetric "
               "within %.2g", c, at, asym);
    UNIT_CHECK(diff < 1e-5, "cyclic: the rotated loop filters to the "
               "rotated result within %.2g", diff);
    {
        /* the response decays: 2 ms (32 frames) away under 1 % of the
           peak, so a burst is not spread into a ring */
        double tail = 0.0;
        for (int d = 32; d < N / 2; d++)
            tail = fmax(tail, fabs(a[(c + d) % N]));
        UNIT_CHECK(tail < 0.01 * peak, "2 ms out: %.2g of the peak",
                   tail / peak);
    }
    free(a);
    free(b);
}

UNIT_TEST(grid_and_bad_arguments)
{
    double fp, fs;
    float x[64] = {1.0f};
    aero_band_limit_grid(10.0, 0.04 / 32.0, &fp, &fs);
    UNIT_CHECK(fabs(fp - 500.0) < 1e-9 && fabs(fs - 1000.0) < 1e-9,
               "the sword's grid (1.25 mm cells, 10 m/s): %g-%g Hz", fp, fs);
    UNIT_CHECK(aero_band_limit_apply(x, 64, 1, RATE, 2000.0, 1000.0) == -1 &&
                   aero_band_limit_apply(x, 64, 0, RATE, 1000.0, 2000.0) ==
                       -1 &&
                   aero_band_limit_apply(x, 64, 1, RATE, NAN, 2000.0) == -1 &&
                   aero_band_limit_apply(x, 64, 1, RATE, 1000.0, INFINITY) ==
                       -1 &&
                   x[0] == 1.0f,
               "bad bands refused, x unchanged");
    UNIT_CHECK(aero_band_limit_apply(x, 64, 1, RATE, 9000.0, 18000.0) == 0 &&
                   x[0] == 1.0f,
               "a pass band above Nyquist leaves x as it is");
}

UNIT_MAIN(UNIT_CASE(passes_stops_rolls_off), UNIT_CASE(zero_phase_and_cyclic),
          UNIT_CASE(grid_and_bad_arguments))
