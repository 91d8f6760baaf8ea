/* aero: a moving 3D body played from an object texture (see
 * body.h). */
#include "body.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "aero_air.h"
#include "strouhal.h"

#define MIN_SPEED 1e-6       /* below this the flow direction is unknown */

static void rotate(const double *q, const double *v, double *out)
{
    aero_quat_rotate(q, v, out);
}

void aero_body_quaternion_from_rotvec(const double r[3], double q[4])
{
    aero_quat_from_rotvec(r, q);
}

/* --- life cycle ----------------------------------------------------------- */

static void drop_ghost_texture(aero_body *s)
{
    if (s->ghost_texture) {
        aero_texture_free(s->ghost_texture);
        free(s->ghost_texture);
        s->ghost_texture = NULL;
    }
    s->ghost_moving = 0;
}

static void restart_sources(aero_body *s)
{
    for (int i = 0; i < AERO_BODY_MAX_SOURCES; i++) {
        memset(&s->src[i], 0, sizeof(s->src[i]));
        if (s->texture)
            s->src[i].pos = 0.5 * (aero_uniform(&s->base.rng) + 1.0) *
                            s->texture->frames;
    }
}

int aero_body_init(aero_body *s, double sample_rate,
                   int n_ears, uint32_t seed)
{
    static const double unturned[7] = {0, 0, 0, 1, 0, 0, 0};
    memset(s, 0, sizeof(*s));
    s->scale = AERO_BODY_SCALE_DEFAULT;
    s->fade_in = HUGE_VAL; /* no jump to fade in from */
    memcpy(s->pose, unturned, sizeof(unturned));
    aero_pose_path_jump(&s->path, 7, unturned);
    int sr_ok = sample_rate >= AERO_MOVING_SR_MIN &&
                sample_rate <= AERO_MOVING_SR_MAX;
    if (aero_moving_player_init(&s->base,
                                sr_ok ? sample_rate : AERO_SAMPLE_RATE_FALLBACK,
                                n_ears, seed, AERO_BODY_CHUNK,
                                AERO_BODY_MAX_DELAY_S))
        return -1; /* no rings: process is silent until a sample rate */
    return sr_ok ? 0 : -1;
}

void aero_body_free(aero_body *s)
{
    aero_moving_player_free(&s->base);
    drop_ghost_texture(s);
    if (s->texture) {
        aero_texture_free(s->texture);
        free(s->texture);
        s->texture = NULL;
    }
}

/* "a,b,c,..." into out, n values in (0, 100): 0 or -1 */
static int parse_sizes(const char *p, int n, double *out)
{
    for (int l = 0; l < n; l++) {
        char *end;
        double v = strtod(p, &end);
        if (end == p || !(v > 0.0 && v < 100.0))
            return -1;
        out[l] = v;
        p = end;
        if (l < n - 1 ? *p != ',' : (*p != 0 && *p != '\n'))
            return -1;
        p++;
    }
    return 0;
}

/* a strip-theory texture's regions follow Roshko's St(Re) and Norberg's
   C_L'(Re) away from the texture's Re: 1 if t is one (method=strip with
   its regions' diameters and nu), the diameters and nu into s */
static int strip_re_law(aero_body *s, const aero_texture *t)
{
    double nu = t->head.nu;
    s->tex_nu = nu;
    return !strcmp(t->head.method, "strip") && nu > 0.0 && nu < 1.0 &&
           t->head.diameters &&
           parse_sizes(t->head.diameters, t->regions, s->region_d) == 0;
}

/* "x,y,z;x,y,z;..." into centre, n triples: 0 or -1 */
static int parse_centres(const char *p, int n, double *centre)
{
    for (int l = 0; l < n; l++)
        for (int a = 0; a < 3; a++) {
            char *end;
            double v = strtod(p, &end);
            if (end == p || !aero_is_finite(v) || fabs(v) > 1e3)
                return -1;
            centre[3 * l + a] = v;
            p = end;
            if (a < 2 ? *p != ',' : (l < n - 1 ? *p != ';' : 0))
                return -1;
            if (!(l == n - 1 && a == 2))
                p++;
        }
    return *p == 0 || *p == '\n' ? 0 : -1;
}

