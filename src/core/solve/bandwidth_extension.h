/* aero: spectral bandwidth extension of a looped sound texture above the
 * band a simulation resolves (after Chadwick and James 2011: their
 * physically based fire sound stops at the simulation's low band and is
 * extended upwards by noise whose spectrum continues the band's and whose
 * envelope follows it).
 *
 * The physical band is left as it is: below f1 (where the simulation's
 * own taper starts) not one bin changes. Over the loop (n frames, taken
 * as periodic, so the loop stays seamless):
 *  1. the power spectrum's law |X(f)|^2 = A f^s is fitted (least squares
 *     in log-log over third-octave bands) on [f1 / 4, f1], the top two
 *     octaves of the resolved band;
 *  2. the envelope e(t) of that band (the magnitude of its analytic
 *     signal, low-passed below f1 / 4, mean square 1) carries the
 *     flow's bursts up;
 *  3. white noise times e(t), shaped in frequency to A f^s times a
 *     weight g(f) that is 0 below f1, 1 - T(f)^2 between f1 and f2 (T the
 *     simulation's raised-cosine taper, so the sum keeps the law's level
 *     across the cross-over) and 1 above, to 0 over [f_top, 1.1 f_top],
 *     is added.
 * Nothing is added when the fitted slope is not falling (s >= 0): a
 * spectrum that still rises at f1 has no law to continue.
 *
 * No globals; allocates its own FFT buffers (FFTW, double). */
#ifndef AERO_BANDWIDTH_EXTENSION_H
#define AERO_BANDWIDTH_EXTENSION_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    double slope;        /* fitted s of |X|^2 ~ f^s */
    double fit_lo, fit_hi; /* Hz */
    int extended;        /* 0: left alone (rising spectrum or no room) */
} aero_bandext_info;

/* x[k * stride], k < n, at rate Hz, in place; f1 < f2 <= f_top < rate/2.
   0, or -1 (bad arguments or out of memory: x unchanged). */
int aero_bandext_apply(float *x, int n, int stride, double rate, double f1,
                       double f2, double f_top, uint32_t seed,
                       aero_bandext_info *info);

#endif
