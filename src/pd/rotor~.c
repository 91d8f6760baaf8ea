/* [rotor~]: a fan, a propeller, a drone's rotor or a wind turbine: B blades
 * turning at a speed in rpm given as a signal, their steady thrust and
 * torque heard as the blade-passing tone and its harmonics (Gutin 1936 per
 * blade strip, with thickness) and, behind struts, their unsteady loading
 * (Lowson and Ollerhead 1969), from a hub placed and turned by a pose.
 * Thin Pd wrapper around src/core/play/rotor: it parses flags, routes
 * messages to setters and calls process from perform.
 *
 *   [rotor~ -blades 2 -radius 0.12 -thrust 4 -torque 0.06 -design 6000]
 *   inlet 1 (signal): the speed of rotation, rpm
 *   outlet(s) (signal): sound pressure at the listener (ears), Pa
 */
#include "aero_pd.h"

#include <math.h>
#include <stdlib.h>

#include "rotor.h"

static t_class *rotor_tilde_class;

typedef struct _rotor_tilde {
    t_object x_obj;
    t_float x_f;
    aero_pd_base x_base;
    aero_rotor x_core;
    aero_pd_pose_clock x_clock; /* poses' intervals and block offsets */
    /* a blade table read in a worker and taken by the clock (aero_pd_swap:
       its job, its poll, the latest asked for meanwhile; no core is
       swapped, the table is set on the live one) */
    aero_pd_swap x_swap;
    int x_creating;
} t_rotor_tilde;

#define OBJ "[rotor~]"

/* a blade table being read: the worker writes b, err and bad only */
typedef struct rotor_blade_load {
    char path[MAXPDSTRING];
    aero_rotor_blade b;
    char err[256];
    int bad;
} rotor_blade_load;

static int rotor_tilde_process(void *obj, const float *in, float *const *out,
                               int n)
{
    t_rotor_tilde *x = obj;
    aero_pd_pose_clock_block(&x->x_clock);
    int clamped = aero_rotor_process(&x->x_core, in, out, n);
    aero_pd_near(&x->x_base, &x->x_core.base.near);
    return clamped;
}

static void rotor_tilde_dsp(t_rotor_tilde *x, t_signal **sp)
{
    aero_pd_pose_clock_dsp(&x->x_clock, sp[0]);
    if (aero_rotor_set_sample_rate(&x->x_core, sp[0]->s_sr))
        aero_pd_rate_failed(&x->x_base, sp[0]->s_sr);
    aero_pd_dsp(&x->x_base, sp, 1, rotor_tilde_process);
}

/* --- messages (each also a creation flag of the same name) --------------- */

/* pose|place x y z [rx ry rz | qw qx qy qz]: a position alone keeps the
   orientation; three more numbers are a rotation vector (axis times angle
   in degrees), four a quaternion */
static void rotor_tilde_pose(t_rotor_tilde *x, t_symbol *s, int argc,
                             t_atom *argv)
{
    double v[3], q[4], now[4], interval;
    int offset;
    aero_rotor_orientation(&x->x_core, now);
    if (aero_pd_pose(&x->x_base, &x->x_clock, s, argc, argv, now, v, q,
                     &interval, &offset))
        return;
    if (aero_rotor_set_pose_at(&x->x_core, v, q, interval, offset))
        aero_pd_refused_list(&x->x_base, s->s_name);
}

static void rotor_tilde_wind(t_rotor_tilde *x, t_symbol *s, int argc,
                             t_atom *argv)
{
    double v[3];
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (aero_rotor_set_wind(&x->x_core, v))
        aero_pd_refused_list(&x->x_base, s->s_name);
}

static void rotor_tilde_listener(t_rotor_tilde *x, t_symbol *s, int argc,
                                 t_atom *argv)
{
    aero_ears e;
    if (aero_pd_ears(&x->x_base, s, argc, argv, &e) &&
        aero_rotor_set_ears(&x->x_core, &e))
        aero_pd_bad_ears(&x->x_base, e.n);
}

AERO_PD_SETTER_WHOLE(rotor_tilde, t_rotor_tilde, blades, x_core,
                     aero_rotor_set_blades)
AERO_PD_SETTER_WHOLE(rotor_tilde, t_rotor_tilde, strips, x_core,
                     aero_rotor_set_strips)