/* The body jumps while it sounds: what it sounded goes on where it was,
   fading as a stopped stream's sound does (render_ghosts), and the
   sources start again from rest at the new place; moving the sounding
   sources with it jumped their delays within a chunk (issue 48). */
static void leave_sound(aero_body *s)
{
    drop_ghost_texture(s);
    for (int l = 0; l < s->regions; l++) {
        aero_body_source *src = &s->src[l], *gh = &s->ghost[l];
        *gh = *src;
        aero_ghost_begin(&gh->fade, src->then.amp, src->then.inc, src->step);
        src->then.amp = 0.0;
        memset(src->velocity, 0, sizeof(src->velocity));
    }
    s->n_ghosts = s->regions;
    s->fade_in = 0.0;
}

/* a texture of kind object this player can read: 0 with its regions'
   centres (body frame) and symmetry, or -1 with a message in err */
static int check_texture(const aero_texture *t, double *centre, int *sphere,
                         char *err, size_t errlen)
{
    const char *sym = t->head.symmetry;
    double v0 = t->head.v0;
    double d = t->head.diameter;
    if (aero_texture_wrong_kind(t, "object", err, errlen)) {
        return -1;
    }
    if (strcmp(sym, "sphere") && strcmp(sym, "axis")) {
        snprintf(err, errlen, "symmetry must be sphere or axis");
        return -1;
    }
    *sphere = !strcmp(sym, "sphere");
    if (!(v0 > 0.0 && v0 < 1e3) || !(d > 0.0 && d < 100.0) ||
        !(t->rate > 0.0) || t->frames < 2 || t->directions < 1 ||
        t->regions < 1 || t->regions > AERO_BODY_MAX_SOURCES ||
        (*sphere && t->directions != 1)) {
        snprintf(err, errlen, "bad metadata (v0 %g, diameter %g, %d "
                 "directions, %d regions, %d frames)", v0, d,
                 t->directions, t->regions, t->frames);
        return -1;
    }
    for (int k = 0; k < t->directions; k++)
        if (!(t->angles[k] >= 0.0 && t->angles[k] <= 180.0) ||
            (k && !(t->angles[k] > t->angles[k - 1]))) {
            snprintf(err, errlen, "angles must increase within 0..180");
            return -1;
        }
    if (!t->head.centres ||
        parse_centres(t->head.centres, t->regions, centre)) {
        snprintf(err, errlen, "centres= must list %d x,y,z triples "
                 "separated by ';'", t->regions);
        return -1;
    }
    return 0;
}

/* a texture changed while sounding: the old sources fade out reading the
   old texture, moving on as they were, as the new ones (at the body's
   speed) fade in; cutting them stepped the sound */
static void change_while_sounding(aero_body *s, aero_texture *t,
                                  int was_regions)
{
    double velocity[AERO_BODY_MAX_SOURCES][2][3];
    for (int l = 0; l < AERO_BODY_MAX_SOURCES; l++) {
        memcpy(velocity[l][0], s->src[l].velocity, sizeof(velocity[l][0]));
        memcpy(velocity[l][1], s->src[l].stream_velocity,
               sizeof(velocity[l][1]));
    }
    int regions = s->regions;
    s->regions = was_regions; /* the old sources */
    leave_sound(s);
    s->regions = regions;
    s->ghost_texture = s->texture;
    s->ghost_regions = was_regions;
    s->ghost_moving = 1;
    s->texture = t;
    restart_sources(s);
    for (int l = 0; l < AERO_BODY_MAX_SOURCES; l++) {
        memcpy(s->src[l].velocity, velocity[l][0], sizeof(velocity[l][0]));
        memcpy(s->src[l].stream_velocity, velocity[l][1],
               sizeof(velocity[l][1]));
    }
}

