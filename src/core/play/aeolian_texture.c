/* aero: [aeolian~]'s texture mode, a moving stick played from a sound
 * texture (Dobashi et al. 2003; see aeolian.h). It reads the object's
 * settings; its state is *a->texture, made when first needed. */
#include "aeolian_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "aero_air.h"
#include "aero_ramp.h"
#include "aero_util.h"
#include "strouhal.h"

#define MIN_SPEED 1e-6       /* below this the flow direction is unknown */
/* Sources further apart than the correlation length must add their powers,
   as model mode's segments do. Offsets alone do not give that: every
   source reads the same periodic texture at the same rate, so their phases
   stay frozen and each line of the sum gets a random gain of its own. So
   each source's phase wanders, a random walk whose Lorentzian line is
   AERO_AEOLIAN_PHASE_WANDER_DEFAULT (1 %) wide relative to f (full width at
   half maximum): wide enough to lose the sources' mutual phase in a
   fraction of a second (0.16 s at 200 Hz), narrower than the turbulent
   wake's few percent (model mode), so the texture's own spectrum still
   shapes the line. */

/* --- helpers ------------------------------------------------------------- */

#define dot3 aero_dot3
#define cross3 aero_cross3
#define normalise3 aero_normalise3
/* the stick's short names for aeolian.h's sizes */
#define AERO_STICK_CHUNK AERO_AEOLIAN_TEXTURE_CHUNK
#define AERO_STICK_MAX_EARS AERO_AEOLIAN_MAX_EARS
#define AERO_STICK_MAX_DELAY_S AERO_AEOLIAN_MAX_DELAY_S

/* the object's target of gliding setting k, and the glide itself */
static double target_of(const aero_aeolian *a, int k)
{
    return k >= AERO_AEO_ROLL   ? a->roll_deg
           : k >= AERO_AEO_WIND ? a->wind[k - AERO_AEO_WIND]
                                : a->target[k];
}

static aero_aeolian_glide *glide_of(aero_aeolian_texture *s, int k)
{
    return k >= AERO_AEO_ROLL   ? &s->roll
           : k >= AERO_AEO_WIND ? &s->wind[k - AERO_AEO_WIND]
           : k >= AERO_AEO_EAR  ? &s->ear[k - AERO_AEO_EAR]
                                : &s->gain;
}

/* setting k glides to its target in ~ the ramp time, in whole chunks (as
   aero_ramp_to does). The ears and the gain go there at once while no
   source sounds: nothing heard moves, and a listener placed as a stream
   of poses begins (at load, at a spawn) is not still flying there, 2 m in
   20 ms, when the sound starts; the Doppler rate that then stepped at the
   glide's end was a click of a tenth of the signal (a sword whirled from
   rest: click measure 45-80 at a chord of 90 deg, issue 48). */
void aero_aeolian_texture_retarget(aero_aeolian *a, int k)
{
    aero_aeolian_glide *g = glide_of(a->texture, k);
    double chunks = ceil(a->ramp_ms * 0.001 * a->sample_rate /
                         AERO_STICK_CHUNK);
    if (!a->texture->sounding && k < AERO_AEO_WIND)
        chunks = 0.0;
    if (!(chunks >= 1.0)) {
        g->value = target_of(a, k);
        g->left = 0.0;
    } else
        g->left = chunks * AERO_STICK_CHUNK;
}

/* the value of setting k after m more samples (a chunk, shorter where a
   pose splits it) */
static double glide_advance(const aero_aeolian *a, int k, int m)
{
    aero_aeolian_glide *g = glide_of(a->texture, k);
    if (g->left > 0.0) {
        double target = target_of(a, k);
        aero_glide_values(&g->value, &target, 1,
                          aero_glide_fraction(&g->left, m));
    }
    return g->value;
}

/* --- life cycle ------------------------------------------------------------ */

static void default_pose(aero_aeolian_texture *s, double length)
{
    double half = 0.5 * length;
    double p[6] = {0.0, 0.0, -half, 0.0, 0.0, half};
    aero_pose_path_jump(&s->path, 6, p);
}

/* the diameter given, else the texture's */
static double current_diameter(const aero_aeolian *a)
{
    const aero_aeolian_texture *s = a->texture;
    if (a->diameter_set || !(s->tex_diameter > 0.0))
        return a->target[AERO_AEO_DIAMETER];
    return s->tex_diameter;
}

/* A circle texture corrected to a 3D cylinder (span3d.h) holds St and
   sectional C_L' of its own Re. Away from it both follow the circle's
   published laws, Roshko (1954) St(Re) and Norberg (2003) C_L'(Re), as
   model mode does, so the two modes agree at every speed. */
static void set_re_law(aero_aeolian_texture *s, const aero_texture *t,
                       double v0, double d)
{
    double re = t->head.re;
    s->re_law = !strcmp(t->head.shape, "circle") &&
                !strcmp(t->head.span3d, "circle-calibrated") &&
                re > AERO_RE_ONSET && re < 1e7;
    if (!s->re_law)
        return;
    s->tex_nu = v0 * d / re;
    s->tex_strouhal = aero_strouhal(re);
    s->tex_lift_rms = aero_lift_rms(re);
    s->re_law = s->tex_strouhal > 0.0 && s->tex_lift_rms > 0.0;
}

/* St(Re) / St(Re of the texture): 1 unless the law applies */
static double re_pitch(const aero_aeolian_texture *s, double v, double d)
{
    if (!s->re_law || !(v > MIN_SPEED))
        return 1.0;
    return aero_strouhal(v * d / s->tex_nu) / s->tex_strouhal;
}

/* C_L'(Re) / C_L'(Re of the texture) */
static double re_level(const aero_aeolian_texture *s, double v, double d)
{
    if (!s->re_law || !(v > MIN_SPEED))
        return 1.0;
    return aero_lift_rms(v * d / s->tex_nu) / s->tex_lift_rms;
}

static double stick_length(const double *pose)
{
    double d[3] = {pose[3] - pose[0], pose[4] - pose[1], pose[5] - pose[2]};
    return sqrt(dot3(d, d));
}

