/* aero: a moving 3D body played from an object texture (Dobashi et al. 2003,
 * the 3D case: w(l, s, u) per region l; textures made by `aerotex object`).
 *
 * The body has a pose: a position P and an orientation (a unit quaternion
 * q, rotating body coordinates into the world). Region l is a point
 * source at P + R(q) (scale c_l), c_l its centre in body coordinates from
 * the texture. Per source, per control chunk (AERO_BODY_CHUNK samples,
 * values interpolated per sample in between):
 *   - its velocity (from the pose stream, rotation included), the air's
 *     velocity relative to it (wind - body), speed v and direction f;
 *   - the sample frame e1, e2, e3 of the texture (body_flow.h: the flow
 *     arrives at theta from e3 towards e1):
 *       symmetry=axis (bodies of revolution about body z; a mesh is
 *       treated so): e3 = the body axis R(q) z, theta = angle(f, e3),
 *       e1 = f's part normal to the axis, e2 = e3 x e1;
 *       symmetry=sphere: one sampled direction, theta = 90: e1 = f,
 *       e3 = the body axis made normal to f, e2 = e3 x e1 (a sphere's
 *       regions are sectors around the flow: they follow e1, e2, e3);
 *     mirror=1 (a body symmetric under z -> -z, sampled over 0..90 deg):
 *     theta > 90 reads 180 - theta with e2, e3 negated and the regions in
 *     reverse order;
 *   - the two sampled directions around theta and their weights;
 *   - the texture coordinate advancing by (v/v0)/scale per unit of time
 *     (frequency St v / d, d = scale d_tex), the amplitude
 *     (v/v0)^exponent times scale (dF/dt ~ rho U^3 d for a whole 3D body:
 *     pressure, not the paper's intensity law); a texture made by strip
 *     theory (method=strip, with the regions' diameters) also follows the
 *     circle's laws away from the Re it was made at, as [aeolian~]'s
 *     texture mode does: each region's rate times St(Re)/St(Re_tex) and
 *     its amplitude times that and C_L'(Re)/C_L'(Re_tex) (Roshko 1954,
 *     Norberg 2003), Re on the cross-flow speed v sin(theta);
 *   - Curle's far field p = (x - y).g / (4 pi c0 |x - y|^2), g =
 *     SUM_c g_c e_c, heard |x - y|/c0 later per ear through one delay ring
 *     per ear (exact Doppler of moving sources, interaural delay).
 * Each region starts at its own texture offset (they add incoherently, as
 * sources further apart than the correlation length do).
 *
 * Life cycle: init, set_texture (takes ownership), set_*, process (any
 * block size), free. No globals. */
#ifndef AERO_BODY_H
#define AERO_BODY_H

#include <stddef.h>
#include <stdint.h>

#include "ghost_fade.h"
#include "moving_player.h"
#include "pose_glide.h"
#include "texture.h"

#define AERO_BODY_MAX_EARS AERO_EARS_MAX
#define AERO_BODY_MAX_SOURCES 64
#define AERO_BODY_CHUNK 32
#define AERO_BODY_MAX_DELAY_S 1.0
/* the near-field limit (aero_near_field), times the texture's body size
   and the scale: the far field does not hold inside the body */
#define AERO_BODY_NEAR 0.25
#define AERO_BODY_SCALE_MIN 1e-3 /* of the texture's body */
#define AERO_BODY_SCALE_MAX 1e3
#define AERO_BODY_SCALE_DEFAULT 1.0

/* one source's geometry at a chunk's end */
typedef struct {
    double inc;                       /* texture frames per sample */
    double theta;                     /* folded flow angle, deg */
    double amp;
    double proj[AERO_BODY_MAX_EARS][3]; /* (x - y).e_c / (4 pi c0 r^2) */
    double delay[AERO_BODY_MAX_EARS];   /* samples */
    int flip;                         /* read the mirrored region */
} aero_body_geometry;

typedef struct {
    double pos;                 /* texture coordinate, frames */
    double velocity[3];         /* smoothed, m/s */
    double stream_velocity[3];  /* of the pose stream */
    aero_body_geometry then;    /* at the previous chunk's end */
    double step[AERO_BODY_MAX_EARS]; /* arrival step over that chunk */
    int primed;
    aero_ghost fade; /* as a ghost (ghost_fade.h) */
} aero_body_source;

