/* [treebranch~]: the sound of a tree's branches in the wind (paper 003).
 * Thin Pd wrapper around src/core/treebranch.
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
    aero_treebranch x_tb;
    t_canvas *x_canvas;
    double x_dir[3];        /* unit wind direction */
    double x_speed;         /* the last block's speed, m/s */
    int x_stereo;
    int x_clamped, x_warned_clamp;
    t_clock *x_clock;
    t_outlet *x_out[2];
} t_treebranch_tilde;

#define OBJ "[treebranch~]"

static void treebranch_tilde_report(t_treebranch_tilde *x)
{
    if (x->x_clamped && !x->x_warned_clamp) {
        pd_error(x, OBJ ": wind above Mach 0.3 clamped to %g m/s (the model "
                 "does not hold there)", 0.3 * 343.0);
        x->x_warned_clamp = 1;
    }
}

static void treebranch_tilde_apply_wind(t_treebranch_tilde *x, double speed)
{
    double w[3];
    int k;
    if (!(speed == speed) || fabs(speed) > 1e30)
        speed = 0.0;
    for (k = 0; k < 3; k++)
        w[k] = x->x_dir[k] * speed;
    x->x_speed = speed;
    if (aero_treebranch_set_wind(&x->x_tb, w) == 1 && !x->x_clamped) {
        x->x_clamped = 1;
        clock_delay(x->x_clock, 0);
    }
}

static t_int *treebranch_tilde_perform(t_int *w)
{
    t_treebranch_tilde *x = (t_treebranch_tilde *)(w[1]);
    t_sample *in = (t_sample *)(w[2]);
    t_sample *out0 = (t_sample *)(w[3]);
    t_sample *out1 = x->x_stereo ? (t_sample *)(w[4]) : NULL;
    int n = (int)(w[5]), i;
    double sum = 0.0;
    /* the wind speed is the block's mean (frames are ~10 ms apart); read
       before writing: in and out may share a buffer */
    for (i = 0; i < n; i++)
        sum += in[i];
    if (n > 0 && sum / n != x->x_speed)
        treebranch_tilde_apply_wind(x, sum / n);
    aero_treebranch_process(&x->x_tb, out0, out1, n);
    return w + 6;
}

static void treebranch_tilde_dsp(t_treebranch_tilde *x, t_signal **sp)
{
    if (aero_treebranch_set_sample_rate(&x->x_tb, sp[0]->s_sr))
        pd_error(x, OBJ ": bad sample rate %g (or out of memory)",
                 sp[0]->s_sr);
    dsp_add(treebranch_tilde_perform, 5, x, sp[0]->s_vec, sp[1]->s_vec,
            x->x_stereo ? sp[2]->s_vec : sp[1]->s_vec, (t_int)sp[0]->s_n);
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
    if (aero_pd_find_tree(x->x_canvas, treebranch_tilde_class, name->s_name,
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
    double v[3], speed;
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (!(fabs(v[0]) < 1e30 && fabs(v[1]) < 1e30 && fabs(v[2]) < 1e30)) {
        pd_error(x, OBJ ": wind must be finite");
        return;
    }
    speed = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (speed > 0.0) {
        x->x_dir[0] = v[0] / speed;
        x->x_dir[1] = v[1] / speed;
        x->x_dir[2] = v[2] / speed;
    }
    /* the inlet's float is the speed along the direction (a connected
       signal overrides it) */
    x->x_f = (t_float)speed;
    treebranch_tilde_apply_wind(x, speed);
}

static void treebranch_tilde_listener(t_treebranch_tilde *x, t_symbol *s,
                                      int argc, t_atom *argv)
{
    double v[3];
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (aero_treebranch_set_listener(&x->x_tb, v))
        pd_error(x, OBJ ": listener position must be finite, within 1e5 m");
}

static void treebranch_tilde_ears(t_treebranch_tilde *x, t_symbol *s,
                                  int argc, t_atom *argv)
{
    double v[6];
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 6, v))
        return;
    if (!x->x_stereo)
        pd_error(x, OBJ ": 'ears' needs -stereo (the left ear is used)");
    if (aero_treebranch_set_ears(&x->x_tb, v, v + 3))
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
        pd_error(x, OBJ ": k %g out of range (0..20)", f);
}

