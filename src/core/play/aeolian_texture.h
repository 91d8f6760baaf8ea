/* aero: a moving stick played from a sound texture (Dobashi et al. 2003,
 * real-time part), with pressure ~ U^3 and 1/r (Curle 1955).
 *
 * The stick runs from end A to end B, diameter d, and carries n point
 * sources at the centres of n equal segments (spacing ~ the spanwise
 * correlation length 3 d unless n is given). Per source, per control chunk
 * (AERO_STICK_CHUNK samples, values interpolated per sample in between):
 *   - its velocity from the interpolated pose, the air's velocity relative
 *     to it (wind - body), the component normal to the axis (property 3 of
 *     the paper: an inclined stick sees v cos(phi)) and that component's
 *     direction in the body's cross-section;
 *   - the texture direction pair around that angle (symmetry and mirror
 *     folding as textures/README.md describes) and its weights;
 *   - the texture coordinate advancing by (v/v0)(d_tex/d) per unit of time
 *     (eq. 3 of the paper: frequency St v / d), the amplitude
 *     (v/v0)^exponent (3 by default: pressure, not the paper's intensity
 *     law 6) times the segment length (g is per unit span);
 *   - Curle's far field p = (q - o).g / (4 pi c0 r^2) per ear, emitted at
 *     the source's position and heard r/c0 later: every source adds its
 *     sample into one delay ring per ear at the fractional arrival time, so
 *     Doppler (exact for any source motion) and interaural delay come for
 *     free and n sources cost one ring per ear, not one delay line each.
 * Each source starts at its own texture offset and its phase wanders (a
 * random walk, stick_texture.c), so their powers add, as model mode's
 * segments do.
 *
 * Life cycle: init (allocates the rings), set_texture (takes ownership),
 * set_*, process (any block size), free. No globals. */
#ifndef AERO_STICK_TEXTURE_H
#define AERO_STICK_TEXTURE_H

#include <stddef.h>
#include <stdint.h>

#include "moving_player.h"
#include "texture.h"

#define AERO_STICK_MAX_EARS AERO_EARS_MAX
#define AERO_STICK_MAX_SOURCES 256
#define AERO_STICK_CHUNK 32          /* samples per geometry update */
#define AERO_STICK_MAX_DELAY_S 1.0   /* sound travel time kept: 343 m */

typedef struct {
    double pos;          /* texture coordinate, frames */
    double inc;          /* frames per sample at the last chunk's end */
    double angle;        /* flow angle in the body frame at that end, deg */
    double amp;          /* amplitude factor at that end */
    double fx[AERO_STICK_MAX_EARS], fy[AERO_STICK_MAX_EARS]; /* Curle, 1/m */
    double delay[AERO_STICK_MAX_EARS]; /* samples */
    double sign;         /* side of the mirror fold (-1: mirrored) */
    uint32_t rng;        /* its phase wander's generator */
    double wander;       /* phase rate now, frames per sample */
    int wander_left;     /* samples until the next draw */
    double law_speed, law_diameter, law_pitch, law_level; /* Re law cache */
    int primed;
} aero_stick_source;

typedef struct aero_stick_texture {
    /* sample rate, rings, ears, wind, gain, ramp, exponent, clamp */
    aero_moving_player base;

    /* the texture (owned) and what the player needs of it */
    aero_texture *texture;
    double v0, tex_diameter, tex_rate, st;
    /* a circle texture corrected to a 3D cylinder: its St and C_L' follow
       Re away from its own (stick_texture.c); tex_nu its viscosity */
    int re_law;
    double tex_nu, tex_strouhal, tex_lift_rms;
    double frames_per_cycle; /* texture frames per shedding period */
    double phase_wander_width; /* relative line width of the wander */
    double period;       /* symmetry period, deg (0: one direction) */
    int mirror;

    /* object */
    double diameter;     /* 0: the texture's */
    double length;       /* of the default pose */
    int sources_wanted;  /* 0: length / (3 d) */
    int n_sources;

    /* pose: from -> to over `pose_duration` samples */
    double pose[6], pose_from[6], pose_to[6];
    double pose_elapsed, pose_duration;
    int pose_set;        /* a pose message has arrived */
    double pose_velocity[6]; /* of the pose stream, from its time stamps */
    double velocity[6];  /* smoothed velocity of both ends, m/s */
    double reference[3]; /* body x axis, kept normal to the stick axis */
    aero_ramp roll;      /* deg, about the axis */

    aero_stick_source src[AERO_STICK_MAX_SOURCES];
} aero_stick_texture;

/* 0, or -1 when out of memory. Defaults: no texture (silent), a stick of
 * length 0.5 m along z centred at the origin, still air, one listener 1 m
 * away along +y, exponent 3, gain 0 dB, ramp 20 ms. */
int aero_stick_texture_init(aero_stick_texture *s, double sample_rate,
                            int n_ears, uint32_t seed);
void aero_stick_texture_free(aero_stick_texture *s);

/* Takes ownership of a loaded texture of kind aeolian (NULL removes it):
 * 0, or -1 with a message in err (then the texture is NOT taken). */
int aero_stick_texture_set_texture(aero_stick_texture *s, aero_texture *t,
                                   char *err, size_t errlen);

/* Setters: 0 accepted, -1 invalid (the previous value stays). */
int aero_stick_texture_set_sample_rate(aero_stick_texture *s, double sr);
int aero_stick_texture_set_diameter(aero_stick_texture *s, double d);
int aero_stick_texture_set_length(aero_stick_texture *s, double l);
int aero_stick_texture_set_sources(aero_stick_texture *s, int n);
int aero_stick_texture_set_exponent(aero_stick_texture *s, double e);
int aero_stick_texture_set_gain_db(aero_stick_texture *s, double db);
int aero_stick_texture_set_ramp_ms(aero_stick_texture *s, double ms);
void aero_stick_texture_set_seed(aero_stick_texture *s, uint32_t seed);
/* full width at half maximum of each source's phase wander relative to f
 * (default 0.01, stick_texture.c; 0 freezes the phases, as unit tests of
 * exact pitch need); -1 outside 0..0.1, nothing changed */
int aero_stick_texture_set_phase_wander(aero_stick_texture *s, double width);
/* ends A and B; interval_s is the time since the previous pose: the motion
 * is interpolated over it (at least 1 ms). The first pose, a pose more than
 * 0.5 s after the previous one (a new gesture) and interval_s < 0 (a
 * placement) jump there without motion. */
int aero_stick_texture_set_pose(aero_stick_texture *s, const double a[3],
                                const double b[3], double interval_s);
/* the body's x axis (angle 0 of the texture's directions); projected onto
 * the plane normal to the stick and carried along as it turns */
int aero_stick_texture_set_reference(aero_stick_texture *s,
                                     const double x[3]);
int aero_stick_texture_set_roll_deg(aero_stick_texture *s, double deg);
int aero_stick_texture_set_wind(aero_stick_texture *s, const double w[3]);
/* ears 0..e->n-1 (e->n at most the ears the player was made with) */
int aero_stick_texture_set_ears(aero_stick_texture *s, const aero_ears *e);

/* n samples; speed[i] (may be NULL) adds a wind along +x; out[e][i] is the
 * sound pressure at ear e in Pa. Returns 1 if a speed was clamped. */
int aero_stick_texture_process(aero_stick_texture *s, const float *speed,
                               float *const *out, int n);

/* the tone St v / d this texture gives a stick normal to a flow v (Hz) */
double aero_stick_texture_tone_hz(const aero_stick_texture *s, double v);
/* the number of point sources now */
int aero_stick_texture_source_count(const aero_stick_texture *s);

#endif
