/* [cavity~]: cavity tones (a draft through a gap, wind over a hollow, a
 * bottle). Thin Pd wrapper around src/core/play/cavity (the Rossiter
 * model, or a texture once one is loaded).
 *
 *   [cavity~ -L 0.02 -D 0.01 -W 0.05 -texture cavity -exponent 2 -stereo]
 *   inlet 1 (signal): flow speed over the opening, m/s
 *   outlet(s) (signal): sound pressure at the listener (ears), Pa
 */
#include "aero_pd.h"

#include "cavity.h"

static t_class *cavity_tilde_class;

typedef struct _cavity_tilde {
    t_object x_obj;
    t_float x_f;
    aero_pd_base x_base;
    aero_cavity x_core;
} t_cavity_tilde;


static int cavity_tilde_process(void *obj, const float *in,
                                float *const *out, int n)
{
    t_cavity_tilde *x = obj;
    /* the near-field policy: reported once (the last block's record) */
    aero_pd_near(&x->x_base, &x->x_core.near);
    return aero_cavity_process(&x->x_core, in, out, n);
}

static void cavity_tilde_dsp(t_cavity_tilde *x, t_signal **sp)
{
    if (aero_cavity_set_sample_rate(&x->x_core, sp[0]->s_sr))
        aero_pd_rate_failed(&x->x_base, sp[0]->s_sr);
    aero_pd_dsp(&x->x_base, sp, 1, cavity_tilde_process);
}

/* --- messages: the setters, refusals worded from the table -------------- */

AERO_PD_SETTER(cavity_tilde, t_cavity_tilde, length, x_core,
               aero_cavity_set_length)
AERO_PD_SETTER(cavity_tilde, t_cavity_tilde, depth, x_core,
               aero_cavity_set_depth)
AERO_PD_SETTER(cavity_tilde, t_cavity_tilde, width, x_core,
               aero_cavity_set_width)
AERO_PD_SETTER(cavity_tilde, t_cavity_tilde, gain, x_core,
               aero_cavity_set_gain_db)
AERO_PD_SETTER(cavity_tilde, t_cavity_tilde, ramp, x_core,
               aero_cavity_set_ramp_ms)
AERO_PD_SETTER(cavity_tilde, t_cavity_tilde, exponent, x_core,
               aero_cavity_set_exponent)

static void cavity_tilde_seed(t_cavity_tilde *x, t_floatarg f)
{
    uint32_t seed;
    if (!aero_pd_seed_of(&x->x_base, f, &seed) &&
        aero_cavity_set_seed(&x->x_core, seed))
        aero_pd_refused(&x->x_base, "seed", f);
}

static void cavity_tilde_listener(t_cavity_tilde *x, t_symbol *s, int argc,
                                  t_atom *argv)
{
    aero_ears e;
    if (aero_pd_ears(&x->x_base, s, argc, argv, &e) &&
        aero_cavity_set_ears(&x->x_core, &e))
        aero_pd_bad_ears(&x->x_base, e.n);
}

static int cavity_tilde_set_texture(void *core, aero_texture *t, char *err,
                                    size_t len)
{
    return aero_cavity_set_texture(core, t, err, len);
}

/* file I/O here, in the message domain, never in perform */
static void cavity_tilde_texture(t_cavity_tilde *x, t_symbol *name)
{
    aero_pd_load_texture(&x->x_base, cavity_tilde_class, name,
                         cavity_tilde_set_texture, &x->x_core,
                         "using model mode");
}

static void cavity_tilde_model(t_cavity_tilde *x)
{
    char err[8];
    aero_cavity_set_texture(&x->x_core, NULL, err, sizeof(err));
    x->x_base.has_file = 0;
}

#define SIZE(def)                                                         \
    AERO_PD_RANGE_DEF(AERO_CAVITY_SIZE_MIN, AERO_CAVITY_SIZE_MAX, def, "m")