/* a generator for one source's phase wander: the next state of the
   player's generator would only replay its own stream one step later (the
   sources' wanders equal and their phases frozen), so it is scrambled to
   another place in the xorshift cycle (Murmur3's finaliser) */
static uint32_t source_generator(aero_aeolian_texture *s)
{
    return aero_scramble32(aero_xorshift32(&s->rng));
}

/* a random offset of the texture and a generator of its own for the
   phase wander, which starts again */
static void seed_source(aero_aeolian_texture *s, aero_aeolian_source *src)
{
    src->pos = 0.5 * (aero_uniform(&s->rng) + 1.0) *
               (s->texture ? s->texture->frames : 1);
    src->rng = source_generator(s);
    src->wander_from = src->wander = 0.0;
    src->wander_left = 0;
    /* the blade's noise from the source's own generator, no draw of the
       player's (every other texture plays as before, sample for sample) */
    if (s->voices)
        aero_blade_voice_reset(&s->voices[src - s->src],
                               src->rng ^ 0x5bd1e995u);
}

/* a new source: nothing carried over */
static void start_source(aero_aeolian_texture *s, aero_aeolian_source *src)
{
    memset(src, 0, sizeof(*src));
    seed_source(s, src);
}

/* n from the pose's length and the correlation length 3 d (Dobashi et
   al. 2003), for a stick of diameter d */
static void count_sources(aero_aeolian *a, double d)
{
    aero_aeolian_texture *s = a->texture;
    int n = a->sources;
    if (n <= 0) {
        double len = stick_length(s->path.to);
        /* clamp before the cast: a 1e5 m pose of a 1e-5 m stick asks for
           3e9 sources, beyond int */
        double want = floor(len / (AERO_CORRELATION_DIAMETERS * d) + 0.5);
        n = !(want >= 1.0) ? 1
            : want > AERO_AEOLIAN_SOURCES_MAX ? AERO_AEOLIAN_SOURCES_MAX
                                              : (int)want;
    }
    if (n < 1)
        n = 1;
    if (n > AERO_AEOLIAN_SOURCES_MAX)
        n = AERO_AEOLIAN_SOURCES_MAX;
    for (int i = s->n_sources; i < n; i++) /* new ones fade in */
        start_source(s, &s->src[i]);
    s->n_sources = n;
}

static void update_source_count(aero_aeolian *a)
{
    count_sources(a, current_diameter(a));
}

static int alloc_rings(aero_aeolian *a, double sr)
{
    return aero_arrivals_alloc(&a->texture->arrivals, a->n_ears, sr,
                               AERO_STICK_MAX_DELAY_S, 4 * AERO_STICK_CHUNK);
}

/* The part starts as a stick at the defaults (0.5 m along z, 1 cm,
 * gain 1, the default ears) and is then given the object's diameter (when
 * set) and length, in that order, each starting the sources it adds, and
 * glides its gain and ears to the object's. Its generator continues the
 * model's stream (xored, so the two differ) until a seed is given. */
int aero_aeolian_texture_make(aero_aeolian *a)
{
    if (a->texture)
        return 0;
    aero_aeolian_texture *s = calloc(1, sizeof(*s));
    if (!s)
        return -1;
    a->texture = s;
    if (alloc_rings(a, a->sample_rate)) {
        aero_aeolian_texture_free(a);
        return -1;
    }
    s->ring_rate = a->sample_rate;
    s->fade_in = HUGE_VAL; /* no jump to fade in from */
    uint32_t seed = a->model.rng ^ 0x9e3779b9u;
    s->rng = seed ? seed : 1;
    s->gain.value = 1.0;
    for (int e = 0; e < AERO_EARS_MAX; e++) {
        s->ear[3 * e + 0].value = a->n_ears == 2 ? (e ? AERO_EAR_HALF_SPACING
                                                      : -AERO_EAR_HALF_SPACING)
                                                 : 0.0;
        s->ear[3 * e + 1].value = 1.0;
    }
    s->reference[0] = 1.0;
    default_pose(s, AERO_AEOLIAN_LENGTH_DEFAULT);
    count_sources(a, AERO_AEOLIAN_DIAMETER_DEFAULT);
    if (a->diameter_set)
        count_sources(a, a->target[AERO_AEO_DIAMETER]);
    default_pose(s, a->target[AERO_AEO_LENGTH]);
    update_source_count(a);
    aero_aeolian_texture_retarget(a, AERO_AEO_GAIN);
    for (int k = 0; k < 3 * a->n_ears; k++)
        aero_aeolian_texture_retarget(a, AERO_AEO_EAR + k);
    return 0;
}

/* the blade's noise bank and voices, made for a blade texture and
   dropped for any other */
static void drop_blade(aero_aeolian_texture *s)
{
    free(s->blade);
    s->blade = NULL;
    s->voices = NULL;
}

/* The stick jumps while it sounds: what it sounded goes on where it was,
   fading as a stopped stream's sound does (its velocity, hence its rate,
   falling with AERO_VELOCITY_TAU_S, its amplitude as the rate to the exponent:
   render_ghosts), and the sources start again from rest at the new place.
   Moving the sounding sources with the stick instead jumped their delays
   within a chunk, the tail of the old sound cut where the new place's
   arrivals began (a step of a fifth of the signal, issue 48). */
static void drop_ghost_texture(aero_aeolian_texture *s)
{
    if (s->ghost_texture) {
        aero_texture_free(s->ghost_texture);
        free(s->ghost_texture);
        s->ghost_texture = NULL;
    }
    free(s->ghost_blade); /* its block, the bank first */
    s->ghost_blade = NULL;
    s->ghost_moving = 0;
}

