/* [vortex~]: vortex sound of turbulent air (fire, flamethrowers, jets,
 * explosions) from a vortex texture Q(u, t) made by `aerotex vortex`
 * (paper 004), plus the combustion noise of a flame (`power` in kW).
 * Thin Pd wrapper around src/core/vortex_player.
 *
 *   [vortex~ -texture fire -n 8 -stereo -power 30 -length 0.02 -clip 20]
 *   inlet 1 (signal): average flow speed, m/s, added to each source's own
 *                     speed (`speeds`)
 *   outlet 1 (and 2 with -stereo): sound pressure at the listener, Pa
 */
#include "aero_pd.h"

#include "vortex_player.h"

#include <math.h>

static t_class *vortex_tilde_class;

typedef struct _vortex_tilde {
    t_object x_obj;
    t_float x_f;
    aero_vortex_player x_player;
    t_canvas *x_canvas;
    int x_stereo;
    int x_clamped, x_warned_clamp;
    t_clock *x_clock;
    t_outlet *x_out[2];
    t_sample *x_outs[2];
} t_vortex_tilde;

#define OBJ "[vortex~]"

static void vortex_tilde_report(t_vortex_tilde *x)
{
    if (x->x_clamped && !x->x_warned_clamp) {
        pd_error(x, OBJ ": flow speed above Mach 0.3 clamped to %g m/s "
                 "(the model does not hold there)", 0.3 * 343.0);
        x->x_warned_clamp = 1;
    }
}

static t_int *vortex_tilde_perform(t_int *w)
{
    t_vortex_tilde *x = (t_vortex_tilde *)(w[1]);
    t_sample *outs[2];
    outs[0] = (t_sample *)(w[3]);
    outs[1] = (t_sample *)(w[4]);
    if (aero_vortex_player_process(&x->x_player, (t_sample *)(w[2]), outs,
                                   (int)(w[5])) &&
        !x->x_clamped) {
        x->x_clamped = 1;
        clock_delay(x->x_clock, 0);
    }
    return w + 6;
}

static void vortex_tilde_dsp(t_vortex_tilde *x, t_signal **sp)
{
    if (aero_vortex_player_set_sample_rate(&x->x_player, sp[0]->s_sr))
        pd_error(x, OBJ ": bad sample rate %g", sp[0]->s_sr);
    dsp_add(vortex_tilde_perform, 5, x, sp[0]->s_vec, sp[1]->s_vec,
            x->x_stereo ? sp[2]->s_vec : sp[1]->s_vec, (t_int)sp[0]->s_n);
}

/* file I/O here, in the message domain, never in perform */
static void vortex_tilde_texture(t_vortex_tilde *x, t_symbol *name)
{
    char path[MAXPDSTRING], err[256];
    aero_texture *t;
    if (aero_pd_find_texture(x->x_canvas, vortex_tilde_class, name->s_name,
                             path, sizeof(path))) {
        pd_error(x, OBJ ": can't find texture '%s': silent until a texture "
                 "is loaded", name->s_name);
        return;
    }
    t = getbytes(sizeof(*t));
    if (aero_texture_load(path, t, err, sizeof(err)) ||
        aero_vortex_player_set_texture(&x->x_player, t, err, sizeof(err))) {
        pd_error(x, OBJ ": texture %s: %s: keeping the previous one", path,
                 err);
        aero_texture_free(t);
        freebytes(t, sizeof(*t));
    }
}

static void vortex_tilde_n(t_vortex_tilde *x, t_floatarg f)
{
    int n;
    if (aero_pd_whole(f, 1, AERO_VORTEX_MAX_SOURCES, &n) ||
        aero_vortex_player_set_count(&x->x_player, n))
        pd_error(x, OBJ ": n %g: the number of source volumes is a whole "
                 "number 1..%d", f, AERO_VORTEX_MAX_SOURCES);
}

