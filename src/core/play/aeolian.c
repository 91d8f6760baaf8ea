/* aero: [aeolian~]'s engine, model or texture (see aeolian.h). */
#include "aeolian.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int aero_aeolian_init(aero_aeolian *a, double sample_rate, int n_ears,
                      uint32_t seed)
{
    a->stick = NULL;
    a->n_ears = n_ears;
    a->diameter_set = 0;
    return aero_aeolian_model_init(&a->model, sample_rate, n_ears, seed);
}

void aero_aeolian_free(aero_aeolian *a)
{
    if (a->stick) {
        aero_stick_texture_free(a->stick);
        free(a->stick);
        a->stick = NULL;
    }
}

int aero_aeolian_texture_mode(const aero_aeolian *a)
{
    return a->stick && a->stick->texture;
}

/* the texture engine, made from the model's settings the first time */
static aero_stick_texture *stick(aero_aeolian *a)
{
    if (a->stick)
        return a->stick;
    const aero_aeolian_model *m = &a->model;
    aero_stick_texture *st = calloc(1, sizeof(*st));
    if (!st || aero_stick_texture_init(st, m->sample_rate, a->n_ears,
                                       m->rng ^ 0x9e3779b9u)) {
        if (st)
            aero_stick_texture_free(st);
        free(st);
        return NULL;
    }
    if (a->diameter_set)
        aero_stick_texture_set_diameter(st, m->ctl_target[AERO_CTL_DIAMETER]);
    aero_stick_texture_set_length(st, m->ctl_target[AERO_CTL_LENGTH]);
    aero_stick_texture_set_ramp_ms(st,
                                   m->ramp_samples / m->sample_rate * 1000.0);
    aero_stick_texture_set_gain_db(
        st, fmax(-200.0, 20.0 * log10(m->ctl_target[AERO_CTL_GAIN] + 1e-10)));
    aero_ears ears = {a->n_ears, {{0}}};
    memcpy(ears.pos, m->ctl_target + AERO_CTL_EAR,
           sizeof(double) * 3 * a->n_ears);
    aero_stick_texture_set_ears(st, &ears);
    a->stick = st;
    return st;
}

int aero_aeolian_set_texture(aero_aeolian *a, aero_texture *t, char *err,
                             size_t errlen)
{
    if (!t && !a->stick)
        return 0; /* the model already */
    aero_stick_texture *st = stick(a);
    if (!st) {
        if (err && errlen)
            snprintf(err, errlen, "out of memory for texture mode");
        return -1;
    }
    return aero_stick_texture_set_texture(st, t, err, errlen);
}

int aero_aeolian_set_sample_rate(aero_aeolian *a, double sr)
{
    return aero_aeolian_model_set_sample_rate(&a->model, sr) ||
                   (a->stick &&
                    aero_stick_texture_set_sample_rate(a->stick, sr))
               ? -1
               : 0;
}

int aero_aeolian_set_diameter(aero_aeolian *a, double d)
{
    if (aero_aeolian_model_set_diameter(&a->model, d) ||
        (a->stick && aero_stick_texture_set_diameter(a->stick, d)))
        return -1;
    a->diameter_set = 1;
    return 0;
}

int aero_aeolian_set_length(aero_aeolian *a, double l)
{
    return aero_aeolian_model_set_length(&a->model, l) ||
                   (a->stick && aero_stick_texture_set_length(a->stick, l))
               ? -1
               : 0;
}

int aero_aeolian_set_gain_db(aero_aeolian *a, double db)
{
    return aero_aeolian_model_set_gain_db(&a->model, db) ||
                   (a->stick && aero_stick_texture_set_gain_db(a->stick, db))
               ? -1
               : 0;
}

int aero_aeolian_set_ramp_ms(aero_aeolian *a, double ms)
{
    return aero_aeolian_model_set_ramp_ms(&a->model, ms) ||
                   (a->stick && aero_stick_texture_set_ramp_ms(a->stick, ms))
               ? -1
               : 0;
}

void aero_aeolian_set_seed(aero_aeolian *a, uint32_t seed)
{
    aero_aeolian_model_set_seed(&a->model, seed);
    if (a->stick)
        aero_stick_texture_set_seed(a->stick, seed);
}

int aero_aeolian_set_ears(aero_aeolian *a, const aero_ears *e)
{
    return aero_aeolian_model_set_ears(&a->model, e) ||
                   (a->stick && aero_stick_texture_set_ears(a->stick, e))
               ? -1
               : 0;
}

int aero_aeolian_set_pose(aero_aeolian *a, const double end_a[3],
                          const double end_b[3], double interval_s)
{
    aero_stick_texture *st = stick(a);
    return st ? aero_stick_texture_set_pose(st, end_a, end_b, interval_s) : -1;
}

int aero_aeolian_set_reference(aero_aeolian *a, const double x[3])
{
    aero_stick_texture *st = stick(a);
    return st ? aero_stick_texture_set_reference(st, x) : -1;
}

int aero_aeolian_set_wind(aero_aeolian *a, const double w[3])
{
    aero_stick_texture *st = stick(a);
    return st ? aero_stick_texture_set_wind(st, w) : -1;
}

int aero_aeolian_set_roll_deg(aero_aeolian *a, double deg)
{
    aero_stick_texture *st = stick(a);
    return st ? aero_stick_texture_set_roll_deg(st, deg) : -1;
}

int aero_aeolian_set_sources(aero_aeolian *a, int n)
{
    aero_stick_texture *st = stick(a);
    return st ? aero_stick_texture_set_sources(st, n) : -1;
}

int aero_aeolian_set_exponent(aero_aeolian *a, double e)
{
    aero_stick_texture *st = stick(a);
    return st ? aero_stick_texture_set_exponent(st, e) : -1;
}

int aero_aeolian_process(aero_aeolian *a, const float *speed,
                         float *const *out, int n)
{
    /* both engines read each chunk of speed before writing that chunk of
     * the outputs: in and out may share a buffer */
    return aero_aeolian_texture_mode(a)
               ? aero_stick_texture_process(a->stick, speed, out, n)
               : aero_aeolian_model_process(&a->model, speed, out, n);
}
