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
#include <stdlib.h>
#include <string.h>

static t_class *leafwave_tilde_class;

typedef struct _leafwave_tilde {
    t_object x_obj;
    t_float x_f;
    aero_pd_base x_base;
    aero_pd_wind x_wind;
    aero_leafwave x_core;
    /* A tree file read, or the tables / reach / seed changed: a new core
       is built in a worker and swapped in by the clock with a fade; the
       old core plays meanwhile (aero_pd_swap). */
    aero_pd_swap x_swap;
    int x_creating;           /* in new(): the setters act at once */
    aero_leafwave_rebuild x_want; /* the tables, reach and seed asked */
} t_leafwave_tilde;

typedef struct lw_load {
    int has_file;             /* else a rebuild of the live tree, if any */
    aero_pd_tree_file read;
    aero_tree live;           /* the live core's tree (shared, read-only) */
    int has_live, owns_live;  /* owns: its object was deleted meanwhile */
    aero_leafwave snap;       /* the live core's numbers at the start */
    aero_leafwave_rebuild want;
    aero_leafwave core;       /* built in the worker */
    int ok, nleaves;
    char err[256];
} lw_load;

#define OBJ "[leafwave~]"

static int leafwave_tilde_process(void *obj, const float *in,
                                  float *const *out, int n)
{
    t_leafwave_tilde *x = obj;
    /* the near-field policy: reported once (the last block's record) */
    aero_pd_near(&x->x_base, &x->x_core.near);
    aero_leafwave *old = x->x_swap.old;
    if (old) {
        /* the old core into scratch first (the inlet may alias out[0]),
           faded out under the new one in chunks */
        float a[2][64];
        int clamped = 0;
        for (int done = 0; done < n;) {
            int m = n - done < 64 ? n - done : 64;
            float *ao[2] = {a[0], a[1]};
            float *no[2] = {out[0] + done, out[1] ? out[1] + done : NULL};
            aero_leafwave_process(old, in ? in + done : NULL, ao, m);
            clamped |= aero_leafwave_process(&x->x_core,
                                             in ? in + done : NULL, no, m);
            for (int i = 0; i < m; i++) {
                float g = aero_pd_swap_gain(&x->x_swap);
                for (int e = 0; e < x->x_core.n_ears && e < 2; e++)
                    no[e][i] += g * a[e][i];
            }
            done += m;
        }
        return clamped;
    }
    /* the inlet is the speed along the wind's direction; the core takes
       the block's mean and reports a clamp */
    return aero_leafwave_process(&x->x_core, in, out, n);
}

static void leafwave_tilde_dsp(t_leafwave_tilde *x, t_signal **sp)
{
    if (aero_leafwave_set_sample_rate(&x->x_core, sp[0]->s_sr))
        aero_pd_rate_failed(&x->x_base, sp[0]->s_sr);
    aero_pd_dsp(&x->x_base, sp, 1, leafwave_tilde_process);
}

/* --- the tree file ------------------------------------------------------ */

static int leafwave_tilde_build(void *arg)
{
    lw_load *l = arg;
    aero_tree t, *tp = NULL;
    if (l->has_file) {
        if (aero_pd_tree_read(&l->read, &t))
            return -1;
        tp = &t;
    } else if (l->has_live) {
        if (aero_tree_copy(&t, &l->live)) {
            snprintf(l->err, sizeof(l->err), "out of memory");
            return -1;
        }
        tp = &t;
    }
    l->nleaves = tp ? tp->nleaves : 0;
    if (aero_leafwave_build(&l->core, &l->snap, &l->want, tp, l->err,
                            sizeof(l->err)))
        return -1;
    l->ok = 1;
    return 0;
}

/* a job's leftovers (load_job.h: also from the worker, when abandoned) */
static void leafwave_tilde_drop_load(void *arg)
{
    lw_load *l = arg;
    if (l->ok)
        aero_leafwave_free(&l->core);
    if (l->owns_live)
        aero_tree_free(&l->live);
    free(l);
}

static void leafwave_tilde_free_core(void *core)
{
    aero_leafwave_free(core);
}

static int leafwave_tilde_wants_rebuild(const t_leafwave_tilde *x)
{
    const aero_leafwave *c = &x->x_core;
    const aero_leafwave_rebuild *w = &x->x_want;
    return w->fm != c->fm || w->per_octave != c->tables_per_octave ||
        w->octaves != c->octaves || w->reach != c->reach ||
        w->seed != c->seed;
}

static void leafwave_tilde_start(t_leafwave_tilde *x, t_symbol *name,
                                 int now);

/* what is asked is what plays: the live core's tables, reach and seed */
static void leafwave_tilde_want_live(t_leafwave_tilde *x)
{
    x->x_want.fm = x->x_core.fm;
    x->x_want.per_octave = x->x_core.tables_per_octave;
    x->x_want.octaves = x->x_core.octaves;
    x->x_want.reach = x->x_core.reach;
    x->x_want.seed = x->x_core.seed;
}