int aero_body_set_texture(aero_body *s, aero_texture *t,
                          char *err, size_t errlen)
{
    int was_regions = s->regions;
    if (t) {
        double centre[3 * AERO_BODY_MAX_SOURCES];
        int sphere;
        if (check_texture(t, centre, &sphere, err, errlen))
            return -1;
        s->v0 = t->head.v0;
        s->tex_size = t->head.diameter;
        s->tex_rate = t->rate;
        s->regions = t->regions;
        s->sphere = sphere;
        s->mirror = fabs(t->head.mirror) >= 1.0;
        memcpy(s->centre, centre, sizeof(double) * 3 * t->regions);
        s->re_law = !sphere && strip_re_law(s, t);
    }
    if (s->base.sounding && s->texture && t) {
        change_while_sounding(s, t, was_regions);
        return 0;
    }
    drop_ghost_texture(s);
    s->n_ghosts = 0; /* they read the old texture */
    if (s->texture) {
        aero_texture_free(s->texture);
        free(s->texture);
    }
    s->texture = t;
    if (!t)
        s->regions = 0;
    restart_sources(s);
    return 0;
}

/* --- setters --------------------------------------------------------------- */

int aero_body_set_sample_rate(aero_body *s, double sr)
{
    int rc = aero_moving_player_set_sample_rate(&s->base, sr);
    if (rc > 0) {
        for (int i = 0; i < AERO_BODY_MAX_SOURCES; i++)
            s->src[i].primed = 0;
        s->n_ghosts = 0;
        drop_ghost_texture(s);
    }
    return rc < 0 ? -1 : 0;
}

int aero_body_set_scale(aero_body *s, double scale)
{
    if (!(scale >= AERO_BODY_SCALE_MIN && scale <= AERO_BODY_SCALE_MAX))
        return -1;
    s->scale = scale;
    return 0;
}

int aero_body_set_exponent(aero_body *s, double e)
{
    return aero_moving_player_set_exponent(&s->base, e);
}

int aero_body_set_gain_db(aero_body *s, double db)
{
    return aero_moving_player_set_gain_db(&s->base, db);
}

int aero_body_set_ramp_ms(aero_body *s, double ms)
{
    return aero_moving_player_set_ramp_ms(&s->base, ms);
}

int aero_body_set_seed(aero_body *s, uint32_t seed)
{
    s->base.rng = seed ? seed : 1;
    restart_sources(s);
    return 0;
}

/* where region l's body-frame centre is for a pose */
static void region_point(const aero_body *s, const double *pose,
                         int l, double *x)
{
    double c[3] = {s->scale * s->centre[3 * l], s->scale * s->centre[3 * l + 1],
                   s->scale * s->centre[3 * l + 2]};
    rotate(pose + 3, c, x);
    for (int i = 0; i < 3; i++)
        x[i] += pose[i];
}

/* pos and quat as a pose p (the quaternion normalised): 0, or -1 */
static int make_pose(const double pos[3], const double quat[4], double *p)
{
    double n = sqrt(quat[0] * quat[0] + quat[1] * quat[1] +
                    quat[2] * quat[2] + quat[3] * quat[3]);
    if (!aero_position_ok(pos) || !aero_finite_within(quat, 4, 1e6) ||
        !(n > 1e-9))
        return -1;
    for (int i = 0; i < 3; i++)
        p[i] = pos[i];
    for (int i = 0; i < 4; i++)
        p[3 + i] = quat[i] / n;
    return 0;
}

