/* [aeolian~]: the aeolian tone of a cylinder in a flow (wind past a wire, a
 * rod, a branch), or, with a texture, of any stick that moves and turns (a
 * sword, a thrown stick, a fence rail). Thin Pd wrapper around
 * src/core/play/aeolian (the Strouhal/Reynolds model, or a texture once one is
 * loaded).
 *
 *   [aeolian~ -d 0.01 -l 0.5 -gain 0 -seed 1 -ramp 20 -stereo]
 *   [aeolian~ -texture sword -n 8 -exponent 3 -stereo]
 *   inlet 1 (signal): flow speed across the axis, m/s (texture mode: a wind
 *                     along +x added to `wind`)
 *   outlet(s) (signal): sound pressure at the listener (ears), Pa
 */
#include "aero_pd.h"

#include "aeolian.h"
#include "aero_air.h"

static t_class *aeolian_tilde_class;

typedef struct _aeolian_tilde {
    t_object x_obj;
    t_float x_f;
    aero_pd_base x_base;
    aero_aeolian x_core;
    aero_pd_pose_clock x_clock; /* poses' intervals and block offsets */
} t_aeolian_tilde;

#define OBJ "[aeolian~]"

static int aeolian_tilde_process(void *obj, const float *in,
                                 float *const *out, int n)
{
    t_aeolian_tilde *x = obj;
    aero_pd_pose_clock_block(&x->x_clock);
    int clamped = aero_aeolian_process(&x->x_core, in, out, n);
    aero_pd_near(&x->x_base, &x->x_core.near);
    return clamped;
}

static void aeolian_tilde_dsp(t_aeolian_tilde *x, t_signal **sp)
{
    aero_pd_pose_clock_dsp(&x->x_clock, sp[0]);
    if (aero_aeolian_set_sample_rate(&x->x_core, sp[0]->s_sr))
        aero_pd_rate_failed(&x->x_base, sp[0]->s_sr);
    aero_pd_dsp(&x->x_base, sp, 1, aeolian_tilde_process);
}

/* --- messages (each also a creation flag of the same name) --------------- */

AERO_PD_SETTER(aeolian_tilde, t_aeolian_tilde, diameter, x_core,
               aero_aeolian_set_diameter)
AERO_PD_SETTER(aeolian_tilde, t_aeolian_tilde, length, x_core,
               aero_aeolian_set_length)
AERO_PD_SETTER(aeolian_tilde, t_aeolian_tilde, gain, x_core,
               aero_aeolian_set_gain_db)
AERO_PD_SETTER(aeolian_tilde, t_aeolian_tilde, ramp, x_core,
               aero_aeolian_set_ramp_ms)
AERO_PD_SETTER(aeolian_tilde, t_aeolian_tilde, roll, x_core,
               aero_aeolian_set_roll_deg)
AERO_PD_SETTER_WHOLE(aeolian_tilde, t_aeolian_tilde, n, x_core,
                     aero_aeolian_set_sources)
AERO_PD_SETTER(aeolian_tilde, t_aeolian_tilde, exponent, x_core,
               aero_aeolian_set_exponent)

AERO_PD_SEED_SETTER(aeolian_tilde, t_aeolian_tilde, x_core,
                    aero_aeolian_set_seed)

static void aeolian_tilde_listener(t_aeolian_tilde *x, t_symbol *s, int argc,
                                   t_atom *argv)
{
    aero_ears e;
    if (aero_pd_ears(&x->x_base, s, argc, argv, &e) &&
        aero_aeolian_set_ears(&x->x_core, &e))
        aero_pd_bad_ears(&x->x_base, e.n);
}

static int aeolian_tilde_set_texture(void *core, aero_texture *t, char *err,
                                     size_t len)
{
    return aero_aeolian_set_texture(core, t, err, len);
}

/* file I/O here, in the message domain, never in perform */
static void aeolian_tilde_texture(t_aeolian_tilde *x, t_symbol *name)
{
    aero_pd_load_texture(&x->x_base, aeolian_tilde_class, name,
                         aeolian_tilde_set_texture, &x->x_core,
                         "using the Strouhal/Reynolds model");
}

static void aeolian_tilde_model(t_aeolian_tilde *x)
{
    char err[8];
    aero_aeolian_set_texture(&x->x_core, NULL, err, sizeof(err));
    x->x_base.has_file = 0;
}

/* pose|place ax ay az bx by bz [ux uy uz]: the stick's ends, and the
   body's x axis (angle 0 of the texture's directions) */
static void aeolian_tilde_pose(t_aeolian_tilde *x, t_symbol *s, int argc,
                               t_atom *argv)
{
    double v[9];
    if (argc != 6 && argc != 9) {
        pd_error(x, OBJ ": '%s' takes ax ay az bx by bz [ux uy uz] "
                 "(6 or 9 numbers), got %d", s->s_name, argc);
        return;
    }
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, argc, v))
        return;
    int offset; /* place: a jump, no motion */
    double interval = aero_pd_pose_clock_pose(
        &x->x_clock, !strcmp(s->s_name, "place"), &offset);
    if (aero_aeolian_set_pose_at(&x->x_core, v, v + 3,
                                 argc == 9 ? v + 6 : NULL, interval, offset))
        aero_pd_refused_list(&x->x_base, s->s_name);
}

static void aeolian_tilde_wind(t_aeolian_tilde *x, t_symbol *s, int argc,
                               t_atom *argv)
{
    double v[3];
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (aero_aeolian_set_wind(&x->x_core, v))
        aero_pd_refused_list(&x->x_base, s->s_name);
}

