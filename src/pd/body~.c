/* [body~]: the aeolian sound of a 3D body that moves and turns (a sphere
 * whirled on a wire, a club, the ends of a thrown stick), played from an
 * object texture made by `aerotex object` (Dobashi et al. 2003, the 3D case).
 * Thin Pd wrapper around src/core/play/body: it parses flags, routes
 * messages to setters and calls process from perform.
 *
 *   [body~ -texture sphere -stereo -scale 1 -exponent 3 -gain 0]
 *   inlet 1 (signal): a wind along +x, m/s, added to `wind`
 *   outlet(s) (signal): sound pressure at the listener (ears), Pa
 */
#include "aero_pd.h"

#include <math.h>

#include "aero_air.h"
#include "body.h"

static t_class *body_tilde_class;

typedef struct _body_tilde {
    t_object x_obj;
    t_float x_f;
    aero_pd_base x_base;
    aero_body x_core;
    aero_pd_pose_clock x_clock; /* poses' intervals and block offsets */
} t_body_tilde;

#define OBJ "[body~]"

static int body_tilde_process(void *obj, const float *in, float *const *out,
                              int n)
{
    t_body_tilde *x = obj;
    aero_pd_pose_clock_block(&x->x_clock);
    int clamped = aero_body_process(&x->x_core, in, out, n);
    aero_pd_near(&x->x_base, &x->x_core.base.near);
    return clamped;
}

static void body_tilde_dsp(t_body_tilde *x, t_signal **sp)
{
    aero_pd_pose_clock_dsp(&x->x_clock, sp[0]);
    if (aero_body_set_sample_rate(&x->x_core, sp[0]->s_sr))
        aero_pd_rate_failed(&x->x_base, sp[0]->s_sr);
    aero_pd_dsp(&x->x_base, sp, 1, body_tilde_process);
}

/* --- messages (each also a creation flag of the same name) --------------- */

static int body_tilde_set_texture(void *core, aero_texture *t, char *err,
                                  size_t len)
{
    return aero_body_set_texture(core, t, err, len);
}

/* file I/O here, in the message domain, never in perform */
static void body_tilde_texture(t_body_tilde *x, t_symbol *name)
{
    aero_pd_load_texture(&x->x_base, body_tilde_class, name,
                         body_tilde_set_texture, &x->x_core, "silent");
}

/* pose|place x y z [rx ry rz | qw qx qy qz]: a position alone keeps the
   orientation; three more numbers are a rotation vector (axis times angle
   in degrees), four a quaternion */
static void body_tilde_pose(t_body_tilde *x, t_symbol *s, int argc,
                            t_atom *argv)
{
    double v[3], q[4], now[4], interval;
    int offset;
    aero_body_orientation(&x->x_core, now);
    if (aero_pd_pose(&x->x_base, &x->x_clock, s, argc, argv, now, v, q,
                     &interval, &offset))
        return;
    if (aero_body_set_pose_at(&x->x_core, v, q, interval, offset))
        aero_pd_refused_list(&x->x_base, s->s_name);
}

static void body_tilde_wind(t_body_tilde *x, t_symbol *s, int argc,
                            t_atom *argv)
{
    double v[3];
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (aero_body_set_wind(&x->x_core, v))
        aero_pd_refused_list(&x->x_base, s->s_name);
}

static void body_tilde_listener(t_body_tilde *x, t_symbol *s, int argc,
                                t_atom *argv)
{
    aero_ears e;
    if (aero_pd_ears(&x->x_base, s, argc, argv, &e) &&
        aero_body_set_ears(&x->x_core, &e))
        aero_pd_bad_ears(&x->x_base, e.n);
}

AERO_PD_SETTER(body_tilde, t_body_tilde, scale, x_core,
               aero_body_set_scale)
AERO_PD_SETTER(body_tilde, t_body_tilde, exponent, x_core,
               aero_body_set_exponent)
AERO_PD_SETTER(body_tilde, t_body_tilde, gain, x_core,
               aero_body_set_gain_db)
AERO_PD_SETTER(body_tilde, t_body_tilde, ramp, x_core,
               aero_body_set_ramp_ms)