/* a valid pose p (make_pose) */
static void apply_pose(aero_body *s, double *p, double interval_s)
{
    const double *to = s->path.to;
    /* the shorter way round: q and -q are the same turn */
    if (p[3] * to[3] + p[4] * to[4] + p[5] * to[5] + p[6] * to[6] < 0.0)
        for (int i = 3; i < 7; i++)
            p[i] = -p[i];
    /* the first pose, one after a pause (a new gesture: the stream had
       ended) or a placement (interval < 0) jumps */
    if (!s->pose_set || interval_s < 0.0 || interval_s > 0.5 ||
        aero_pose_path_ended(&s->path)) {
        if (s->base.sounding && s->texture)
            leave_sound(s);
        aero_pose_path_jump(&s->path, 7, p);
        memcpy(s->pose, p, 7 * sizeof(double));
        for (int l = 0; l < AERO_BODY_MAX_SOURCES; l++)
            memset(s->src[l].stream_velocity, 0, sizeof(double) * 3);
        s->pose_set = 1;
        return;
    }
    if (!(interval_s >= 0.001))
        interval_s = 0.001;
    if (aero_pose_path_waited(&s->path, interval_s * s->base.sample_rate)) {
        double from[7]; /* the gesture began at the last pose */
        memcpy(from, s->path.to, sizeof(from));
        if (s->base.sounding && s->texture)
            leave_sound(s);
        aero_pose_path_jump(&s->path, 7, from);
        for (int l = 0; l < AERO_BODY_MAX_SOURCES; l++)
            memset(s->src[l].velocity, 0, sizeof(s->src[l].velocity));
    }
    /* each region's velocity from the stream's own time stamps */
    for (int l = 0; l < s->regions; l++) {
        double a[3], b[3];
        region_point(s, to, l, a);
        region_point(s, p, l, b);
        for (int i = 0; i < 3; i++)
            s->src[l].stream_velocity[i] = (b[i] - a[i]) / interval_s;
    }
    /* the orientation on the same Hermite path as the position, its
       quaternion normalised (advance_pose): C1 like the position, and for
       the few degrees a body turns between poses as near the constant
       rate of a slerp as the path's speed is to the stream's */
    aero_pose_path_to(&s->path, p, interval_s * s->base.sample_rate);
}

static void flush_poses(aero_body *s)
{
    while (s->queue.n > 0) {
        aero_pose_event e = *aero_pose_queue_front(&s->queue);
        aero_pose_queue_pop(&s->queue);
        apply_pose(s, e.x, e.interval_s);
    }
}

int aero_body_set_pose(aero_body *s, const double pos[3],
                       const double quat[4], double interval_s)
{
    double p[7];
    if (make_pose(pos, quat, p))
        return -1;
    flush_poses(s); /* the poses in the order given */
    apply_pose(s, p, interval_s);
    return 0;
}

int aero_body_set_pose_at(aero_body *s, const double pos[3],
                          const double quat[4], double interval_s,
                          int offset)
{
    aero_pose_event e, oldest;
    if (make_pose(pos, quat, e.x))
        return -1;
    e.has_extra = 0;
    e.interval_s = interval_s;
    e.offset = offset;
    if (aero_pose_queue_push(&s->queue, &e, &oldest))
        apply_pose(s, oldest.x, oldest.interval_s); /* full: at once */
    return 0;
}

int aero_body_set_wind(aero_body *s, const double w[3])
{
    return aero_moving_player_set_wind(&s->base, w);
}

int aero_body_set_ears(aero_body *s, const aero_ears *e)
{
    return aero_moving_player_set_ears(&s->base, e);
}

/* --- processing --------------------------------------------------------------- */

/* the pose at the chunk's end on the path (pose_glide.h), the quaternion
   normalised */
static void advance_pose(aero_body *s, int m)
{
    double n = 0.0;
    aero_pose_path_advance(&s->path, m);
    memcpy(s->pose, s->path.pos, sizeof(s->pose));
    for (int i = 3; i < 7; i++)
        n += s->pose[i] * s->pose[i];
    n = sqrt(n);
    for (int i = 3; i < 7; i++)
        s->pose[i] = n > 1e-12 ? s->pose[i] / n : (i == 3);
}

/* a ramp's value after m samples (a chunk, shorter where a pose splits
   it) */
static double ramp_advance(aero_ramp *r, int m)
{
    if (r->left > 0.0)
        aero_glide_values(&r->value, &r->target, 1,
                          aero_glide_fraction(&r->left, m));
    return r->value;
}

