/* [aeolian~]: the aeolian tone of a cylinder in a flow (wind past a wire, a
 * rod, a branch), or, with a texture, of any stick that moves and turns (a
 * sword, a thrown stick, a fence rail). Thin Pd wrapper around
 * src/core/aeolian_model (Strouhal/Reynolds model mode) and
 * src/core/stick_texture (texture mode): it parses flags, routes messages
 * to setters and calls process from perform.
 *
 *   [aeolian~ -d 0.01 -l 0.5 -gain 0 -seed 1 -ramp 20 -stereo]
 *   [aeolian~ -texture sword -n 8 -exponent 3 -stereo]
 *   inlet 1 (signal): flow speed across the axis, m/s (texture mode: a wind
 *                     along +x added to `wind`)
 *   outlet(s) (signal): sound pressure at the listener (ears), Pa
 */
#include "aero_pd.h"

#include <math.h>

#include "aeolian_model.h"
#include "aero_air.h"
#include "stick_texture.h"

static t_class *aeolian_tilde_class;

typedef struct _aeolian_tilde {
    t_object x_obj;
    t_float x_f;
    aero_aeolian_model x_model;
    aero_stick_texture *x_stick; /* texture mode state, made on first use */
    t_canvas *x_canvas;
    double x_pose_time;          /* logical time of the last pose */
    int x_stereo;
    int x_diameter_set;          /* -d given: texture mode uses it too */
    int x_clamped;        /* set by perform, reported by the clock */
    int x_warned_clamp;
    t_clock *x_clock;
    t_outlet *x_out[2];
} t_aeolian_tilde;

#define OBJ "[aeolian~]"

static void aeolian_tilde_report(t_aeolian_tilde *x)
{
    if (x->x_clamped && !x->x_warned_clamp) {
        pd_error(x, OBJ ": flow speed above Mach 0.3 clamped to %g m/s "
                 "(the model does not hold there)", 0.3 * 343.0);
        x->x_warned_clamp = 1;
    }
}

static int aeolian_tilde_texture_mode(const t_aeolian_tilde *x)
{
    return x->x_stick && x->x_stick->texture;
}

static t_int *aeolian_tilde_perform(t_int *w)
{
    t_aeolian_tilde *x = (t_aeolian_tilde *)(w[1]);
    t_sample *speed = (t_sample *)(w[2]);
    t_sample *outs[2] = {(t_sample *)(w[3]), (t_sample *)(w[4])};
    int n = (int)(w[5]);
    /* the cores read each chunk of speed before writing that chunk of the
     * outputs, so Pd may hand us aliased in and out buffers */
    int clamped = aeolian_tilde_texture_mode(x)
        ? aero_stick_texture_process(x->x_stick, speed, outs, n)
        : aero_aeolian_model_process(&x->x_model, speed, outs, n);
    if (clamped && !x->x_clamped) {
        x->x_clamped = 1;
        clock_delay(x->x_clock, 0);
    }
    return w + 6;
}

static void aeolian_tilde_dsp(t_aeolian_tilde *x, t_signal **sp)
{
    if (aero_aeolian_model_set_sample_rate(&x->x_model, sp[0]->s_sr) ||
        (x->x_stick &&
         aero_stick_texture_set_sample_rate(x->x_stick, sp[0]->s_sr)))
        pd_error(x, OBJ ": bad sample rate %g", sp[0]->s_sr);
    dsp_add(aeolian_tilde_perform, 5, x, sp[0]->s_vec, sp[1]->s_vec,
            x->x_stereo ? sp[2]->s_vec : sp[1]->s_vec, (t_int)sp[0]->s_n);
}

/* --- messages (each also a creation flag of the same name) --------------- */

/* the texture-mode state, made the first time a message needs it (model
 * mode objects, the common case by the hundred, do not pay for its delay
 * rings); it starts from the model's settings */