typedef struct aero_body {
    /* sample rate, rings, ears, wind, gain, ramp, exponent, clamp */
    aero_moving_player base;

    aero_texture *texture;      /* owned */
    double v0, tex_size, tex_rate;
    int regions, sphere, mirror;
    double centre[3 * AERO_BODY_MAX_SOURCES]; /* body frame, m */
    /* a slender body made by strip theory (method=strip, strip_body.h):
       each region's diameter, and the air's viscosity it was made for */
    int re_law;
    double region_d[AERO_BODY_MAX_SOURCES], tex_nu;

    double scale;

    /* pose: position and quaternion (w, x, y, z) now (the path's,
       the quaternion normalised), its path through the poses
       (pose_glide.h) and the poses waiting for their sample */
    double pose[7];
    aero_pose_path path;
    aero_pose_queue queue;
    int pose_set;

    aero_body_source src[AERO_BODY_MAX_SOURCES];
    /* the sources as they were when the body jumped while sounding,
       fading where they were */
    aero_body_source ghost[AERO_BODY_MAX_SOURCES];
    int n_ghosts;
    double fade_in;             /* samples since the jump, as they fade */
    /* after a texture change while sounding: the ghosts' texture (owned)
       and its regions; they go on moving as they were */
    aero_texture *ghost_texture;
    int ghost_regions, ghost_moving;
} aero_body;

/* n_ears 1 (the listener) or 2 (the ears). 0, or -1 when out of memory
 * (silent then, until a sample rate is set) or the sample rate is not
 * usable (AERO_SAMPLE_RATE_FALLBACK is taken). Defaults: no texture
 * (silent), the body at the origin unturned, still air, one listener 1 m
 * away along +y (stereo:
 * ears at x = -+AERO_EAR_HALF_SPACING), scale AERO_BODY_SCALE_DEFAULT,
 * exponent, gain and ramp as moving_player.h's. */
int aero_body_init(aero_body *s, double sample_rate,
                   int n_ears, uint32_t seed);
void aero_body_free(aero_body *s);

/* Takes ownership of a loaded texture of kind object (NULL removes it):
 * 0, or -1 with a message in err (then the texture is NOT taken). */
int aero_body_set_texture(aero_body *s, aero_texture *t,
                          char *err, size_t errlen);

/* setters: 0 accepted, -1 invalid (the previous value stays) */
int aero_body_set_sample_rate(aero_body *s, double sr);
int aero_body_set_scale(aero_body *s, double scale);
int aero_body_set_exponent(aero_body *s, double e);
int aero_body_set_gain_db(aero_body *s, double db);
int aero_body_set_ramp_ms(aero_body *s, double ms);
int aero_body_set_seed(aero_body *s, uint32_t seed); /* any seed: 0 */
/* position and orientation (unit quaternion w x y z; normalised here),
 * applied now; interval_s as for sticks: the body moves on a smooth path
 * to it over that time (pose_glide.h); the first pose, one after a 0.5 s
 * pause and interval_s < 0 jump without motion */
int aero_body_set_pose(aero_body *s, const double pos[3],
                       const double quat[4], double interval_s);
/* the same at sample `offset` of the next process call (a host gives each
 * pose its logical time within the block, as [vline~] times its
 * segments): queued (up to AERO_GLIDE_QUEUE; beyond, the oldest is
 * applied at once), the process call split there; a pose beyond the
 * call waits for the next (each call counts its samples off). 0, or -1
 * invalid (nothing queued). */
int aero_body_set_pose_at(aero_body *s, const double pos[3],
                          const double quat[4], double interval_s,
                          int offset);
/* the orientation of the last pose given (w x y z), for a pose that moves
 * alone */
static inline void aero_body_orientation(const aero_body *s,
                                         double quat[4])
{
    const aero_pose_event *e = aero_pose_queue_back(&s->queue);
    for (int k = 0; k < 4; k++)
        quat[k] = e ? e->x[3 + k] : s->path.to[3 + k];
}
int aero_body_set_wind(aero_body *s, const double w[3]);
/* ears 0..e->n-1 (e->n at most the ears the player was made with) */
int aero_body_set_ears(aero_body *s, const aero_ears *e);

/* n samples; speed[i] (may be NULL) adds a wind along +x; out[e][i] is the
 * sound pressure at ear e in Pa. Returns 1 if a speed was clamped. */
int aero_body_process(aero_body *s, const float *speed,
                      float *const *out, int n);

/* a rotation vector (axis times angle in degrees) as a unit quaternion */
void aero_body_quaternion_from_rotvec(const double r[3], double q[4]);

#endif