static void leave_sound(aero_aeolian_texture *s)
{
    drop_ghost_texture(s);
    for (int i = 0; i < s->n_sources; i++) {
        s->ghost[i] = s->src[i];
        aero_ghost_begin(&s->ghost[i].fade, s->src[i].amp, s->src[i].inc,
                         s->src[i].step);
        s->src[i].amp = 0.0;
        /* the blade's noise goes on with its ghost, filters and gains as
           they were, and fades in again with the new source */
        if (s->voices)
            s->voices[AERO_AEOLIAN_SOURCES_MAX + i] = s->voices[i];
        s->src[i].namp = 0.0;
    }
    s->n_ghosts = s->n_sources;
    s->fade_in = 0.0;
    memset(s->velocity, 0, sizeof(s->velocity));
}

void aero_aeolian_texture_free(aero_aeolian *a)
{
    aero_aeolian_texture *s = a->texture;
    if (!s)
        return;
    aero_arrivals_free(&s->arrivals);
    drop_blade(s);
    drop_ghost_texture(s);
    if (s->texture) {
        aero_texture_free(s->texture);
        free(s->texture);
    }
    free(s);
    a->texture = NULL;
}

/* A blade section's metadata (aerotex writes it for a blade polygon,
 * textures/README.md): chord, trailing-edge thickness and angle, and
 * whether its boundary layer is taken as tripped. The shipped sword.wav
 * was made before these keys: its section (sword.poly, lenticular, chord
 * 40 mm, sharp edges whose sides meet at 27.3 deg: what aerotex writes
 * for it) is read as such.
 * 1 for a blade (out filled), else 0. */
static int read_blade(const aero_texture *t, aero_airfoil *out)
{
    char buf[32];
    double chord = aero_texture_getd(t, "blade_chord", 0.0);
    const char *bl = aero_texture_get(t, "blade_boundary_layer", buf,
                                      sizeof buf);
    memset(out, 0, sizeof(*out));
    if (!(aero_texture_getd(t, "band_limit_stop", 0.0) > 0.0))
        return 0; /* the texture holds its whole band */
    if (chord > 0.0) {
        out->chord = (float)chord;
        out->te_thickness =
            (float)aero_texture_getd(t, "blade_te_thickness", 0.0);
        out->te_angle_deg = (float)aero_texture_getd(t, "blade_te_angle",
                                                     14.0);
        out->tripped = !bl || strcmp(bl, "untripped") != 0;
    } else if (!strcmp(t->head.shape, "polygon sword.poly")) {
        out->chord = (float)t->head.diameter;
        out->te_thickness = 0.0f;
        out->te_angle_deg = 27.3f;
        out->tripped = 1;
    } else
        return 0;
    out->span = 1.0f;
    out->tip = AERO_AIRFOIL_NO_TIP;
    return 1;
}

typedef struct {
    aero_blade_noise bank;
    aero_blade_voice voice[2 * AERO_AEOLIAN_SOURCES_MAX]; /* then ghosts' */
} blade_block;

/* the bank for texture t when it is a blade's, else none (out of
   memory: none, the texture plays alone) */
static void set_blade(aero_aeolian *a, const aero_texture *t)
{
    aero_aeolian_texture *s = a->texture;
    aero_airfoil section;
    double sr = a->sample_rate >= 1000 ? a->sample_rate : 48000.0;
    if (!t || !read_blade(t, &section)) {
        drop_blade(s);
        return;
    }
    if (!s->blade) {
        blade_block *b = calloc(1, sizeof(*b));
        if (!b)
            return;
        s->blade = &b->bank;
        s->voices = b->voice;
    }
    if (aero_blade_noise_init(s->blade, &section, t->head.v0,
                              aero_texture_getd(t, "band_limit_pass", 0.0),
                              aero_texture_getd(t, "band_limit_stop", 0.0),
                              sr) != 0)
        drop_blade(s); /* metadata it cannot use: the texture alone */
}

int aero_aeolian_texture_set(aero_aeolian *a, aero_texture *t, char *err,
                             size_t errlen)
{
    aero_aeolian_texture *s = a->texture;
    /* what the old texture's sources need to fade out reading it */
    double was_period = s->period, was_frames_per_cycle = s->frames_per_cycle;
    int was_mirror = s->mirror;
    if (t) {
        if (aero_texture_wrong_kind(t, "aeolian", err, errlen)) {
            return -1;
        }
        double v0 = t->head.v0;
        double d = t->head.diameter;
        /* range before the cast (a file may say symmetry=1e300) */
        double symmetry_value = t->head.symmetry_deg;
        int symmetry = symmetry_value >= 0.0 && symmetry_value <= 360.0
                           ? (int)symmetry_value : -1;
        if (!(v0 > 0.0 && v0 < 1e3) || !(d > 0.0 && d < 100.0) ||
            !(t->rate > 0.0) || t->frames < 2 || t->directions < 1 ||
            symmetry < 0 || symmetry > 360) {
            snprintf(err, errlen, "bad metadata (v0 %g, diameter %g, "
                     "symmetry %d, %d frames)", v0, d, symmetry, t->frames);
            return -1;
        }
        for (int k = 1; k < t->directions; k++)
            if (!(t->angles[k] > t->angles[k - 1])) {
                snprintf(err, errlen, "angles are not increasing");
                return -1;
            }
        s->v0 = v0;
        s->tex_diameter = d;
        s->tex_rate = t->rate;
        s->st = t->head.st;
        s->period = symmetry > 0 && t->directions > 1 ? 360.0 / symmetry
                                                       : 0.0;
        s->mirror = fabs(t->head.mirror) >= 1.0;
        s->frames_per_cycle = s->st > 0.0 && v0 > 0.0 && d > 0.0
                                  ? t->rate * d / (s->st * v0)
                                  : 0.0;
        set_re_law(s, t, v0, d);
    }
    if (s->sounding && s->texture && t) {
        /* a texture changed while sounding: the old sources fade out
           reading the old texture, moving on as they were, as the new
           ones fade in (fade_in); cutting them stepped the sound */
        double velocity[6]; /* the stick goes on moving */
        memcpy(velocity, s->velocity, sizeof(velocity));
        leave_sound(s);
        memcpy(s->velocity, velocity, sizeof(velocity));
        s->ghost_texture = s->texture;
        s->ghost_period = was_period;
        s->ghost_mirror = was_mirror;
        s->ghost_frames_per_cycle = was_frames_per_cycle;
        s->ghost_moving = 1;
        /* the ghosts keep the old texture's noise bank and voices */
        s->ghost_blade = s->blade;
        s->blade = NULL;
        s->voices = NULL;
    } else {
        drop_ghost_texture(s);
        s->n_ghosts = 0; /* they read the old texture */
        if (s->texture) {
            aero_texture_free(s->texture);
            free(s->texture);
        }
    }
    s->texture = t;
    set_blade(a, t);
    /* sources restart from random offsets of the new texture */
    for (int i = 0; i < AERO_AEOLIAN_SOURCES_MAX; i++)
        start_source(s, &s->src[i]);
    update_source_count(a);
    return 0;
}