/* a list of floats of at most max entries; the count or -1 */
static int float_list(t_vortex_tilde *x, const char *what, int argc,
                      t_atom *argv, int per, double *v, int max)
{
    if (argc < per || argc % per || argc / per > max) {
        pd_error(x, OBJ ": '%s' takes 1..%d group(s) of %d number(s), one "
                 "per source volume (n = %d), got %d numbers", what, max, per,
                 max, argc);
        return -1;
    }
    for (int i = 0; i < argc; i++) {
        if (argv[i].a_type != A_FLOAT) {
            pd_error(x, OBJ ": '%s' takes numbers only", what);
            return -1;
        }
        v[i] = argv[i].a_w.w_float;
    }
    return argc / per;
}

static void vortex_tilde_speeds(t_vortex_tilde *x, t_symbol *s, int argc,
                                t_atom *argv)
{
    int n = x->x_player.n, count;
    double *v = getbytes(sizeof(double) * (size_t)(argc > 0 ? argc : 1));
    count = float_list(x, s->s_name, argc, argv, 1, v, n);
    if (count > 0 && aero_vortex_player_set_speeds(&x->x_player, v, count))
        pd_error(x, OBJ ": speeds must be 0..%g m/s (Mach 0.3)", 0.3 * 343.0);
    freebytes(v, sizeof(double) * (size_t)(argc > 0 ? argc : 1));
}

static void vortex_tilde_positions(t_vortex_tilde *x, t_symbol *s, int argc,
                                   t_atom *argv)
{
    int n = x->x_player.n, count;
    double *v = getbytes(sizeof(double) * (size_t)(argc > 0 ? argc : 1));
    count = float_list(x, s->s_name, argc, argv, 3, v, n);
    if (count > 0 &&
        aero_vortex_player_set_positions(&x->x_player, v, count))
        pd_error(x, OBJ ": positions must be finite, within 1e5 m");
    freebytes(v, sizeof(double) * (size_t)(argc > 0 ? argc : 1));
}

static void vortex_tilde_listener(t_vortex_tilde *x, t_symbol *s, int argc,
                                  t_atom *argv)
{
    double v[3];
    if (x->x_stereo) {
        pd_error(x, OBJ ": created with -stereo: use 'ears lx ly lz rx ry rz'");
        return;
    }
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (aero_vortex_player_set_listener(&x->x_player, v[0], v[1], v[2]))
        pd_error(x, OBJ ": listener position must be finite, within 1e5 m");
}

static void vortex_tilde_ears(t_vortex_tilde *x, t_symbol *s, int argc,
                              t_atom *argv)
{
    double v[6];
    if (!x->x_stereo) {
        pd_error(x, OBJ ": 'ears' needs -stereo; use 'listener x y z'");
        return;
    }
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 6, v))
        return;
    if (aero_vortex_player_set_ears(&x->x_player, v))
        pd_error(x, OBJ ": ear positions must be finite, within 1e5 m");
}

static void vortex_tilde_gain(t_vortex_tilde *x, t_floatarg f)
{
    if (aero_vortex_player_set_gain_db(&x->x_player, f))
        pd_error(x, OBJ ": gain %g dB out of range (-200..200)", f);
}

static void vortex_tilde_clip(t_vortex_tilde *x, t_floatarg f)
{
    if (aero_vortex_player_set_clip(&x->x_player, f))
        pd_error(x, OBJ ": clip %g Pa out of range (0 = off, up to 1e6)", f);
}

static void vortex_tilde_ramp(t_vortex_tilde *x, t_floatarg f)
{
    if (aero_vortex_player_set_ramp_ms(&x->x_player, f))
        pd_error(x, OBJ ": ramp %g ms out of range (0..600000)", f);
}

/* combustion noise (combustion_noise.h): the flame's mean heat release */
static void vortex_tilde_power(t_vortex_tilde *x, t_floatarg f)
{
    if (aero_combustion_set_power_kw(&x->x_player.combustion, f))
        pd_error(x, OBJ ": power %g kW out of range (0 = no combustion "
                 "noise, up to 1e6)", f);
}

static void vortex_tilde_length(t_vortex_tilde *x, t_floatarg f)
{
    if (aero_combustion_set_length(&x->x_player.combustion, f))
        pd_error(x, OBJ ": length %g m out of range (0.001..100)", f);
}

