/* aero: [cavity~]'s object: its settings, each validated and stored once,
 * and the choice of mode (see cavity.h). The modes render in
 * cavity_model.c and cavity_texture.c. */
#include "cavity_internal.h"

#include "aero_lanes.h"
#include "aero_ramp.h"
#include "aero_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int aero_cavity_init(aero_cavity *m, double sample_rate, int n_ears,
                     uint32_t seed)
{
    static const double listener[3] = AERO_CAVITY_LISTENER_DEFAULT;
    memset(m, 0, sizeof(*m));
    int sr_ok = aero_is_finite(sample_rate) &&
                sample_rate >= AERO_CAVITY_SR_MIN &&
                sample_rate <= AERO_CAVITY_SR_MAX;
    m->sample_rate = sr_ok ? sample_rate : AERO_SAMPLE_RATE_FALLBACK;
    m->n_ears = n_ears == 2 ? 2 : 1;
    m->exponent = AERO_CAVITY_EXPONENT_DEFAULT;
    m->ctl_target[AERO_CAV_LENGTH] = AERO_CAVITY_LENGTH_DEFAULT;
    m->ctl_target[AERO_CAV_DEPTH] = AERO_CAVITY_DEPTH_DEFAULT;
    m->ctl_target[AERO_CAV_WIDTH] = AERO_CAVITY_WIDTH_DEFAULT;
    m->ctl_target[AERO_CAV_GAIN] = pow(10.0, AERO_GAIN_DB_DEFAULT / 20.0);
    for (int e = 0; e < m->n_ears; e++) {
        double *ear = m->ctl_target + AERO_CAV_EAR + 3 * e;
        memcpy(ear, listener, sizeof(listener));
        if (m->n_ears == 2)
            ear[0] += e ? AERO_EAR_HALF_SPACING : -AERO_EAR_HALF_SPACING;
    }
    memcpy(m->ctl, m->ctl_target, sizeof(m->ctl));
    m->laws_dirty = 1;
    aero_cavity_set_ramp_ms(m, AERO_RAMP_MS_DEFAULT);
    aero_cavity_set_seed(m, seed);
    return sr_ok ? 0 : -1;
}

void aero_cavity_free(aero_cavity *m)
{
    if (m->texture) {
        aero_texture_free(m->texture);
        free(m->texture);
        m->texture = NULL;
    }
}

int aero_cavity_set_seed(aero_cavity *m, uint32_t seed)
{
    uint32_t s = seed * 2654435761u + 0x7f4a7c15u;
    s ^= s >> 16;
    m->rng = s ? s : 0x2545f491u;
    for (int k = 0; k < AERO_CAVITY_MODES; k++)
    {
        double p = 0.5 + 0.5 * aero_uniform(&m->rng);
        aero_cis_cycles(&p, &m->phasor[k][0], &m->phasor[k][1], 1);
    }
    m->texture_pos = 0.5 + 0.5 * aero_uniform(&m->rng); /* scaled at use */
    /* the noise's and the tones' generators (four lanes each), never 0 */
    for (int j = 0; j < 8; j++) {
        uint32_t x = aero_xorshift32(&m->rng) ^ (0x9e3779b9u * (j + 1));
        uint32_t *state = j < 4 ? m->noise_rng + j : m->tone_rng + (j - 4);
        *state = x ? x : 0x6c8e9cf5u + j;
    }
    return 0;
}

static int size_ok(double v)
{
    return aero_is_finite(v) && v >= AERO_CAVITY_SIZE_MIN &&
           v <= AERO_CAVITY_SIZE_MAX;
}

static int set_ctl(aero_cavity *m, int k, double v)
{
    m->laws_dirty = 1;
    m->ctl_target[k] = v;
    if (!m->primed)
        m->ctl[k] = v;
    else
        m->ramp_left = m->ramp_samples;
    return 0;
}

int aero_cavity_set_sample_rate(aero_cavity *m, double sr)
{
    if (!aero_is_finite(sr) || sr < AERO_CAVITY_SR_MIN ||
        sr > AERO_CAVITY_SR_MAX)
        return -1;
    double ms = 1000.0 * m->ramp_samples / m->sample_rate;
    m->sample_rate = sr;
    return aero_cavity_set_ramp_ms(m, ms);
}

int aero_cavity_set_length(aero_cavity *m, double l)
{
    if (!size_ok(l))
        return -1;
    return set_ctl(m, AERO_CAV_LENGTH, l);
}

int aero_cavity_set_depth(aero_cavity *m, double d)
{
    if (!size_ok(d))
        return -1;
    return set_ctl(m, AERO_CAV_DEPTH, d);
}

int aero_cavity_set_width(aero_cavity *m, double w)
{
    if (!size_ok(w))
        return -1;
    return set_ctl(m, AERO_CAV_WIDTH, w);
}

