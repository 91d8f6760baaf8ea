/* [cavity~]: cavity tones (a draft through a gap, wind over a hollow, a
 * bottle). Thin Pd wrapper around src/core/cavity_model.
 *
 *   [cavity~ -L 0.02 -D 0.01 -W 0.05 -texture cavity -exponent 2]
 *   inlet 1 (signal): flow speed over the opening, m/s
 *   outlet 1 (signal): sound pressure at the listener, Pa
 */
#include "aero_pd.h"

#include "cavity_model.h"

static t_class *cavity_tilde_class;

typedef struct _cavity_tilde {
    t_object x_obj;
    t_float x_f;
    aero_cavity_model x_model;
    t_canvas *x_canvas;
    int x_clamped, x_warned_clamp;
    t_clock *x_clock;
    t_outlet *x_out;
} t_cavity_tilde;

#define OBJ "[cavity~]"

static void cavity_tilde_report(t_cavity_tilde *x)
{
    if (x->x_clamped && !x->x_warned_clamp) {
        pd_error(x, OBJ ": flow speed above Mach 0.3 clamped to %g m/s "
                 "(the model does not hold there)", 0.3 * 343.0);
        x->x_warned_clamp = 1;
    }
}

static t_int *cavity_tilde_perform(t_int *w)
{
    t_cavity_tilde *x = (t_cavity_tilde *)(w[1]);
    /* the core reads each chunk of speed before writing it: in and out
     * may be the same buffer */
    if (aero_cavity_model_process(&x->x_model, (t_sample *)(w[2]),
                                  (t_sample *)(w[3]), (int)(w[4])) &&
        !x->x_clamped) {
        x->x_clamped = 1;
        clock_delay(x->x_clock, 0);
    }
    return w + 5;
}

static void cavity_tilde_dsp(t_cavity_tilde *x, t_signal **sp)
{
    if (aero_cavity_model_set_sample_rate(&x->x_model, sp[0]->s_sr))
        pd_error(x, OBJ ": bad sample rate %g", sp[0]->s_sr);
    dsp_add(cavity_tilde_perform, 4, x, sp[0]->s_vec, sp[1]->s_vec,
            (t_int)sp[0]->s_n);
}

static void cavity_tilde_length(t_cavity_tilde *x, t_floatarg f)
{
    if (aero_cavity_model_set_length(&x->x_model, f))
        pd_error(x, OBJ ": length %g m out of range (1e-4..100)", f);
}

static void cavity_tilde_depth(t_cavity_tilde *x, t_floatarg f)
{
    if (aero_cavity_model_set_depth(&x->x_model, f))
        pd_error(x, OBJ ": depth %g m out of range (1e-4..100)", f);
}

static void cavity_tilde_width(t_cavity_tilde *x, t_floatarg f)
{
    if (aero_cavity_model_set_width(&x->x_model, f))
        pd_error(x, OBJ ": width %g m out of range (1e-4..100)", f);
}

static void cavity_tilde_gain(t_cavity_tilde *x, t_floatarg f)
{
    if (aero_cavity_model_set_gain_db(&x->x_model, f))
        pd_error(x, OBJ ": gain %g dB out of range (-200..120)", f);
}

static void cavity_tilde_ramp(t_cavity_tilde *x, t_floatarg f)
{
    if (aero_cavity_model_set_ramp_ms(&x->x_model, f))
        pd_error(x, OBJ ": ramp %g ms out of range (0..600000)", f);
}

static void cavity_tilde_exponent(t_cavity_tilde *x, t_floatarg f)
{
    if (aero_cavity_model_set_exponent(&x->x_model, f))
        pd_error(x, OBJ ": exponent %g out of range (0..8)", f);
}

static void cavity_tilde_seed(t_cavity_tilde *x, t_floatarg f)
{
    aero_cavity_model_set_seed(&x->x_model, aero_pd_seed(f));
}

static void cavity_tilde_listener(t_cavity_tilde *x, t_symbol *s, int argc,
                                  t_atom *argv)
{
    double v[3];
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (aero_cavity_model_set_listener(&x->x_model, v[0], v[1], v[2]))
        pd_error(x, OBJ ": listener position must be finite, within 1e5 m");
}

/* file I/O here, in the message domain, never in perform */
static void cavity_tilde_texture(t_cavity_tilde *x, t_symbol *name)
{
    char path[MAXPDSTRING], err[256];
    if (aero_pd_find_texture(x->x_canvas, cavity_tilde_class, name->s_name,
                             path, sizeof(path))) {
        pd_error(x, OBJ ": can't find texture '%s' (looked %s): staying in "
                 "model mode", name->s_name, path);
        aero_cavity_model_set_texture(&x->x_model, NULL, err, sizeof(err));
        return;
    }
    aero_texture *t = getbytes(sizeof(*t));
    if (aero_texture_load(path, t, err, sizeof(err)) ||
        aero_cavity_model_set_texture(&x->x_model, t, err, sizeof(err))) {
        pd_error(x, OBJ ": texture %s: %s: using model mode", path, err);
        aero_texture_free(t);
        freebytes(t, sizeof(*t));
        aero_cavity_model_set_texture(&x->x_model, NULL, err, sizeof(err));
        return;
    }
}