/* --- creation -------------------------------------------------------------- */

#define DIAMETER                                                          \
    AERO_PD_RANGE_DEF(AERO_AEOLIAN_D_MIN, AERO_AEOLIAN_D_MAX,            \
                      AERO_AEOLIAN_DIAMETER_DEFAULT, "m")
#define LENGTH                                                            \
    AERO_PD_RANGE_DEF(AERO_AEOLIAN_L_MIN, AERO_AEOLIAN_L_MAX,            \
                      AERO_AEOLIAN_LENGTH_DEFAULT, "m")
#define POSE                                                              \
    AERO_PD_RANGE_NOTE(-AERO_POSITION_LIMIT, AERO_POSITION_LIMIT, "m",   \
                       "two distinct finite ends; a finite non-zero axis")

static const aero_pd_method aeolian_tilde_methods[] = {
    {"stereo", AERO_PD_SWITCH, 0, NULL, 0, AERO_PD_NO_RULE},
    /* the diameter first, so that a texture loaded by -texture sees it */
    {"d", AERO_PD_FLOAT, 0, (t_method)aeolian_tilde_diameter, AERO_PD_EARLY,
     DIAMETER},
    {"diameter", AERO_PD_FLOAT, 0, (t_method)aeolian_tilde_diameter,
     AERO_PD_EARLY, DIAMETER},
    {"l", AERO_PD_FLOAT, 0, (t_method)aeolian_tilde_length, 0, LENGTH},
    {"length", AERO_PD_FLOAT, 0, (t_method)aeolian_tilde_length, 0, LENGTH},
    {"gain", AERO_PD_FLOAT, 0, (t_method)aeolian_tilde_gain, 0,
     AERO_PD_GAIN},
    {"seed", AERO_PD_FLOAT, 0, (t_method)aeolian_tilde_seed, 0,
     AERO_PD_SEED},
    {"ramp", AERO_PD_FLOAT, 0, (t_method)aeolian_tilde_ramp, 0,
     AERO_PD_RAMP},
    {"listener", AERO_PD_LIST, 3, (t_method)aeolian_tilde_listener, 0, AERO_PD_NO_RULE},
    {"ears", AERO_PD_LIST, 6, (t_method)aeolian_tilde_listener, 0, AERO_PD_NO_RULE},
    {"texture", AERO_PD_SYMBOL, 0, (t_method)aeolian_tilde_texture, 0, AERO_PD_NO_RULE},
    {"n", AERO_PD_FLOAT, 0, (t_method)aeolian_tilde_n, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_AEOLIAN_SOURCES_MIN, AERO_AEOLIAN_SOURCES_MAX,
                            AERO_AEOLIAN_SOURCES_DEFAULT, NULL,
                            "point sources, 0: auto, length / 3 d")},
    {"exponent", AERO_PD_FLOAT, 0, (t_method)aeolian_tilde_exponent, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_AEOLIAN_EXPONENT_MIN,
                            AERO_AEOLIAN_EXPONENT_MAX,
                            AERO_AEOLIAN_EXPONENT_DEFAULT, NULL,
                            "3 is physical, 6 the paper's")},
    {"roll", AERO_PD_FLOAT, 0, (t_method)aeolian_tilde_roll, 0,
     AERO_PD_NOTE("finite degrees")},
    {"wind", AERO_PD_LIST, 3, (t_method)aeolian_tilde_wind, 0,
     AERO_PD_RANGE_NOTE(AERO_MOVING_WIND_MIN, AERO_MOVING_WIND_MAX, "m/s",
                        "finite")},
    {"model", AERO_PD_BANG, 0, (t_method)aeolian_tilde_model,
     AERO_PD_MESSAGE_ONLY, AERO_PD_NO_RULE},
    {"pose", AERO_PD_LIST, 0, (t_method)aeolian_tilde_pose,
     AERO_PD_MESSAGE_ONLY, POSE},
    {"place", AERO_PD_LIST, 0, (t_method)aeolian_tilde_pose,
     AERO_PD_MESSAGE_ONLY, POSE},
};

static const aero_pd_spec aeolian_tilde_spec = {
    "aeolian~", aeolian_tilde_methods, AERO_PD_COUNT(aeolian_tilde_methods),
    NULL};

static void *aeolian_tilde_new(t_symbol *s, int argc, t_atom *argv)
{
    (void)s;
    t_aeolian_tilde *x = (t_aeolian_tilde *)pd_new(aeolian_tilde_class);
    aero_pd_base_init(&x->x_base, x, &aeolian_tilde_spec, argc, argv);
    if (aero_aeolian_init(&x->x_core, sys_getsr(),
                          x->x_base.stereo ? 2 : 1, aero_pd_default_seed()))
        aero_pd_init_failed(&x->x_base, sys_getsr());
    aero_pd_pose_clock_init(&x->x_clock);
    aero_pd_parse_flags(&x->x_base, argc, argv);
    aero_pd_base_outlets(&x->x_base);
    return x;
}

static void aeolian_tilde_free(t_aeolian_tilde *x)
{
    aero_pd_base_free(&x->x_base);
    aero_aeolian_free(&x->x_core);
}

AERO_PD_EXPORT void aeolian_tilde_setup(void)
{
    aeolian_tilde_class = aero_pd_class_new(
        &aeolian_tilde_spec, (t_newmethod)(t_method)aeolian_tilde_new,
        (t_method)aeolian_tilde_free, sizeof(t_aeolian_tilde),
        offsetof(t_aeolian_tilde, x_f), (t_method)aeolian_tilde_dsp);
}
