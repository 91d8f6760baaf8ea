/* aero: the top of a blade's sound, above what its texture's grid
 * resolves: turbulent boundary-layer trailing-edge noise from the
 * airfoil self-noise model (Brooks et al. 1989; airfoil_noise.h), as
 * band-filtered noise for each point source of [aeolian~]'s texture mode.
 *
 * A URANS texture holds nothing above v0 / (8 h) (band_limit.h): a raised
 * cosine G(f) passes its content below f_pass and none from f_stop, both
 * scaled by the speed it is played at. The model's band is the power
 * complement, weighted by 1 - G(f)^2 at the same frequencies: the two are
 * independent signals, so their powers add, and the sum crossfades from
 * the simulation to the model over the same octave with neither counted
 * twice. Each source's noise is white noise through a bank of one-third-
 * octave band-pass filters (the standard centres, shared coefficients),
 * each driven by noise of its own (xorshift) with the gain that gives
 * its band the model's power for the
 * source's speed, angle of attack and span; the gains glide over each
 * chunk and are computed again when the speed moves by 1 % or the angle
 * by half a degree. The noise is in the texture's units, dF/dt (N/s):
 * heard through the same Curle projection, delay and Doppler as the
 * source's texture, it gives the model's level broadside at 1 m.
 * No allocation after init, no globals; seeded. */
#ifndef AERO_BLADE_NOISE_H
#define AERO_BLADE_NOISE_H

#include <stdint.h>

#include "airfoil_noise.h"

/* the bank: standard third-octave bands from 200 Hz to 20 kHz (at most) */
#define AERO_BLADE_BANDS_MAX 21
#define AERO_BLADE_LOWEST_HZ 200.0

typedef struct {
    aero_airfoil section; /* chord, TE, boundary layer (span per source) */
    double v0;            /* the texture's base speed, m/s */
    double f_pass, f_stop; /* its band limit at v0, Hz (texture frequency) */
    double sample_rate;
    int n_bands;
    double hz[AERO_BLADE_BANDS_MAX];
    float b0[AERO_BLADE_BANDS_MAX], a1[AERO_BLADE_BANDS_MAX],
        a2[AERO_BLADE_BANDS_MAX];
    /* leak[k][j]: power in band k of band j's filter output for white
       noise of unit variance (a filter of the bank spreads a third of its
       power into its neighbours; the gains are solved for it) */
    double leak[AERO_BLADE_BANDS_MAX][AERO_BLADE_BANDS_MAX];
    /* the arrival ring's mean power loss in each band, made up (.c) */
    double ring_loss[AERO_BLADE_BANDS_MAX];
} aero_blade_noise;

typedef struct {
    float gain[AERO_BLADE_BANDS_MAX];   /* each band's gain now */
    float target[AERO_BLADE_BANDS_MAX]; /* and at the chunk's end */
    /* each band's noise, one and two samples back, and its two sections'
       outputs (the first's are the second's inputs) */
    float x1[AERO_BLADE_BANDS_MAX], x2[AERO_BLADE_BANDS_MAX];
    float y1[AERO_BLADE_BANDS_MAX], y2[AERO_BLADE_BANDS_MAX];
    float z1[AERO_BLADE_BANDS_MAX], z2[AERO_BLADE_BANDS_MAX];
    uint32_t rng[AERO_BLADE_BANDS_MAX]; /* each band's noise generator */
    double law_speed, law_alpha, law_span, law_scale; /* targets made for */
    int lo, hi; /* bands [lo, hi) run */
} aero_blade_voice;

/* the section (span ignored), the texture's v0 and band limit (f_pass <
   f_stop, Hz at v0) and the sample rate: 0, or -1 (bad values) */
int aero_blade_noise_init(aero_blade_noise *b, const aero_airfoil *section,
                          double v0, double f_pass, double f_stop,
                          double sample_rate);
/* a new sample rate: 0, or -1 (refused, the old one kept) */
int aero_blade_noise_set_rate(aero_blade_noise *b, double sample_rate);

/* silent, its filters at rest, its noise from seed (0 taken as 1) */
void aero_blade_voice_reset(aero_blade_voice *v, uint32_t seed);

/* the gains the next chunk glides to: the model's spectrum for a source
   of span `span` (m) at `speed` (m/s, normal to the blade) and angle of
   attack alpha_deg, whose texture is heard `scale` times its own
   frequency (the band limit moves with it); chord and trailing edge are
   the section's times `size` (the player's diameter over the texture's) */
void aero_blade_voice_target(const aero_blade_noise *b, aero_blade_voice *v,
                             double speed, double alpha_deg, double span,
                             double scale, double size);

/* what those targets aim at: the model's power in each band of the bank
   (b->hz), in (N/s)^2, after the band limit's complement (0 where the
   texture holds the band) */
void aero_blade_noise_band_powers(const aero_blade_noise *b, double speed,
                                  double alpha_deg, double span,
                                  double scale, double size, double *p);

/* m samples of the voice's noise (dF/dt, N/s) into out, the gains gliding
   to their targets */
void aero_blade_voice_render(const aero_blade_noise *b, aero_blade_voice *v,
                             float *out, int m);

#endif