static void vortex_tilde_strouhal(t_vortex_tilde *x, t_floatarg f)
{
    if (aero_combustion_set_strouhal(&x->x_player.combustion, f))
        pd_error(x, OBJ ": strouhal %g out of range (0.01..100)", f);
}

static void vortex_tilde_fluctuation(t_vortex_tilde *x, t_floatarg f)
{
    if (aero_combustion_set_fluctuation(&x->x_player.combustion, f))
        pd_error(x, OBJ ": fluctuation %g out of range (0..1)", f);
}

static void vortex_tilde_falloff(t_vortex_tilde *x, t_floatarg f)
{
    if ((f != 1 && f != 3) ||
        aero_vortex_player_set_falloff(&x->x_player, (int)f))
        pd_error(x, OBJ ": falloff %g: 1 (p ~ 1/r, the far field) or 3 "
                 "(the paper's 1/r^3)", f);
}

static void vortex_tilde_seed(t_vortex_tilde *x, t_floatarg f)
{
    aero_vortex_player_set_seed(&x->x_player, aero_pd_seed(f));
}

static int vortex_tilde_flag(void *obj, t_symbol *flag, int argc,
                             t_atom *argv)
{
    t_vortex_tilde *x = obj;
    static const struct {
        const char *name;
        int count;
    } flags[] = {{"-texture", 1}, {"-n", 1},     {"-gain", 1},
                 {"-clip", 1},    {"-ramp", 1},  {"-seed", 1},
                 {"-listener", 3}, {"-ears", 6}, {"-stereo", 0},
                 {"-power", 1},   {"-length", 1}, {"-strouhal", 1},
                 {"-fluctuation", 1}, {"-falloff", 1}};
    for (size_t k = 0; k < sizeof(flags) / sizeof(flags[0]); k++) {
        if (strcmp(flag->s_name, flags[k].name))
            continue;
        int count = flags[k].count;
        const char *name = flags[k].name + 1;
        if (argc < count) {
            pd_error(x, OBJ ": flag %s needs %d value(s)", flag->s_name, count);
            return argc + 1;
        }
        if (!strcmp(name, "stereo"))
            return 1; /* handled in new */
        if (!strcmp(name, "texture")) {
            if (argv[0].a_type != A_SYMBOL) {
                pd_error(x, OBJ ": flag -texture needs a name");
                return 2;
            }
            vortex_tilde_texture(x, argv[0].a_w.w_symbol);
            return 2;
        }
        for (int i = 0; i < count; i++)
            if (argv[i].a_type != A_FLOAT) {
                pd_error(x, OBJ ": flag %s needs numbers", flag->s_name);
                return count + 1;
            }
        t_float f = atom_getfloat(argv);
        if (!strcmp(name, "n"))
            vortex_tilde_n(x, f);
        else if (!strcmp(name, "gain"))
            vortex_tilde_gain(x, f);
        else if (!strcmp(name, "clip"))
            vortex_tilde_clip(x, f);
        else if (!strcmp(name, "ramp"))
            vortex_tilde_ramp(x, f);
        else if (!strcmp(name, "seed"))
            vortex_tilde_seed(x, f);
        else if (!strcmp(name, "power"))
            vortex_tilde_power(x, f);
        else if (!strcmp(name, "length"))
            vortex_tilde_length(x, f);
        else if (!strcmp(name, "strouhal"))
            vortex_tilde_strouhal(x, f);
        else if (!strcmp(name, "fluctuation"))
            vortex_tilde_fluctuation(x, f);
        else if (!strcmp(name, "falloff"))
            vortex_tilde_falloff(x, f);
        else if (!strcmp(name, "listener"))
            vortex_tilde_listener(x, gensym("listener"), 3, argv);
        else if (!strcmp(name, "ears"))
            vortex_tilde_ears(x, gensym("ears"), 6, argv);
        return count + 1;
    }
    return 0;
}