static aero_stick_texture *aeolian_tilde_stick(t_aeolian_tilde *x)
{
    if (x->x_stick)
        return x->x_stick;
    aero_stick_texture *st = getbytes(sizeof(*st));
    if (!st || aero_stick_texture_init(st, x->x_model.sample_rate,
                                       x->x_stereo ? 2 : 1,
                                       x->x_model.rng ^ 0x9e3779b9u)) {
        pd_error(x, OBJ ": out of memory for texture mode");
        if (st) {
            aero_stick_texture_free(st);
            freebytes(st, sizeof(*st));
        }
        return NULL;
    }
    aero_aeolian_model *m = &x->x_model;
    if (x->x_diameter_set)
        aero_stick_texture_set_diameter(st, m->ctl_target[AERO_CTL_DIAMETER]);
    aero_stick_texture_set_length(st, m->ctl_target[AERO_CTL_LENGTH]);
    aero_stick_texture_set_ramp_ms(st, m->ramp_samples / m->sample_rate *
                                           1000.0);
    aero_stick_texture_set_gain_db(
        st, fmax(-200.0, 20.0 * log10(m->ctl_target[AERO_CTL_GAIN] + 1e-10)));
    for (int e = 0; e < (x->x_stereo ? 2 : 1); e++) {
        const double *p = m->ctl_target + AERO_CTL_EAR + 3 * e;
        aero_stick_texture_set_ear(st, e, p[0], p[1], p[2]);
    }
    x->x_stick = st;
    return st;
}

static void aeolian_tilde_diameter(t_aeolian_tilde *x, t_floatarg f)
{
    if (aero_aeolian_model_set_diameter(&x->x_model, f) ||
        (x->x_stick && aero_stick_texture_set_diameter(x->x_stick, f)))
        pd_error(x, OBJ ": diameter %g m out of range (1e-5..10), kept %g",
                 f, x->x_model.ctl_target[AERO_CTL_DIAMETER]);
    else
        x->x_diameter_set = 1;
}

static void aeolian_tilde_length(t_aeolian_tilde *x, t_floatarg f)
{
    if (aero_aeolian_model_set_length(&x->x_model, f) ||
        (x->x_stick && aero_stick_texture_set_length(x->x_stick, f)))
        pd_error(x, OBJ ": length %g m out of range (1e-5..1000), kept %g",
                 f, x->x_model.ctl_target[AERO_CTL_LENGTH]);
}

static void aeolian_tilde_gain(t_aeolian_tilde *x, t_floatarg f)
{
    if (aero_aeolian_model_set_gain_db(&x->x_model, f) ||
        (x->x_stick && aero_stick_texture_set_gain_db(x->x_stick, f)))
        pd_error(x, OBJ ": gain %g dB out of range (-200..120)", f);
}

static void aeolian_tilde_ramp(t_aeolian_tilde *x, t_floatarg f)
{
    if (aero_aeolian_model_set_ramp_ms(&x->x_model, f) ||
        (x->x_stick && aero_stick_texture_set_ramp_ms(x->x_stick, f)))
        pd_error(x, OBJ ": ramp %g ms out of range (0..600000)", f);
}

static void aeolian_tilde_seed(t_aeolian_tilde *x, t_floatarg f)
{
    aero_aeolian_model_set_seed(&x->x_model, aero_pd_seed(f));
    if (x->x_stick)
        aero_stick_texture_set_seed(x->x_stick, aero_pd_seed(f));
}

/* --- texture mode ------------------------------------------------------------ */

/* file I/O here, in the message domain, never in perform */
static void aeolian_tilde_texture(t_aeolian_tilde *x, t_symbol *name)
{
    char path[MAXPDSTRING], err[256];
    aero_stick_texture *st = aeolian_tilde_stick(x);
    if (!st)
        return;
    if (aero_pd_find_texture(x->x_canvas, aeolian_tilde_class, name->s_name,
                             path, sizeof(path))) {
        pd_error(x, OBJ ": can't find texture '%s' (looked %s): using the "
                 "Strouhal/Reynolds model", name->s_name, path);
        aero_stick_texture_set_texture(st, NULL, err, sizeof(err));
        return;
    }
    /* calloc: the core releases it with free() */
    aero_texture *t = calloc(1, sizeof(*t));
    if (!t || aero_texture_load(path, t, err, sizeof(err)) ||
        aero_stick_texture_set_texture(st, t, err, sizeof(err))) {
        pd_error(x, OBJ ": texture %s: %s: using the Strouhal/Reynolds model",
                 path, t ? err : "out of memory");
        if (t)
            aero_texture_free(t);
        free(t);
        aero_stick_texture_set_texture(st, NULL, err, sizeof(err));
    }
}