/* the finished job: its report, then the new core swapped in (the old one
   fades out); then the next job, if one was asked meanwhile */
static void leafwave_tilde_finish(void *owner)
{
    t_leafwave_tilde *x = owner;
    lw_load *l = aero_pd_swap_take(&x->x_swap);
    if (l->has_file && aero_pd_tree_report(&x->x_base, &l->read)) {
        ; /* refused: the tree that played, if any, plays on */
    } else if (!l->ok) {
        if (l->has_file) { /* refused as the last was: that one plays on */
            pd_error(x, OBJ ": %s: %s: %s", l->read.path, l->err,
                     x->x_core.has_tree ? "the previous tree stays"
                                        : "silent");
        } else {
            pd_error(x, OBJ ": %s: the old tables and neighbours stay",
                     l->err);
            leafwave_tilde_want_live(x);
        }
    } else {
        /* what changed while it was built */
        aero_leafwave_set_sample_rate(&l->core, x->x_core.sample_rate);
        aero_leafwave_copy_settings(&l->core, &x->x_core);
        aero_leafwave *old = aero_pd_swap_fade_slot(
            &x->x_swap, sizeof(*old), l->core.sample_rate);
        if (old)
            aero_leafwave_move(old, &x->x_core);
        else
            aero_leafwave_free(&x->x_core);
        aero_leafwave_move(&x->x_core, &l->core);
        if (l->has_file && l->nleaves == 0)
            pd_error(x, OBJ ": tree %s has no leaves: silent", l->read.path);
    }
    leafwave_tilde_drop_load(l);
    if (x->x_swap.next) {
        t_symbol *next = x->x_swap.next;
        x->x_swap.next = NULL;
        leafwave_tilde_start(x, next, 0);
    } else if (leafwave_tilde_wants_rebuild(x)) {
        leafwave_tilde_start(x, NULL, 0);
    }
}

/* Starts a job (aero_pd_swap_start): the tree file `name`, or (NULL) the
   live tree again with the tables, reach and seed asked. `now`
   (creation): a file under AERO_PD_SWAP_SMALL_FILE is read here at once,
   so a patch plays its tree from the first block. A job asked while one
   runs follows it. */
static void leafwave_tilde_start(t_leafwave_tilde *x, t_symbol *name,
                                 int now)
{
    if (x->x_swap.job) {
        if (name)
            x->x_swap.next = name; /* the latest wins; a rebuild follows anyway */
        return;
    }
    lw_load *l = calloc(1, sizeof(*l));
    if (!l) {
        pd_error(x, OBJ ": out of memory: silent");
        aero_leafwave_clear_tree(&x->x_core);
        return;
    }
    int small = 0;
    if (name) {
        if (aero_pd_tree_find(&x->x_base, leafwave_tilde_class, name,
                              &l->read)) {
            free(l); /* the tree that played, if any, plays on */
            return;
        }
        l->has_file = 1;
        small = aero_pd_swap_small(l->read.path);
    } else if (x->x_core.has_tree) {
        /* the arrays stay the live core's: not replaced while this runs */
        l->live = x->x_core.tree;
        l->has_live = 1;
    }
    l->snap = x->x_core; /* its numbers only are read */
    l->want = x->x_want;
    if (aero_pd_swap_start(&x->x_swap, leafwave_tilde_build, l,
                           now && small)) {
        free(l);
        pd_error(x, OBJ ": out of memory: silent");
    }
}

static void leafwave_tilde_open(t_leafwave_tilde *x, t_symbol *name)
{
    leafwave_tilde_start(x, name, x->x_creating);
}

/* a rebuild with x_want: at once in new() (the flags), else in a job */
static void leafwave_tilde_rebuild(t_leafwave_tilde *x)
{
    if (!x->x_creating)
        leafwave_tilde_start(x, NULL, 0);
}

/* --- messages (each also a creation flag of the same name) -------------- */

AERO_PD_SETTER(leafwave_tilde, t_leafwave_tilde, gain, x_core,
               aero_leafwave_set_gain_db)
AERO_PD_SETTER(leafwave_tilde, t_leafwave_tilde, ramp, x_core,
               aero_leafwave_set_ramp_ms)
AERO_PD_SETTER(leafwave_tilde, t_leafwave_tilde, stiffness, x_core,
               aero_leafwave_set_stiffness)
AERO_PD_SETTER(leafwave_tilde, t_leafwave_tilde, beta, x_core,
               aero_leafwave_set_beta)
AERO_PD_SETTER(leafwave_tilde, t_leafwave_tilde, k, x_core,
               aero_leafwave_set_mic_k)