/* --- the settings, as the texture mode takes them ---------------------------- */

int aero_aeolian_texture_sample_rate(aero_aeolian *a, double sr)
{
    aero_aeolian_texture *s = a->texture;
    if (!(sr >= AERO_MOVING_SR_MIN && sr <= AERO_MOVING_SR_MAX))
        return -1;
    if (sr == s->ring_rate && s->arrivals.ring[0])
        return 0;
    if (alloc_rings(a, sr))
        return -1;
    s->ring_rate = sr;
    if (s->blade && aero_blade_noise_set_rate(s->blade, sr) != 0)
        drop_blade(s);
    for (int i = 0; i < AERO_AEOLIAN_SOURCES_MAX; i++)
        s->src[i].primed = 0; /* the rings are new */
    s->n_ghosts = 0;
    drop_ghost_texture(s);
    return 0;
}

void aero_aeolian_texture_resize(aero_aeolian *a, int k)
{
    aero_aeolian_texture *s = a->texture;
    if (k == AERO_AEO_LENGTH) {
        if (s->pose_set) /* the poses give the length */
            return;
        default_pose(s, a->target[AERO_AEO_LENGTH]);
    }
    if (k == AERO_AEO_SOURCES && a->sources > 0 &&
        a->sources < s->n_sources)
        s->n_sources = a->sources;
    update_source_count(a);
}

/* the seed as given; each source a new offset and generator, the rest
   kept */
void aero_aeolian_texture_seed(aero_aeolian *a)
{
    aero_aeolian_texture *s = a->texture;
    s->rng = a->seed ? a->seed : 1;
    for (int i = 0; i < AERO_AEOLIAN_SOURCES_MAX; i++)
        if (s->texture)
            seed_source(s, &s->src[i]);
}

static int pose_ok(const double *p)
{
    return aero_position_ok(p) && aero_position_ok(p + 3) &&
           stick_length(p) >= 1e-6;
}

int aero_aeolian_texture_pose(aero_aeolian *a, const double end_a[3],
                              const double end_b[3], double interval_s)
{
    aero_aeolian_texture *s = a->texture;
    double p[6] = {end_a[0], end_a[1], end_a[2], end_b[0], end_b[1], end_b[2]};
    if (!pose_ok(p))
        return -1;
    /* the first pose, one after a pause (a new gesture: the stream had
     * ended) or a placement (interval < 0) jumps: there is nothing to move
     * from */
    if (!s->pose_set || interval_s < 0.0 || interval_s > 0.5 ||
        aero_pose_path_ended(&s->path)) {
        if (s->sounding)
            leave_sound(s);
        aero_pose_path_jump(&s->path, 6, p);
        memset(s->pose_velocity, 0, sizeof(s->pose_velocity));
        if (!s->pose_set)
            update_source_count(a);
        s->pose_set = 1;
        return 0;
    }
    if (!(interval_s >= 0.001))
        interval_s = 0.001;
    if (aero_pose_path_waited(&s->path, interval_s * a->sample_rate)) {
        double from[6]; /* the gesture began at the last pose */
        memcpy(from, s->path.to, sizeof(from));
        if (s->sounding)
            leave_sound(s);
        aero_pose_path_jump(&s->path, 6, from);
        memset(s->velocity, 0, sizeof(s->velocity));
    }
    /* the velocity of the stream itself (its time stamps are exact): what
     * the air sees */
    double was = stick_length(s->path.to), now = stick_length(p);
    for (int i = 0; i < 6; i++)
        s->pose_velocity[i] = (p[i] - s->path.to[i]) / interval_s;
    aero_pose_path_to(&s->path, p, interval_s * a->sample_rate);
    /* keep n unless the length changed a lot (a new object) */
    if (a->sources <= 0 && (now > 1.5 * was || now < was / 1.5))
        update_source_count(a);
    return 0;
}

static void apply_event(aero_aeolian *a, const aero_pose_event *e)
{
    aero_aeolian_texture_pose(a, e->x, e->x + 3, e->interval_s);
    if (e->has_extra)
        aero_aeolian_texture_reference(a, e->x + 6);
}

void aero_aeolian_texture_flush(aero_aeolian *a)
{
    aero_pose_queue *q = &a->texture->queue;
    while (q->n > 0) {
        apply_event(a, aero_pose_queue_front(q));
        aero_pose_queue_pop(q);
    }
}

int aero_aeolian_texture_pose_at(aero_aeolian *a, const double end_a[3],
                                 const double end_b[3], const double *axis,
                                 double interval_s, int offset)
{
    aero_pose_event e, oldest;
    memcpy(e.x, end_a, 3 * sizeof(double));
    memcpy(e.x + 3, end_b, 3 * sizeof(double));
    e.has_extra = axis != NULL;
    if (axis) {
        double v[3] = {axis[0], axis[1], axis[2]};
        if (!aero_position_ok(v) || normalise3(v) < 1e-9)
            return -1;
        memcpy(e.x + 6, axis, 3 * sizeof(double));
    }
    if (!pose_ok(e.x))
        return -1;
    e.interval_s = interval_s;
    e.offset = offset;
    if (aero_pose_queue_push(&a->texture->queue, &e, &oldest))
        apply_event(a, &oldest); /* full: the oldest at once */
    return 0;
}

