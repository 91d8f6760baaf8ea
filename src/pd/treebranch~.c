/* [treebranch~]: the sound of a tree's branches in the wind (Matsuyama et al.
 * 2005). Thin Pd wrapper around src/core/play/treebranch.
 *
 *   [treebranch~ <treefile> -stereo -seed 1 -listener 0 -10 1.7]
 *   inlet 1 (signal or float): wind speed along the wind direction, m/s
 *   outlet 1 (signal): sound pressure at the listener (left ear), Pa
 *   outlet 2 (signal, with -stereo): right ear, Pa
 */
#include "aero_pd.h"
#include "moving_player.h"

#include "treebranch.h"

static t_class *treebranch_tilde_class;

typedef struct _treebranch_tilde {
    t_object x_obj;
    t_float x_f;
    aero_pd_base x_base;
    aero_pd_wind x_wind;
    aero_treebranch x_core;
} t_treebranch_tilde;

#define OBJ "[treebranch~]"

static int treebranch_tilde_process(void *obj, const float *in,
                                    float *const *out, int n)
{
    t_treebranch_tilde *x = obj;
    /* the inlet is the speed along the wind's direction; the core takes
       the block's mean and reports a clamp */
    return aero_treebranch_process_speed(&x->x_core, in, out[0], out[1], n);
}

static void treebranch_tilde_dsp(t_treebranch_tilde *x, t_signal **sp)
{
    if (aero_treebranch_set_sample_rate(&x->x_core, sp[0]->s_sr))
        pd_error(x, OBJ ": bad sample rate %g (or out of memory)",
                 sp[0]->s_sr);
    aero_pd_dsp(&x->x_base, sp, 1, treebranch_tilde_process);
}

/* file I/O here, in the message domain, never in perform */
static void treebranch_tilde_open(t_treebranch_tilde *x, t_symbol *name)
{
    aero_tree t;
    if (aero_pd_load_tree(&x->x_base, treebranch_tilde_class, name, &t))
        return; /* the tree that played, if any, plays on */
    if (aero_treebranch_set_tree(&x->x_core, &t))
        pd_error(x, OBJ ": %s: out of memory: silent", name->s_name);
}

static void treebranch_tilde_wind(t_treebranch_tilde *x, t_symbol *s,
                                  int argc, t_atom *argv)
{
    double speed = aero_pd_wind_message(&x->x_base, &x->x_wind, s, argc, argv);
    if (speed < 0.0)
        return;
    /* the inlet's float is the speed along the direction (a connected
       signal overrides it) */
    x->x_f = (t_float)speed;
    aero_treebranch_set_direction(&x->x_core, x->x_wind.dir);
    if (aero_treebranch_set_speed(&x->x_core, speed) == 1)
        aero_pd_clamped(&x->x_base);
}

static void treebranch_tilde_listener(t_treebranch_tilde *x, t_symbol *s,
                                      int argc, t_atom *argv)
{
    aero_ears e;
    if (aero_pd_ears(&x->x_base, s, argc, argv, &e) &&
        aero_treebranch_set_ears(&x->x_core, &e))
        aero_pd_bad_ears(&x->x_base, e.n);
}

static void treebranch_tilde_mic(t_treebranch_tilde *x, t_symbol *s,
                                 int argc, t_atom *argv)
{
    double v[3];
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (aero_treebranch_set_mic(&x->x_core, v))
        aero_pd_refused_list(&x->x_base, s->s_name);
}

AERO_PD_SETTER(treebranch_tilde, t_treebranch_tilde, k, x_core,
               aero_treebranch_set_mic_k)
AERO_PD_SETTER(treebranch_tilde, t_treebranch_tilde, gain, x_core,
               aero_treebranch_set_gain_db)
AERO_PD_SETTER(treebranch_tilde, t_treebranch_tilde, ramp, x_core,
               aero_treebranch_set_ramp_ms)
AERO_PD_SETTER(treebranch_tilde, t_treebranch_tilde, stiffness, x_core,
               aero_treebranch_set_stiffness)
AERO_PD_SETTER(treebranch_tilde, t_treebranch_tilde, beta, x_core,
               aero_treebranch_set_beta)
AERO_PD_SETTER(treebranch_tilde, t_treebranch_tilde, alpha, x_core,
               aero_treebranch_set_alpha)