static void *vortex_tilde_new(t_symbol *s, int argc, t_atom *argv)
{
    (void)s;
    t_vortex_tilde *x = (t_vortex_tilde *)pd_new(vortex_tilde_class);
    x->x_canvas = canvas_getcurrent();
    /* -stereo decides the outlets, so look for it first */
    for (int i = 0; i < argc; i++)
        if (argv[i].a_type == A_SYMBOL &&
            !strcmp(argv[i].a_w.w_symbol->s_name, "-stereo"))
            x->x_stereo = 1;
    aero_vortex_player_init(&x->x_player, sys_getsr(), x->x_stereo,
                            aero_pd_default_seed());
    x->x_clock = clock_new(x, (t_method)vortex_tilde_report);
    /* -n first, so -texture and the rest see every source */
    for (int i = 0; i + 1 < argc; i++)
        if (argv[i].a_type == A_SYMBOL &&
            !strcmp(argv[i].a_w.w_symbol->s_name, "-n") &&
            argv[i + 1].a_type == A_FLOAT)
            vortex_tilde_n(x, argv[i + 1].a_w.w_float);
    aero_pd_parse_flags(x, OBJ, "-texture -n -stereo -gain -clip -ramp "
                        "-seed -listener -ears -power -length -strouhal "
                        "-fluctuation -falloff", vortex_tilde_flag, argc,
                        argv);
    x->x_out[0] = outlet_new(&x->x_obj, &s_signal);
    if (x->x_stereo)
        x->x_out[1] = outlet_new(&x->x_obj, &s_signal);
    return x;
}

static void vortex_tilde_free(t_vortex_tilde *x)
{
    clock_free(x->x_clock);
    aero_vortex_player_free(&x->x_player);
    outlet_free(x->x_out[0]);
    if (x->x_out[1])
        outlet_free(x->x_out[1]);
}

void vortex_tilde_setup(void)
{
    /* via t_method, the generic function type of Pd's API */
    vortex_tilde_class = class_new(gensym("vortex~"),
                                   (t_newmethod)(t_method)vortex_tilde_new,
                                   (t_method)vortex_tilde_free,
                                   sizeof(t_vortex_tilde), CLASS_DEFAULT,
                                   A_GIMME, 0);
    CLASS_MAINSIGNALIN(vortex_tilde_class, t_vortex_tilde, x_f);
    class_addmethod(vortex_tilde_class, (t_method)vortex_tilde_dsp,
                    gensym("dsp"), A_CANT, 0);
    static const struct {
        const char *name;
        t_method fn;
    } floats[] = {{"n", (t_method)vortex_tilde_n},
                  {"gain", (t_method)vortex_tilde_gain},
                  {"clip", (t_method)vortex_tilde_clip},
                  {"ramp", (t_method)vortex_tilde_ramp},
                  {"seed", (t_method)vortex_tilde_seed},
                  {"power", (t_method)vortex_tilde_power},
                  {"length", (t_method)vortex_tilde_length},
                  {"strouhal", (t_method)vortex_tilde_strouhal},
                  {"fluctuation", (t_method)vortex_tilde_fluctuation},
                  {"falloff", (t_method)vortex_tilde_falloff}};
    for (size_t k = 0; k < sizeof(floats) / sizeof(floats[0]); k++)
        class_addmethod(vortex_tilde_class, floats[k].fn,
                        gensym(floats[k].name), A_FLOAT, 0);
    class_addmethod(vortex_tilde_class, (t_method)vortex_tilde_speeds,
                    gensym("speeds"), A_GIMME, 0);
    class_addmethod(vortex_tilde_class, (t_method)vortex_tilde_positions,
                    gensym("positions"), A_GIMME, 0);
    class_addmethod(vortex_tilde_class, (t_method)vortex_tilde_listener,
                    gensym("listener"), A_GIMME, 0);
    class_addmethod(vortex_tilde_class, (t_method)vortex_tilde_ears,
                    gensym("ears"), A_GIMME, 0);
    class_addmethod(vortex_tilde_class, (t_method)vortex_tilde_texture,
                    gensym("texture"), A_SYMBOL, 0);
}