int aero_aeolian_texture_reference(aero_aeolian *a, const double x[3])
{
    double v[3] = {x[0], x[1], x[2]};
    if (!aero_position_ok(v) || normalise3(v) < 1e-9)
        return -1;
    memcpy(a->texture->reference, v, sizeof(v));
    return 0;
}

double aero_aeolian_texture_tone_hz(const aero_aeolian *a, double v)
{
    double d = current_diameter(a);
    return a->texture->st * re_pitch(a->texture, v, d) * v / d;
}

/* --- directions ------------------------------------------------------------ */

/* the sampled directions around body angle a (deg): k0, k1, the weight of
 * k1 (linear, extrapolated when a lies outside [angle k0, angle k1]) and
 * the sign of the texture's y (lift) component (-1 on the mirrored half) */
typedef struct {
    int k0, k1;
    double a0, a1; /* angles of k0 and k1 (a1 may be period + angle 0) */
    double sign;
} dir_pair;

#define FOLD_HYSTERESIS_DEG 2.0

/* Folds body angle a (deg) into the sampled range. On the mirrored half
 * the texture's y (lift) is negated. Right at a fold line (0 and P/2) both
 * halves are the same flow but their lift has opposite signs, so within
 * FOLD_HYSTERESIS_DEG of one the previous side (*sign on entry) is kept:
 * a stick hovering there does not flip its lift back and forth. */
static double fold_angle(const aero_aeolian_texture *s, double a, double *sign)
{
    double previous = *sign < 0.0 ? -1.0 : 1.0;
    *sign = 1.0;
    if (s->period <= 0.0)
        return 0.0;
    a = fmod(a, s->period);
    if (a < 0.0)
        a += s->period;
    if (!s->mirror)
        return a;
    double half = 0.5 * s->period;
    double to_fold = fmin(fmin(a, s->period - a), fabs(a - half));
    int mirrored = to_fold < FOLD_HYSTERESIS_DEG ? previous < 0.0 : a > half;
    if (a > half)
        a = s->period - a;
    if (mirrored)
        *sign = -1.0;
    return a;
}

static dir_pair find_pair(const aero_aeolian_texture *s, double folded,
                          double sign)
{
    const aero_texture *t = s->texture;
    int n = t->directions;
    dir_pair p = {0, 0, 0.0, 1.0, sign};
    if (n < 2 || s->period <= 0.0)
        return p;
    int k = 0;
    while (k + 1 < n && t->angles[k + 1] <= folded)
        k++;
    if (k == n - 1) {
        if (s->mirror) { /* the last sampled angle is the fold itself */
            k = n - 2;
        } else {         /* between the last angle and period + angle 0 */
            p.k0 = n - 1;
            p.k1 = 0;
            p.a0 = t->angles[n - 1];
            p.a1 = s->period + t->angles[0];
            return p;
        }
    }
    p.k0 = k;
    p.k1 = k + 1;
    p.a0 = t->angles[k];
    p.a1 = t->angles[k + 1];
    return p;
}

static double pair_weight(const dir_pair *p, double folded, double period)
{
    if (p->k0 == p->k1)
        return 0.0;
    double span = p->a1 - p->a0;
    double off = folded - p->a0;
    if (period > 0.0) { /* the nearest image of the angle */
        if (off > 0.5 * period)
            off -= period;
        else if (off < -0.5 * period)
            off += period;
    }
    double w = off / span;
    return w < -0.5 ? -0.5 : w > 1.5 ? 1.5 : w;
}

/* --- processing ------------------------------------------------------------ */

/* Geometry of source at fraction u along the stick for the pose now. */
typedef struct {
    double inc, angle, amp;
    double fx[AERO_STICK_MAX_EARS], fy[AERO_STICK_MAX_EARS];
    double delay[AERO_STICK_MAX_EARS];
    /* a blade's noise: the flow speed normal to the stick, the source's
       span and the gain its noise is heard with */
    double speed, span, namp;
} source_geometry;

typedef struct {
    double a[3], axis[3], len;
    double va[3], vb[3];
    double xb[3], yb[3]; /* body frame, normal to the axis */
    double wind[3];
    double ears[AERO_STICK_MAX_EARS][3];
    double seg_len, gain;
} stick_frame;

/* the Re law's factors for a source at speed v, computed again only when v
   moves by more than 0.1 % (St and C_L' then move by about as little), as
   model mode caches its laws: a log and a power per source and chunk cost
   a fifth of the player */
static void re_factors(const aero_aeolian_texture *s, aero_aeolian_source *src,
                       double v, double d, double *pitch, double *level)
{
    if (!s->re_law || !(v > MIN_SPEED)) {
        *pitch = *level = 1.0;
        return;
    }
    if (!(src->law_speed > 0.0) || d != src->law_diameter ||
        fabs(v - src->law_speed) > 1e-3 * src->law_speed) {
        src->law_speed = v;
        src->law_diameter = d;
        src->law_pitch = re_pitch(s, v, d);
        src->law_level = re_level(s, v, d);
    }
    *pitch = src->law_pitch;
    *level = src->law_level;
}