static void aeolian_tilde_model(t_aeolian_tilde *x)
{
    char err[8];
    if (x->x_stick)
        aero_stick_texture_set_texture(x->x_stick, NULL, err, sizeof(err));
}

static void aeolian_tilde_pose(t_aeolian_tilde *x, t_symbol *s, int argc,
                               t_atom *argv)
{
    double v[9];
    if (argc != 6 && argc != 9) {
        pd_error(x, OBJ ": '%s' takes ax ay az bx by bz [ux uy uz] "
                 "(6 or 9 numbers), got %d", s->s_name, argc);
        return;
    }
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, argc, v))
        return;
    aero_stick_texture *st = aeolian_tilde_stick(x);
    if (!st)
        return;
    double now = clock_getlogicaltime();
    double interval = clock_gettimesince(x->x_pose_time) * 0.001;
    x->x_pose_time = now;
    if (!strcmp(s->s_name, "place")) /* a jump, no motion */
        interval = -1.0;
    if (aero_stick_texture_set_pose(st, v, v + 3, interval))
        pd_error(x, OBJ ": pose needs two distinct finite ends within 1e5 m");
    else if (argc == 9 && aero_stick_texture_set_reference(st, v + 6))
        pd_error(x, OBJ ": pose reference axis must be finite and non-zero");
}

static void aeolian_tilde_wind(t_aeolian_tilde *x, t_symbol *s, int argc,
                               t_atom *argv)
{
    double v[3];
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    aero_stick_texture *st = aeolian_tilde_stick(x);
    if (st && aero_stick_texture_set_wind(st, v))
        pd_error(x, OBJ ": wind must be finite, below %g m/s",
                 AERO_MACH_LIMIT * AERO_C0 * 10.0);
}

static void aeolian_tilde_roll(t_aeolian_tilde *x, t_floatarg f)
{
    aero_stick_texture *st = aeolian_tilde_stick(x);
    if (st && aero_stick_texture_set_roll_deg(st, f))
        pd_error(x, OBJ ": roll %g deg must be finite", f);
}

static void aeolian_tilde_sources(t_aeolian_tilde *x, t_floatarg f)
{
    aero_stick_texture *st = aeolian_tilde_stick(x);
    /* range first: (int) of NaN or 1e30 is undefined behaviour */
    if (st && (!(f >= 0 && f <= AERO_STICK_MAX_SOURCES) || f != (int)f ||
               aero_stick_texture_set_sources(st, (int)f)))
        pd_error(x, OBJ ": n %g: point sources must be 0 (auto: length / "
                 "3 d) to %d", f, AERO_STICK_MAX_SOURCES);
}

static void aeolian_tilde_exponent(t_aeolian_tilde *x, t_floatarg f)
{
    aero_stick_texture *st = aeolian_tilde_stick(x);
    if (st && aero_stick_texture_set_exponent(st, f))
        pd_error(x, OBJ ": exponent %g out of range (0..12; 3 is physical, "
                 "6 the paper's)", f);
}

static void aeolian_tilde_listener(t_aeolian_tilde *x, t_symbol *s, int argc,
                                   t_atom *argv)
{
    double v[3];
    if (x->x_stereo) {
        pd_error(x, OBJ ": created with -stereo: use 'ears lx ly lz rx ry rz'");
        return;
    }
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (aero_aeolian_model_set_ear(&x->x_model, 0, v[0], v[1], v[2]) ||
        (x->x_stick &&
         aero_stick_texture_set_ear(x->x_stick, 0, v[0], v[1], v[2])))
        pd_error(x, OBJ ": listener position must be finite, within 1e5 m");
}

