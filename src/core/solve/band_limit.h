/* aero: the band limit of a looped texture at what its 2D grid resolves.
 *
 * The flow solver (flow2d.h) advects with third-order upwind-biased
 * faces: d/dx as (q[i-2] - 6 q[i-1] + 3 q[i] + 2 q[i+1]) / (6 h). Its
 * modified wavenumber (Fourier analysis of the scheme: Vichnevetsky and
 * Bowles 1982; Lele 1992), on a wave N cells long (theta = 2 pi / N):
 * k' h = (8 sin theta - sin 2 theta) / 6 carried, (1 - cos theta)^2 / 3
 * damped. At N = 16 the wave travels 0.08 % slow and keeps 97 % of its
 * amplitude over each wavelength travelled: carried as the flow carries
 * it. At N = 8 it travels 1.2 % slow and keeps only 80 % per wavelength
 * (41 % over the sword's chord of 32 cells); at N = 4 it travels 15 %
 * slow, its energy at a third of the speed (the group velocity; Trefethen
 * 1982), and keeps 26 %; at 3.5 cells the group velocity turns back.
 * So content shorter than 16 cells is carried ever less faithfully and
 * below 8 cells it is more the grid's than the flow's. A structure of
 * length lambda carried past the body at the flow speed v0 forces it at
 * f = v0 / lambda, so the band of the force history the grid resolves
 * ends between v0 / (16 h) and v0 / (8 h), h the cell. (Cut at
 * v0 / (8 h) to v0 / (4 h) instead, the sword's stalled drags kept bursts
 * once per shedding cycle below 1 kHz that clicked when whirled:
 * textures/README.md.)
 * aero_band_limit_apply passes everything below f_pass untouched, nothing
 * from f_stop up, and a raised cosine between (one octave when f_stop =
 * 2 f_pass): a zero-phase gain over the loop taken as periodic, so the
 * loop stays seamless, a step is smoothed symmetrically (a short,
 * fast-decaying response, no ringing at the cut-off) and no tone moves in
 * phase.
 *
 * No globals; allocates its own FFT buffers (FFTW, double). */
#ifndef AERO_BAND_LIMIT_H
#define AERO_BAND_LIMIT_H

#include <math.h>

#include "aero_air.h"

/* cells per wavelength at the ends of the roll-off (above) */
#define AERO_BAND_LIMIT_CELLS_PASS 16.0
#define AERO_BAND_LIMIT_CELLS_STOP 8.0

/* the roll-off's ends (Hz) for flow speed v0 (m/s) on cells of h (m) */
void aero_band_limit_grid(double v0, double h, double *f_pass,
                          double *f_stop);

/* the gain at f (Hz): 1 up to f_pass, 0 from f_stop, a raised cosine
   between (inline: the players weigh a blade's noise by it without the
   FFT code, blade_noise.h) */
static inline double aero_band_limit_gain(double f, double f_pass,
                                          double f_stop)
{
    if (f <= f_pass)
        return 1.0;
    if (f >= f_stop)
        return 0.0;
    return 0.5 + 0.5 * cos(AERO_PI * (f - f_pass) / (f_stop - f_pass));
}

/* x[k * stride], k < n (one loop of a texture channel at rate Hz), band
   limited in place; 0 < f_pass < f_stop. 0, or -1 (bad arguments or out
   of memory: x unchanged). f_pass at or above rate / 2 leaves x as it
   is. */
int aero_band_limit_apply(float *x, int n, int stride, double rate,
                          double f_pass, double f_stop);

#endif
