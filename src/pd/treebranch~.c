/* [treebranch~]: the sound of a tree's branches in the wind (Matsuyama et al.
 * 2005). Thin Pd wrapper around src/core/play/treebranch.
 *
 *   [treebranch~ <treefile> -stereo -seed 1 -listener 0 -10 1.7]
 *   inlet 1 (signal or float): wind speed along the wind direction, m/s
 *   outlet 1 (signal): sound pressure at the listener (left ear), Pa
 *   outlet 2 (signal, with -stereo): right ear, Pa
 */
#include "aero_pd.h"

#include "treebranch.h"

#include <math.h>

static t_class *treebranch_tilde_class;

typedef struct _treebranch_tilde {
    t_object x_obj;
    t_float x_f;
    aero_pd_base x_base;
    aero_pd_wind x_wind;
    aero_treebranch x_tb;
} t_treebranch_tilde;

#define OBJ "[treebranch~]"

static int treebranch_tilde_process(void *obj, const float *in,
                                    float *const *out, int n)
{
    t_treebranch_tilde *x = obj;
    /* the inlet is the speed along the wind's direction; the core takes
       the block's mean and reports a clamp */
    return aero_treebranch_process_speed(&x->x_tb, in, out[0], out[1], n);
}

static void treebranch_tilde_dsp(t_treebranch_tilde *x, t_signal **sp)
{
    if (aero_treebranch_set_sample_rate(&x->x_tb, sp[0]->s_sr))
        pd_error(x, OBJ ": bad sample rate %g (or out of memory)",
                 sp[0]->s_sr);
    aero_pd_dsp(&x->x_base, sp, 1, treebranch_tilde_process);
}

/* bad lines of a tree file, with their line numbers */
typedef struct {
    t_treebranch_tilde *x;
    const char *path;
    int count;
} tree_report_ctx;

static void treebranch_tilde_line(void *ctx, int line, const char *message)
{
    tree_report_ctx *c = ctx;
    if (++c->count <= 20)
        pd_error(c->x, OBJ ": %s:%d: %s (line skipped)", c->path, line,
                 message);
    else if (c->count == 21)
        pd_error(c->x, OBJ ": %s: more bad lines not shown", c->path);
}

/* file I/O here, in the message domain, never in perform */
static void treebranch_tilde_open(t_treebranch_tilde *x, t_symbol *name)
{
    char path[MAXPDSTRING], err[MAXPDSTRING + 100];
    aero_tree t;
    tree_report_ctx ctx;
    if (aero_pd_find_tree(x->x_base.canvas, treebranch_tilde_class, name->s_name,
                          path, sizeof(path))) {
        pd_error(x, OBJ ": can't find tree '%s' (looked %s): silent",
                 name->s_name, path);
        aero_treebranch_set_tree(&x->x_tb, NULL);
        return;
    }
    ctx.x = x;
    ctx.path = path;
    ctx.count = 0;
    if (aero_tree_load(path, &t, treebranch_tilde_line, &ctx, err,
                       sizeof(err))) {
        pd_error(x, OBJ ": %s: silent", err);
        aero_treebranch_set_tree(&x->x_tb, NULL);
        return;
    }
    if (aero_treebranch_set_tree(&x->x_tb, &t))
        pd_error(x, OBJ ": %s: out of memory: silent", path);
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
    aero_treebranch_set_direction(&x->x_tb, x->x_wind.dir);
    if (aero_treebranch_set_speed(&x->x_tb, speed) == 1)
        aero_pd_clamped(&x->x_base);
}

static void treebranch_tilde_listener(t_treebranch_tilde *x, t_symbol *s,
                                      int argc, t_atom *argv)
{
    double v[3];
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    aero_ears e = aero_ears_at(v[0], v[1], v[2]);
    if (aero_treebranch_set_ears(&x->x_tb, &e))
        pd_error(x, OBJ ": listener position must be finite, within 1e5 m");
}

static void treebranch_tilde_ears(t_treebranch_tilde *x, t_symbol *s,
                                  int argc, t_atom *argv)
{
    double v[6];
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 6, v))
        return;
    if (!x->x_base.stereo)
        pd_error(x, OBJ ": 'ears' needs -stereo (the left ear is used)");
    aero_ears e = {2, {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}}};
    if (aero_treebranch_set_ears(&x->x_tb, &e))
        pd_error(x, OBJ ": ear positions must be finite, within 1e5 m");
}

static void treebranch_tilde_mic(t_treebranch_tilde *x, t_symbol *s,
                                 int argc, t_atom *argv)
{
    double v[3];
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (aero_treebranch_set_mic(&x->x_tb, v))
        pd_error(x, OBJ ": mic direction must be finite");
}