AERO_PD_SETTER(leafwave_tilde, t_leafwave_tilde, sway, x_core,
               aero_leafwave_set_sway)
AERO_PD_SETTER(leafwave_tilde, t_leafwave_tilde, coupling, x_core,
               aero_leafwave_set_coupling)
AERO_PD_SETTER(leafwave_tilde, t_leafwave_tilde, flutter, x_core,
               aero_leafwave_set_flutter)
AERO_PD_SETTER(leafwave_tilde, t_leafwave_tilde, hit, x_core,
               aero_leafwave_set_hit)
AERO_PD_SETTER(leafwave_tilde, t_leafwave_tilde, rub, x_core,
               aero_leafwave_set_rub)
AERO_PD_SETTER_WHOLE(leafwave_tilde, t_leafwave_tilde, voices, x_core,
                     aero_leafwave_set_voices)

/* fm (which 0), tables per octave (1) or octaves (2): the other two stay
   (as last asked) */
static void leafwave_tilde_set_tables(t_leafwave_tilde *x, int which,
                                      t_float f, const char *what)
{
    double v[3];
    int per, oct;
    v[0] = x->x_want.fm;
    v[1] = x->x_want.per_octave;
    v[2] = x->x_want.octaves;
    v[which] = f;
    if (aero_pd_whole_of(&x->x_base, "tables", v[1], &per) ||
        aero_pd_whole_of(&x->x_base, "octaves", v[2], &oct)) {
        aero_pd_refused(&x->x_base, what, f);
        return;
    }
    if ((long)per * oct > AERO_LEAFWAVE_TABLES_MAX) {
        /* each within its range, the product not: say the real limit */
        pd_error(x, OBJ ": %s %g refused: %d tables per octave x %d octaves "
                 "= %ld tables, at most %d in all (with %s %d: %s at most "
                 "%d)", what, f, per, oct, (long)per * oct,
                 AERO_LEAFWAVE_TABLES_MAX, which == 2 ? "tables" : "octaves",
                 which == 2 ? per : oct, which == 2 ? "octaves" : "tables",
                 AERO_LEAFWAVE_TABLES_MAX / (which == 2 ? per : oct));
        return;
    }
    if (!aero_leafwave_tables_valid(v[0], per, oct) ||
        (x->x_creating &&
         aero_leafwave_set_tables(&x->x_core, v[0], per, oct))) {
        aero_pd_refused(&x->x_base, what, f);
        return;
    }
    x->x_want.fm = v[0];
    x->x_want.per_octave = per;
    x->x_want.octaves = oct;
    leafwave_tilde_rebuild(x);
}

static void leafwave_tilde_reach(t_leafwave_tilde *x, t_floatarg f)
{
    if (!aero_leafwave_reach_valid(f) ||
        (x->x_creating && aero_leafwave_set_reach(&x->x_core, f))) {
        aero_pd_refused(&x->x_base, "reach", f);
        return;
    }
    x->x_want.reach = f;
    leafwave_tilde_rebuild(x);
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
    if (aero_pd_seed_of(&x->x_base, f, &seed))
        return;
    if (x->x_creating && aero_leafwave_set_seed(&x->x_core, seed))
        pd_error(x, OBJ ": out of memory restarting from seed %g", f);
    x->x_want.seed = seed;
    leafwave_tilde_rebuild(x);
}

static void leafwave_tilde_wind(t_leafwave_tilde *x, t_symbol *s, int argc,
                                t_atom *argv)
{
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
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (aero_leafwave_set_mic(&x->x_core, v[0], v[1], v[2]))
        aero_pd_refused_list(&x->x_base, s->s_name);
}