static int source_at(aero_aeolian *a, const stick_frame *f, double u,
                     aero_aeolian_source *src, source_geometry *g)
{
    const aero_aeolian_texture *s = a->texture;
    int clamped = 0;
    double pos[3], rel[3];
    for (int i = 0; i < 3; i++) {
        pos[i] = f->a[i] + u * f->len * f->axis[i];
        double vel = f->va[i] + u * (f->vb[i] - f->va[i]);
        rel[i] = f->wind[i] - vel;
    }
    /* property 3: only the component normal to the axis sheds */
    double along = dot3(rel, f->axis);
    double perp[3] = {rel[0] - along * f->axis[0], rel[1] - along * f->axis[1],
                      rel[2] - along * f->axis[2]};
    double v = normalise3(perp);
    double vmax = AERO_MACH_LIMIT * AERO_C0;
    if (v > vmax) {
        v = vmax;
        clamped = 1;
    }
    double d = current_diameter(a);
    double ratio = v / s->v0, pitch, level;
    re_factors(s, src, v, d, &pitch, &level);
    g->inc = ratio * pitch * (s->tex_diameter / d) * s->tex_rate /
             a->sample_rate;
    if (v > MIN_SPEED) {
        g->angle = atan2(dot3(perp, f->yb), dot3(perp, f->xb)) * 180.0 / AERO_PI;
        /* g = dF/dt: the force scales with C_L', its rate with St */
        g->amp = pow(ratio, a->exponent) * pitch * level *
                 f->seg_len * f->gain;
        g->namp = f->gain;
    } else { /* no flow: silent, keep the direction */
        perp[0] = f->xb[0];
        perp[1] = f->xb[1];
        perp[2] = f->xb[2];
        g->angle = 0.0;
        g->amp = 0.0;
        g->namp = 0.0;
    }
    g->speed = v;
    g->span = f->seg_len;
    double across[3];
    cross3(f->axis, perp, across); /* y of the flow frame */
    for (int e = 0; e < a->n_ears; e++) {
        double r[3] = {f->ears[e][0] - pos[0], f->ears[e][1] - pos[1],
                       f->ears[e][2] - pos[2]};
        /* inside the body the far field does not hold: the near-field
           policy (aero_near_field), exactly at the source along the lift */
        aero_near_field(r, 0.5 * d, across, &a->near);
        double dist = sqrt(dot3(r, r));
        /* Curle: (q - o).g / (4 pi c0 r^2), r = |q - o|: falls as 1/r */
        double k = 1.0 / (4.0 * AERO_PI * AERO_C0 * dist * dist);
        g->fx[e] = dot3(r, perp) * k;
        g->fy[e] = dot3(r, across) * k;
        double delay = dist / AERO_C0 * a->sample_rate;
        double dmax = AERO_STICK_MAX_DELAY_S * a->sample_rate;
        g->delay[e] = delay < dmax ? delay : dmax;
    }
    return clamped;
}

/* moves pose, velocities and ramps by m samples; fills the frame at the
 * chunk's end */
static void advance_frame(aero_aeolian *a, int m, double speed,
                          stick_frame *f)
{
    aero_aeolian_texture *s = a->texture;
    aero_pose_path_advance(&s->path, m);
    const double *pose = s->path.pos;
    /* the stream's velocity, smoothed, falling to 0 as the path comes to
     * rest (the stream has ended) */
    double pace = aero_pose_path_pace(&s->path);
    double alpha = 1.0 - exp(-m / (AERO_VELOCITY_TAU_S * a->sample_rate));
    for (int i = 0; i < 6; i++) {
        double v = pace * s->pose_velocity[i];
        s->velocity[i] += alpha * (v - s->velocity[i]);
    }
    for (int i = 0; i < 3; i++) {
        f->a[i] = pose[i];
        f->axis[i] = pose[3 + i] - pose[i];
        f->va[i] = s->velocity[i];
        f->vb[i] = s->velocity[3 + i];
    }
    f->len = normalise3(f->axis);
    /* carry the body's x axis along: project it onto the normal plane */
    double along = dot3(s->reference, f->axis);
    double xb[3] = {s->reference[0] - along * f->axis[0],
                    s->reference[1] - along * f->axis[1],
                    s->reference[2] - along * f->axis[2]};
    if (normalise3(xb) < 1e-6) { /* the axis turned onto it: any normal */
        double t[3] = {fabs(f->axis[0]) < 0.9 ? 1.0 : 0.0,
                       fabs(f->axis[0]) < 0.9 ? 0.0 : 1.0, 0.0};
        cross3(f->axis, t, xb);
        normalise3(xb);
    }
    memcpy(s->reference, xb, sizeof(xb));
    double roll = glide_advance(a, AERO_AEO_ROLL, m) * AERO_PI / 180.0;
    double yb[3];
    cross3(f->axis, xb, yb);
    for (int i = 0; i < 3; i++) {
        f->xb[i] = cos(roll) * xb[i] + sin(roll) * yb[i];
        f->yb[i] = cos(roll) * yb[i] - sin(roll) * xb[i];
    }
    for (int i = 0; i < 3; i++)
        f->wind[i] = glide_advance(a, AERO_AEO_WIND + i, m);
    f->wind[0] += speed;
    for (int e = 0; e < a->n_ears; e++)
        for (int i = 0; i < 3; i++)
            f->ears[e][i] = glide_advance(a, AERO_AEO_EAR + 3 * e + i, m);
    f->seg_len = f->len / s->n_sources;
    f->gain = glide_advance(a, AERO_AEO_GAIN, m);
}

/* coefficients of one ear for a direction pair, from a geometry */
static void pair_coefs(const source_geometry *g, int e, double w, double sign,
                       double *c)
{
    double ax = g->amp * g->fx[e], ay = g->amp * g->fy[e] * sign;
    c[0] = (1.0 - w) * ax;
    c[1] = (1.0 - w) * ay;
    c[2] = w * ax;
    c[3] = w * ay;
}

/* a source's phase rate for its next AERO_STICK_CHUNK samples, frames per
   sample: phase diffusion of full width B = W f (Hz) steps by B K /
   (2 pi sr) cycles^2 over K samples (as aeolian_model.c); with f = inc sr /
   frames_per_cycle that is W inc K frames_per_cycle / (2 pi) frames^2. A
   uniform number on [-1, 1) has variance 1/3. Each source draws from its
   own generator on its own sample count, so any block size gives the same
   sound. */
static double phase_wander(const aero_aeolian *a, aero_aeolian_source *src,
                           double inc)
{
    const aero_aeolian_texture *s = a->texture;
    if (!(a->phase_wander > 0.0) || !(s->frames_per_cycle > 0.0) ||
        !(inc > 0.0))
        return 0.0;
    double variance = a->phase_wander * inc * AERO_STICK_CHUNK *
                      s->frames_per_cycle / (2.0 * AERO_PI);
    return sqrt(3.0 * variance) * aero_uniform(&src->rng) / AERO_STICK_CHUNK;
}

/* the texture read once for all ears over a chunk of m samples: x, y of
 * both directions of the pair, the rate gliding from inc_then to inc_now
 * (frames per sample) with the phase's wander */
