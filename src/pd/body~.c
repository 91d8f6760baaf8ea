/* [body~]: the aeolian sound of a 3D body that moves and turns (a sphere
 * whirled on a wire, a club, the ends of a thrown stick), played from an
 * object texture made by `aerotex object` (paper 000, the 3D case). Thin
 * Pd wrapper around src/core/body_texture: it parses flags, routes
 * messages to setters and calls process from perform.
 *
 *   [body~ -texture sphere -stereo -scale 1 -exponent 3 -gain 0]
 *   inlet 1 (signal): a wind along +x, m/s, added to `wind`
 *   outlet(s) (signal): sound pressure at the listener (ears), Pa
 */
#include "aero_pd.h"

#include <math.h>

#include "aero_air.h"
#include "body_texture.h"

static t_class *body_tilde_class;

typedef struct _body_tilde {
    t_object x_obj;
    t_float x_f;
    aero_body_texture x_body;
    t_canvas *x_canvas;
    double x_pose_time;   /* logical time of the last pose */
    int x_stereo;
    int x_clamped;        /* set by perform, reported by the clock */
    int x_warned_clamp;
    t_clock *x_clock;
    t_outlet *x_out[2];
} t_body_tilde;

#define OBJ "[body~]"

static void body_tilde_report(t_body_tilde *x)
{
    if (x->x_clamped && !x->x_warned_clamp) {
        pd_error(x, OBJ ": flow speed above Mach 0.3 clamped to %g m/s "
                 "(the model does not hold there)", 0.3 * 343.0);
        x->x_warned_clamp = 1;
    }
}

static t_int *body_tilde_perform(t_int *w)
{
    t_body_tilde *x = (t_body_tilde *)(w[1]);
    t_sample *speed = (t_sample *)(w[2]);
    t_sample *outs[2] = {(t_sample *)(w[3]), (t_sample *)(w[4])};
    int n = (int)(w[5]);
    /* the core reads each chunk of speed before writing that chunk of the
       outputs, so aliased in and out buffers are fine */
    if (aero_body_texture_process(&x->x_body, speed, outs, n) &&
        !x->x_clamped) {
        x->x_clamped = 1;
        clock_delay(x->x_clock, 0);
    }
    return w + 6;
}

static void body_tilde_dsp(t_body_tilde *x, t_signal **sp)
{
    if (aero_body_texture_set_sample_rate(&x->x_body, sp[0]->s_sr))
        pd_error(x, OBJ ": bad sample rate %g", sp[0]->s_sr);
    dsp_add(body_tilde_perform, 5, x, sp[0]->s_vec, sp[1]->s_vec,
            x->x_stereo ? sp[2]->s_vec : sp[1]->s_vec, (t_int)sp[0]->s_n);
}

/* --- messages (each also a creation flag of the same name) --------------- */

/* file I/O here, in the message domain, never in perform */
static void body_tilde_texture(t_body_tilde *x, t_symbol *name)
{
    char path[MAXPDSTRING], err[256];
    aero_texture *t;
    if (aero_pd_find_texture(x->x_canvas, body_tilde_class, name->s_name,
                             path, sizeof(path))) {
        pd_error(x, OBJ ": can't find texture '%s' (looked %s): silent",
                 name->s_name, path);
        aero_body_texture_set_texture(&x->x_body, NULL, err, sizeof(err));
        return;
    }
    t = calloc(1, sizeof(*t)); /* the core releases it with free() */
    if (!t || aero_texture_load(path, t, err, sizeof(err)) ||
        aero_body_texture_set_texture(&x->x_body, t, err, sizeof(err))) {
        pd_error(x, OBJ ": texture %s: %s: silent", path,
                 t ? err : "out of memory");
        if (t)
            aero_texture_free(t);
        free(t);
        aero_body_texture_set_texture(&x->x_body, NULL, err, sizeof(err));
    }
}

/* pose|place x y z [rx ry rz | qw qx qy qz]: a position alone keeps the
   orientation; three more numbers are a rotation vector (axis times angle
   in degrees), four a quaternion */
