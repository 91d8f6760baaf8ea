/* aero: what the players of moving bodies share: sample rate and arrival
 * rings, ears, wind, gain, ramp time, amplitude exponent, and the setters
 * that validate them. body.c embeds one (`base`) and keeps its own
 * pose, texture and sources; [aeolian~]'s object holds these settings
 * itself and takes the ranges. No globals. */
#ifndef AERO_MOVING_PLAYER_H
#define AERO_MOVING_PLAYER_H

#include <stdint.h>

#include "aero_air.h"
#include "aero_ears.h"
#include "aero_ramp.h"
#include "aero_ranges.h"
#include "aero_util.h"
#include "arrivals.h"

/* ranges of the shared settings (gain and ramp: aero_ranges.h) */
#define AERO_MOVING_SR_MIN 1000.0
#define AERO_MOVING_SR_MAX 1536000.0
#define AERO_MOVING_EXPONENT_MIN 0.0
#define AERO_MOVING_EXPONENT_MAX 12.0
#define AERO_MOVING_EXPONENT_DEFAULT 3.0 /* pressure ~ U^3 */
/* the wind's speed (the length of its vector) accepted, m/s: up to ten
   times the Mach 0.3 clamp */
#define AERO_MOVING_WIND_MIN 0.0
#define AERO_MOVING_WIND_MAX (AERO_MACH_LIMIT * AERO_C0 * 10.0)

typedef struct {
    double sample_rate;
    int n_ears;
    int chunk;             /* samples per geometry update */
    double max_delay_s;    /* sound travel time the rings hold */
    uint32_t rng;
    double exponent;       /* amplitude ~ (v/v0)^exponent */
    double ramp_samples;
    aero_ramp wind[3];
    aero_ramp ear[3 * AERO_EARS_MAX];
    aero_ramp gain;        /* linear */
    aero_arrivals arrivals; /* one ring per ear (arrivals.h) */
    int clamped;           /* a speed was clamped at Mach 0.3 */
    aero_near near;        /* a listener came within the near-field limit
                              (aero_near_field) */
    int sounding;          /* a source radiated in the player's last chunk
                              (the player sets it): the ears and the gain
                              glide; while nothing sounds they jump */
} aero_moving_player;

/* Defaults: still air, one listener 1 m away along +y (stereo: ears at
 * x = -+AERO_EAR_HALF_SPACING), exponent AERO_MOVING_EXPONENT_DEFAULT,
 * gain and ramp from aero_ranges.h; n_ears is kept within 1..2.
 * sample_rate is taken as given (the player checks it). 0, or -1 when the
 * rings cannot be allocated. */
int aero_moving_player_init(aero_moving_player *p, double sample_rate,
                            int n_ears, uint32_t seed, int chunk,
                            double max_delay_s);
void aero_moving_player_free(aero_moving_player *p);
/* a player whose rings could not be allocated (init, or a sample rate,
 * ran out of memory) is silent: 1 with its n_ears outputs zeroed, else 0
 * (its process goes on) */
static inline int aero_moving_player_silent(const aero_moving_player *p,
                                            float *const *out, int n)
{
    if (p->arrivals.ring[0])
        return 0;
    for (int e = 0; e < p->n_ears; e++)
        for (int i = 0; i < n; i++)
            out[e][i] = 0.0f;
    return 1;
}

/* -1 invalid or out of memory (nothing changes), 0 unchanged, 1 changed:
 * the rings are new, the player re-primes its sources */
int aero_moving_player_set_sample_rate(aero_moving_player *p, double sr);
/* 0 accepted, -1 invalid (the previous value stays). The ears and the
 * gain glide over the ramp time while the player sounds, and are there at
 * once while it is silent. */
int aero_moving_player_set_exponent(aero_moving_player *p, double e);
int aero_moving_player_set_gain_db(aero_moving_player *p, double db);
int aero_moving_player_set_ramp_ms(aero_moving_player *p, double ms);
int aero_moving_player_set_wind(aero_moving_player *p, const double w[3]);
int aero_moving_player_set_ears(aero_moving_player *p, const aero_ears *e);

/* a control ramp to v over the ramp time, in whole chunks */
void aero_moving_player_ramp(const aero_moving_player *p, aero_ramp *r,
                             double v);

#endif