static void aeolian_tilde_ears(t_aeolian_tilde *x, t_symbol *s, int argc,
                               t_atom *argv)
{
    double v[6];
    if (!x->x_stereo) {
        pd_error(x, OBJ ": 'ears' needs -stereo; use 'listener x y z'");
        return;
    }
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 6, v))
        return;
    if (aero_aeolian_model_set_ear(&x->x_model, 0, v[0], v[1], v[2]) ||
        aero_aeolian_model_set_ear(&x->x_model, 1, v[3], v[4], v[5]) ||
        (x->x_stick &&
         (aero_stick_texture_set_ear(x->x_stick, 0, v[0], v[1], v[2]) ||
          aero_stick_texture_set_ear(x->x_stick, 1, v[3], v[4], v[5]))))
        pd_error(x, OBJ ": ear positions must be finite, within 1e5 m");
}

/* --- creation -------------------------------------------------------------- */

/* one flag with its numbers; returns how many atoms it used, 0 if unknown */
static int aeolian_tilde_flag(void *obj, t_symbol *flag, int argc,
                              t_atom *argv)
{
    t_aeolian_tilde *x = obj;
    static const struct {
        const char *name;
        int count;
    } flags[] = {{"-d", 1},      {"-diameter", 1}, {"-l", 1},
                 {"-length", 1}, {"-gain", 1},     {"-seed", 1},
                 {"-ramp", 1},   {"-listener", 3}, {"-ears", 6},
                 {"-stereo", 0}, {"-texture", 1}, {"-n", 1},
                 {"-exponent", 1}, {"-roll", 1},  {"-wind", 3}};
    for (size_t k = 0; k < sizeof(flags) / sizeof(flags[0]); k++) {
        if (strcmp(flag->s_name, flags[k].name))
            continue;
        int count = flags[k].count;
        if (argc < count) {
            pd_error(x, OBJ ": flag %s needs %d number(s)", flag->s_name,
                     count);
            return argc + 1;
        }
        if (!strcmp(flag->s_name, "-texture")) {
            if (argv[0].a_type != A_SYMBOL)
                pd_error(x, OBJ ": flag -texture needs a name");
            else
                aeolian_tilde_texture(x, argv[0].a_w.w_symbol);
            return 2;
        }
        for (int i = 0; i < count; i++)
            if (argv[i].a_type != A_FLOAT) {
                pd_error(x, OBJ ": flag %s needs numbers", flag->s_name);
                return count + 1;
            }
        t_float f = count ? atom_getfloat(argv) : 0;
        const char *name = flags[k].name + 1;
        if (!strcmp(name, "d") || !strcmp(name, "diameter"))
            aeolian_tilde_diameter(x, f);
        else if (!strcmp(name, "l") || !strcmp(name, "length"))
            aeolian_tilde_length(x, f);
        else if (!strcmp(name, "gain"))
            aeolian_tilde_gain(x, f);
        else if (!strcmp(name, "seed"))
            aeolian_tilde_seed(x, f);
        else if (!strcmp(name, "ramp"))
            aeolian_tilde_ramp(x, f);
        else if (!strcmp(name, "listener"))
            aeolian_tilde_listener(x, gensym("listener"), 3, argv);
        else if (!strcmp(name, "ears"))
            aeolian_tilde_ears(x, gensym("ears"), 6, argv);
        else if (!strcmp(name, "n"))
            aeolian_tilde_sources(x, f);
        else if (!strcmp(name, "exponent"))
            aeolian_tilde_exponent(x, f);
        else if (!strcmp(name, "roll"))
            aeolian_tilde_roll(x, f);
        else if (!strcmp(name, "wind"))
            aeolian_tilde_wind(x, gensym("wind"), 3, argv);
        return count + 1;
    }
    return 0;
}

