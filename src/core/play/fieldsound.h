/* aero: field auralization, the real-time half: the retarded-time sum of
 * the sources field_prepare.h found, heard by a moving listener (Shin and
 * Bajaj; the method and where it departs from the paper: field_prepare.h). */
#ifndef AERO_FIELDSOUND_H
#define AERO_FIELDSOUND_H

#include "aero_ears.h"
#include "aero_ranges.h"
#include "field_prepare.h"

#include <stdint.h>

/* --- rendering ----------------------------------------------------------- */
#define AERO_FIELD_CHUNK 64
#define AERO_FIELD_SPEED_MAX 1e6 /* playback, frames per second */
/* the slowest playback: a frame in 1000 s; slower ones (1e-30) would never
   finish */
#define AERO_FIELD_SPEED_MIN 1e-3

typedef struct aero_fieldsound {
    const aero_field_sources *src; /* not owned */
    double sample_rate;
    double speed, speed_target;    /* playback, frames per second */
    double phase;                  /* playhead, data frames */
    int playing;
    double envelope;               /* 0..1, fades on stop */
    double listener[3], target[3];
    double ramp_ms, ramp_left;     /* samples left of the listener ramp */
    double gain;                   /* linear */
    float *dist;                   /* per source, at the last chunk end */
    int dist_valid;
    int direct;                    /* per-sample reference sum */
    int clamped;                   /* listener faster than Mach 0.3 */
    double acc[5 * (AERO_FIELD_CHUNK + 1)];
    aero_near near; /* a listener came within min_distance of a source */
} aero_fieldsound;

/* Defaults: listener at (0, 0, 0) ... set it; speed = the data's rate
 * once sources are set; ramp and gain from aero_ranges.h; stopped.
 * n_ears: 1 (one listener; [fieldsound~] is mono); seed: the contract's,
 * unused (nothing is random). 0, or -1 when the sample rate is not usable
 * (AERO_SAMPLE_RATE_FALLBACK is taken) or n_ears is not 1 (one listener
 * is taken): the player is usable either way. */
int aero_fieldsound_init(aero_fieldsound *r, double sample_rate, int n_ears,
                         uint32_t seed);
void aero_fieldsound_free(aero_fieldsound *r);
/* new sources (NULL: silence); 0, or -1 when out of memory. Stops. */
int aero_fieldsound_set_sources(aero_fieldsound *r,
                                const aero_field_sources *s);
int aero_fieldsound_set_sample_rate(aero_fieldsound *r, double sr);
int aero_fieldsound_set_speed(aero_fieldsound *r, double fps);
/* one listener (mono: e->n must be 1), reached over the ramp time */
int aero_fieldsound_set_ears(aero_fieldsound *r, const aero_ears *e);
/* the same, there at once (offline paths start here) */
int aero_fieldsound_place_ears(aero_fieldsound *r, const aero_ears *e);
/* what a host reads: a volume to play, the listener clamped at Mach 0.3,
   where the listener is going */
static inline int aero_fieldsound_has_sources(const aero_fieldsound *r)
{
    return r->src != 0;
}
static inline int aero_fieldsound_clamped(const aero_fieldsound *r)
{
    return r->clamped;
}
static inline const double *aero_fieldsound_target(
                                                   const aero_fieldsound *r)
{
    return r->target;
}
int aero_fieldsound_set_ramp_ms(aero_fieldsound *r, double ms);
int aero_fieldsound_set_gain_db(aero_fieldsound *r, double db);
void aero_fieldsound_play(aero_fieldsound *r);
void aero_fieldsound_stop(aero_fieldsound *r);
/* n samples of pressure (Pa) into out. Returns 1 while playing. */
int aero_fieldsound_process(aero_fieldsound *r, float *out, int n);
/* seconds until every source has been heard, from play, at the current
 * speed, for a listener at most `distance` m from the origin */
double aero_fieldsound_length(const aero_field_sources *s, double speed,
                              double distance);

#endif
