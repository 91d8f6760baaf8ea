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
#include "moving_player.h"

#include "leafwave.h"
#include "aero_util.h"

#include <math.h>

static t_class *leafwave_tilde_class;

typedef struct _leafwave_tilde {
    t_object x_obj;
    t_float x_f;
    aero_pd_base x_base;
    aero_pd_wind x_wind;
    aero_leafwave x_core;
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
    return aero_leafwave_process(&x->x_core, in, out, n);
}

static void leafwave_tilde_dsp(t_leafwave_tilde *x, t_signal **sp)
{
    if (x->x_ok && aero_leafwave_set_sample_rate(&x->x_core, sp[0]->s_sr))
        pd_error(x, OBJ ": bad sample rate %g", sp[0]->s_sr);
    aero_pd_dsp(&x->x_base, sp, 1, leafwave_tilde_process);
}

/* --- the tree file ------------------------------------------------------ */

/* file I/O and the neighbour search here, in the message domain */
static void leafwave_tilde_open(t_leafwave_tilde *x, t_symbol *name)
{
    char err[256];
    aero_tree t;
    if (!x->x_ok)
        return;
    if (aero_pd_load_tree(&x->x_base, leafwave_tilde_class, name, &t))
        return; /* the tree that played, if any, plays on */
    int nleaves = t.nleaves;
    if (aero_leafwave_set_tree(&x->x_core, &t, err, sizeof(err))) {
        pd_error(x, OBJ ": %s: %s: silent", name->s_name, err);
        return;
    }
    if (nleaves == 0)
        pd_error(x, OBJ ": tree %s has no leaves: silent", name->s_name);
}

/* --- messages (each also a creation flag of the same name) -------------- */

/* the setters: refusals worded from the table; none before the core is
   initialised */