int aero_cavity_set_gain_db(aero_cavity *m, double db)
{
    if (!aero_is_finite(db) || db < AERO_GAIN_DB_MIN || db > AERO_GAIN_DB_MAX)
        return -1;
    return set_ctl(m, AERO_CAV_GAIN, pow(10.0, db / 20.0));
}

int aero_cavity_set_ramp_ms(aero_cavity *m, double ms)
{
    if (!aero_is_finite(ms) || ms < AERO_RAMP_MS_MIN ||
        ms > AERO_RAMP_MS_MAX)
        return -1;
    m->ramp_samples = fmax(1.0, ms * 0.001 * m->sample_rate);
    return 0;
}

int aero_cavity_set_exponent(aero_cavity *m, double n)
{
    if (!aero_is_finite(n) || n < AERO_CAVITY_EXPONENT_MIN ||
        n > AERO_CAVITY_EXPONENT_MAX)
        return -1;
    m->exponent = n;
    m->laws_dirty = 1;
    return 0;
}

int aero_cavity_set_ears(aero_cavity *m, const aero_ears *e)
{
    if (!aero_ears_ok(e, m->n_ears))
        return -1;
    for (int ear = 0; ear < e->n; ear++)
        for (int i = 0; i < 3; i++)
            set_ctl(m, AERO_CAV_EAR + 3 * ear + i, e->pos[ear][i]);
    return 0;
}

int aero_cavity_set_texture(aero_cavity *m, aero_texture *t, char *err,
                            size_t errlen)
{
    if (t) {
        double v0 = t->head.v0;
        if (aero_texture_wrong_kind(t, "cavity", err, errlen)) {
            return -1;
        }
        if (!(v0 > 0) || t->directions < 1 || t->frames < 2 || !(t->rate > 0)) {
            snprintf(err, errlen, "texture has no usable v0, rate or frames");
            return -1;
        }
        m->texture_v0 = v0;
        double l0 = t->head.length;
        m->texture_length =
            l0 > 0.0 && l0 < AERO_CAVITY_SIZE_MAX ? l0 : 0.0;
        m->texture_pos = fmod(fabs(m->texture_pos) * t->frames, t->frames);
    }
    aero_cavity_free(m);
    m->texture = t;
    return 0;
}

/* 1 when the controls moved */
static int advance_ramps(aero_cavity *m, int n)
{
    if (m->ramp_left <= 0)
        return 0;
    aero_glide_values(m->ctl, m->ctl_target, AERO_CAV_COUNT,
                      aero_glide_fraction(&m->ramp_left, n));
    return 1;
}

/* the near-field policy (aero_near_field): both modes use the opening's
   size sqrt(L W) */
double aero_cavity_ear_distance(aero_cavity *m, int e, double r_min)
{
    const double *x = m->ctl + AERO_CAV_EAR + 3 * e;
    double r = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    if (r < r_min)
        aero_near_seen(&m->near, r_min);
    return fmax(r, r_min);
}

/* the sanitised |U| of a chunk (NaN -> 0, clamped at Mach 0.3) and its
   mean, summed in lanes so that it vectorises; 1 when one was clamped */
static int chunk_speeds(const float *speed, float *u, int len, double *mean)
{
    const float limit = (float)(AERO_MACH_LIMIT * AERO_C0);
    int clamped = 0;
    for (int i = 0; i < len; i++) {
        float x = speed[i];
        float v = x == x ? fabsf(x) : 0.0f;
        u[i] = v < limit ? v : limit;
    }
    for (int i = 0; i < len; i++)
        clamped |= fabsf(speed[i]) > limit;
    float lane_sum[8] = {0}, sum = 0;
    int i = 0;
    for (; i + 8 <= len; i += 8)
        for (int j = 0; j < 8; j++)
            lane_sum[j] += u[i + j];
    for (; i < len; i++)
        sum += u[i];
    for (int j = 0; j < 8; j++)
        sum += lane_sum[j];
    *mean = sum / len;
    return clamped;
}

int aero_cavity_process(aero_cavity *m, const float *speed,
                        float *const *outs, int n)
{
    int clamped = 0;
    float u[AERO_CAVITY_CHUNK];
    for (int start = 0; start < n; start += AERO_CAVITY_CHUNK) {
        int len = n - start < AERO_CAVITY_CHUNK ? n - start
                                                : AERO_CAVITY_CHUNK;
        double mean;
        clamped |= chunk_speeds(speed + start, u, len, &mean);
        float *out[AERO_CAVITY_MAX_EARS];
        for (int e = 0; e < m->n_ears; e++)
            out[e] = outs[e] + start;
        if (advance_ramps(m, len))
            m->laws_dirty = 1;
        if (m->texture)
            aero_cavity_texture_process(m, u, out, len, u[len - 1]);
        else
            aero_cavity_model_process(m, u, out, len, mean, u[len - 1]);
        m->primed = 1;
    }
    return clamped;
}
