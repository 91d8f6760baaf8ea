/* aero: [aeolian~]'s object: its settings, each validated and stored once,
 * and the choice of mode (see aeolian.h). The modes render in
 * aeolian_model.c and aeolian_texture.c. */
#include "aeolian_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "aero_util.h"

static const double default_ears[AERO_AEOLIAN_MAX_EARS][3] = {
    {-AERO_EAR_HALF_SPACING, 1.0, 0.0}, {AERO_EAR_HALF_SPACING, 1.0, 0.0}};

int aero_aeolian_init(aero_aeolian *a, double sample_rate, int n_ears,
                      uint32_t seed)
{
    static const double listener[3] = AERO_AEOLIAN_LISTENER_DEFAULT;
    static const double wind[3] = AERO_AEOLIAN_WIND_DEFAULT;
    memset(a, 0, sizeof(*a));
    int sr_ok = sample_rate > 0 && aero_is_finite(sample_rate);
    a->sample_rate = sr_ok ? sample_rate : AERO_SAMPLE_RATE_FALLBACK;
    a->n_ears = n_ears == 2 ? 2 : 1;
    a->seed = seed;
    a->target[AERO_AEO_DIAMETER] = AERO_AEOLIAN_DIAMETER_DEFAULT;
    a->target[AERO_AEO_LENGTH] = AERO_AEOLIAN_LENGTH_DEFAULT;
    a->target[AERO_AEO_GAIN] = pow(10.0, AERO_GAIN_DB_DEFAULT / 20.0);
    for (int e = 0; e < AERO_AEOLIAN_MAX_EARS; e++)
        for (int k = 0; k < 3; k++)
            a->target[AERO_AEO_EAR + 3 * e + k] =
                a->n_ears == 1 ? listener[k] : default_ears[e][k];
    a->ramp_ms = AERO_RAMP_MS_DEFAULT;
    memcpy(a->wind, wind, sizeof(wind));
    a->roll_deg = AERO_AEOLIAN_ROLL_DEFAULT;
    a->sources = AERO_AEOLIAN_SOURCES_DEFAULT;
    a->exponent = AERO_AEOLIAN_EXPONENT_DEFAULT;
    a->phase_wander = AERO_AEOLIAN_PHASE_WANDER_DEFAULT;
    memcpy(a->model.ctl, a->target, sizeof(a->model.ctl));
    a->model.geometry_dirty = 1;
    aero_aeolian_model_seed(a);
    return sr_ok ? 0 : -1;
}

void aero_aeolian_free(aero_aeolian *a)
{
    aero_aeolian_texture_free(a);
}

int aero_aeolian_texture_mode(const aero_aeolian *a)
{
    return a->texture && a->texture->texture;
}

int aero_aeolian_set_texture(aero_aeolian *a, aero_texture *t, char *err,
                             size_t errlen)
{
    if (!t && !a->texture)
        return 0; /* the model already */
    if (aero_aeolian_texture_make(a)) {
        if (err && errlen)
            snprintf(err, errlen, "out of memory for texture mode");
        return -1;
    }
    return aero_aeolian_texture_set(a, t, err, errlen);
}

/* --- the settings both modes read ------------------------------------------- */

int aero_aeolian_set_sample_rate(aero_aeolian *a, double sr)
{
    if (!aero_is_finite(sr) || sr < AERO_AEOLIAN_SR_MIN ||
        sr > AERO_AEOLIAN_SR_MAX)
        return -1;
    if (a->texture && aero_aeolian_texture_sample_rate(a, sr))
        return -1;
    a->sample_rate = sr;
    aero_aeolian_model_unprime(a);
    return 0;
}

/* a gliding setting k takes v, given as `given` within lo..hi */
static int set_target(aero_aeolian *a, int k, double v, double given,
                      double lo, double hi)
{
    if (!aero_is_finite(given) || given < lo || given > hi)
        return -1;
    a->target[k] = v;
    aero_aeolian_model_retarget(a);
    return 0;
}

int aero_aeolian_set_diameter(aero_aeolian *a, double d)
{
    if (set_target(a, AERO_AEO_DIAMETER, d, d, AERO_AEOLIAN_D_MIN,
                   AERO_AEOLIAN_D_MAX))
        return -1;
    a->diameter_set = 1;
    if (a->texture)
        aero_aeolian_texture_resize(a, AERO_AEO_DIAMETER);
    return 0;
}

int aero_aeolian_set_length(aero_aeolian *a, double l)
{
    if (set_target(a, AERO_AEO_LENGTH, l, l, AERO_AEOLIAN_L_MIN,
                   AERO_AEOLIAN_L_MAX))
        return -1;
    if (a->texture)
        aero_aeolian_texture_resize(a, AERO_AEO_LENGTH);
    return 0;
}

