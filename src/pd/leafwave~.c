/* [leafwave~]: the leaves of a tree in the wind (Matsuyama et al. 2005):
 * collisions and friction between neighbouring leaves played from pink wave
 * tables. Thin Pd wrapper around src/core/play/leafwave.
 *
 *   [leafwave~ trees/small.tree -stereo -seed 1 -gain 0 ...]
 *   inlet 1 (signal or float): wind speed along the wind's direction (+x
 *                     until a `wind` message), m/s, the block's mean;
 *                     messages
 *   outlet(s) (signal): sound pressure at the listener (ears), Pa
 */
#include "aero_pd.h"

#include "leafwave.h"
#include "aero_util.h"

#include <math.h>

static t_class *leafwave_tilde_class;

typedef struct _leafwave_tilde {
    t_object x_obj;
    t_float x_f;
    aero_pd_base x_base;
    aero_pd_wind x_wind;
    aero_leafwave x_model;
    int x_ok; /* the core is initialised */
} t_leafwave_tilde;

#define OBJ "[leafwave~]"

static int leafwave_tilde_process(void *obj, const float *in,
                                  float *const *out, int n)
{
    t_leafwave_tilde *x = obj;
    if (!x->x_ok) {
        for (int e = 0; e < 2; e++)
            for (int i = 0; out[e] && i < n; i++)
                out[e][i] = 0;
        return 0;
    }
    /* the inlet is the speed along the wind's direction; the core takes
       the block's mean and reports a clamp */
    return aero_leafwave_process(&x->x_model, in, out, n);
}

static void leafwave_tilde_dsp(t_leafwave_tilde *x, t_signal **sp)
{
    if (x->x_ok && aero_leafwave_set_sample_rate(&x->x_model, sp[0]->s_sr))
        pd_error(x, OBJ ": bad sample rate %g", sp[0]->s_sr);
    aero_pd_dsp(&x->x_base, sp, 1, leafwave_tilde_process);
}

/* --- the tree file ------------------------------------------------------ */

typedef struct {
    t_leafwave_tilde *x;
    const char *path;
} report_ctx;

static void leafwave_tilde_bad_line(void *ctx, int line, const char *message)
{
    report_ctx *c = ctx;
    pd_error(c->x, OBJ ": %s:%d: %s (line skipped)", c->path, line, message);
}

/* file I/O and the neighbour search here, in the message domain */
static void leafwave_tilde_open(t_leafwave_tilde *x, t_symbol *name)
{
    char path[MAXPDSTRING], err[256];
    if (!x->x_ok)
        return;
    if (aero_pd_find_tree(x->x_base.canvas, leafwave_tilde_class, name->s_name,
                          path, sizeof(path))) {
        pd_error(x, OBJ ": can't find tree file '%s' (looked %s): silent "
                 "until 'open'", name->s_name, path);
        aero_leafwave_clear_tree(&x->x_model);
        return;
    }
    aero_tree t;
    report_ctx ctx = {x, path};
    if (aero_tree_load(path, &t, leafwave_tilde_bad_line, &ctx, err,
                       sizeof(err))) {
        pd_error(x, OBJ ": tree %s: %s: silent", path, err);
        aero_leafwave_clear_tree(&x->x_model);
        return;
    }
    int nleaves = t.nleaves;
    if (aero_leafwave_set_tree(&x->x_model, &t, err, sizeof(err))) {
        pd_error(x, OBJ ": tree %s: %s: silent", path, err);
        return;
    }
    if (nleaves == 0)
        pd_error(x, OBJ ": tree %s has no leaves: silent", path);
}

/* --- messages (each also a creation flag of the same name) -------------- */

/* a setter whose range the core states (leafwave.h, tree_motion.h,
   aero_ranges.h): the message quotes it */
#define SETTER(fn, call, what, lo, hi)                                    \
    static void leafwave_tilde_##fn(t_leafwave_tilde *x, t_floatarg f)    \
    {                                                                     \
        if (x->x_ok && call(&x->x_model, f))                              \
            pd_error(x, OBJ ": " what " out of range (%g..%g)", f,        \
                     (double)(lo), (double)(hi));                         \
    }

SETTER(gain, aero_leafwave_set_gain_db, "gain %g dB", AERO_GAIN_DB_MIN,
       AERO_GAIN_DB_MAX)