AERO_PD_SETTER(rotor_tilde, t_rotor_tilde, radius, x_core,
               aero_rotor_set_radius)
AERO_PD_SETTER(rotor_tilde, t_rotor_tilde, chord, x_core,
               aero_rotor_set_chord)
AERO_PD_SETTER(rotor_tilde, t_rotor_tilde, thickness, x_core,
               aero_rotor_set_thickness)
AERO_PD_SETTER(rotor_tilde, t_rotor_tilde, hub, x_core, aero_rotor_set_hub)
AERO_PD_SETTER(rotor_tilde, t_rotor_tilde, thrust, x_core,
               aero_rotor_set_thrust)
AERO_PD_SETTER(rotor_tilde, t_rotor_tilde, torque, x_core,
               aero_rotor_set_torque)
AERO_PD_SETTER(rotor_tilde, t_rotor_tilde, design, x_core,
               aero_rotor_set_design)
AERO_PD_SETTER(rotor_tilde, t_rotor_tilde, noise, x_core,
               aero_rotor_set_noise_db)
AERO_PD_SETTER_WHOLE(rotor_tilde, t_rotor_tilde, struts, x_core,
                     aero_rotor_set_struts)
AERO_PD_SETTER(rotor_tilde, t_rotor_tilde, distortion, x_core,
               aero_rotor_set_distortion)
AERO_PD_SETTER(rotor_tilde, t_rotor_tilde, wake, x_core,
               aero_rotor_set_wake)
AERO_PD_SETTER(rotor_tilde, t_rotor_tilde, gain, x_core,
               aero_rotor_set_gain_db)
AERO_PD_SETTER(rotor_tilde, t_rotor_tilde, ramp, x_core,
               aero_rotor_set_ramp_ms)

AERO_PD_SEED_SETTER(rotor_tilde, t_rotor_tilde, x_core,
                    aero_rotor_set_seed)

/* --- the blade's table (chord and twist per radius) ----------------------- */

static int rotor_tilde_read(void *arg)
{
    rotor_blade_load *l = arg;
    l->bad = aero_rotor_blade_load(l->path, &l->b, l->err, sizeof(l->err));
    return l->bad;
}

static void rotor_tilde_blade(t_rotor_tilde *x, t_symbol *name);

/* the read done: the table taken, or why not (the old blade stays) */
static void rotor_tilde_finish(void *owner)
{
    t_rotor_tilde *x = owner;
    rotor_blade_load *l = aero_pd_swap_take(&x->x_swap);
    if (l->bad)
        pd_error(x, OBJ ": blade: %s: the previous blade stays", l->err);
    else if (aero_rotor_set_blade(&x->x_core, &l->b))
        pd_error(x, OBJ ": blade: %s refused: the previous blade stays",
                 l->path);
    free(l);
    if (x->x_swap.next) {
        t_symbol *next = x->x_swap.next;
        x->x_swap.next = NULL;
        rotor_tilde_blade(x, next);
    }
}

/* aero_pd_swap's old core: never set here */
static void rotor_tilde_no_core(void *core)
{
    (void)core;
}

/* blade <file>: a table of r/R chord twist_deg (found as textures and
   trees are, then in abstractions/), read in a worker so that Pd's thread
   never waits on the disk; at creation (-blade) at once, so the first
   block plays it. `blade` alone: the uniform chord again */
static void rotor_tilde_blade(t_rotor_tilde *x, t_symbol *name)
{
    if (!name || !*name->s_name) {
        if (x->x_swap.job)
            x->x_swap.next = NULL;
        aero_rotor_set_blade(&x->x_core, NULL);
        return;
    }
    if (x->x_swap.job) {
        x->x_swap.next = name; /* the latest wins */
        return;
    }
    rotor_blade_load *l = calloc(1, sizeof(*l));
    if (!l) {
        pd_error(x, OBJ ": blade: out of memory: the previous blade stays");
        return;
    }
    if (aero_pd_find_file(x->x_base.canvas, rotor_tilde_class, name->s_name,
                          ".blade", "abstractions", l->path,
                          sizeof(l->path))) {
        pd_error(x, OBJ ": blade: can't find '%s' (looked %s): the previous "
                 "blade stays", name->s_name, l->path);
        free(l);
        return;
    }
    /* blade files are small (AERO_ROTOR_BLADE_FILE_MAX): read at once at
       creation */
    if (aero_pd_swap_start(&x->x_swap, rotor_tilde_read, l,
                           x->x_creating)) {
        free(l);
        pd_error(x, OBJ ": blade: out of memory: the previous blade stays");
    }
}

