/* aero: what the files of [aeolian~]'s core share (aeolian.c, the object;
 * aeolian_model.c and aeolian_texture.c, its two modes). Not for hosts:
 * they use aeolian.h. */
#ifndef AERO_AEOLIAN_INTERNAL_H
#define AERO_AEOLIAN_INTERNAL_H

#include "aeolian.h"
#include "arrivals.h"
#include "blade_noise.h"
#include "ghost_fade.h"
#include "pose_glide.h"

/* --- model mode (aeolian_model.c) ------------------------------------------ */

/* the model's generator and oscillator from the object's seed */
void aero_aeolian_model_seed(aero_aeolian *a);
/* the settings' values glide to their (new) targets over the ramp time;
 * before the first block they are taken at once */
void aero_aeolian_model_retarget(aero_aeolian *a);
/* a new sample rate: the coefficients are taken again at once */
void aero_aeolian_model_unprime(aero_aeolian *a);
int aero_aeolian_model_process(aero_aeolian *a, const float *speed,
                               float *const *out, int n);
double aero_aeolian_model_tone_hz(const aero_aeolian *a, double speed);

/* --- texture mode (aeolian_texture.c) -------------------------------------- */

/* a setting gliding to the object's target in whole texture chunks (the
   glide of aero_ramp.h, its target read from the object) */
typedef struct {
    double value;
    double left; /* samples of the glide to go, whole chunks */
} aero_aeolian_glide;

typedef struct {
    double pos;          /* texture coordinate, frames */
    double inc;          /* frames per sample at the last chunk's end */
    double angle;        /* flow angle in the body frame at that end, deg */
    double amp;          /* amplitude factor at that end */
    double namp;         /* its blade noise's gain at that end */
    double fx[AERO_AEOLIAN_MAX_EARS], fy[AERO_AEOLIAN_MAX_EARS]; /* Curle, 1/m */
    double delay[AERO_AEOLIAN_MAX_EARS]; /* samples */
    double step[AERO_AEOLIAN_MAX_EARS];  /* arrival step over that chunk */
    double sign;         /* side of the mirror fold (-1: mirrored) */
    uint32_t rng;        /* its phase wander's generator */
    double wander_from;  /* phase rate offset at the last draw, and */
    double wander;       /* the one it glides to by the next, frames per
                            sample */
    int wander_left;     /* samples until the next draw */
    double law_speed, law_diameter, law_pitch, law_level; /* Re law cache */
    int primed;
    aero_ghost fade; /* as a ghost (ghost_fade.h) */
} aero_aeolian_source;

struct aero_aeolian_texture {
    aero_arrivals arrivals; /* one ring per ear (arrivals.h) */
    double ring_rate;       /* the sample rate the rings were made for */
    uint32_t rng;
    int clamped;            /* a speed was clamped at Mach 0.3 */
    /* the gliding settings' values now */
    aero_aeolian_glide wind[3], ear[3 * AERO_AEOLIAN_MAX_EARS], gain, roll;
    /* a source radiated in the last chunk: the ears' and the gain's
       changes glide; while nothing sounds they jump (aeolian_texture.c) */
    int sounding;

    /* the texture (owned) and what the player needs of it */
    aero_texture *texture;
    double v0, tex_diameter, tex_rate, st;
    /* a circle texture corrected to a 3D cylinder: its St and C_L' follow
       Re away from its own (aeolian_texture.c); tex_nu its viscosity */
    int re_law;
    double tex_nu, tex_strouhal, tex_lift_rms;
    double frames_per_cycle; /* texture frames per shedding period */
    double period;       /* symmetry period, deg (0: one direction) */
    int mirror;

    int n_sources;

    /* the ends' path through the poses (pose_glide.h) and the poses
       waiting for their sample in the next block */
    aero_pose_path path;
    aero_pose_queue queue;
    int pose_set;        /* a pose message has arrived */
    double pose_velocity[6]; /* of the pose stream, from its time stamps */
    double velocity[6];  /* smoothed velocity of both ends, m/s */
    double reference[3]; /* body x axis, kept normal to the stick axis */

    aero_aeolian_source src[AERO_AEOLIAN_SOURCES_MAX];

    /* a blade texture's top above its band limit (blade_noise.h): the
       bank and one voice per source, or NULL for any other texture */
    aero_blade_noise *blade;
    aero_blade_voice *voices; /* after *blade: one per source, then one per
                                 ghost (2 AERO_AEOLIAN_SOURCES_MAX) */
    /* the sources as they were when the stick jumped while sounding,
       fading where they were (aeolian_texture.c) */
    aero_aeolian_source ghost[AERO_AEOLIAN_SOURCES_MAX];
    int n_ghosts;
    double fade_in;      /* samples since the jump, as the ghosts fade */
    /* after a texture change while sounding: the ghosts' texture (owned)
       and what they read of it; they go on moving as they were */
    aero_texture *ghost_texture;
    double ghost_period, ghost_frames_per_cycle;
    int ghost_mirror, ghost_moving;
    /* and the old texture's noise bank, when it was a blade's (owned; NULL:
       the ghosts' noise is the bank above, or none) */
    aero_blade_noise *ghost_blade;
};

/* the texture mode's state, made from the object's settings when first
 * needed: 0, or -1 out of memory */
int aero_aeolian_texture_make(aero_aeolian *a);
void aero_aeolian_texture_free(aero_aeolian *a);
int aero_aeolian_texture_set(aero_aeolian *a, aero_texture *t, char *err,
                             size_t errlen);
/* -1 the rings cannot follow (the rate is refused), else 0 */
int aero_aeolian_texture_sample_rate(aero_aeolian *a, double sr);
void aero_aeolian_texture_seed(aero_aeolian *a);
/* texture mode's gliding settings after the object's targets, and its
   source count */
enum {
    AERO_AEO_WIND = AERO_AEO_COUNT, /* x y z */
    AERO_AEO_ROLL = AERO_AEO_WIND + 3,
    AERO_AEO_SOURCES
};
/* gliding setting k (AERO_AEO_GAIN, _EAR + i, _WIND + i, _ROLL) changed:
   its glide starts (the ears and the gain: at once while nothing sounds) */
void aero_aeolian_texture_retarget(aero_aeolian *a, int k);
/* k (AERO_AEO_DIAMETER, _LENGTH, _SOURCES) changed: the source count and
   the default pose follow */
void aero_aeolian_texture_resize(aero_aeolian *a, int k);
int aero_aeolian_texture_pose(aero_aeolian *a, const double end_a[3],
                              const double end_b[3], double interval_s);
int aero_aeolian_texture_reference(aero_aeolian *a, const double x[3]);
/* the queued poses applied now, in order */
void aero_aeolian_texture_flush(aero_aeolian *a);
/* as _pose (and _reference when axis is not NULL), at sample `offset` of
   the next process call */
int aero_aeolian_texture_pose_at(aero_aeolian *a, const double end_a[3],
                                 const double end_b[3], const double *axis,
                                 double interval_s, int offset);
int aero_aeolian_texture_process(aero_aeolian *a, const float *speed,
                                 float *const *out, int n);
double aero_aeolian_texture_tone_hz(const aero_aeolian *a, double v);

#endif