SETTER(ramp, aero_leafwave_set_ramp_ms, "ramp %g ms", 0, AERO_RAMP_MS_MAX)
SETTER(stiffness, aero_leafwave_set_stiffness, "stiffness %g",
       AERO_TREE_STIFFNESS_MIN, AERO_TREE_STIFFNESS_MAX)
SETTER(beta, aero_leafwave_set_beta, "beta %g", 0, AERO_TREE_BETA_MAX)
SETTER(k, aero_leafwave_set_mic_k, "k %g", 0, AERO_LEAFWAVE_MIC_K_MAX)
SETTER(sway, aero_leafwave_set_sway, "sway %g rad", 0,
       AERO_LEAFWAVE_SWAY_MAX)
SETTER(coupling, aero_leafwave_set_coupling, "coupling %g",
       -AERO_LEAFWAVE_COUPLING_MAX, AERO_LEAFWAVE_COUPLING_MAX)
SETTER(flutter, aero_leafwave_set_flutter, "flutter %g Hz",
       AERO_LEAFWAVE_FLUTTER_MIN, AERO_LEAFWAVE_FLUTTER_MAX)
SETTER(hit, aero_leafwave_set_hit, "hit %g Pa", 0, AERO_LEAFWAVE_PA_MAX)
SETTER(rub, aero_leafwave_set_rub, "rub %g Pa", 0, AERO_LEAFWAVE_PA_MAX)
SETTER(reach, aero_leafwave_set_reach, "reach %g", AERO_LEAFWAVE_REACH_MIN,
       AERO_LEAFWAVE_REACH_MAX)

static void leafwave_tilde_voices(t_leafwave_tilde *x, t_floatarg f)
{
    int n;
    if (x->x_ok && (aero_pd_whole(f, 1, AERO_LEAFWAVE_VOICES_MAX, &n) ||
                    aero_leafwave_set_voices(&x->x_model, n)))
        pd_error(x, OBJ ": voices %g out of range (1..%d)", f,
                 AERO_LEAFWAVE_VOICES_MAX);
}

static void leafwave_tilde_set_tables(t_leafwave_tilde *x, double fm,
                                      double per_octave, double octaves,
                                      const char *what, double value)
{
    int per, oct;
    if (!x->x_ok)
        return;
    if (aero_pd_whole(per_octave, 1, AERO_LEAFWAVE_PER_OCTAVE_MAX, &per) ||
        aero_pd_whole(octaves, 1, AERO_LEAFWAVE_OCTAVES_MAX, &oct) ||
        aero_leafwave_set_tables(&x->x_model, fm, per, oct))
        pd_error(x, OBJ ": %s %g out of range (fm %g..%g Hz, tables "
                 "1..%d per octave, octaves 1..%d, at most %d tables)",
                 what, value, AERO_LEAFWAVE_FM_MIN, AERO_LEAFWAVE_FM_MAX,
                 AERO_LEAFWAVE_PER_OCTAVE_MAX, AERO_LEAFWAVE_OCTAVES_MAX,
                 AERO_LEAFWAVE_TABLES_MAX);
}

static void leafwave_tilde_fm(t_leafwave_tilde *x, t_floatarg f)
{
    leafwave_tilde_set_tables(x, f, x->x_model.tables_per_octave,
                              x->x_model.octaves, "fm", f);
}

static void leafwave_tilde_tables(t_leafwave_tilde *x, t_floatarg f)
{
    leafwave_tilde_set_tables(x, x->x_model.fm, f, x->x_model.octaves,
                              "tables", f);
}

static void leafwave_tilde_octaves(t_leafwave_tilde *x, t_floatarg f)
{
    leafwave_tilde_set_tables(x, x->x_model.fm, x->x_model.tables_per_octave,
                              f, "octaves", f);
}

static void leafwave_tilde_seed(t_leafwave_tilde *x, t_floatarg f)
{
    if (x->x_ok && aero_leafwave_set_seed(&x->x_model, aero_pd_seed(f)))
        pd_error(x, OBJ ": out of memory restarting from seed %g", f);
}

static void leafwave_tilde_wind(t_leafwave_tilde *x, t_symbol *s, int argc,
                                t_atom *argv)
{
    if (!x->x_ok)
        return;
    double speed = aero_pd_wind_message(&x->x_base, &x->x_wind, s, argc, argv);
    if (speed < 0.0)
        return;
    /* the inlet's float is the speed along the direction (a connected
       signal overrides it), as in [treebranch~] */
    x->x_f = (t_float)speed;
    const double *dir = x->x_wind.dir;
    aero_leafwave_set_direction(&x->x_model, dir[0], dir[1], dir[2]);
    if (aero_leafwave_set_speed(&x->x_model, speed) == 1)
        aero_pd_clamped(&x->x_base);
}