static void body_tilde_pose(t_body_tilde *x, t_symbol *s, int argc,
                            t_atom *argv)
{
    double v[7], q[4];
    double now = clock_getlogicaltime(), interval;
    if (argc != 3 && argc != 6 && argc != 7) {
        pd_error(x, OBJ ": '%s' takes x y z, x y z rx ry rz (rotation "
                 "vector, deg) or x y z qw qx qy qz (quaternion), got %d "
                 "numbers", s->s_name, argc);
        return;
    }
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, argc, v))
        return;
    if (argc == 3)
        memcpy(q, x->x_body.pose_to + 3, sizeof(q));
    else if (argc == 6) {
        if (!(fabs(v[3]) < 1e9 && fabs(v[4]) < 1e9 && fabs(v[5]) < 1e9)) {
            pd_error(x, OBJ ": '%s': the rotation vector must be finite",
                     s->s_name);
            return;
        }
        aero_body_quaternion_from_rotvec(v + 3, q);
    } else
        memcpy(q, v + 3, sizeof(q));
    interval = clock_gettimesince(x->x_pose_time) * 0.001;
    x->x_pose_time = now;
    if (!strcmp(s->s_name, "place")) /* a jump, no motion */
        interval = -1.0;
    if (aero_body_texture_set_pose(&x->x_body, v, q, interval))
        pd_error(x, OBJ ": '%s' needs a finite position within 1e5 m and a "
                 "non-zero finite quaternion", s->s_name);
}

static void body_tilde_wind(t_body_tilde *x, t_symbol *s, int argc,
                            t_atom *argv)
{
    double v[3];
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (aero_body_texture_set_wind(&x->x_body, v))
        pd_error(x, OBJ ": wind must be finite, below %g m/s",
                 AERO_MACH_LIMIT * AERO_C0 * 10.0);
}

static void body_tilde_listener(t_body_tilde *x, t_symbol *s, int argc,
                                t_atom *argv)
{
    double v[3];
    if (x->x_stereo) {
        pd_error(x, OBJ ": created with -stereo: use 'ears lx ly lz rx ry rz'");
        return;
    }
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 3, v))
        return;
    if (aero_body_texture_set_ear(&x->x_body, 0, v[0], v[1], v[2]))
        pd_error(x, OBJ ": listener position must be finite, within 1e5 m");
}

static void body_tilde_ears(t_body_tilde *x, t_symbol *s, int argc,
                            t_atom *argv)
{
    double v[6];
    if (!x->x_stereo) {
        pd_error(x, OBJ ": 'ears' needs -stereo; use 'listener x y z'");
        return;
    }
    if (aero_pd_floats(x, OBJ, s->s_name, argc, argv, 6, v))
        return;
    if (aero_body_texture_set_ear(&x->x_body, 0, v[0], v[1], v[2]) ||
        aero_body_texture_set_ear(&x->x_body, 1, v[3], v[4], v[5]))
        pd_error(x, OBJ ": ear positions must be finite, within 1e5 m");
}

static void body_tilde_scale(t_body_tilde *x, t_floatarg f)
{
    if (aero_body_texture_set_scale(&x->x_body, f))
        pd_error(x, OBJ ": scale %g out of range (0.001..1000), kept %g", f,
                 x->x_body.scale);
}

static void body_tilde_exponent(t_body_tilde *x, t_floatarg f)
{
    if (aero_body_texture_set_exponent(&x->x_body, f))
        pd_error(x, OBJ ": exponent %g out of range (0..12; 3 is physical, "
                 "6 the paper's)", f);
}

static void body_tilde_gain(t_body_tilde *x, t_floatarg f)
{
    if (aero_body_texture_set_gain_db(&x->x_body, f))
        pd_error(x, OBJ ": gain %g dB out of range (-200..120)", f);
}

static void body_tilde_ramp(t_body_tilde *x, t_floatarg f)
{
    if (aero_body_texture_set_ramp_ms(&x->x_body, f))
        pd_error(x, OBJ ": ramp %g ms out of range (0..600000)", f);
}

static void body_tilde_seed(t_body_tilde *x, t_floatarg f)
{
    aero_body_texture_set_seed(&x->x_body, aero_pd_seed(f));
}

/* --- creation -------------------------------------------------------------- */

/* one flag with its numbers; returns how many atoms it used, 0 if unknown */
static int body_tilde_flag(void *obj, t_symbol *flag, int argc, t_atom *argv)
{
    t_body_tilde *x = obj;
    static const struct {
        const char *name;
        int count;
    } flags[] = {{"-texture", 1}, {"-stereo", 0},   {"-scale", 1},
                 {"-exponent", 1}, {"-gain", 1},    {"-ramp", 1},
                 {"-seed", 1},    {"-listener", 3}, {"-ears", 6},
                 {"-wind", 3}};
    for (size_t k = 0; k < sizeof(flags) / sizeof(flags[0]); k++) {
        const char *name = flags[k].name + 1;
        int count = flags[k].count;
        t_float f;
        if (strcmp(flag->s_name, flags[k].name))
            continue;
        if (argc < count) {
            pd_error(x, OBJ ": flag %s needs %d argument(s)", flag->s_name,
                     count);
            return argc + 1;
        }
        if (!strcmp(name, "texture")) {
            if (argv[0].a_type != A_SYMBOL)
                pd_error(x, OBJ ": flag -texture needs a name");
            else
                body_tilde_texture(x, argv[0].a_w.w_symbol);
            return 2;
        }
        for (int i = 0; i < count; i++)
            if (argv[i].a_type != A_FLOAT) {
                pd_error(x, OBJ ": flag %s needs numbers", flag->s_name);
                return count + 1;
            }
        f = count ? atom_getfloat(argv) : 0;
        if (!strcmp(name, "scale"))
            body_tilde_scale(x, f);
        else if (!strcmp(name, "exponent"))
            body_tilde_exponent(x, f);
        else if (!strcmp(name, "gain"))
            body_tilde_gain(x, f);
        else if (!strcmp(name, "ramp"))
            body_tilde_ramp(x, f);
        else if (!strcmp(name, "seed"))
            body_tilde_seed(x, f);
        else if (!strcmp(name, "listener"))
            body_tilde_listener(x, gensym("listener"), 3, argv);
        else if (!strcmp(name, "ears"))
            body_tilde_ears(x, gensym("ears"), 6, argv);
        else if (!strcmp(name, "wind"))
            body_tilde_wind(x, gensym("wind"), 3, argv);
        return count + 1;
    }
    return 0;
}

