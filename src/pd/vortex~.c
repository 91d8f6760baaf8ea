/* [vortex~]: vortex sound of turbulent air (fire, flamethrowers, jets,
 * explosions) from a vortex texture Q(u, t) made by `aerotex vortex`
 * (Dobashi et al. 2004), plus the combustion noise of a flame (`power` in kW).
 * Thin Pd wrapper around src/core/play/vortex.
 *
 *   [vortex~ -texture fire -n 8 -stereo -power 30 -length 0.02 -clip 20]
 *   inlet 1 (signal): average flow speed, m/s, added to each source's own
 *                     speed (`speeds`)
 *   outlet 1 (and 2 with -stereo): sound pressure at the listener, Pa
 */
#include "aero_pd.h"

#include "aero_air.h"
#include "vortex.h"

#include <math.h>

static t_class *vortex_tilde_class;

typedef struct _vortex_tilde {
    t_object x_obj;
    t_float x_f;
    aero_pd_base x_base;
    aero_vortex x_core;
} t_vortex_tilde;

#define OBJ "[vortex~]"

static int vortex_tilde_process(void *obj, const float *in,
                                float *const *out, int n)
{
    t_vortex_tilde *x = obj;
    /* the near-field policy: reported once (the last block's record) */
    aero_pd_near(&x->x_base, &x->x_core.near);
    return aero_vortex_process(&x->x_core, in, out, n);
}

static void vortex_tilde_dsp(t_vortex_tilde *x, t_signal **sp)
{
    if (aero_vortex_set_sample_rate(&x->x_core, sp[0]->s_sr))
        aero_pd_rate_failed(&x->x_base, sp[0]->s_sr);
    aero_pd_dsp(&x->x_base, sp, 1, vortex_tilde_process);
}

static int vortex_tilde_set_texture(void *core, aero_texture *t, char *err,
                                    size_t len)
{
    return aero_vortex_set_texture(core, t, err, len);
}

/* file I/O here, in the message domain, never in perform */
static void vortex_tilde_texture(t_vortex_tilde *x, t_symbol *name)
{
    aero_pd_load_texture(&x->x_base, vortex_tilde_class, name,
                         vortex_tilde_set_texture, &x->x_core, "silent");
}

AERO_PD_SETTER_WHOLE(vortex_tilde, t_vortex_tilde, n, x_core,
                     aero_vortex_set_count)

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
    int n = aero_vortex_count(&x->x_core), count;
    double *v = getbytes(sizeof(double) * (size_t)(argc > 0 ? argc : 1));
    count = float_list(x, s->s_name, argc, argv, 1, v, n);
    if (count > 0 && aero_vortex_set_speeds(&x->x_core, v, count))
        aero_pd_refused_list(&x->x_base, s->s_name);
    freebytes(v, sizeof(double) * (size_t)(argc > 0 ? argc : 1));
}

static void vortex_tilde_positions(t_vortex_tilde *x, t_symbol *s, int argc,
                                   t_atom *argv)
{
    int n = aero_vortex_count(&x->x_core), count;
    double *v = getbytes(sizeof(double) * (size_t)(argc > 0 ? argc : 1));
    count = float_list(x, s->s_name, argc, argv, 3, v, n);
    if (count > 0 &&
        aero_vortex_set_positions(&x->x_core, v, count))
        aero_pd_refused_list(&x->x_base, s->s_name);
    freebytes(v, sizeof(double) * (size_t)(argc > 0 ? argc : 1));
}

static void vortex_tilde_listener(t_vortex_tilde *x, t_symbol *s, int argc,
                                  t_atom *argv)
{
    aero_ears e;
    if (aero_pd_ears(&x->x_base, s, argc, argv, &e) &&
        aero_vortex_set_ears(&x->x_core, &e))
        aero_pd_bad_ears(&x->x_base, e.n);
}

AERO_PD_SETTER(vortex_tilde, t_vortex_tilde, gain, x_core,
               aero_vortex_set_gain_db)
AERO_PD_SETTER(vortex_tilde, t_vortex_tilde, clip, x_core,
               aero_vortex_set_clip)
AERO_PD_SETTER(vortex_tilde, t_vortex_tilde, ramp, x_core,
               aero_vortex_set_ramp_ms)
/* combustion noise (combustion_noise.h): the flame's mean heat release */
AERO_PD_SETTER(vortex_tilde, t_vortex_tilde, power, x_core,
               aero_vortex_set_power_kw)
AERO_PD_SETTER(vortex_tilde, t_vortex_tilde, length, x_core,
               aero_vortex_set_flame_length)
AERO_PD_SETTER(vortex_tilde, t_vortex_tilde, strouhal, x_core,
               aero_vortex_set_strouhal)
AERO_PD_SETTER(vortex_tilde, t_vortex_tilde, fluctuation, x_core,
               aero_vortex_set_fluctuation)

static void vortex_tilde_falloff(t_vortex_tilde *x, t_floatarg f)
{
    if ((f != 1 && f != 3) ||
        aero_vortex_set_falloff(&x->x_core, (int)f))
        aero_pd_refused(&x->x_base, "falloff", f);
}

AERO_PD_SEED_SETTER(vortex_tilde, t_vortex_tilde, x_core,
                    aero_vortex_set_seed)