AERO_PD_SEED_SETTER(body_tilde, t_body_tilde, x_core,
                    aero_body_set_seed)

/* --- creation -------------------------------------------------------------- */

#define POSE                                                              \
    AERO_PD_RANGE_NOTE(-AERO_POSITION_LIMIT, AERO_POSITION_LIMIT, "m",   \
                       "x y z, a finite rotation vector rx ry rz in deg " \
                       "or a non-zero quaternion qw qx qy qz")

static const aero_pd_method body_tilde_methods[] = {
    {"stereo", AERO_PD_SWITCH, 0, NULL, 0, AERO_PD_NO_RULE},
    {"texture", AERO_PD_SYMBOL, 0, (t_method)body_tilde_texture, 0, AERO_PD_NO_RULE},
    {"scale", AERO_PD_FLOAT, 0, (t_method)body_tilde_scale, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_BODY_SCALE_MIN, AERO_BODY_SCALE_MAX,
                            AERO_BODY_SCALE_DEFAULT, NULL,
                            "of the texture's body")},
    {"exponent", AERO_PD_FLOAT, 0, (t_method)body_tilde_exponent, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_MOVING_EXPONENT_MIN,
                            AERO_MOVING_EXPONENT_MAX,
                            AERO_MOVING_EXPONENT_DEFAULT, NULL,
                            "3 is physical, 6 the paper's")},
    {"gain", AERO_PD_FLOAT, 0, (t_method)body_tilde_gain, 0,
     AERO_PD_GAIN},
    {"ramp", AERO_PD_FLOAT, 0, (t_method)body_tilde_ramp, 0,
     AERO_PD_RAMP},
    {"seed", AERO_PD_FLOAT, 0, (t_method)body_tilde_seed, 0,
     AERO_PD_SEED},
    {"listener", AERO_PD_LIST, 3, (t_method)body_tilde_listener, 0, AERO_PD_NO_RULE},
    {"ears", AERO_PD_LIST, 6, (t_method)body_tilde_listener, 0, AERO_PD_NO_RULE},
    {"wind", AERO_PD_LIST, 3, (t_method)body_tilde_wind, 0,
     AERO_PD_RANGE_NOTE(AERO_MOVING_WIND_MIN, AERO_MOVING_WIND_MAX, "m/s",
                        "finite")},
    {"pose", AERO_PD_LIST, 0, (t_method)body_tilde_pose,
     AERO_PD_MESSAGE_ONLY, POSE},
    {"place", AERO_PD_LIST, 0, (t_method)body_tilde_pose,
     AERO_PD_MESSAGE_ONLY, POSE},
};

static const aero_pd_spec body_tilde_spec = {
    "body~", body_tilde_methods, AERO_PD_COUNT(body_tilde_methods), NULL};

static void *body_tilde_new(t_symbol *s, int argc, t_atom *argv)
{
    (void)s;
    t_body_tilde *x = (t_body_tilde *)pd_new(body_tilde_class);
    aero_pd_base_init(&x->x_base, x, &body_tilde_spec, argc, argv);
    if (aero_body_init(&x->x_core, sys_getsr(), x->x_base.stereo ? 2 : 1,
                       aero_pd_default_seed()))
        aero_pd_init_failed(&x->x_base, sys_getsr());
    aero_pd_pose_clock_init(&x->x_clock);
    aero_pd_parse_flags(&x->x_base, argc, argv);
    aero_pd_no_file(&x->x_base, "texture", "texture");
    aero_pd_base_outlets(&x->x_base);
    return x;
}

static void body_tilde_free(t_body_tilde *x)
{
    aero_pd_base_free(&x->x_base);
    aero_body_free(&x->x_core);
}

AERO_PD_EXPORT void body_tilde_setup(void)
{
    body_tilde_class = aero_pd_class_new(
        &body_tilde_spec, (t_newmethod)(t_method)body_tilde_new,
        (t_method)body_tilde_free, sizeof(t_body_tilde),
        offsetof(t_body_tilde, x_f), (t_method)body_tilde_dsp);
}