/* --- creation -------------------------------------------------------------- */

#define POSE                                                              \
    AERO_PD_RANGE_NOTE(-AERO_POSITION_LIMIT, AERO_POSITION_LIMIT, "m",   \
                       "x y z, a finite rotation vector rx ry rz in deg " \
                       "or a non-zero quaternion qw qx qy qz")

static const aero_pd_method rotor_tilde_methods[] = {
    {"stereo", AERO_PD_SWITCH, 0, NULL, 0, AERO_PD_NO_RULE},
    {"blades", AERO_PD_FLOAT, 0, (t_method)rotor_tilde_blades, 0,
     AERO_PD_RANGE_DEF(AERO_ROTOR_BLADES_MIN, AERO_ROTOR_BLADES_MAX,
                       AERO_ROTOR_BLADES_DEFAULT, NULL)},
    {"radius", AERO_PD_FLOAT, 0, (t_method)rotor_tilde_radius, 0,
     AERO_PD_RANGE_DEF(AERO_ROTOR_RADIUS_MIN, AERO_ROTOR_RADIUS_MAX,
                       AERO_ROTOR_RADIUS_DEFAULT, "m")},
    {"chord", AERO_PD_FLOAT, 0, (t_method)rotor_tilde_chord, 0,
     AERO_PD_RANGE_DEF(AERO_ROTOR_CHORD_MIN, AERO_ROTOR_CHORD_MAX,
                       AERO_ROTOR_CHORD_DEFAULT, "m")},
    {"thickness", AERO_PD_FLOAT, 0, (t_method)rotor_tilde_thickness, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_ROTOR_THICKNESS_MIN,
                            AERO_ROTOR_THICKNESS_MAX,
                            AERO_ROTOR_THICKNESS_DEFAULT, NULL,
                            "of the chord")},
    {"hub", AERO_PD_FLOAT, 0, (t_method)rotor_tilde_hub, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_ROTOR_HUB_MIN, AERO_ROTOR_HUB_MAX,
                            AERO_ROTOR_HUB_DEFAULT, NULL, "of the radius")},
    {"strips", AERO_PD_FLOAT, 0, (t_method)rotor_tilde_strips, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_ROTOR_STRIPS_MIN, AERO_ROTOR_STRIPS_MAX,
                            AERO_ROTOR_STRIPS_DEFAULT, NULL,
                            "per blade; 1 = at 0.8 of the radius")},
    {"thrust", AERO_PD_FLOAT, 0, (t_method)rotor_tilde_thrust, 0,
     AERO_PD_RANGE_NOTE_DEF(-AERO_ROTOR_THRUST_LIMIT, AERO_ROTOR_THRUST_LIMIT,
                            AERO_ROTOR_THRUST_DEFAULT, "N",
                            "at the design rpm")},
    {"torque", AERO_PD_FLOAT, 0, (t_method)rotor_tilde_torque, 0,
     AERO_PD_RANGE_NOTE_DEF(-AERO_ROTOR_TORQUE_LIMIT, AERO_ROTOR_TORQUE_LIMIT,
                            AERO_ROTOR_TORQUE_DEFAULT, "N m",
                            "at the design rpm")},
    {"design", AERO_PD_FLOAT, 0, (t_method)rotor_tilde_design, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_ROTOR_DESIGN_MIN, AERO_ROTOR_DESIGN_MAX,
                            AERO_ROTOR_DESIGN_DEFAULT, "rpm",
                            "thrust and torque scale as (rpm/design)^2")},
    {"noise", AERO_PD_FLOAT, 0, (t_method)rotor_tilde_noise, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_ROTOR_NOISE_DB_MIN, AERO_ROTOR_NOISE_DB_MAX,
                            AERO_ROTOR_NOISE_DB_DEFAULT, "dB",
                            "the blades' self-noise (Brooks et al. 1989)")},
    {"struts", AERO_PD_FLOAT, 0, (t_method)rotor_tilde_struts, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_ROTOR_STRUTS_MIN, AERO_ROTOR_STRUTS_MAX,
                            AERO_ROTOR_STRUTS_DEFAULT, NULL,
                            "wakes in the inflow, evenly spaced")},
    {"distortion", AERO_PD_FLOAT, 0, (t_method)rotor_tilde_distortion, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_ROTOR_DISTORTION_MIN,
                            AERO_ROTOR_DISTORTION_MAX,
                            AERO_ROTOR_DISTORTION_DEFAULT, NULL,
                            "the loading's dip in a wake, of the steady; "
                            "< 0 a rise")},
    {"wake", AERO_PD_FLOAT, 0, (t_method)rotor_tilde_wake, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_ROTOR_WAKE_MIN, AERO_ROTOR_WAKE_MAX,
                            AERO_ROTOR_WAKE_DEFAULT, "m",
                            "a wake's width at half depth")},
    {"gain", AERO_PD_FLOAT, 0, (t_method)rotor_tilde_gain, 0, AERO_PD_GAIN},
    {"ramp", AERO_PD_FLOAT, 0, (t_method)rotor_tilde_ramp, 0, AERO_PD_RAMP},
    {"seed", AERO_PD_FLOAT, 0, (t_method)rotor_tilde_seed, 0, AERO_PD_SEED},
    {"listener", AERO_PD_LIST, 3, (t_method)rotor_tilde_listener, 0,
     AERO_PD_NO_RULE},
    {"ears", AERO_PD_LIST, 6, (t_method)rotor_tilde_listener, 0,
     AERO_PD_NO_RULE},
    {"wind", AERO_PD_LIST, 3, (t_method)rotor_tilde_wind, 0,
     AERO_PD_RANGE_NOTE(AERO_MOVING_WIND_MIN, AERO_MOVING_WIND_MAX, "m/s",
                        "finite")},
    {"blade", AERO_PD_SYMBOL, 0, (t_method)rotor_tilde_blade, 0,
     AERO_PD_NO_RULE},
    {"pose", AERO_PD_LIST, 0, (t_method)rotor_tilde_pose,
     AERO_PD_MESSAGE_ONLY, POSE},
    {"place", AERO_PD_LIST, 0, (t_method)rotor_tilde_pose,
     AERO_PD_MESSAGE_ONLY, POSE},
};