static void read_texture(aero_aeolian *a, aero_aeolian_source *src,
                         const dir_pair *p, double inc_then, double inc_now,
                         int m, float tex[4][AERO_STICK_CHUNK])
{
    const aero_texture *t = a->texture->texture;
    const int ch = t->channels;
    const long frames = t->frames;
    double pos = src->pos, inc = inc_then;
    const double dinc = (inc_now - inc_then) * (1.0 / m);
    double from = src->wander_from, wander = src->wander;
    int left = src->wander_left;
    const int c0 = 3 * p->k0, c1 = 3 * p->k1;
    for (int j = 0; j < m; j++) {
        long i0 = (long)pos;
        float fr = (float)(pos - (double)i0);
        long i1 = i0 + 1 == frames ? 0 : i0 + 1;
        const float *r0 = t->data + i0 * ch, *r1 = t->data + i1 * ch;
        tex[0][j] = r0[c0] + fr * (r1[c0] - r0[c0]);
        tex[1][j] = r0[c0 + 1] + fr * (r1[c0 + 1] - r0[c0 + 1]);
        tex[2][j] = r0[c1] + fr * (r1[c1] - r0[c1]);
        tex[3][j] = r0[c1 + 1] + fr * (r1[c1 + 1] - r0[c1 + 1]);
        inc += dinc;
        if (left <= 0) {
            from = wander;
            wander = phase_wander(a, src, inc);
            left = AERO_STICK_CHUNK;
        }
        left--;
        /* the rate glides from one draw to the next: a rate that stepped
           every chunk clicked on a pure tone (each step a kink of the
           phase); the phase's long-run diffusion, hence the line width,
           is the same */
        double w = wander + (from - wander) * ((double)left / AERO_STICK_CHUNK);
        pos = aero_texture_wrap(pos + (inc + w > 0.0 ? inc + w : 0.0), frames);
    }
    src->pos = pos;
    src->wander_from = from;
    src->wander = wander;
    src->wander_left = left;
}

/* the chunk's texture projected for each ear (Curle's dipole, its
 * coefficients gliding from `then` to `now`) and added into the ear's ring
 * at its arrival time; a blade's noise (NULL: none) with it, projected
 * on the lift's direction */
static void radiate(aero_aeolian *a, const source_geometry *then,
                    const source_geometry *now, double w0, double w1,
                    double sign_then, double sign_now, int m,
                    float tex[4][AERO_STICK_CHUNK], const float *noise,
                    double *step_last)
{
    aero_aeolian_texture *s = a->texture;
    const double inv_m = 1.0 / m;
    for (int e = 0; e < a->n_ears; e++) {
        double c[4], cend[4];
        float cf[4], dcf[4];
        pair_coefs(then, e, w0, sign_then, c);
        pair_coefs(now, e, w1, sign_now, cend);
        for (int k = 0; k < 4; k++) {
            cf[k] = (float)c[k];
            dcf[k] = (float)((cend[k] - c[k]) * inv_m);
        }
        float cn = (float)(then->namp * then->fy[e]);
        const float dcn = (float)((now->namp * now->fy[e] -
                                   then->namp * then->fy[e]) * inv_m);
        const double delay = then->delay[e];
        const double ddelay = (now->delay[e] - delay) * inv_m;
        float *ring = s->arrivals.ring[e];
        const long mask = s->arrivals.mask;
        double at = (double)s->arrivals.head + delay;
        const double step = 1.0 + ddelay, last = step_last[e];
        step_last[e] = step;
        for (int j = 0; j < m; j++) {
            float v = cf[0] * tex[0][j] + cf[1] * tex[1][j] +
                      cf[2] * tex[2][j] + cf[3] * tex[3][j];
            if (noise) {
                v += cn * noise[j];
                cn += dcn;
            }
            aero_arrivals_add_chunk(ring, mask, at, step, last, j, m, v);
            cf[0] += dcf[0];
            cf[1] += dcf[1];
            cf[2] += dcf[2];
            cf[3] += dcf[3];
            at += 1.0 + ddelay;
        }
    }
}

/* a source's noise voice, or its ghost's (after the sources' own) */
static aero_blade_voice *voice_of(aero_aeolian_texture *s,
                                  const aero_aeolian_source *src)
{
    if (src >= s->ghost && src < s->ghost + AERO_AEOLIAN_SOURCES_MAX)
        return &s->voices[AERO_AEOLIAN_SOURCES_MAX + (src - s->ghost)];
    return &s->voices[src - s->src];
}

/* a blade's noise for the chunk: its bands aimed at the model's spectrum
 * for the source's speed, angle of attack (the flow's angle to the chord,
 * 0 edge-on, folded to 0-90 deg: either edge may trail) and span, heard
 * at the texture's pitch; NULL for any other texture */
static const float *blade_noise(aero_aeolian *a, aero_aeolian_source *src,
                                const source_geometry *g, int m,
                                float *noise)
{
    aero_aeolian_texture *s = a->texture;
    if (!s->blade)
        return NULL;
    aero_blade_voice *v = voice_of(s, src);
    double alpha = fabs(remainder(g->angle, 180.0));
    double scale = g->inc * a->sample_rate / s->tex_rate;
    aero_blade_voice_target(s->blade, v, g->speed, alpha, g->span, scale,
                            current_diameter(a) / s->tex_diameter);
    aero_blade_voice_render(s->blade, v, noise, m);
    return noise;
}

/* one source over a chunk of m samples: texture read, Curle projection,
 * added into each ear's ring at its arrival time; 1 if it sounded */