static void cavity_tilde_model(t_cavity_tilde *x)
{
    char err[8];
    aero_cavity_model_set_texture(&x->x_model, NULL, err, sizeof(err));
}

static int cavity_tilde_flag(void *obj, t_symbol *flag, int argc,
                             t_atom *argv)
{
    t_cavity_tilde *x = obj;
    static const struct {
        const char *name;
        int count;
    } flags[] = {{"-L", 1},      {"-length", 1},   {"-D", 1},
                 {"-depth", 1},  {"-W", 1},        {"-width", 1},
                 {"-gain", 1},   {"-seed", 1},     {"-ramp", 1},
                 {"-exponent", 1}, {"-listener", 3}, {"-texture", 1}};
    for (size_t k = 0; k < sizeof(flags) / sizeof(flags[0]); k++) {
        if (strcmp(flag->s_name, flags[k].name))
            continue;
        int count = flags[k].count;
        const char *name = flags[k].name + 1;
        if (argc < count) {
            pd_error(x, OBJ ": flag %s needs %d value(s)", flag->s_name, count);
            return argc + 1;
        }
        if (!strcmp(name, "texture")) {
            if (argv[0].a_type != A_SYMBOL) {
                pd_error(x, OBJ ": flag -texture needs a name");
                return 2;
            }
            cavity_tilde_texture(x, argv[0].a_w.w_symbol);
            return 2;
        }
        for (int i = 0; i < count; i++)
            if (argv[i].a_type != A_FLOAT) {
                pd_error(x, OBJ ": flag %s needs numbers", flag->s_name);
                return count + 1;
            }
        t_float f = atom_getfloat(argv);
        if (!strcmp(name, "L") || !strcmp(name, "length"))
            cavity_tilde_length(x, f);
        else if (!strcmp(name, "D") || !strcmp(name, "depth"))
            cavity_tilde_depth(x, f);
        else if (!strcmp(name, "W") || !strcmp(name, "width"))
            cavity_tilde_width(x, f);
        else if (!strcmp(name, "gain"))
            cavity_tilde_gain(x, f);
        else if (!strcmp(name, "seed"))
            cavity_tilde_seed(x, f);
        else if (!strcmp(name, "ramp"))
            cavity_tilde_ramp(x, f);
        else if (!strcmp(name, "exponent"))
            cavity_tilde_exponent(x, f);
        else if (!strcmp(name, "listener"))
            cavity_tilde_listener(x, gensym("listener"), 3, argv);
        return count + 1;
    }
    return 0;
}

static void *cavity_tilde_new(t_symbol *s, int argc, t_atom *argv)
{
    (void)s;
    t_cavity_tilde *x = (t_cavity_tilde *)pd_new(cavity_tilde_class);
    x->x_canvas = canvas_getcurrent();
    aero_cavity_model_init(&x->x_model, sys_getsr(), aero_pd_default_seed());
    x->x_clock = clock_new(x, (t_method)cavity_tilde_report);
    aero_pd_parse_flags(x, OBJ, "-L -D -W -gain -seed -ramp -exponent "
                        "-listener -texture", cavity_tilde_flag, argc, argv);
    x->x_out = outlet_new(&x->x_obj, &s_signal);
    return x;
}

static void cavity_tilde_free(t_cavity_tilde *x)
{
    clock_free(x->x_clock);
    aero_cavity_model_free(&x->x_model);
    outlet_free(x->x_out);
}

void cavity_tilde_setup(void)
{
    /* via t_method, the generic function type of Pd's API */
    cavity_tilde_class = class_new(gensym("cavity~"),
                                   (t_newmethod)(t_method)cavity_tilde_new,
                                   (t_method)cavity_tilde_free,
                                   sizeof(t_cavity_tilde), CLASS_DEFAULT,
                                   A_GIMME, 0);
    CLASS_MAINSIGNALIN(cavity_tilde_class, t_cavity_tilde, x_f);
    class_addmethod(cavity_tilde_class, (t_method)cavity_tilde_dsp,
                    gensym("dsp"), A_CANT, 0);
    static const struct {
        const char *name;
        t_method fn;
    } floats[] = {
        {"length", (t_method)cavity_tilde_length},
        {"L", (t_method)cavity_tilde_length},
        {"depth", (t_method)cavity_tilde_depth},
        {"D", (t_method)cavity_tilde_depth},
        {"width", (t_method)cavity_tilde_width},
        {"W", (t_method)cavity_tilde_width},
        {"gain", (t_method)cavity_tilde_gain},
        {"ramp", (t_method)cavity_tilde_ramp},
        {"seed", (t_method)cavity_tilde_seed},
        {"exponent", (t_method)cavity_tilde_exponent}};
    for (size_t k = 0; k < sizeof(floats) / sizeof(floats[0]); k++)
        class_addmethod(cavity_tilde_class, floats[k].fn,
                        gensym(floats[k].name), A_FLOAT, 0);
    class_addmethod(cavity_tilde_class, (t_method)cavity_tilde_listener,
                    gensym("listener"), A_GIMME, 0);
    class_addmethod(cavity_tilde_class, (t_method)cavity_tilde_texture,
                    gensym("texture"), A_SYMBOL, 0);
    class_addmethod(cavity_tilde_class, (t_method)cavity_tilde_model,
                    gensym("model"), 0);
}