static void *body_tilde_new(t_symbol *s, int argc, t_atom *argv)
{
    t_body_tilde *x = (t_body_tilde *)pd_new(body_tilde_class);
    (void)s;
    /* -stereo decides the outlets, so look for it first */
    for (int i = 0; i < argc; i++)
        if (argv[i].a_type == A_SYMBOL &&
            !strcmp(argv[i].a_w.w_symbol->s_name, "-stereo"))
            x->x_stereo = 1;
    if (aero_body_texture_init(&x->x_body, sys_getsr(), x->x_stereo ? 2 : 1,
                               aero_pd_default_seed()))
        pd_error(x, OBJ ": out of memory for the delay lines: silent");
    x->x_clock = clock_new(x, (t_method)body_tilde_report);
    x->x_canvas = canvas_getcurrent();
    x->x_pose_time = clock_getlogicaltime();
    aero_pd_parse_flags(x, OBJ, "-texture -stereo -scale -exponent -gain "
                        "-ramp -seed -listener -ears -wind", body_tilde_flag,
                        argc, argv);
    x->x_out[0] = outlet_new(&x->x_obj, &s_signal);
    if (x->x_stereo)
        x->x_out[1] = outlet_new(&x->x_obj, &s_signal);
    return x;
}

static void body_tilde_free(t_body_tilde *x)
{
    clock_free(x->x_clock);
    aero_body_texture_free(&x->x_body);
    for (int i = 0; i < 2; i++)
        if (x->x_out[i])
            outlet_free(x->x_out[i]);
}

void body_tilde_setup(void)
{
    body_tilde_class = class_new(gensym("body~"),
                                 (t_newmethod)(t_method)body_tilde_new,
                                 (t_method)body_tilde_free,
                                 sizeof(t_body_tilde), CLASS_DEFAULT,
                                 A_GIMME, 0);
    CLASS_MAINSIGNALIN(body_tilde_class, t_body_tilde, x_f);
    class_addmethod(body_tilde_class, (t_method)body_tilde_dsp,
                    gensym("dsp"), A_CANT, 0);
    class_addmethod(body_tilde_class, (t_method)body_tilde_texture,
                    gensym("texture"), A_SYMBOL, 0);
    class_addmethod(body_tilde_class, (t_method)body_tilde_pose,
                    gensym("pose"), A_GIMME, 0);
    class_addmethod(body_tilde_class, (t_method)body_tilde_pose,
                    gensym("place"), A_GIMME, 0);
    class_addmethod(body_tilde_class, (t_method)body_tilde_wind,
                    gensym("wind"), A_GIMME, 0);
    class_addmethod(body_tilde_class, (t_method)body_tilde_listener,
                    gensym("listener"), A_GIMME, 0);
    class_addmethod(body_tilde_class, (t_method)body_tilde_ears,
                    gensym("ears"), A_GIMME, 0);
    class_addmethod(body_tilde_class, (t_method)body_tilde_scale,
                    gensym("scale"), A_FLOAT, 0);
    class_addmethod(body_tilde_class, (t_method)body_tilde_exponent,
                    gensym("exponent"), A_FLOAT, 0);
    class_addmethod(body_tilde_class, (t_method)body_tilde_gain,
                    gensym("gain"), A_FLOAT, 0);
    class_addmethod(body_tilde_class, (t_method)body_tilde_ramp,
                    gensym("ramp"), A_FLOAT, 0);
    class_addmethod(body_tilde_class, (t_method)body_tilde_seed,
                    gensym("seed"), A_FLOAT, 0);
    class_sethelpsymbol(body_tilde_class, gensym("body~"));
}