/* the direction pair around theta and the weight of the second */
static void direction_pair(const aero_texture *t, double theta, int *k0,
                           int *k1, double *w)
{
    int n = t->directions, k = 0;
    *k0 = *k1 = 0;
    *w = 0.0;
    if (n < 2)
        return;
    while (k + 2 < n && t->angles[k + 1] <= theta)
        k++;
    *k0 = k;
    *k1 = k + 1;
    *w = (theta - t->angles[k]) / (t->angles[k + 1] - t->angles[k]);
    if (*w < 0.0) *w = 0.0;
    if (*w > 1.0) *w = 1.0;
}

/* the body's x axis in the world */
static void body_x_axis(const aero_body *s, double *out)
{
    const double xb[3] = {1.0, 0.0, 0.0};
    rotate(s->pose + 3, xb, out);
}

/* the unit part of v normal to the unit n (c = v.n); the body's x axis
   when v lies along n */
static void normal_part(const aero_body *s, const double *v,
                        const double *n, double c, double *out)
{
    for (int i = 0; i < 3; i++)
        out[i] = v[i] - c * n[i];
    if (aero_normalise3(out) < 1e-6) /* flow along the axis */
        body_x_axis(s, out);
}

/* the sample frame (e1, e2, e3) of the flow rel on the body's axis, the
   angle between them (theta) and whether a mirror-symmetric body reads
   it mirrored (flip): a sphere's frame follows the flow (e1 along it),
   any other body's its axis (e3) */
static void sample_frame(const aero_body *s, const double *rel,
                         const double *axis, double *e1, double *e2,
                         double *e3, aero_body_geometry *g)
{
    const double cth = aero_dot3(rel, axis);
    g->flip = 0;
    if (s->sphere) {
        memcpy(e1, rel, 3 * sizeof(double));
        normal_part(s, axis, rel, cth, e3);
        aero_cross3(e3, e1, e2);
        g->theta = 90.0;
        return;
    }
    memcpy(e3, axis, 3 * sizeof(double));
    normal_part(s, rel, axis, cth, e1);
    aero_cross3(e3, e1, e2);
    g->theta = acos(cth < -1.0 ? -1.0 : cth > 1.0 ? 1.0 : cth) * 180.0 /
               AERO_PI;
    if (s->mirror && g->theta > 90.0) {
        g->theta = 180.0 - g->theta;
        g->flip = 1;
        for (int i = 0; i < 3; i++) {
            e2[i] = -e2[i];
            e3[i] = -e3[i];
        }
    }
}

/* pitch and level at speed v off the texture's Reynolds number: Re on
   the cross-flow speed, at play and as the texture holds it (Roshko
   1954's St, Norberg 2003's C_L') */
static void follow_reynolds(const aero_body *s, int l, double v,
                            aero_body_geometry *g)
{
    double across = sin(g->theta * AERO_PI / 180.0) / s->tex_nu;
    double re0 = s->v0 * s->region_d[l] * across,
           re = v * s->scale * s->region_d[l] * across;
    if (re0 > AERO_RE_ONSET) {
        double pitch = aero_strouhal(re) / aero_strouhal(re0);
        g->inc *= pitch;
        g->amp *= pitch * aero_lift_rms(re) / aero_lift_rms(re0);
    }
}

/* per ear: the dipole's projection r . e_i / (4 pi c0 r^2) (Curle 1955)
   and the delay r / c0, from the source at pos */
