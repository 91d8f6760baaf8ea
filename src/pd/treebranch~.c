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

#include <stdlib.h>
#include <string.h>

static t_class *treebranch_tilde_class;

typedef struct _treebranch_tilde {
    t_object x_obj;
    t_float x_f;
    aero_pd_base x_base;
    aero_pd_wind x_wind;
    aero_treebranch x_core;
    /* a tree loading in a worker: read and a new core built there,
       swapped in by the clock with a fade; the old core plays meanwhile
       (aero_pd_swap) */
    aero_pd_swap x_swap;
    int x_creating;           /* in new(): a seed acts at once */
    uint32_t x_want_seed;     /* the seed asked (a job builds it) */
} t_treebranch_tilde;

typedef struct tb_load {
    int has_file;             /* else the live tree again (a new seed) */
    aero_pd_tree_file read;
    aero_tree live;           /* the live core's tree (shared, read-only) */
    int has_live, owns_live;  /* owns: its object was deleted meanwhile */
    aero_treebranch snap;     /* the live core's numbers at the start */
    aero_treebranch core;     /* built in the worker */
    int ok;
} tb_load;

#define OBJ "[treebranch~]"

static int treebranch_tilde_process(void *obj, const float *in,
                                    float *const *out, int n)
{
    t_treebranch_tilde *x = obj;
    /* the near-field policy: reported once (the last block's record) */
    aero_pd_near(&x->x_base, &x->x_core.near);
    aero_treebranch *old = x->x_swap.old;
    if (old) {
        /* the old core into scratch first (the inlet may alias out[0]),
           faded out under the new one in chunks */
        float a[2][64];
        for (int done = 0; done < n;) {
            int m = n - done < 64 ? n - done : 64;
            aero_treebranch_process_speed(old, in ? in + done : NULL,
                                          a[0], out[1] ? a[1] : NULL, m);
            aero_treebranch_process_speed(&x->x_core, in ? in + done : NULL,
                                          out[0] + done,
                                          out[1] ? out[1] + done : NULL, m);
            for (int i = 0; i < m; i++) {
                float g = aero_pd_swap_gain(&x->x_swap);
                out[0][done + i] += g * a[0][i];
                if (out[1])
                    out[1][done + i] += g * a[1][i];
            }
            done += m;
        }
        return 0;
    }
    /* the inlet is the speed along the wind's direction; the core takes
       the block's mean and reports a clamp */
    return aero_treebranch_process_speed(&x->x_core, in, out[0], out[1], n);
}

static void treebranch_tilde_dsp(t_treebranch_tilde *x, t_signal **sp)
{
    if (aero_treebranch_set_sample_rate(&x->x_core, sp[0]->s_sr))
        aero_pd_rate_failed(&x->x_base, sp[0]->s_sr);
    aero_pd_dsp(&x->x_base, sp, 1, treebranch_tilde_process);
}

/* ---- the tree file: read and built in a worker --------------------------- */

static int treebranch_tilde_build(void *arg)
{
    tb_load *l = arg;
    aero_tree t;
    if (l->has_file ? aero_pd_tree_read(&l->read, &t)
                    : aero_tree_copy(&t, &l->live))
        return -1;
    if (aero_treebranch_init(&l->core, l->snap.sample_rate, l->snap.seed) ||
        aero_treebranch_copy_settings(&l->core, &l->snap) ||
        aero_treebranch_set_tree(&l->core, &t)) {
        aero_tree_free(&t);
        return -1;
    }
    l->ok = 1;
    return 0;
}

/* a job's leftovers (load_job.h: also from the worker, when abandoned) */
static void treebranch_tilde_drop_load(void *arg)
{
    tb_load *l = arg;
    if (l->ok)
        aero_treebranch_free(&l->core);
    if (l->owns_live)
        aero_tree_free(&l->live);
    free(l);
}

static void treebranch_tilde_free_core(void *core)
{
    aero_treebranch_free(core);
}