static void leafwave_tilde_listener(t_leafwave_tilde *x, t_symbol *s,
                                    int argc, t_atom *argv)
{
    aero_ears e;
    if (aero_pd_ears(&x->x_base, s, argc, argv, &e) &&
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
     AERO_PD_RANGE_NOTE(AERO_MOVING_WIND_MIN, AERO_MOVING_WIND_MAX, "m/s",
                        "the vector's length")},
    {"listener", AERO_PD_LIST, 3, (t_method)leafwave_tilde_listener, 0, AERO_PD_NO_RULE},
    {"ears", AERO_PD_LIST, 6, (t_method)leafwave_tilde_listener, 0, AERO_PD_NO_RULE},
    {"mic", AERO_PD_LIST, 3, (t_method)leafwave_tilde_mic, 0,
     AERO_PD_NOTE("a finite direction; 0 0 0 aims it at the tree")},
    {"k", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_k, 0,
     AERO_PD_RANGE_DEF(AERO_LEAFWAVE_MIC_K_MIN, AERO_LEAFWAVE_MIC_K_MAX,
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
     AERO_PD_RANGE_DEF(AERO_TREE_BETA_MIN, AERO_TREE_BETA_MAX,
                       AERO_TREE_BETA_DEFAULT, NULL)},
    {"sway", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_sway, 0,
     AERO_PD_RANGE_DEF(AERO_LEAFWAVE_SWAY_MIN, AERO_LEAFWAVE_SWAY_MAX,
                       AERO_LEAFWAVE_SWAY_DEFAULT, "rad")},
    {"coupling", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_coupling, 0,
     AERO_PD_RANGE_DEF(-AERO_LEAFWAVE_COUPLING_MAX, AERO_LEAFWAVE_COUPLING_MAX,
                       AERO_LEAFWAVE_COUPLING_DEFAULT, NULL)},
    {"flutter", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_flutter, 0,
     AERO_PD_RANGE_DEF(AERO_LEAFWAVE_FLUTTER_MIN, AERO_LEAFWAVE_FLUTTER_MAX,
                       AERO_LEAFWAVE_FLUTTER_DEFAULT, "Hz")},
    {"hit", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_hit, 0,
     AERO_PD_RANGE_DEF(AERO_LEAFWAVE_PA_MIN, AERO_LEAFWAVE_PA_MAX,
                       AERO_LEAFWAVE_HIT_DEFAULT, "Pa")},
    {"rub", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_rub, 0,
     AERO_PD_RANGE_DEF(AERO_LEAFWAVE_PA_MIN, AERO_LEAFWAVE_PA_MAX,
                       AERO_LEAFWAVE_RUB_DEFAULT, "Pa")},
    {"reach", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_reach, 0,
     AERO_PD_RANGE_DEF(AERO_LEAFWAVE_REACH_MIN, AERO_LEAFWAVE_REACH_MAX,
                       AERO_LEAFWAVE_REACH_DEFAULT, NULL)},
    {"voices", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_voices, 0,
     AERO_PD_RANGE_DEF(AERO_LEAFWAVE_VOICES_MIN, AERO_LEAFWAVE_VOICES_MAX,
                       AERO_LEAFWAVE_VOICES_DEFAULT, NULL)},
    {"fm", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_fm, 0,
     AERO_PD_RANGE_DEF(AERO_LEAFWAVE_FM_MIN, AERO_LEAFWAVE_FM_MAX,
                       AERO_LEAFWAVE_FM_DEFAULT, "Hz")},
    {"tables", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_tables, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_LEAFWAVE_PER_OCTAVE_MIN,
                            AERO_LEAFWAVE_PER_OCTAVE_MAX,
                            AERO_LEAFWAVE_PER_OCTAVE_DEFAULT, "per octave",
                            TABLES_NOTE)},
    {"octaves", AERO_PD_FLOAT, 0, (t_method)leafwave_tilde_octaves, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_LEAFWAVE_OCTAVES_MIN,
                            AERO_LEAFWAVE_OCTAVES_MAX,
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
    aero_pd_swap_init(&x->x_swap, x, leafwave_tilde_finish,
                      leafwave_tilde_free_core);
    x->x_creating = 1;
    /* a failed init leaves a silent core, safe to use */
    if (aero_leafwave_init(&x->x_core, sys_getsr(), x->x_base.stereo ? 2 : 1,
                           aero_pd_default_seed()))
        aero_pd_init_failed(&x->x_base, sys_getsr());
    /* the tree file: the first argument that is not a flag; the seed and
       the tables are set by the flags first, so the tree is built once */
    t_symbol *file = aero_pd_first_symbol(&argc, &argv);
    aero_pd_parse_flags(&x->x_base, argc, argv);
    leafwave_tilde_want_live(x);
    if (file)
        leafwave_tilde_open(x, file);
    aero_pd_no_file(&x->x_base, "tree", "open");
    x->x_creating = 0;
    aero_pd_base_outlets(&x->x_base);
    return x;
}

static void leafwave_tilde_free(t_leafwave_tilde *x)
{
    aero_pd_base_free(&x->x_base);
    lw_load *l = x->x_swap.load;
    /* a job is not waited for: the worker drops what it made when done;
       the live tree it may still be copying becomes the job's */
    if (x->x_swap.job && l->has_live) {
        l->owns_live = 1;
        memset(&x->x_core.tree, 0, sizeof(x->x_core.tree));
    }
    aero_pd_swap_free(&x->x_swap, leafwave_tilde_drop_load);
    aero_leafwave_free(&x->x_core);
}

AERO_PD_EXPORT void leafwave_tilde_setup(void)
{
    leafwave_tilde_class = aero_pd_class_new(
        &leafwave_tilde_spec, (t_newmethod)(t_method)leafwave_tilde_new,
        (t_method)leafwave_tilde_free, sizeof(t_leafwave_tilde),
        offsetof(t_leafwave_tilde, x_f), (t_method)leafwave_tilde_dsp);
}