#define SETTER(msg, call, whole)                                          \
    static void leafwave_tilde_##msg(t_leafwave_tilde *x, t_floatarg f)   \
    {                                                                     \
        int n = 0;                                                        \
        if (x->x_ok &&                                                    \
            ((whole && aero_pd_whole_of(&x->x_base, #msg, f, &n)) ||      \
             call(&x->x_core,                                            \
                  whole ? n : aero_pd_at_bound(&x->x_base, #msg, f))))   \
            aero_pd_refused(&x->x_base, #msg, f);                         \
    }

SETTER(gain, aero_leafwave_set_gain_db, 0)
SETTER(ramp, aero_leafwave_set_ramp_ms, 0)
SETTER(stiffness, aero_leafwave_set_stiffness, 0)
SETTER(beta, aero_leafwave_set_beta, 0)
SETTER(k, aero_leafwave_set_mic_k, 0)
SETTER(sway, aero_leafwave_set_sway, 0)
SETTER(coupling, aero_leafwave_set_coupling, 0)
SETTER(flutter, aero_leafwave_set_flutter, 0)
SETTER(hit, aero_leafwave_set_hit, 0)
SETTER(rub, aero_leafwave_set_rub, 0)
SETTER(reach, aero_leafwave_set_reach, 0)
SETTER(voices, aero_leafwave_set_voices, 1)

/* fm (which 0), tables per octave (1) or octaves (2): the other two stay */
static void leafwave_tilde_set_tables(t_leafwave_tilde *x, int which,
                                      t_float f, const char *what)
{
    double v[3];
    int per, oct;
    if (!x->x_ok)
        return;
    aero_leafwave_tables(&x->x_core, &v[0], &per, &oct);
    v[1] = per;
    v[2] = oct;
    v[which] = f;
    if (aero_pd_whole_of(&x->x_base, "tables", v[1], &per) ||
        aero_pd_whole_of(&x->x_base, "octaves", v[2], &oct)) {
        aero_pd_refused(&x->x_base, what, f);
    } else if ((long)per * oct > AERO_LEAFWAVE_TABLES_MAX) {
        /* each within its range, the product not: say the real limit */
        pd_error(x, OBJ ": %s %g refused: %d tables per octave x %d octaves "
                 "= %ld tables, at most %d in all (with %s %d: %s at most "
                 "%d)", what, f, per, oct, (long)per * oct,
                 AERO_LEAFWAVE_TABLES_MAX, which == 2 ? "tables" : "octaves",
                 which == 2 ? per : oct, which == 2 ? "octaves" : "tables",
                 AERO_LEAFWAVE_TABLES_MAX / (which == 2 ? per : oct));
    } else if (aero_leafwave_set_tables(&x->x_core, v[0], per, oct)) {
        aero_pd_refused(&x->x_base, what, f);
    }
}

static void leafwave_tilde_fm(t_leafwave_tilde *x, t_floatarg f)
{
    leafwave_tilde_set_tables(x, 0, f, "fm");
}

static void leafwave_tilde_tables(t_leafwave_tilde *x, t_floatarg f)
{
    leafwave_tilde_set_tables(x, 1, f, "tables");
}

static void leafwave_tilde_octaves(t_leafwave_tilde *x, t_floatarg f)
{
    leafwave_tilde_set_tables(x, 2, f, "octaves");
}

static void leafwave_tilde_seed(t_leafwave_tilde *x, t_floatarg f)
{
    uint32_t seed;
    if (x->x_ok && !aero_pd_seed_of(&x->x_base, f, &seed) &&
        aero_leafwave_set_seed(&x->x_core, seed))
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
    aero_leafwave_set_direction(&x->x_core, dir[0], dir[1], dir[2]);
    if (aero_leafwave_set_speed(&x->x_core, speed) == 1)
        aero_pd_clamped(&x->x_base);
}

static void leafwave_tilde_mic(t_leafwave_tilde *x, t_symbol *s, int argc,
                               t_atom *argv)
{
    double v[3];
    if (!x->x_ok || aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (aero_leafwave_set_mic(&x->x_core, v[0], v[1], v[2]))
        aero_pd_refused_list(&x->x_base, s->s_name);
}

static void leafwave_tilde_listener(t_leafwave_tilde *x, t_symbol *s,
                                    int argc, t_atom *argv)
{
    aero_ears e;
    if (x->x_ok && aero_pd_ears(&x->x_base, s, argc, argv, &e) &&
        aero_leafwave_set_ears(&x->x_core, &e))
        aero_pd_bad_ears(&x->x_base, e.n);
}

/* --- creation ------------------------------------------------------------- */

#define TABLES_NOTE "at most " AERO_PD_STR(AERO_LEAFWAVE_TABLES_MAX) \
    " tables in all"

static const aero_pd_method leafwave_tilde_methods[] = {
    {"stereo", AERO_PD_SWITCH, 0, NULL, 0, AERO_PD_NO_RULE},
    {"open", AERO_PD_SYMBOL, 0, (t_method)leafwave_tilde_open, 0, AERO_PD_NO_RULE},
    {"tree", AERO_PD_SYMBOL, 0, (t_method)leafwave_tilde_open, 0, AERO_PD_NO_RULE},
    {"wind", AERO_PD_LIST, 3, (t_method)leafwave_tilde_wind, 0,
     AERO_PD_RANGE_NOTE(0, AERO_MOVING_WIND_MAX, "m/s",
                        "the vector's length")},
    {"listener", AERO_PD_LIST, 3, (t_method)leafwave_tilde_listener, 0, AERO_PD_NO_RULE},
    {"ears", AERO_PD_LIST, 6, (t_method)leafwave_tilde_listener, 0, AERO_PD_NO_RULE},
    {"mic", AERO_PD_LIST, 3, (t_method)leafwave_tilde_mic, 0,
     AERO_PD_NOTE("a finite direction; 0 0 0 aims it at the tree")},
    {"k", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_k, 0,
     AERO_PD_RANGE_DEF(0, AERO_LEAFWAVE_MIC_K_MAX,
                       AERO_LEAFWAVE_MIC_K_DEFAULT, NULL)},
    {"gain", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_gain, 0,
     AERO_PD_GAIN},
    {"seed", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_seed, 0,
     AERO_PD_SEED},
    {"ramp", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_ramp, 0,
     AERO_PD_RAMP},
    {"stiffness", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_stiffness, 0,
     AERO_PD_RANGE_DEF(AERO_TREE_STIFFNESS_MIN, AERO_TREE_STIFFNESS_MAX,
                       AERO_TREE_STIFFNESS_DEFAULT, NULL)},
    {"beta", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_beta, 0,
     AERO_PD_RANGE_DEF(0, AERO_TREE_BETA_MAX, AERO_TREE_BETA_DEFAULT, NULL)},
    {"sway", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_sway, 0,
     AERO_PD_RANGE_DEF(0, AERO_LEAFWAVE_SWAY_MAX,
                       AERO_LEAFWAVE_SWAY_DEFAULT, "rad")},
    {"coupling", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_coupling, 0,
     AERO_PD_RANGE_DEF(-AERO_LEAFWAVE_COUPLING_MAX, AERO_LEAFWAVE_COUPLING_MAX,
                       AERO_LEAFWAVE_COUPLING_DEFAULT, NULL)},
    {"flutter", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_flutter, 0,
     AERO_PD_RANGE_DEF(AERO_LEAFWAVE_FLUTTER_MIN, AERO_LEAFWAVE_FLUTTER_MAX,
                       AERO_LEAFWAVE_FLUTTER_DEFAULT, "Hz")},
    {"hit", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_hit, 0,
     AERO_PD_RANGE_DEF(0, AERO_LEAFWAVE_PA_MAX, AERO_LEAFWAVE_HIT_DEFAULT,
                       "Pa")},
    {"rub", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_rub, 0,
     AERO_PD_RANGE_DEF(0, AERO_LEAFWAVE_PA_MAX, AERO_LEAFWAVE_RUB_DEFAULT,
                       "Pa")},
    {"reach", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_reach, 0,
     AERO_PD_RANGE_DEF(AERO_LEAFWAVE_REACH_MIN, AERO_LEAFWAVE_REACH_MAX,
                       AERO_LEAFWAVE_REACH_DEFAULT, NULL)},
    {"voices", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_voices, 0,
     AERO_PD_RANGE_DEF(1, AERO_LEAFWAVE_VOICES_MAX,
                       AERO_LEAFWAVE_VOICES_DEFAULT, NULL)},
    {"fm", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_fm, 0,
     AERO_PD_RANGE_DEF(AERO_LEAFWAVE_FM_MIN, AERO_LEAFWAVE_FM_MAX,
                       AERO_LEAFWAVE_FM_DEFAULT, "Hz")},
    {"tables", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_tables, 0,
     AERO_PD_RANGE_NOTE_DEF(1, AERO_LEAFWAVE_PER_OCTAVE_MAX,
                            AERO_LEAFWAVE_PER_OCTAVE_DEFAULT, "per octave",
                            TABLES_NOTE)},
    {"octaves", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_octaves, 0,
     AERO_PD_RANGE_NOTE_DEF(1, AERO_LEAFWAVE_OCTAVES_MAX,
                            AERO_LEAFWAVE_OCTAVES_DEFAULT, NULL, TABLES_NOTE)},
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
    x->x_ok = aero_leafwave_init(&x->x_core, sys_getsr(),
                                 x->x_base.stereo ? 2 : 1,
                                 aero_pd_default_seed()) == 0;
    if (!x->x_ok)
        pd_error(x, OBJ ": out of memory: silent");
    /* the tree file: the first argument that is not a flag; the seed and
       the tables are set by the flags first, so the tree is built once */
    t_symbol *file = aero_pd_first_symbol(&argc, &argv);
    aero_pd_parse_flags(&x->x_base, argc, argv);
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
        aero_leafwave_free(&x->x_core);
}

AERO_PD_EXPORT void leafwave_tilde_setup(void)
{
    leafwave_tilde_class = aero_pd_class_new(
        &leafwave_tilde_spec, (t_newmethod)(t_method)leafwave_tilde_new,
        (t_method)leafwave_tilde_free, sizeof(t_leafwave_tilde),
        offsetof(t_leafwave_tilde, x_f), (t_method)leafwave_tilde_dsp);
}