static void treebranch_tilde_gain(t_treebranch_tilde *x, t_floatarg f)
{
    if (aero_treebranch_set_gain_db(&x->x_tb, f))
        pd_error(x, OBJ ": gain %g dB out of range (-200..120)", f);
}

static void treebranch_tilde_ramp(t_treebranch_tilde *x, t_floatarg f)
{
    if (aero_treebranch_set_ramp_ms(&x->x_tb, f))
        pd_error(x, OBJ ": ramp %g ms out of range (0..600000)", f);
}

static void treebranch_tilde_stiffness(t_treebranch_tilde *x, t_floatarg f)
{
    if (aero_treebranch_set_stiffness(&x->x_tb, f))
        pd_error(x, OBJ ": stiffness %g out of range (0.001..1000)", f);
}

static void treebranch_tilde_beta(t_treebranch_tilde *x, t_floatarg f)
{
    if (aero_treebranch_set_beta(&x->x_tb, f))
        pd_error(x, OBJ ": beta %g out of range (0..2)", f);
}

static void treebranch_tilde_alpha(t_treebranch_tilde *x, t_floatarg f)
{
    if (aero_treebranch_set_alpha(&x->x_tb, f))
        pd_error(x, OBJ ": alpha %g out of range (0.5..8)", f);
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

static int treebranch_tilde_flag(void *obj, t_symbol *flag, int argc,
                                 t_atom *argv)
{
    t_treebranch_tilde *x = obj;
    static const struct {
        const char *name;
        int count;
    } flags[] = {{"-stereo", 0},   {"-seed", 1},     {"-gain", 1},
                 {"-stiffness", 1}, {"-beta", 1},    {"-alpha", 1},
                 {"-k", 1},        {"-ramp", 1},     {"-mic", 3},
                 {"-listener", 3}, {"-ears", 6},     {"-wind", 3}};
    for (size_t k = 0; k < sizeof(flags) / sizeof(flags[0]); k++) {
        if (strcmp(flag->s_name, flags[k].name))
            continue;
        int count = flags[k].count;
        const char *name = flags[k].name + 1;
        if (argc < count) {
            pd_error(x, OBJ ": flag %s needs %d value(s)", flag->s_name, count);
            return argc + 1;
        }
        for (int i = 0; i < count; i++)
            if (argv[i].a_type != A_FLOAT) {
                pd_error(x, OBJ ": flag %s needs numbers", flag->s_name);
                return count + 1;
            }
        t_float f = count ? atom_getfloat(argv) : 0;
        if (!strcmp(name, "stereo"))
            ; /* read before the outlets were made */
        else if (!strcmp(name, "seed"))
            treebranch_tilde_seed(x, f);
        else if (!strcmp(name, "gain"))
            treebranch_tilde_gain(x, f);
        else if (!strcmp(name, "stiffness"))
            treebranch_tilde_stiffness(x, f);
        else if (!strcmp(name, "beta"))
            treebranch_tilde_beta(x, f);
        else if (!strcmp(name, "alpha"))
            treebranch_tilde_alpha(x, f);
        else if (!strcmp(name, "k"))
            treebranch_tilde_k(x, f);
        else if (!strcmp(name, "ramp"))
            treebranch_tilde_ramp(x, f);
        else
            (!strcmp(name, "mic") ? treebranch_tilde_mic
             : !strcmp(name, "listener") ? treebranch_tilde_listener
             : !strcmp(name, "ears") ? treebranch_tilde_ears
                                     : treebranch_tilde_wind)(
                x, gensym(name), count, argv);
        return count + 1;
    }
    return 0;
}

static void *treebranch_tilde_new(t_symbol *s, int argc, t_atom *argv)
{
    (void)s;
    t_treebranch_tilde *x =
        (t_treebranch_tilde *)pd_new(treebranch_tilde_class);
    x->x_canvas = canvas_getcurrent();
    x->x_dir[0] = 1.0; /* default wind direction: +x */
    x->x_clock = clock_new(x, (t_method)treebranch_tilde_report);
    if (aero_treebranch_init(&x->x_tb, sys_getsr(), aero_pd_default_seed()))
        pd_error(x, OBJ ": out of memory: silent");
    for (int i = 0; i < argc; i++)
        if (argv[i].a_type == A_SYMBOL
            && !strcmp(argv[i].a_w.w_symbol->s_name, "-stereo"))
            x->x_stereo = 1;
    aero_treebranch_set_stereo(&x->x_tb, x->x_stereo);
    /* the tree file: the first argument, when it is not a flag */
    if (argc > 0 && argv[0].a_type == A_SYMBOL
        && argv[0].a_w.w_symbol->s_name[0] != '-') {
        treebranch_tilde_open(x, argv[0].a_w.w_symbol);
        argc--;
        argv++;
    }
    aero_pd_parse_flags(x, OBJ, "<treefile> -stereo -seed -gain -stiffness "
                        "-beta -alpha -k -ramp -mic -listener -ears -wind",
                        treebranch_tilde_flag, argc, argv);
    x->x_out[0] = outlet_new(&x->x_obj, &s_signal);
    if (x->x_stereo)
        x->x_out[1] = outlet_new(&x->x_obj, &s_signal);
    return x;
}

static void treebranch_tilde_free(t_treebranch_tilde *x)
{
    clock_free(x->x_clock);
    aero_treebranch_free(&x->x_tb);
    outlet_free(x->x_out[0]);
    if (x->x_out[1])
        outlet_free(x->x_out[1]);
}

void treebranch_tilde_setup(void)
{
    treebranch_tilde_class =
        class_new(gensym("treebranch~"),
                  (t_newmethod)(t_method)treebranch_tilde_new,
                  (t_method)treebranch_tilde_free, sizeof(t_treebranch_tilde),
                  CLASS_DEFAULT, A_GIMME, 0);
    CLASS_MAINSIGNALIN(treebranch_tilde_class, t_treebranch_tilde, x_f);
    class_addmethod(treebranch_tilde_class, (t_method)treebranch_tilde_dsp,
                    gensym("dsp"), A_CANT, 0);
    static const struct {
        const char *name;
        t_method fn;
    } floats[] = {{"gain", (t_method)treebranch_tilde_gain},
                  {"ramp", (t_method)treebranch_tilde_ramp},
                  {"seed", (t_method)treebranch_tilde_seed},
                  {"stiffness", (t_method)treebranch_tilde_stiffness},
                  {"beta", (t_method)treebranch_tilde_beta},
                  {"alpha", (t_method)treebranch_tilde_alpha},
                  {"k", (t_method)treebranch_tilde_k}};
    for (size_t k = 0; k < sizeof(floats) / sizeof(floats[0]); k++)
        class_addmethod(treebranch_tilde_class, floats[k].fn,
                        gensym(floats[k].name), A_FLOAT, 0);
    static const struct {
        const char *name;
        t_method fn;
    } lists[] = {{"wind", (t_method)treebranch_tilde_wind},
                 {"listener", (t_method)treebranch_tilde_listener},
                 {"ears", (t_method)treebranch_tilde_ears},
                 {"mic", (t_method)treebranch_tilde_mic}};
    for (size_t k = 0; k < sizeof(lists) / sizeof(lists[0]); k++)
        class_addmethod(treebranch_tilde_class, lists[k].fn,
                        gensym(lists[k].name), A_GIMME, 0);
    class_addmethod(treebranch_tilde_class, (t_method)treebranch_tilde_open,
                    gensym("open"), A_SYMBOL, 0);
}
