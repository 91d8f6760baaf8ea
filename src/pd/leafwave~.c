/* [leafwave~]: the leaves of a tree in the wind (paper 003): collisions and
 * friction between neighbouring leaves played from pink wave tables. Thin
 * Pd wrapper around src/core/leafwave.
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
    aero_leafwave x_model;
    int x_ok;             /* the core is initialised */
    int x_stereo;
    t_canvas *x_canvas;
    double x_dir[3];      /* unit wind direction */
    double x_speed;       /* the last block's speed, m/s */
    int x_clamped, x_warned_clamp;
    t_clock *x_clock;
    t_outlet *x_out[2];
} t_leafwave_tilde;

#define OBJ "[leafwave~]"

static void leafwave_tilde_report(t_leafwave_tilde *x)
{
    if (x->x_clamped && !x->x_warned_clamp) {
        pd_error(x, OBJ ": wind above Mach 0.3 clamped to %g m/s "
                 "(the model does not hold there)", 0.3 * 343.0);
        x->x_warned_clamp = 1;
    }
}

static void leafwave_tilde_apply_wind(t_leafwave_tilde *x, double speed)
{
    if (!(speed == speed) || fabs(speed) > 1e30)
        speed = 0.0;
    x->x_speed = speed;
    if (aero_leafwave_set_wind(&x->x_model, x->x_dir[0] * speed,
                               x->x_dir[1] * speed, x->x_dir[2] * speed) &&
        !x->x_clamped) {
        x->x_clamped = 1;
        clock_delay(x->x_clock, 0);
    }
}

static t_int *leafwave_tilde_perform(t_int *w)
{
    t_leafwave_tilde *x = (t_leafwave_tilde *)(w[1]);
    t_sample *speed = (t_sample *)(w[2]);
    t_sample *outs[2] = {(t_sample *)(w[3]), (t_sample *)(w[4])};
    int n = (int)(w[5]);
    if (!x->x_ok) {
        for (int i = 0; i < n; i++)
            outs[0][i] = outs[1][i] = 0;
        return w + 6;
    }
    /* the wind, as [treebranch~] takes it: the inlet is the speed along
       the wind's direction, the block's mean; read before writing (in and
       out may share a buffer) */
    double sum = 0.0;
    for (int i = 0; i < n; i++)
        sum += speed[i];
    if (n > 0 && sum / n != x->x_speed)
        leafwave_tilde_apply_wind(x, sum / n);
    aero_leafwave_process(&x->x_model, NULL, outs, n);
    return w + 6;
}