static const aero_pd_method vortex_tilde_methods[] = {
    {"stereo", AERO_PD_SWITCH, 0, NULL, 0, AERO_PD_NO_RULE},
    /* -n first, so -texture and the rest see every source */
    {"n", AERO_PD_FLOAT, 0, (t_method)vortex_tilde_n, AERO_PD_EARLY,
     AERO_PD_RANGE_NOTE_DEF(AERO_VORTEX_MIN_SOURCES,
                            AERO_VORTEX_MAX_SOURCES,
                            AERO_VORTEX_SOURCES_DEFAULT, NULL,
                            "source volumes, a whole number")},
    {"texture", AERO_PD_SYMBOL, 0, (t_method)vortex_tilde_texture, 0, AERO_PD_NO_RULE},
    {"gain", AERO_PD_FLOAT, 0, (t_method)vortex_tilde_gain, 0,
     AERO_PD_RANGE_DEF(AERO_GAIN_DB_MIN, AERO_VORTEX_GAIN_DB_MAX,
                       AERO_GAIN_DB_DEFAULT, "dB")},
    {"clip", AERO_PD_FLOAT, 0, (t_method)vortex_tilde_clip, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_VORTEX_CLIP_MIN, AERO_VORTEX_CLIP_MAX,
                            AERO_VORTEX_CLIP_DEFAULT, "Pa", "0 = off")},
    {"ramp", AERO_PD_FLOAT, 0, (t_method)vortex_tilde_ramp, 0,
     AERO_PD_RAMP},
    {"seed", AERO_PD_FLOAT, 0, (t_method)vortex_tilde_seed, 0,
     AERO_PD_SEED},
    {"power", AERO_PD_FLOAT, 0, (t_method)vortex_tilde_power, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_COMBUSTION_POWER_KW_MIN,
                            AERO_COMBUSTION_POWER_KW_MAX,
                            AERO_COMBUSTION_POWER_KW_DEFAULT, "kW",
                            "0 = no combustion noise")},
    {"length", AERO_PD_FLOAT, 0, (t_method)vortex_tilde_length, 0,
     AERO_PD_RANGE_DEF(AERO_COMBUSTION_LENGTH_MIN, AERO_COMBUSTION_LENGTH_MAX,
                       AERO_COMBUSTION_LENGTH_DEFAULT, "m")},
    {"strouhal", AERO_PD_FLOAT, 0, (t_method)vortex_tilde_strouhal, 0,
     AERO_PD_RANGE_DEF(AERO_COMBUSTION_ST_MIN, AERO_COMBUSTION_ST_MAX,
                       AERO_COMBUSTION_ST_DEFAULT, NULL)},
    {"fluctuation", AERO_PD_FLOAT, 0, (t_method)vortex_tilde_fluctuation, 0,
     AERO_PD_RANGE_DEF(AERO_COMBUSTION_FLUCTUATION_MIN,
                       AERO_COMBUSTION_FLUCTUATION_MAX,
                       AERO_COMBUSTION_FLUCTUATION_DEFAULT, NULL)},
    {"falloff", AERO_PD_FLOAT, 0, (t_method)vortex_tilde_falloff, 0,
     AERO_PD_RANGE_NOTE_DEF(AERO_VORTEX_FALLOFF_MIN, AERO_VORTEX_FALLOFF_MAX,
                            AERO_VORTEX_FALLOFF_DEFAULT, NULL,
                            "1: p ~ 1/r, the far field, or 3: the "
                            "paper's 1/r^3")},
    {"listener", AERO_PD_LIST, 3, (t_method)vortex_tilde_listener, 0, AERO_PD_NO_RULE},
    {"ears", AERO_PD_LIST, 6, (t_method)vortex_tilde_listener, 0, AERO_PD_NO_RULE},
    {"speeds", AERO_PD_LIST, 0, (t_method)vortex_tilde_speeds,
     AERO_PD_MESSAGE_ONLY,
     AERO_PD_RANGE_NOTE(AERO_VORTEX_SPEED_MIN, AERO_VORTEX_SPEED_MAX, "m/s",
                        "Mach 0.3")},
    {"positions", AERO_PD_LIST, 0, (t_method)vortex_tilde_positions,
     AERO_PD_MESSAGE_ONLY,
     AERO_PD_RANGE_NOTE(-AERO_POSITION_LIMIT, AERO_POSITION_LIMIT, "m",
                        "finite")},
};

static const aero_pd_spec vortex_tilde_spec = {
    "vortex~", vortex_tilde_methods, AERO_PD_COUNT(vortex_tilde_methods),
    NULL};

static void *vortex_tilde_new(t_symbol *s, int argc, t_atom *argv)
{
    (void)s;
    t_vortex_tilde *x = (t_vortex_tilde *)pd_new(vortex_tilde_class);
    aero_pd_base_init(&x->x_base, x, &vortex_tilde_spec, argc, argv);
    if (aero_vortex_init(&x->x_core, sys_getsr(), x->x_base.stereo ? 2 : 1,
                         aero_pd_default_seed()))
        aero_pd_init_failed(&x->x_base, sys_getsr());
    aero_pd_parse_flags(&x->x_base, argc, argv);
    aero_pd_base_outlets(&x->x_base);
    return x;
}

static void vortex_tilde_free(t_vortex_tilde *x)
{
    aero_pd_base_free(&x->x_base);
    aero_vortex_free(&x->x_core);
}

AERO_PD_EXPORT void vortex_tilde_setup(void)
{
    vortex_tilde_class = aero_pd_class_new(
        &vortex_tilde_spec, (t_newmethod)(t_method)vortex_tilde_new,
        (t_method)vortex_tilde_free, sizeof(t_vortex_tilde),
        offsetof(t_vortex_tilde, x_f), (t_method)vortex_tilde_dsp);
}