#define LENGTH SIZE(AERO_CAVITY_LENGTH_DEFAULT)
#define DEPTH SIZE(AERO_CAVITY_DEPTH_DEFAULT)
#define WIDTH SIZE(AERO_CAVITY_WIDTH_DEFAULT)

static const aero_pd_method cavity_tilde_methods[] = {
    {"stereo", AERO_PD_SWITCH, 0, NULL, 0, AERO_PD_NO_RULE},
    {"length", AERO_PD_FLOAT, 0, (t_method)cavity_tilde_length, 0, LENGTH},
    {"L", AERO_PD_FLOAT, 0, (t_method)cavity_tilde_length, 0, LENGTH},
    {"depth", AERO_PD_FLOAT, 0, (t_method)cavity_tilde_depth, 0, DEPTH},
    {"D", AERO_PD_FLOAT, 0, (t_method)cavity_tilde_depth, 0, DEPTH},
    {"width", AERO_PD_FLOAT, 0, (t_method)cavity_tilde_width, 0, WIDTH},
    {"W", AERO_PD_FLOAT, 0, (t_method)cavity_tilde_width, 0, WIDTH},
    {"gain", AERO_PD_FLOAT, 0, (t_method)cavity_tilde_gain, 0,
     AERO_PD_GAIN},
    {"ramp", AERO_PD_FLOAT, 0, (t_method)cavity_tilde_ramp, 0,
     AERO_PD_RAMP},
    {"seed", AERO_PD_FLOAT, 0, (t_method)cavity_tilde_seed, 0,
     AERO_PD_SEED},
    {"exponent", AERO_PD_FLOAT, 0, (t_method)cavity_tilde_exponent, 0,
     AERO_PD_RANGE_DEF(AERO_CAVITY_EXPONENT_MIN, AERO_CAVITY_EXPONENT_MAX,
                       AERO_CAVITY_EXPONENT_DEFAULT, NULL)},
    {"listener", AERO_PD_LIST, 3, (t_method)cavity_tilde_listener, 0, AERO_PD_NO_RULE},
    {"ears", AERO_PD_LIST, 6, (t_method)cavity_tilde_listener, 0, AERO_PD_NO_RULE},
    {"texture", AERO_PD_SYMBOL, 0, (t_method)cavity_tilde_texture, 0, AERO_PD_NO_RULE},
    {"model", AERO_PD_BANG, 0, (t_method)cavity_tilde_model,
     AERO_PD_MESSAGE_ONLY, AERO_PD_NO_RULE},
};

static const aero_pd_spec cavity_tilde_spec = {
    "cavity~", cavity_tilde_methods, AERO_PD_COUNT(cavity_tilde_methods),
    NULL};

static void *cavity_tilde_new(t_symbol *s, int argc, t_atom *argv)
{
    (void)s;
    t_cavity_tilde *x = (t_cavity_tilde *)pd_new(cavity_tilde_class);
    aero_pd_base_init(&x->x_base, x, &cavity_tilde_spec, argc, argv);
    if (aero_cavity_init(&x->x_core, sys_getsr(), x->x_base.stereo ? 2 : 1,
                         aero_pd_default_seed()))
        aero_pd_init_failed(&x->x_base, sys_getsr());
    aero_pd_parse_flags(&x->x_base, argc, argv);
    aero_pd_base_outlets(&x->x_base);
    return x;
}

static void cavity_tilde_free(t_cavity_tilde *x)
{
    aero_pd_base_free(&x->x_base);
    aero_cavity_free(&x->x_core);
}

AERO_PD_EXPORT void cavity_tilde_setup(void)
{
    cavity_tilde_class = aero_pd_class_new(
        &cavity_tilde_spec, (t_newmethod)(t_method)cavity_tilde_new,
        (t_method)cavity_tilde_free, sizeof(t_cavity_tilde),
        offsetof(t_cavity_tilde, x_f), (t_method)cavity_tilde_dsp);
}