static void treebranch_tilde_k(t_treebranch_tilde *x, t_floatarg f)
{
    if (aero_treebranch_set_mic_k(&x->x_tb, f))
        pd_error(x, OBJ ": k %g out of range (0..%g)", f,
                 AERO_TREEBRANCH_MIC_K_MAX);
}

static void treebranch_tilde_gain(t_treebranch_tilde *x, t_floatarg f)
{
    if (aero_treebranch_set_gain_db(&x->x_tb, f))
        pd_error(x, OBJ ": gain %g dB out of range (%g..%g)", f,
                 AERO_GAIN_DB_MIN, AERO_GAIN_DB_MAX);
}

static void treebranch_tilde_ramp(t_treebranch_tilde *x, t_floatarg f)
{
    if (aero_treebranch_set_ramp_ms(&x->x_tb, f))
        pd_error(x, OBJ ": ramp %g ms out of range (0..%g)", f,
                 AERO_RAMP_MS_MAX);
}

static void treebranch_tilde_stiffness(t_treebranch_tilde *x, t_floatarg f)
{
    if (aero_treebranch_set_stiffness(&x->x_tb, f))
        pd_error(x, OBJ ": stiffness %g out of range (%g..%g)", f,
                 AERO_TREE_STIFFNESS_MIN, AERO_TREE_STIFFNESS_MAX);
}

static void treebranch_tilde_beta(t_treebranch_tilde *x, t_floatarg f)
{
    if (aero_treebranch_set_beta(&x->x_tb, f))
        pd_error(x, OBJ ": beta %g out of range (0..%g)", f,
                 AERO_TREE_BETA_MAX);
}

static void treebranch_tilde_alpha(t_treebranch_tilde *x, t_floatarg f)
{
    if (aero_treebranch_set_alpha(&x->x_tb, f))
        pd_error(x, OBJ ": alpha %g out of range (%g..%g)", f,
                 AERO_TREEBRANCH_ALPHA_MIN, AERO_TREEBRANCH_ALPHA_MAX);
}

static void treebranch_tilde_seed(t_treebranch_tilde *x, t_floatarg f)
{
    if (!(f == f) || f < 0 || f > 4294967295.0) {
        pd_error(x, OBJ ": seed %g out of range (0..2^32-1)", f);
        return;
    }
    if (aero_treebranch_set_seed(&x->x_tb, (uint32_t)(int64_t)f))
        pd_error(x, OBJ ": out of memory restarting the tree: silent");
}

static const aero_pd_method treebranch_tilde_methods[] = {
    {"stereo", AERO_PD_SWITCH, 0, NULL, 0},
    {"seed", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_seed, 0},
    {"gain", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_gain, 0},
    {"stiffness", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_stiffness, 0},
    {"beta", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_beta, 0},
    {"alpha", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_alpha, 0},
    {"k", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_k, 0},
    {"ramp", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_ramp, 0},
    {"mic", AERO_PD_LIST, 3, (t_method)treebranch_tilde_mic, 0},
    {"listener", AERO_PD_LIST, 3, (t_method)treebranch_tilde_listener, 0},
    {"ears", AERO_PD_LIST, 6, (t_method)treebranch_tilde_ears, 0},
    {"wind", AERO_PD_LIST, 3, (t_method)treebranch_tilde_wind, 0},
    {"open", AERO_PD_SYMBOL, 0, (t_method)treebranch_tilde_open,
     AERO_PD_MESSAGE_ONLY},
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
    if (aero_treebranch_init(&x->x_tb, sys_getsr(), aero_pd_default_seed()))
        pd_error(x, OBJ ": out of memory: silent");
    aero_treebranch_set_stereo(&x->x_tb, x->x_base.stereo);
    /* the tree file: the first argument, when it is not a flag */
    t_symbol *file = aero_pd_first_symbol(&argc, &argv);
    if (file)
        treebranch_tilde_open(x, file);
    aero_pd_parse_flags(x, &treebranch_tilde_spec, argc, argv);
    aero_pd_base_outlets(&x->x_base);
    return x;
}

static void treebranch_tilde_free(t_treebranch_tilde *x)
{
    aero_pd_base_free(&x->x_base);
    aero_treebranch_free(&x->x_tb);
}

AERO_PD_EXPORT void treebranch_tilde_setup(void)
{
    treebranch_tilde_class = aero_pd_class_new(
        &treebranch_tilde_spec, (t_newmethod)(t_method)treebranch_tilde_new,
        (t_method)treebranch_tilde_free, sizeof(t_treebranch_tilde),
        offsetof(t_treebranch_tilde, x_f), (t_method)treebranch_tilde_dsp);
}