static void leafwave_tilde_mic(t_leafwave_tilde *x, t_symbol *s, int argc,
                               t_atom *argv)
{
    double v[3];
    if (!x->x_ok || aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (aero_leafwave_set_mic(&x->x_model, v[0], v[1], v[2]))
        pd_error(x, OBJ ": mic direction must be finite");
}

static void leafwave_tilde_listener(t_leafwave_tilde *x, t_symbol *s,
                                    int argc, t_atom *argv)
{
    aero_ears e;
    if (x->x_ok && aero_pd_ears(&x->x_base, s, argc, argv, &e) &&
        aero_leafwave_set_ears(&x->x_model, &e))
        aero_pd_bad_ears(&x->x_base, e.n);
}

/* --- creation ------------------------------------------------------------- */

static const aero_pd_method leafwave_tilde_methods[] = {
    {"stereo", AERO_PD_SWITCH, 0, NULL, 0},
    {"open", AERO_PD_SYMBOL, 0, (t_method)leafwave_tilde_open, 0},
    {"tree", AERO_PD_SYMBOL, 0, (t_method)leafwave_tilde_open, 0},
    {"wind", AERO_PD_LIST, 3, (t_method)leafwave_tilde_wind, 0},
    {"listener", AERO_PD_LIST, 3, (t_method)leafwave_tilde_listener, 0},
    {"ears", AERO_PD_LIST, 6, (t_method)leafwave_tilde_listener, 0},
    {"mic", AERO_PD_LIST, 3, (t_method)leafwave_tilde_mic, 0},
    {"k", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_k, 0},
    {"gain", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_gain, 0},
    {"seed", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_seed, 0},
    {"ramp", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_ramp, 0},
    {"stiffness", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_stiffness, 0},
    {"beta", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_beta, 0},
    {"sway", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_sway, 0},
    {"coupling", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_coupling, 0},
    {"flutter", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_flutter, 0},
    {"hit", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_hit, 0},
    {"rub", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_rub, 0},
    {"reach", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_reach, 0},
    {"voices", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_voices, 0},
    {"fm", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_fm, 0},
    {"tables", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_tables, 0},
    {"octaves", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_octaves, 0},
};

static const aero_pd_spec leafwave_tilde_spec = {
    "leafwave~", leafwave_tilde_methods,
    AERO_PD_COUNT(leafwave_tilde_methods), "<treefile>"};

static void *leafwave_tilde_new(t_symbol *s, int argc, t_atom *argv)
{
    (void)s;
    t_leafwave_tilde *x = (t_leafwave_tilde *)pd_new(leafwave_tilde_class);
    aero_pd_base_init(&x->x_base, x, &leafwave_tilde_spec, argc, argv);
    aero_pd_wind_init(&x->x_wind);
    x->x_ok = aero_leafwave_init(&x->x_model, sys_getsr(),
                                 x->x_base.stereo ? 2 : 1,
                                 aero_pd_default_seed()) == 0;
    if (!x->x_ok)
        pd_error(x, OBJ ": out of memory: silent");
    /* the tree file: the first argument that is not a flag; the seed and
       the tables are set by the flags first, so the tree is built once */
    t_symbol *file = aero_pd_first_symbol(&argc, &argv);
    aero_pd_parse_flags(x, &leafwave_tilde_spec, argc, argv);
    if (file)
        leafwave_tilde_open(x, file);
    else
        post(OBJ ": no tree file given: silent until 'open <file>'");
    aero_pd_base_outlets(&x->x_base);
    return x;
}

static void leafwave_tilde_free(t_leafwave_tilde *x)
{
    aero_pd_base_free(&x->x_base);
    if (x->x_ok)
        aero_leafwave_free(&x->x_model);
}

AERO_PD_EXPORT void leafwave_tilde_setup(void)
{
    leafwave_tilde_class = aero_pd_class_new(
        &leafwave_tilde_spec, (t_newmethod)(t_method)leafwave_tilde_new,
        (t_method)leafwave_tilde_free, sizeof(t_leafwave_tilde),
        offsetof(t_leafwave_tilde, x_f), (t_method)leafwave_tilde_dsp);
}