static void project_on_ears(aero_body *s, const double (*ears)[3],
                            const double *pos, const double *e1,
                            const double *e2, const double *e3,
                            aero_body_geometry *g)
{
    for (int e = 0; e < s->base.n_ears; e++) {
        double r[3] = {ears[e][0] - pos[0], ears[e][1] - pos[1],
                       ears[e][2] - pos[2]};
        /* inside the body the far field does not hold: the near-field
           policy (aero_near_field), exactly at the source along e2, the
           lift (across the flow and the axis) */
        aero_near_field(r, AERO_BODY_NEAR * s->scale * s->tex_size, e2,
                        &s->base.near);
        double dist = sqrt(aero_dot3(r, r)), k;
        double dmax = AERO_BODY_MAX_DELAY_S * s->base.sample_rate;
        k = 1.0 / (4.0 * AERO_PI * AERO_C0 * dist * dist);
        g->proj[e][0] = aero_dot3(r, e1) * k;
        g->proj[e][1] = aero_dot3(r, e2) * k;
        g->proj[e][2] = aero_dot3(r, e3) * k;
        g->delay[e] = dist / AERO_C0 * s->base.sample_rate;
        if (g->delay[e] > dmax)
            g->delay[e] = dmax;
    }
}

/* geometry of region l at the chunk's end; returns 1 if clamped */
static int geometry(aero_body *s, int l, const double *wind,
                    const double (*ears)[3], double gain,
                    aero_body_geometry *g)
{
    aero_body_source *src = &s->src[l];
    double rel[3], axis[3], e1[3], e2[3], e3[3], pos[3], v;
    const double z[3] = {0.0, 0.0, 1.0};
    int clamped = 0;
    for (int i = 0; i < 3; i++)
        rel[i] = wind[i] - src->velocity[i];
    v = aero_normalise3(rel);
    if (v > AERO_MACH_LIMIT * AERO_C0) {
        v = AERO_MACH_LIMIT * AERO_C0;
        clamped = 1;
    }
    rotate(s->pose + 3, z, axis);
    if (v <= MIN_SPEED) /* still air: silent, any frame */
        body_x_axis(s, rel);
    sample_frame(s, rel, axis, e1, e2, e3, g);
    /* where it radiates from: a sphere's sectors turn with the flow */
    if (s->sphere) {
        const double *c = s->centre + 3 * l;
        for (int i = 0; i < 3; i++)
            pos[i] = s->pose[i] + s->scale * (c[0] * e1[i] + c[1] * e2[i] +
                                              c[2] * e3[i]);
    } else {
        region_point(s, s->pose, l, pos); /* the region itself; a flipped
                                             read takes its mirror image's
                                             channel (render) */
    }
    g->inc = v / s->v0 / s->scale * s->tex_rate / s->base.sample_rate;
    g->amp = v > MIN_SPEED ? pow(v / s->v0, s->base.exponent) * s->scale * gain
                           : 0.0;
    if (s->re_law && v > MIN_SPEED)
        follow_reynolds(s, l, v, g);
    project_on_ears(s, ears, pos, e1, e2, e3, g);
    return clamped;
}

/* the texture's two direction channels c0 and c1 (3 components each)
   of a source read over m samples into tex, the read position gliding
   from then's increment to g's; Catmull-Rom between frames, around the
   seamless loop */
static void read_texture(aero_body *s, aero_body_source *src,
                         const aero_body_geometry *then,
                         const aero_body_geometry *g, int c0, int c1,
                         float (*tex)[AERO_BODY_CHUNK], int m)
{
    const aero_texture *t = s->texture;
    const int ch = t->channels;
    const long frames = t->frames;
    double pos = src->pos, inc = then->inc;
    const double dinc = (g->inc - then->inc) * (1.0 / m);
    for (int j = 0; j < m; j++) {
        long i1 = (long)pos;
        float fr = (float)(pos - (double)i1);
        /* the loop's neighbours of frame i1 (it wraps seamlessly) */
        long i0 = i1 == 0 ? frames - 1 : i1 - 1;
        long i2 = i1 + 1 >= frames ? i1 + 1 - frames : i1 + 1;
        long i3 = i2 + 1 >= frames ? i2 + 1 - frames : i2 + 1;
        const float *r0 = t->data + i0 * ch, *r1 = t->data + i1 * ch,
                    *r2 = t->data + i2 * ch, *r3 = t->data + i3 * ch;
        for (int c = 0; c < 3; c++) {
            tex[c][j] = aero_catmull_rom(r0[c0 + c], r1[c0 + c],
                                         r2[c0 + c], r3[c0 + c], fr);
            tex[3 + c][j] = aero_catmull_rom(r0[c1 + c], r1[c1 + c],
                                             r2[c1 + c], r3[c1 + c], fr);
        }
        inc += dinc;
        pos = aero_texture_wrap(pos + inc, frames);
    }
    src->pos = pos;
}