static void *aeolian_tilde_new(t_symbol *s, int argc, t_atom *argv)
{
    (void)s;
    t_aeolian_tilde *x = (t_aeolian_tilde *)pd_new(aeolian_tilde_class);
    /* -stereo decides the outlets, so look for it first */
    for (int i = 0; i < argc; i++)
        if (argv[i].a_type == A_SYMBOL &&
            !strcmp(argv[i].a_w.w_symbol->s_name, "-stereo"))
            x->x_stereo = 1;
    aero_aeolian_model_init(&x->x_model, sys_getsr(), x->x_stereo ? 2 : 1,
                            aero_pd_default_seed());
    x->x_clock = clock_new(x, (t_method)aeolian_tilde_report);
    x->x_canvas = canvas_getcurrent();
    x->x_pose_time = clock_getlogicaltime();

    /* -d first, so that a texture loaded by -texture sees it */
    for (int i = 0; i + 1 < argc; i++)
        if (argv[i].a_type == A_SYMBOL && argv[i + 1].a_type == A_FLOAT &&
            (!strcmp(argv[i].a_w.w_symbol->s_name, "-d") ||
             !strcmp(argv[i].a_w.w_symbol->s_name, "-diameter")))
            aeolian_tilde_diameter(x, argv[i + 1].a_w.w_float);
    aero_pd_parse_flags(x, OBJ, "-d -l -gain -seed -ramp -listener -ears "
                        "-stereo -texture -n -exponent -roll -wind",
                        aeolian_tilde_flag, argc, argv);

    x->x_out[0] = outlet_new(&x->x_obj, &s_signal);
    if (x->x_stereo)
        x->x_out[1] = outlet_new(&x->x_obj, &s_signal);
    return x;
}

static void aeolian_tilde_free(t_aeolian_tilde *x)
{
    clock_free(x->x_clock);
    if (x->x_stick) {
        aero_stick_texture_free(x->x_stick);
        freebytes(x->x_stick, sizeof(*x->x_stick));
    }
    for (int i = 0; i < 2; i++)
        if (x->x_out[i])
            outlet_free(x->x_out[i]);
}

void aeolian_tilde_setup(void)
{
    /* via t_method (void (*)(void)), which gcc's -Wcast-function-type
     * accepts as the generic function type Pd's API means */
    aeolian_tilde_class = class_new(gensym("aeolian~"),
                                    (t_newmethod)(t_method)aeolian_tilde_new,
                                    (t_method)aeolian_tilde_free,
                                    sizeof(t_aeolian_tilde), CLASS_DEFAULT,
                                    A_GIMME, 0);
    CLASS_MAINSIGNALIN(aeolian_tilde_class, t_aeolian_tilde, x_f);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_dsp,
                    gensym("dsp"), A_CANT, 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_diameter,
                    gensym("diameter"), A_FLOAT, 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_diameter,
                    gensym("d"), A_FLOAT, 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_length,
                    gensym("length"), A_FLOAT, 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_length,
                    gensym("l"), A_FLOAT, 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_gain,
                    gensym("gain"), A_FLOAT, 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_ramp,
                    gensym("ramp"), A_FLOAT, 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_seed,
                    gensym("seed"), A_FLOAT, 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_listener,
                    gensym("listener"), A_GIMME, 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_ears,
                    gensym("ears"), A_GIMME, 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_texture,
                    gensym("texture"), A_SYMBOL, 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_model,
                    gensym("model"), 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_pose,
                    gensym("pose"), A_GIMME, 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_pose,
                    gensym("place"), A_GIMME, 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_wind,
                    gensym("wind"), A_GIMME, 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_roll,
                    gensym("roll"), A_FLOAT, 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_sources,
                    gensym("n"), A_FLOAT, 0);
    class_addmethod(aeolian_tilde_class, (t_method)aeolian_tilde_exponent,
                    gensym("exponent"), A_FLOAT, 0);
    class_sethelpsymbol(aeolian_tilde_class, gensym("aeolian~"));
}