static void treebranch_tilde_start(t_treebranch_tilde *x, t_symbol *name,
                                   int now);

/* the finished load: its report, then the new core swapped in (the old
   one fades out) */
static void treebranch_tilde_finish(void *owner)
{
    t_treebranch_tilde *x = owner;
    tb_load *l = aero_pd_swap_take(&x->x_swap);
    if (l->has_file && aero_pd_tree_report(&x->x_base, &l->read)) {
        ; /* refused: the tree that played, if any, plays on */
    } else if (!l->ok && l->has_file) {
        pd_error(x, OBJ ": %s: out of memory: silent", l->read.path);
        aero_treebranch_set_tree(&x->x_core, NULL);
    } else if (!l->ok) {
        pd_error(x, OBJ ": out of memory restarting the tree: silent");
        aero_treebranch_set_tree(&x->x_core, NULL);
        x->x_want_seed = x->x_core.seed;
    } else {
        /* what changed while it loaded */
        aero_treebranch_set_sample_rate(&l->core, x->x_core.sample_rate);
        aero_treebranch_copy_settings(&l->core, &x->x_core);
        aero_treebranch *old = aero_pd_swap_fade_slot(
            &x->x_swap, sizeof(*old), l->core.sample_rate);
        if (old)
            aero_treebranch_move(old, &x->x_core);
        else
            aero_treebranch_free(&x->x_core);
        aero_treebranch_move(&x->x_core, &l->core);
    }
    treebranch_tilde_drop_load(l);
    if (x->x_swap.next) {
        t_symbol *next = x->x_swap.next;
        x->x_swap.next = NULL;
        treebranch_tilde_start(x, next, 0);
    } else if (x->x_want_seed != x->x_core.seed) {
        if (x->x_core.has_tree)
            treebranch_tilde_start(x, NULL, 0);
        else
            aero_treebranch_set_seed(&x->x_core, x->x_want_seed);
    }
}

/* Starts reading `name` in the worker (aero_pd_swap_start). `now`
   (creation): a file under AERO_PD_SWAP_SMALL_FILE is read here at once,
   so a patch plays its tree from the first block. */
static void treebranch_tilde_start(t_treebranch_tilde *x, t_symbol *name,
                                   int now)
{
    if (x->x_swap.job) {
        if (name)
            x->x_swap.next = name; /* the latest wins; a new seed follows */
        return;
    }
    tb_load *l = calloc(1, sizeof(*l));
    if (!l) {
        pd_error(x, OBJ ": out of memory: silent");
        aero_treebranch_set_tree(&x->x_core, NULL);
        return;
    }
    int small = 0;
    if (name) {
        if (aero_pd_tree_find(&x->x_base, treebranch_tilde_class, name,
                              &l->read)) {
            free(l); /* the tree that played, if any, plays on */
            return;
        }
        l->has_file = 1;
        small = aero_pd_swap_small(l->read.path);
    } else {
        /* the arrays stay the live core's: not replaced while this runs */
        l->live = x->x_core.tree;
        l->has_live = 1;
    }
    l->snap = x->x_core; /* its numbers only are read */
    l->snap.seed = x->x_want_seed;
    if (aero_pd_swap_start(&x->x_swap, treebranch_tilde_build, l,
                           now && small)) {
        free(l);
        pd_error(x, OBJ ": out of memory: silent");
    }
}