static void leafwave_tilde_dsp(t_leafwave_tilde *x, t_signal **sp)
{
    if (x->x_ok && aero_leafwave_set_sample_rate(&x->x_model, sp[0]->s_sr))
        pd_error(x, OBJ ": bad sample rate %g", sp[0]->s_sr);
    dsp_add(leafwave_tilde_perform, 5, x, sp[0]->s_vec, sp[1]->s_vec,
            x->x_stereo ? sp[2]->s_vec : sp[1]->s_vec, (t_int)sp[0]->s_n);
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
    if (aero_pd_find_tree(x->x_canvas, leafwave_tilde_class, name->s_name,
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

#define SETTER(fn, call, what)                                            \
    static void leafwave_tilde_##fn(t_leafwave_tilde *x, t_floatarg f)    \
    {                                                                     \
        if (x->x_ok && call(&x->x_model, f))                              \
            pd_error(x, OBJ ": " what, f);                                \
    }

SETTER(gain, aero_leafwave_set_gain_db, "gain %g dB out of range (-200..120)")
SETTER(ramp, aero_leafwave_set_ramp_ms, "ramp %g ms out of range (0..600000)")
SETTER(stiffness, aero_leafwave_set_stiffness,
       "stiffness %g out of range (0.001..1000)")
SETTER(beta, aero_leafwave_set_beta, "beta %g out of range (0..2)")
SETTER(k, aero_leafwave_set_mic_k, "k %g out of range (0..100)")
SETTER(sway, aero_leafwave_set_sway, "sway %g rad out of range (0..1.5)")
SETTER(coupling, aero_leafwave_set_coupling,
       "coupling %g out of range (-10..10)")
SETTER(flutter, aero_leafwave_set_flutter,
       "flutter %g Hz out of range (0.01..30)")
SETTER(hit, aero_leafwave_set_hit, "hit %g Pa out of range (0..100)")
SETTER(rub, aero_leafwave_set_rub, "rub %g Pa out of range (0..100)")
SETTER(reach, aero_leafwave_set_reach, "reach %g out of range (0.1..10)")

static void leafwave_tilde_voices(t_leafwave_tilde *x, t_floatarg f)
{
    int n;
    if (x->x_ok && (aero_pd_whole(f, 1, 65536, &n) ||
                    aero_leafwave_set_voices(&x->x_model, n)))
        pd_error(x, OBJ ": voices %g out of range (1..65536)", f);
}

static void leafwave_tilde_set_tables(t_leafwave_tilde *x, double fm,
                                      double per_octave, double octaves,
                                      const char *what, double value)
{
    int per, oct;
    if (!x->x_ok)
        return;
    if (aero_pd_whole(per_octave, 1, 128, &per) ||
        aero_pd_whole(octaves, 1, 8, &oct) ||
        aero_leafwave_set_tables(&x->x_model, fm, per, oct))
        pd_error(x, OBJ ": %s %g out of range (fm 20..10000 Hz, tables "
                 "1..128 per octave, octaves 1..8, at most 512 tables)",
                 what, value);
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
    double v[3];
    if (!x->x_ok || aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (!aero_is_finite(v[0]) || !aero_is_finite(v[1]) ||
        !aero_is_finite(v[2])) {
        pd_error(x, OBJ ": wind must be finite");
        return;
    }
    double speed = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (speed > 0.0)
        for (int k = 0; k < 3; k++)
            x->x_dir[k] = v[k] / speed;
    /* the inlet's float is the speed along the direction (a connected
       signal overrides it), as in [treebranch~] */
    x->x_f = (t_float)speed;
    leafwave_tilde_apply_wind(x, speed);
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
    double v[3];
    if (!x->x_ok)
        return;
    if (x->x_stereo) {
        pd_error(x, OBJ ": created with -stereo: use 'ears lx ly lz rx ry rz'");
        return;
    }
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (aero_leafwave_set_ear(&x->x_model, 0, v[0], v[1], v[2]))
        pd_error(x, OBJ ": listener position must be finite, within 1e5 m");
}

static void leafwave_tilde_ears(t_leafwave_tilde *x, t_symbol *s, int argc,
                                t_atom *argv)
{
    double v[6];
    if (!x->x_ok)
        return;
    if (!x->x_stereo) {
        pd_error(x, OBJ ": 'ears' needs -stereo; use 'listener x y z'");
        return;
    }
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 6, v))
        return;
    if (aero_leafwave_set_ear(&x->x_model, 0, v[0], v[1], v[2]) ||
        aero_leafwave_set_ear(&x->x_model, 1, v[3], v[4], v[5]))
        pd_error(x, OBJ ": ear positions must be finite, within 1e5 m");
}

/* --- creation ------------------------------------------------------------- */

typedef void (*float_method)(t_leafwave_tilde *x, t_floatarg f);
typedef void (*list_method)(t_leafwave_tilde *x, t_symbol *s, int argc,
                            t_atom *argv);

static const struct {
    const char *name;
    float_method fn;
} float_messages[] = {
    {"gain", leafwave_tilde_gain},         {"ramp", leafwave_tilde_ramp},
    {"stiffness", leafwave_tilde_stiffness}, {"beta", leafwave_tilde_beta},
    {"k", leafwave_tilde_k},               {"sway", leafwave_tilde_sway},
    {"coupling", leafwave_tilde_coupling}, {"flutter", leafwave_tilde_flutter},
    {"hit", leafwave_tilde_hit},           {"rub", leafwave_tilde_rub},
    {"reach", leafwave_tilde_reach},       {"voices", leafwave_tilde_voices},
    {"fm", leafwave_tilde_fm},             {"tables", leafwave_tilde_tables},
    {"octaves", leafwave_tilde_octaves},   {"seed", leafwave_tilde_seed}};

static const struct {
    const char *name;
    int count;
    list_method fn;
} list_messages[] = {{"wind", 3, leafwave_tilde_wind},
                     {"mic", 3, leafwave_tilde_mic},
                     {"listener", 3, leafwave_tilde_listener},
                     {"ears", 6, leafwave_tilde_ears}};

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

static int leafwave_tilde_flag(void *obj, t_symbol *flag, int argc,
                               t_atom *argv)
{
    t_leafwave_tilde *x = obj;
    const char *name = flag->s_name + 1;
    if (flag->s_name[0] != '-')
        return 0;
    if (!strcmp(name, "stereo"))
        return 1;
    if (!strcmp(name, "open") || !strcmp(name, "tree")) {
        if (argc < 1 || argv[0].a_type != A_SYMBOL) {
            pd_error(x, OBJ ": flag %s needs a file name", flag->s_name);
            return 1 + (argc > 0);
        }
        leafwave_tilde_open(x, argv[0].a_w.w_symbol);
        return 2;
    }
    for (size_t k = 0; k < COUNT(float_messages); k++) {
        if (strcmp(name, float_messages[k].name))
            continue;
        if (argc < 1 || argv[0].a_type != A_FLOAT) {
            pd_error(x, OBJ ": flag %s needs a number", flag->s_name);
            return 1 + (argc > 0);
        }
        float_messages[k].fn(x, atom_getfloat(argv));
        return 2;
    }
    for (size_t k = 0; k < COUNT(list_messages); k++) {
        int count = list_messages[k].count;
        if (strcmp(name, list_messages[k].name))
            continue;
        int have = 0;
        while (have < count && have < argc && argv[have].a_type == A_FLOAT)
            have++;
        if (have < count) {
            pd_error(x, OBJ ": flag %s needs %d numbers", flag->s_name, count);
            return 1 + have;
        }
        list_messages[k].fn(x, gensym(name), count, argv);
        return count + 1;
    }
    return 0;
}

static void *leafwave_tilde_new(t_symbol *s, int argc, t_atom *argv)
{
    (void)s;
    t_leafwave_tilde *x = (t_leafwave_tilde *)pd_new(leafwave_tilde_class);
    x->x_canvas = canvas_getcurrent();
    x->x_dir[0] = 1.0; /* +x until a `wind` message */
    /* -stereo decides the outlets, so look for it first */
    for (int i = 0; i < argc; i++)
        if (argv[i].a_type == A_SYMBOL &&
            !strcmp(argv[i].a_w.w_symbol->s_name, "-stereo"))
            x->x_stereo = 1;
    x->x_ok = aero_leafwave_init(&x->x_model, sys_getsr(),
                                 x->x_stereo ? 2 : 1,
                                 aero_pd_default_seed()) == 0;
    if (!x->x_ok)
        pd_error(x, OBJ ": out of memory: silent");
    x->x_clock = clock_new(x, (t_method)leafwave_tilde_report);
    /* the tree file: the first argument that is not a flag; the seed and
       the tables are set by the flags first, so the tree is built once */
    t_symbol *file = NULL;
    int file_at = -1;
    if (argc > 0 && argv[0].a_type == A_SYMBOL &&
        argv[0].a_w.w_symbol->s_name[0] != '-') {
        file = argv[0].a_w.w_symbol;
        file_at = 0;
    }
    if (file_at == 0) {
        argc--;
        argv++;
    }
    aero_pd_parse_flags(x, OBJ, "<treefile> -stereo -open -wind -listener "
                        "-ears -mic -k -gain -seed -ramp -stiffness -beta "
                        "-sway -coupling -flutter -hit -rub -reach -voices "
                        "-fm -tables -octaves", leafwave_tilde_flag, argc,
                        argv);
    if (file)
        leafwave_tilde_open(x, file);
    else
        post(OBJ ": no tree file given: silent until 'open <file>'");
    x->x_out[0] = outlet_new(&x->x_obj, &s_signal);
    if (x->x_stereo)
        x->x_out[1] = outlet_new(&x->x_obj, &s_signal);
    return x;
}

static void leafwave_tilde_free(t_leafwave_tilde *x)
{
    clock_free(x->x_clock);
    if (x->x_ok)
        aero_leafwave_free(&x->x_model);
    for (int i = 0; i < 2; i++)
        if (x->x_out[i])
            outlet_free(x->x_out[i]);
}

void leafwave_tilde_setup(void)
{
    leafwave_tilde_class = class_new(gensym("leafwave~"),
                                     (t_newmethod)(t_method)leafwave_tilde_new,
                                     (t_method)leafwave_tilde_free,
                                     sizeof(t_leafwave_tilde), CLASS_DEFAULT,
                                     A_GIMME, 0);
    CLASS_MAINSIGNALIN(leafwave_tilde_class, t_leafwave_tilde, x_f);
    class_addmethod(leafwave_tilde_class, (t_method)leafwave_tilde_dsp,
                    gensym("dsp"), A_CANT, 0);
    for (size_t k = 0; k < COUNT(float_messages); k++)
        class_addmethod(leafwave_tilde_class, (t_method)float_messages[k].fn,
                        gensym(float_messages[k].name), A_FLOAT, 0);
    for (size_t k = 0; k < COUNT(list_messages); k++)
        class_addmethod(leafwave_tilde_class, (t_method)list_messages[k].fn,
                        gensym(list_messages[k].name), A_GIMME, 0);
    class_addmethod(leafwave_tilde_class, (t_method)leafwave_tilde_open,
                    gensym("open"), A_SYMBOL, 0);
    class_sethelpsymbol(leafwave_tilde_class, gensym("leafwave~"));
}