static int render_source(aero_aeolian *a, aero_aeolian_source *src,
                          const source_geometry *g, int m)
{
    aero_aeolian_texture *s = a->texture;
    double sign_then = src->sign, sign_now = src->sign;
    double folded = fold_angle(s, g->angle, &sign_now);
    dir_pair p = find_pair(s, folded, sign_now);
    double w1 = pair_weight(&p, folded, s->mirror ? 0.0 : s->period);
    source_geometry then;
    if (!src->primed) { /* first chunk: start where it ends, amplitude 0 */
        then = *g;
        then.amp = 0.0;
        then.namp = 0.0;
        src->primed = 1;
        memset(src->step, 0, sizeof(src->step));
    } else {
        then.inc = src->inc;
        then.angle = src->angle;
        then.amp = src->amp;
        then.namp = src->namp;
        for (int e = 0; e < a->n_ears; e++) {
            then.fx[e] = src->fx[e];
            then.fy[e] = src->fy[e];
            then.delay[e] = src->delay[e];
        }
    }
    double folded_then = fold_angle(s, then.angle, &sign_then);
    src->sign = sign_now;
    double w0 = pair_weight(&p, folded_then, s->mirror ? 0.0 : s->period);

    /* the texture once for all ears: x, y of both directions */
    float tex[4][AERO_STICK_CHUNK], noise[AERO_STICK_CHUNK];
    read_texture(a, src, &p, then.inc, g->inc, m, tex);
    radiate(a, &then, g, w0, w1, sign_then, sign_now, m, tex,
            blade_noise(a, src, g, m, noise), src->step);
    src->inc = g->inc;
    src->angle = g->angle;
    src->amp = g->amp;
    src->namp = g->namp;
    for (int e = 0; e < a->n_ears; e++) {
        src->fx[e] = g->fx[e];
        src->fy[e] = g->fy[e];
        src->delay[e] = g->delay[e];
    }
    return then.amp != 0.0 || g->amp != 0.0;
}

/* the ghosts' next m samples, each at its own place, fading
   (ghost_fade.h); 1 if one sounded */
static int render_ghosts(aero_aeolian *a, int m)
{
    aero_aeolian_texture *s = a->texture;
    const double span = AERO_GHOST_FADE_S * a->sample_rate;
    int sounding = 0;
    /* after a texture change they read the old one */
    aero_texture *texture = s->texture;
    double period = s->period, frames_per_cycle = s->frames_per_cycle;
    int mirror = s->mirror;
    if (s->ghost_texture) {
        s->texture = s->ghost_texture;
        s->period = s->ghost_period;
        s->mirror = s->ghost_mirror;
        s->frames_per_cycle = s->ghost_frames_per_cycle;
    }
    /* and the old texture's noise bank: none when it was not a blade's */
    aero_blade_noise *blade = s->blade;
    aero_blade_voice *voices = s->voices;
    if (s->ghost_blade) {
        s->blade = s->ghost_blade;
        s->voices = ((blade_block *)(void *)s->ghost_blade)->voice;
    } else if (s->ghost_texture) {
        s->blade = NULL;
        s->voices = NULL;
    }
    for (int i = 0; i < s->n_ghosts; i++) {
        aero_aeolian_source *gh = &s->ghost[i];
        double v_then, v;
        if (!gh->primed || !(gh->fade.samples < span))
            continue;
        /* after a texture change the stick goes on */
        aero_ghost_advance(&gh->fade.samples, m, span, s->ghost_moving,
                           &v_then, &v);
        double fade = aero_ghost_fade(gh->fade.samples, a->sample_rate,
                                      a->exponent);
        source_geometry g;
        g.inc = gh->fade.inc * v;
        g.angle = gh->angle;
        g.amp = gh->fade.amp * fade;
        /* its noise fades as its texture does, its spectrum held */
        g.namp = gh->namp * fade;
        g.speed = g.span = 0.0;
        if (s->voices) {
            const aero_blade_voice *bv = voice_of(s, gh);
            g.speed = bv->law_speed;
            g.span = bv->law_span;
        }
        for (int e = 0; e < a->n_ears; e++) {
            g.fx[e] = gh->fx[e];
            g.fy[e] = gh->fy[e];
            /* it moves on as it slows: its delay's rate falls with v */
            g.delay[e] = gh->delay[e] + gh->fade.rate[e] * 0.5 * (v_then + v) * m;
        }
        sounding |= render_source(a, gh, &g, m);
    }
    s->blade = blade;
    s->voices = voices;
    s->texture = texture;
    s->period = period;
    s->mirror = mirror;
    s->frames_per_cycle = frames_per_cycle;
    if (!sounding) {
        s->n_ghosts = 0;
        drop_ghost_texture(s);
    }
    return sounding;
}

int aero_aeolian_texture_process(aero_aeolian *a, const float *speed,
                                 float *const *out, int n)
{
    aero_aeolian_texture *s = a->texture;
    s->clamped = 0;
    for (int done = 0; done < n;) {
        int m = n - done < AERO_STICK_CHUNK ? n - done : AERO_STICK_CHUNK;
        /* the poses due at this sample, then a chunk up to the next */
        while ((m = aero_pose_queue_until(&s->queue, done, m)) == 0) {
            apply_event(a, aero_pose_queue_front(&s->queue));
            aero_pose_queue_pop(&s->queue);
            m = n - done < AERO_STICK_CHUNK ? n - done : AERO_STICK_CHUNK;
        }
        /* the inlet's mean speed over the chunk (aero_speed_in) */
        double sp = 0.0;
        if (speed) {
            for (int j = 0; j < m; j++) {
                float v = speed[done + j];
                sp += aero_speed_in(v, &s->clamped);
            }
            sp /= m;
        }
        stick_frame f;
        advance_frame(a, m, sp, &f);
        int sounding = 0;
        if (s->texture) {
            double faded = aero_ghost_fade_in(&s->fade_in, m, a->sample_rate,
                                              a->exponent);
            for (int i = 0; i < s->n_sources; i++) {
                source_geometry g;
                double u = (i + 0.5) / s->n_sources;
                s->clamped |= source_at(a, &f, u, &s->src[i], &g);
                g.amp *= faded;
                sounding |= render_source(a, &s->src[i], &g, m);
            }
        }
        if (s->n_ghosts && s->texture)
            sounding |= render_ghosts(a, m);
        s->sounding = sounding;
        aero_arrivals_take(&s->arrivals, out, done, m);
        done += m;
    }
    aero_pose_queue_elapse(&s->queue, n);
    return s->clamped;
}