static void treebranch_tilde_open(t_treebranch_tilde *x, t_symbol *name)
{
    treebranch_tilde_start(x, name, 0);
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

/* a new seed restarts the motion of every branch: in a job (a copy of
   the tree and a new core) when there is a tree, but at once in new() (the
   flag) or without a tree, where it costs nothing */
static void treebranch_tilde_seed(t_treebranch_tilde *x, t_floatarg f)
{
    uint32_t seed;
    if (aero_pd_seed_of(&x->x_base, f, &seed))
        return;
    x->x_want_seed = seed;
    if (x->x_creating || (!x->x_swap.job && !x->x_core.has_tree)) {
        if (aero_treebranch_set_seed(&x->x_core, x->x_want_seed))
            pd_error(x, OBJ ": out of memory restarting the tree: silent");
    } else {
        treebranch_tilde_start(x, NULL, 0);
    }
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
     AERO_PD_RANGE_DEF(AERO_TREE_BETA_MIN, AERO_TREE_BETA_MAX,
                       AERO_TREE_BETA_DEFAULT, NULL)},
    {"alpha", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_alpha, 0,
     AERO_PD_RANGE_DEF(AERO_TREEBRANCH_ALPHA_MIN, AERO_TREEBRANCH_ALPHA_MAX,
                       AERO_TREEBRANCH_ALPHA_DEFAULT, NULL)},
    {"k", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_k, 0,
     AERO_PD_RANGE_DEF(AERO_TREEBRANCH_MIC_K_MIN, AERO_TREEBRANCH_MIC_K_MAX,
                       AERO_TREEBRANCH_MIC_K_DEFAULT, NULL)},
    {"ramp", AERO_PD_FLOAT, 0, (t_method)treebranch_tilde_ramp, 0,
     AERO_PD_RAMP},
    {"mic", AERO_PD_LIST, 3, (t_method)treebranch_tilde_mic, 0,
     AERO_PD_NOTE("a finite direction; 0 0 0 aims it at the tree")},
    {"listener", AERO_PD_LIST, 3, (t_method)treebranch_tilde_listener, 0,
     AERO_PD_NO_RULE},
    {"ears", AERO_PD_LIST, 6, (t_method)treebranch_tilde_listener, 0, AERO_PD_NO_RULE},
    {"wind", AERO_PD_LIST, 3, (t_method)treebranch_tilde_wind, 0,
     AERO_PD_RANGE_NOTE(AERO_MOVING_WIND_MIN, AERO_MOVING_WIND_MAX, "m/s",
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
    aero_pd_swap_init(&x->x_swap, x, treebranch_tilde_finish,
                      treebranch_tilde_free_core);
    x->x_creating = 1;
    if (aero_treebranch_init(&x->x_core, sys_getsr(), aero_pd_default_seed()))
        aero_pd_init_failed(&x->x_base, sys_getsr());
    aero_treebranch_set_stereo(&x->x_core, x->x_base.stereo);
    x->x_want_seed = x->x_core.seed;
    /* the tree file: the first argument, when it is not a flag */
    t_symbol *file = aero_pd_first_symbol(&argc, &argv);
    if (file)
        treebranch_tilde_start(x, file, 1);
    aero_pd_parse_flags(&x->x_base, argc, argv);
    x->x_creating = 0;
    aero_pd_no_file(&x->x_base, "tree", "open");
    aero_pd_base_outlets(&x->x_base);
    return x;
}

static void treebranch_tilde_free(t_treebranch_tilde *x)
{
    aero_pd_base_free(&x->x_base);
    tb_load *l = x->x_swap.load;
    /* a job is not waited for: the worker drops what it made when done;
       the live tree it may still be copying becomes the job's */
    if (x->x_swap.job && l->has_live) {
        l->owns_live = 1;
        memset(&x->x_core.tree, 0, sizeof(x->x_core.tree));
    }
    aero_pd_swap_free(&x->x_swap, treebranch_tilde_drop_load);
    aero_treebranch_free(&x->x_core);
}

AERO_PD_EXPORT void treebranch_tilde_setup(void)
{
    treebranch_tilde_class = aero_pd_class_new(
        &treebranch_tilde_spec, (t_newmethod)(t_method)treebranch_tilde_new,
        (t_method)treebranch_tilde_free, sizeof(t_treebranch_tilde),
        offsetof(t_treebranch_tilde, x_f), (t_method)treebranch_tilde_dsp);
}