static const aero_pd_spec rotor_tilde_spec = {
    "rotor~", rotor_tilde_methods, AERO_PD_COUNT(rotor_tilde_methods), NULL};

static void *rotor_tilde_new(t_symbol *s, int argc, t_atom *argv)
{
    (void)s;
    t_rotor_tilde *x = (t_rotor_tilde *)pd_new(rotor_tilde_class);
    aero_pd_base_init(&x->x_base, x, &rotor_tilde_spec, argc, argv);
    x->x_base.clamp_words = "rpm clamped where the blade tips reach Mach "
        AERO_PD_STR(AERO_ROTOR_MACH_TIP_MAX);
    if (aero_rotor_init(&x->x_core, sys_getsr(), x->x_base.stereo ? 2 : 1,
                        aero_pd_default_seed()))
        aero_pd_init_failed(&x->x_base, sys_getsr());
    aero_pd_pose_clock_init(&x->x_clock);
    aero_pd_swap_init(&x->x_swap, x, rotor_tilde_finish,
                      rotor_tilde_no_core);
    x->x_creating = 1;
    aero_pd_parse_flags(&x->x_base, argc, argv);
    x->x_creating = 0;
    aero_pd_base_outlets(&x->x_base);
    return x;
}

static void rotor_tilde_free(t_rotor_tilde *x)
{
    /* a read running: the worker frees its load when it is done */
    aero_pd_swap_free(&x->x_swap, free);
    aero_pd_base_free(&x->x_base);
    aero_rotor_free(&x->x_core);
}

AERO_PD_EXPORT void rotor_tilde_setup(void)
{
    rotor_tilde_class = aero_pd_class_new(
        &rotor_tilde_spec, (t_newmethod)(t_method)rotor_tilde_new,
        (t_method)rotor_tilde_free, sizeof(t_rotor_tilde),
        offsetof(t_rotor_tilde, x_f), (t_method)rotor_tilde_dsp);
}