static void treebranch_tilde_seed(t_treebranch_tilde *x, t_floatarg f)
{
    uint32_t seed;
    if (aero_pd_seed_of(&x->x_base, f, &seed))
        return;
    if (aero_treebranch_set_seed(&x->x_core, seed))
        pd_error(x, OBJ ": out of memory restarting the tree: silent");
}

static const aero_pd_method treebranch_tilde_methods[] = {
    {"stereo", AERO_PD_SWITCH, 0, NULL, 0, AERO_PD_NO_RULE},
    {"seed", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_seed, 0,
     AERO_PD_SEED},
    {"gain", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_gain, 0,
     AERO_PD_GAIN},
    {"stiffness", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_stiffness, 0,
     AERO_PD_RANGE_DEF(AERO_TREE_STIFFNESS_MIN, AERO_TREE_STIFFNESS_MAX,
                       AERO_TREE_STIFFNESS_DEFAULT, NULL)},
    {"beta", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_beta, 0,
     AERO_PD_RANGE_DEF(0, AERO_TREE_BETA_MAX, AERO_TREE_BETA_DEFAULT, NULL)},
    {"alpha", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_alpha, 0,
     AERO_PD_RANGE_DEF(AERO_TREEBRANCH_ALPHA_MIN, AERO_TREEBRANCH_ALPHA_MAX,
                       AERO_TREEBRANCH_ALPHA_DEFAULT, NULL)},
    {"k", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_k, 0,
     AERO_PD_RANGE_DEF(0, AERO_TREEBRANCH_MIC_K_MAX,
                       AERO_TREEBRANCH_MIC_K_DEFAULT, NULL)},
    {"ramp", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_ramp, 0,
     AERO_PD_RAMP},
    {"mic", AERO_PD_LIST, 3, (t_method)treebranch_tilde_mic, 0,
     AERO_PD_NOTE("a finite direction; 0 0 0 aims it at the tree")},
    {"listener", AERO_PD_LIST, 3, (t_method)treebranch_tilde_listener, 0,
     AERO_PD_NO_RULE},
    {"ears", AERO_PD_LIST, 6, (t_method)treebranch_tilde_listener, 0, AERO_PD_NO_RULE},
    {"wind", AERO_PD_LIST, 3, (t_method)treebranch_tilde_wind, 0,
     AERO_PD_RANGE_NOTE(0, AERO_MOVING_WIND_MAX, "m/s",
                        "the vector's length")},
    {"open", AERO_PD_SYMBOL, 0, (t_method)treebranch_tilde_open,
     AERO_PD_MESSAGE_ONLY, AERO_PD_NO_RULE},
};

static const aero_pd_spec treebranch_tilde_spec = {
    "treebranch~", treebranch_tilde_methods,
    AERO_PD_COUNT(treebranch_tilde_methods), "<treefile>"};

static void *treebranch_tilde_new(t_symbol *s, int argc, t_atom *argv)
{
    (void)s;
    t_treebranch_tilde *x =
        (t_treebranch_tilde *)pd_new(treebranch_tilde_class);
    aero_pd_base_init(&x->x_base, x, &treebranch_tilde_spec, argc, argv);
    aero_pd_wind_init(&x->x_wind);
    if (aero_treebranch_init(&x->x_core, sys_getsr(), aero_pd_default_seed()))
        pd_error(x, OBJ ": out of memory: silent");
    aero_treebranch_set_stereo(&x->x_core, x->x_base.stereo);
    /* the tree file: the first argument, when it is not a flag */
    t_symbol *file = aero_pd_first_symbol(&argc, &argv);
    if (file)
        treebranch_tilde_open(x, file);
    aero_pd_parse_flags(&x->x_base, argc, argv);
    aero_pd_no_file(&x->x_base, "tree", "open");
    aero_pd_base_outlets(&x->x_base);
    return x;
}

static void treebranch_tilde_free(t_treebranch_tilde *x)
{
    aero_pd_base_free(&x->x_base);
    aero_treebranch_free(&x->x_core);
}

AERO_PD_EXPORT void treebranch_tilde_setup(void)
{
    treebranch_tilde_class = aero_pd_class_new(
        &treebranch_tilde_spec, (t_newmethod)(t_method)treebranch_tilde_new,
        (t_method)treebranch_tilde_free, sizeof(t_treebranch_tilde),
        offsetof(t_treebranch_tilde, x_f), (t_method)treebranch_tilde_dsp);
}