/* the source's dipole as ear e hears it: the two channels' forces
   projected on the ear (Curle 1955), weighted between the pair's
   directions, gliding from then to g, into the ear's arrivals at the
   gliding delay */
static void radiate(aero_body *s, const aero_body_geometry *then,
                    const aero_body_geometry *g, double w_then,
                    double w_now, float (*tex)[AERO_BODY_CHUNK], int e,
                    int m, double *step_last)
{
    const double inv_m = 1.0 / m;
    float cf[6], dcf[6];
    float *ring = s->base.arrivals.ring[e];
    const long mask = s->base.arrivals.mask;
    const double ddelay = (g->delay[e] - then->delay[e]) * inv_m;
    double at = (double)s->base.arrivals.head + then->delay[e];
    const double step = 1.0 + ddelay, last = step_last[e];
    step_last[e] = step;
    for (int c = 0; c < 3; c++) {
        double a0 = then->amp * then->proj[e][c], a1 = g->amp * g->proj[e][c];
        double s0 = (1.0 - w_then) * a0, s1 = (1.0 - w_now) * a1;
        double t0 = w_then * a0, t1 = w_now * a1;
        cf[c] = (float)s0;
        dcf[c] = (float)((s1 - s0) * inv_m);
        cf[3 + c] = (float)t0;
        dcf[3 + c] = (float)((t1 - t0) * inv_m);
    }
    for (int j = 0; j < m; j++) {
        float v = 0.0f;
        for (int q = 0; q < 6; q++) {
            v += cf[q] * tex[q][j];
            cf[q] += dcf[q];
        }
        aero_arrivals_add_chunk(ring, mask, at, step, last, j, m, v);
        at += 1.0 + ddelay;
    }
}

/* one source (region l's, or its ghost) over a chunk of m samples; 1 if
   it sounded */
static int render(aero_body *s, aero_body_source *src, int l,
                  const aero_body_geometry *g, int m)
{
    const aero_texture *t = s->texture;
    const int R = s->regions;
    aero_body_geometry then = src->primed ? src->then : *g;
    float tex[6][AERO_BODY_CHUNK];
    int k0, k1, region;
    double w_then, w_now;
    if (!src->primed) { /* first chunk: amplitude from 0 */
        then.amp = 0.0;
        src->primed = 1;
        memset(src->step, 0, sizeof(src->step));
    }
    /* the pair of the chunk's end serves its whole chunk */
    direction_pair(t, g->theta, &k0, &k1, &w_now);
    {
        int a, b;
        direction_pair(t, then.theta, &a, &b, &w_then);
        (void)b;
        if (a != k0) /* crossed into another pair: its nearest end */
            w_then = then.theta < t->angles[k0] ? 0.0 : 1.0;
    }
    if (then.flip != g->flip) /* turned through 90 deg: start from 0 */
        then.amp = 0.0;
    region = g->flip ? R - 1 - l : l;
    read_texture(s, src, &then, g, 3 * (k0 * R + region),
                 3 * (k1 * R + region), tex, m);
    for (int e = 0; e < s->base.n_ears; e++)
        radiate(s, &then, g, w_then, w_now, tex, e, m, src->step);
    src->then = *g;
    return then.amp != 0.0 || g->amp != 0.0;
}

/* the ghosts' next m samples, each where it was, fading (ghost_fade.h);
   1 if one sounded */