int aero_aeolian_set_gain_db(aero_aeolian *a, double db)
{
    if (set_target(a, AERO_AEO_GAIN, pow(10.0, db / 20.0), db,
                   AERO_GAIN_DB_MIN, AERO_GAIN_DB_MAX))
        return -1;
    if (a->texture)
        aero_aeolian_texture_retarget(a, AERO_AEO_GAIN);
    return 0;
}

int aero_aeolian_set_ramp_ms(aero_aeolian *a, double ms)
{
    if (!aero_is_finite(ms) || ms < AERO_RAMP_MS_MIN ||
        ms > AERO_RAMP_MS_MAX)
        return -1;
    a->ramp_ms = ms; /* for the glides that start from now on */
    return 0;
}

int aero_aeolian_set_seed(aero_aeolian *a, uint32_t seed)
{
    a->seed = seed;
    aero_aeolian_model_seed(a);
    if (a->texture)
        aero_aeolian_texture_seed(a);
    return 0;
}

int aero_aeolian_set_ears(aero_aeolian *a, const aero_ears *e)
{
    if (!aero_ears_ok(e, a->n_ears))
        return -1;
    memcpy(a->target + AERO_AEO_EAR, e->pos, sizeof(double) * 3 * e->n);
    aero_aeolian_model_retarget(a);
    for (int k = 0; a->texture && k < 3 * e->n; k++)
        aero_aeolian_texture_retarget(a, AERO_AEO_EAR + k);
    return 0;
}

/* --- texture mode's settings ------------------------------------------------
 * Each makes the texture part (as a texture does), then validates. */

int aero_aeolian_set_pose(aero_aeolian *a, const double end_a[3],
                          const double end_b[3], double interval_s)
{
    if (aero_aeolian_texture_make(a))
        return -1;
    aero_aeolian_texture_flush(a); /* the poses in the order given */
    return aero_aeolian_texture_pose(a, end_a, end_b, interval_s);
}

int aero_aeolian_set_pose_at(aero_aeolian *a, const double end_a[3],
                             const double end_b[3], const double *axis,
                             double interval_s, int offset)
{
    return aero_aeolian_texture_make(a)
               ? -1
               : aero_aeolian_texture_pose_at(a, end_a, end_b, axis,
                                              interval_s, offset);
}

int aero_aeolian_set_reference(aero_aeolian *a, const double x[3])
{
    return aero_aeolian_texture_make(a)
               ? -1
               : aero_aeolian_texture_reference(a, x);
}

int aero_aeolian_set_wind(aero_aeolian *a, const double w[3])
{
    if (aero_aeolian_texture_make(a) ||
        !aero_finite_within(w, 3, AERO_MOVING_WIND_MAX))
        return -1;
    for (int i = 0; i < 3; i++) {
        a->wind[i] = w[i];
        aero_aeolian_texture_retarget(a, AERO_AEO_WIND + i);
    }
    return 0;
}

int aero_aeolian_set_roll_deg(aero_aeolian *a, double deg)
{
    if (aero_aeolian_texture_make(a) || !aero_is_finite(deg) ||
        fabs(deg) > AERO_AEOLIAN_ROLL_MAX)
        return -1;
    a->roll_deg = deg;
    aero_aeolian_texture_retarget(a, AERO_AEO_ROLL);
    return 0;
}

int aero_aeolian_set_sources(aero_aeolian *a, int n)
{
    if (aero_aeolian_texture_make(a) || n < AERO_AEOLIAN_SOURCES_MIN ||
        n > AERO_AEOLIAN_SOURCES_MAX)
        return -1;
    a->sources = n;
    aero_aeolian_texture_resize(a, AERO_AEO_SOURCES);
    return 0;
}

int aero_aeolian_set_exponent(aero_aeolian *a, double e)
{
    if (aero_aeolian_texture_make(a) || !(e >= AERO_AEOLIAN_EXPONENT_MIN &&
                                          e <= AERO_AEOLIAN_EXPONENT_MAX))
        return -1;
    a->exponent = e;
    return 0;
}

int aero_aeolian_set_phase_wander(aero_aeolian *a, double width)
{
    if (!(width >= 0.0 && width <= AERO_AEOLIAN_PHASE_WANDER_MAX))
        return -1;
    a->phase_wander = width;
    return 0;
}

/* --- rendering ---------------------------------------------------------------- */

int aero_aeolian_process(aero_aeolian *a, const float *speed,
                         float *const *out, int n)
{
    return aero_aeolian_texture_mode(a)
               ? aero_aeolian_texture_process(a, speed, out, n)
               : aero_aeolian_model_process(a, speed, out, n);
}

double aero_aeolian_tone_hz(const aero_aeolian *a, double v)
{
    return aero_aeolian_texture_mode(a) ? aero_aeolian_texture_tone_hz(a, v)
                                        : aero_aeolian_model_tone_hz(a, v);
}

int aero_aeolian_source_count(const aero_aeolian *a)
{
    return a->texture ? a->texture->n_sources : 0;
}