static int render_ghosts(aero_body *s, int m)
{
    const double span = AERO_GHOST_FADE_S * s->base.sample_rate;
    int sounding = 0;
    /* after a texture change they read the old one */
    aero_texture *texture = s->texture;
    int regions = s->regions;
    if (s->ghost_texture) {
        s->texture = s->ghost_texture;
        s->regions = s->ghost_regions;
    }
    for (int l = 0; l < s->n_ghosts; l++) {
        aero_body_source *gh = &s->ghost[l];
        double v_then, v;
        if (!gh->primed || !(gh->fade.samples < span))
            continue;
        /* after a texture change the body goes on */
        aero_ghost_advance(&gh->fade.samples, m, span, s->ghost_moving,
                           &v_then, &v);
        aero_body_geometry g = gh->then;
        g.inc = gh->fade.inc * v;
        g.amp = gh->fade.amp * aero_ghost_fade(gh->fade.samples,
                                               s->base.sample_rate,
                                               s->base.exponent);
        /* it moves on as it slows: its delay's rate falls with v */
        for (int e = 0; e < s->base.n_ears; e++)
            g.delay[e] += gh->fade.rate[e] * 0.5 * (v_then + v) * m;
        sounding |= render(s, gh, l, &g, m);
    }
    s->texture = texture;
    s->regions = regions;
    if (!sounding) {
        s->n_ghosts = 0;
        drop_ghost_texture(s);
    }
    return sounding;
}

int aero_body_process(aero_body *s, const float *speed,
                      float *const *out, int n)
{
    s->base.clamped = 0;
    if (aero_moving_player_silent(&s->base, out, n))
        return 0;
    for (int done = 0; done < n;) {
        int m = n - done < AERO_BODY_CHUNK ? n - done : AERO_BODY_CHUNK;
        /* the poses due at this sample, then a chunk up to the next */
        while ((m = aero_pose_queue_until(&s->queue, done, m)) == 0) {
            aero_pose_event e = *aero_pose_queue_front(&s->queue);
            aero_pose_queue_pop(&s->queue);
            apply_pose(s, e.x, e.interval_s);
            m = n - done < AERO_BODY_CHUNK ? n - done : AERO_BODY_CHUNK;
        }
        double sp = 0.0, wind[3], ears[AERO_BODY_MAX_EARS][3], gain, alpha;
        double pace;
        if (speed) { /* the inlet's mean over the chunk (aero_speed_in) */
            for (int j = 0; j < m; j++) {
                float v = speed[done + j];
                sp += aero_speed_in(v, &s->base.clamped);
            }
            sp /= m;
        }
        advance_pose(s, m);
        pace = aero_pose_path_pace(&s->path);
        alpha = 1.0 - exp(-m / (AERO_VELOCITY_TAU_S * s->base.sample_rate));
        for (int i = 0; i < 3; i++)
            wind[i] = ramp_advance(&s->base.wind[i], m);
        wind[0] += sp;
        for (int e = 0; e < s->base.n_ears; e++)
            for (int i = 0; i < 3; i++)
                ears[e][i] = ramp_advance(&s->base.ear[3 * e + i], m);
        gain = ramp_advance(&s->base.gain, m);
        s->base.sounding = 0;
        if (s->texture) {
            double faded = aero_ghost_fade_in(&s->fade_in, m,
                                              s->base.sample_rate,
                                              s->base.exponent);
            for (int l = 0; l < s->regions; l++) {
                aero_body_geometry g;
                for (int i = 0; i < 3; i++) {
                    double v = pace * s->src[l].stream_velocity[i];
                    s->src[l].velocity[i] += alpha * (v - s->src[l].velocity[i]);
                }
                s->base.clamped |= geometry(s, l, wind, (const double (*)[3])ears,
                                       gain, &g);
                g.amp *= faded;
                s->base.sounding |= render(s, &s->src[l], l, &g, m);
            }
        }
        if (s->n_ghosts && s->texture)
            s->base.sounding |= render_ghosts(s, m);
        aero_arrivals_take(&s->base.arrivals, out, done, m);
        done += m;
    }
    aero_pose_queue_elapse(&s->queue, n);
    return s->base.clamped;
}
