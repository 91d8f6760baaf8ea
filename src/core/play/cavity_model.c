/* aero: cavity tones, model and texture mode (see cavity_model.h). */
#include "cavity_model.h"

#include "aero_air.h"
#include "aero_util.h"
#include "aero_ramp.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Rossiter's constants (Rossiter 1964) */
#define ROSSITER_ALPHA 0.25
#define ROSSITER_KAPPA 0.57
/* flanged end correction of an opening of radius a: 0.82 a (Rayleigh;
 * Norris & Sheng 1989 give 0.8216 a) */
#define END_CORRECTION 0.82
/* Relative strengths of Rossiter modes 1..4 in a shallow cavity: mode 2
 * usually dominates for L/D ~ 1-4 (Rossiter 1964, Fig. 9 of his report). */
static const double mode_weight[AERO_CAVITY_MODES] = {0.6, 1.0, 0.5, 0.25};
/* Lock-in: a Rossiter mode within a few percent of a depth mode grows by
 * up to LOCK_GAIN in amplitude (+20 dB) and narrows. */
#define LOCK_GAIN 10.0
#define LOCK_WIDTH 0.04
/* Width of an unlocked shear-layer tone, relative to f (FWHM). */
#define TONE_WIDTH 0.03
/* Level: p_rms = LEVEL (rho/2) U^2 sqrt(L W) / r at the reference speed;
 * a chosen calibration (a 2 x 5 cm gap at 10 m/s gives ~50 dB SPL at 1 m),
 * not a published value. */
#define LEVEL 0.002
#define REFERENCE_SPEED 10.0
/* broadband shear-layer noise relative to the tones (rms) */
#define NOISE_LEVEL 0.3

/* sin(2 pi p), p in [0, 1): quarter-period reflection, Taylor to t^9 */
static float sin_cycles(float p)
{
    float x = p - 0.5f;
    float a = fabsf(x);
    float b = fminf(a, 0.5f - a);
    float t = 6.28318530717958647f * b, t2 = t * t;
    float s = t * (1.0f + t2 * (-1.0f / 6 + t2 * (1.0f / 120 +
              t2 * (-1.0f / 5040 + t2 * (1.0f / 362880)))));
    return copysignf(s, -x);
}

double aero_cavity_rossiter_hz(double speed, double length, int mode)
{
    double u = fabs(speed), mach = u / AERO_C0;
    return u / length * (mode - ROSSITER_ALPHA) /
           (mach + 1.0 / ROSSITER_KAPPA);
}

double aero_cavity_locked_hz(double f, double depth, double length,
                             double width)
{
    double pulled = f, best = 0.0;
    for (int j = 1; j <= AERO_CAVITY_DEPTH_MODES; j++) {
        double fd = aero_cavity_depth_hz(depth, length, width, j);
        double x = (f - fd) / (LOCK_WIDTH * fd), x4 = x * x * x * x;
        double pull = 1.0 / (1.0 + x4);
        if (pull > best) {
            best = pull;
            pulled = f - (f - fd) * pull;
        }
    }
    return pulled;
}

double aero_cavity_depth_hz(double depth, double length, double width, int n)
{
    double radius = sqrt(length * width / AERO_PI);
    return (2 * n - 1) * AERO_C0 / (4.0 * (depth + END_CORRECTION * radius));
}

int aero_cavity_model_init(aero_cavity_model *m, double sample_rate,
                           uint32_t seed)
{
    memset(m, 0, sizeof(*m));
    int sr_ok = sample_rate > 0 && aero_is_finite(sample_rate);
    m->sample_rate = sr_ok ? sample_rate : 44100.0;
    m->exponent = 2.0;
    m->ctl_target[AERO_CAV_LENGTH] = 0.02;
    m->ctl_target[AERO_CAV_DEPTH] = 0.01;
    m->ctl_target[AERO_CAV_WIDTH] = 0.05;
    m->ctl_target[AERO_CAV_GAIN] = 1.0;
    m->ctl_target[AERO_CAV_EAR + 1] = 1.0;
    memcpy(m->ctl, m->ctl_target, sizeof(m->ctl));
    aero_cavity_model_set_ramp_ms(m, 20.0);
    aero_cavity_model_set_seed(m, seed);
    return sr_ok ? 0 : -1;
}

void aero_cavity_model_free(aero_cavity_model *m)
{
    if (m->texture) {
        aero_texture_free(m->texture);
        free(m->texture);
        m->texture = NULL;
    }
}

void aero_cavity_model_set_seed(aero_cavity_model *m, uint32_t seed)
{
    uint32_t s = seed * 2654435761u + 0x7f4a7c15u;
    s ^= s >> 16;
    m->rng = s ? s : 0x2545f491u;
    for (int k = 0; k < AERO_CAVITY_MODES; k++)
        m->phase[k] = 0.5 + 0.5 * aero_uniform(&m->rng);
    m->texture_pos = 0.5 + 0.5 * aero_uniform(&m->rng); /* scaled at use */
}

static int size_ok(double v)
{
    return aero_is_finite(v) && v >= AERO_CAVITY_SIZE_MIN &&
           v <= AERO_CAVITY_SIZE_MAX;
}

static int set_ctl(aero_cavity_model *m, int k, double v)
{
    m->ctl_target[k] = v;
    if (!m->primed)
        m->ctl[k] = v;
    else
        m->ramp_left = m->ramp_samples;
    return 0;
}

int aero_cavity_model_set_sample_rate(aero_cavity_model *m, double sr)
{
    if (!aero_is_finite(sr) || sr < 1.0 || sr > 1e7)
        return -1;
    double ms = 1000.0 * m->ramp_samples / m->sample_rate;
    m->sample_rate = sr;
    return aero_cavity_model_set_ramp_ms(m, ms);
}

int aero_cavity_model_set_length(aero_cavity_model *m, double l)
{
    if (!size_ok(l))
        return -1;
    return set_ctl(m, AERO_CAV_LENGTH, l);
}

int aero_cavity_model_set_depth(aero_cavity_model *m, double d)
{
    if (!size_ok(d))
        return -1;
    return set_ctl(m, AERO_CAV_DEPTH, d);
}

int aero_cavity_model_set_width(aero_cavity_model *m, double w)
{
    if (!size_ok(w))
        return -1;
    return set_ctl(m, AERO_CAV_WIDTH, w);
}

int aero_cavity_model_set_gain_db(aero_cavity_model *m, double db)
{
    if (!aero_is_finite(db) || db < AERO_GAIN_DB_MIN || db > AERO_GAIN_DB_MAX)
        return -1;
    return set_ctl(m, AERO_CAV_GAIN, pow(10.0, db / 20.0));
}

int aero_cavity_model_set_ramp_ms(aero_cavity_model *m, double ms)
{
    if (!aero_is_finite(ms) || ms < 0.0 || ms > AERO_RAMP_MS_MAX)
        return -1;
    m->ramp_samples = fmax(1.0, ms * 0.001 * m->sample_rate);
    return 0;
}

int aero_cavity_model_set_exponent(aero_cavity_model *m, double n)
{
    if (!aero_is_finite(n) || n < 0.0 || n > AERO_CAVITY_EXPONENT_MAX)
        return -1;
    m->exponent = n;
    return 0;
}

int aero_cavity_model_set_ears(aero_cavity_model *m, const aero_ears *e)
{
    if (!aero_ears_ok(e, 1))
        return -1;
    for (int i = 0; i < 3; i++)
        set_ctl(m, AERO_CAV_EAR + i, e->pos[0][i]);
    return 0;
}

int aero_cavity_model_set_texture(aero_cavity_model *m, aero_texture *t,
                                  char *err, size_t errlen)
{
    if (t) {
        char kind[32] = "";
        aero_texture_get(t, "kind", kind, sizeof(kind));
        double v0 = aero_texture_getd(t, "v0", 0.0);
        if (strcmp(kind, "cavity")) {
            snprintf(err, errlen, "not a cavity texture (kind=%s)",
                     kind[0] ? kind : "?");
            return -1;
        }
        if (!(v0 > 0) || t->directions < 1 || t->frames < 2 || !(t->rate > 0)) {
            snprintf(err, errlen, "texture has no usable v0, rate or frames");
            return -1;
        }
        m->texture_v0 = v0;
        double l0 = aero_texture_getd(t, "length", 0.0);
        m->texture_length = l0 > 0.0 && l0 < 100.0 ? l0 : 0.0;
        m->texture_pos = fmod(fabs(m->texture_pos) * t->frames, t->frames);
    }
    aero_cavity_model_free(m);
    m->texture = t;
    return 0;
}

static void advance_ramps(aero_cavity_model *m, int n)
{
    if (m->ramp_left <= 0)
        return;
    aero_glide_values(m->ctl, m->ctl_target, AERO_CAV_COUNT,
                      aero_glide_fraction(&m->ramp_left, n));
}

static double listener_distance(const aero_cavity_model *m, double r_min)
{
    const double *e = m->ctl + AERO_CAV_EAR;
    return fmax(sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]), r_min);
}

/* Model mode: per block the Rossiter frequencies per unit speed, the
 * lock-in gains and the level; per sample four narrow-band tones. */
static void process_model(aero_cavity_model *m, const float *u, float *out,
                          int n, double u_end)
{
    double l = m->ctl[AERO_CAV_LENGTH], d = m->ctl[AERO_CAV_DEPTH];
    double w = m->ctl[AERO_CAV_WIDTH], sr = m->sample_rate;
    double mach = u_end / AERO_C0;
    double gain_end[AERO_CAVITY_MODES], jitter[AERO_CAVITY_MODES];
    double weight_sum = 0;
    for (int k = 0; k < AERO_CAVITY_MODES; k++)
        weight_sum += mode_weight[k] * mode_weight[k];
    /* p_rms = LEVEL (rho/2) U_ref^(2-n) U^n sqrt(L W) / r; the tones share
     * it by their weights (sqrt 2: rms -> amplitude) */
    double r = listener_distance(m, sqrt(l * w));
    double level = LEVEL * 0.5 * AERO_RHO *
                   pow(REFERENCE_SPEED, 2.0 - m->exponent) * sqrt(l * w) / r *
                   m->ctl[AERO_CAV_GAIN];
    for (int k = 0; k < AERO_CAVITY_MODES; k++) {
        m->freq_factor[k] = (k + 1 - ROSSITER_ALPHA) /
                            (l * (mach + 1.0 / ROSSITER_KAPPA));
        double f = m->freq_factor[k] * u_end, lock = 0;
        for (int j = 1; j <= AERO_CAVITY_DEPTH_MODES; j++) {
            double fd = aero_cavity_depth_hz(d, l, w, j);
            double x = (f - fd) / (LOCK_WIDTH * fd);
            lock = fmax(lock, 1.0 / (1.0 + x * x));
        }
        double grow = 1.0 + LOCK_GAIN * lock;
        /* the locked tone's frequency holds on the depth mode */
        if (f > 0.0)
            m->freq_factor[k] *= aero_cavity_locked_hz(f, d, l, w) / f;
        gain_end[k] = level * sqrt(2.0) * mode_weight[k] / sqrt(weight_sum) *
                      grow;
        /* a locked tone is purer: the width shrinks as it grows */
        double width = TONE_WIDTH * f / grow;
        jitter[k] = sqrt(3.0 * width / (2.0 * AERO_PI * sr));
    }
    if (!m->primed)
        memcpy(m->mode_gain, gain_end, sizeof(gain_end));
    /* shear-layer noise: white noise between two one-pole low-passes at
     * f_1 / 2 and 4 f_4, scaled to NOISE_LEVEL of the tones */
    double f_lo = 0.5 * m->freq_factor[0] * u_end,
           f_hi = 4.0 * m->freq_factor[AERO_CAVITY_MODES - 1] * u_end;
    double a_lo = 1.0 - exp(-2.0 * AERO_PI * fmin(f_lo, 0.4 * sr) / sr);
    double a_hi = 1.0 - exp(-2.0 * AERO_PI * fmin(f_hi, 0.4 * sr) / sr);
    double noise_scale = a_hi > 1e-9 ? NOISE_LEVEL * level /
                                           sqrt((1.0 / 3.0) * a_hi / (2.0 - a_hi))
                                     : 0.0;
    double exponent = m->exponent;
    for (int i = 0; i < n; i++) {
        double t = (i + 1.0) / n, s = 0;
        /* one random word gives the four modes' phase steps, a byte each
         * (uniform on [-1, 1): only the variance of the diffusion matters) */
        uint32_t word = aero_xorshift32(&m->rng);
        for (int k = 0; k < AERO_CAVITY_MODES; k++) {
            double g = m->mode_gain[k] + (gain_end[k] - m->mode_gain[k]) * t;
            double p = m->phase[k] + m->freq_factor[k] * u[i] / sr +
                       jitter[k] * (double)(int8_t)(word >> (8 * k)) * (1.0 / 128.0);
            /* a short cavity in a fast flow (or a low sample rate) puts
             * a mode above the sample rate: the phase may step by more
             * than a cycle, so wrap by floor (sin_cycles needs [0, 1)) */
            if (p < 0.0 || p >= 1.0)
                p -= floor(p);
            m->phase[k] = p;
            s += g * sin_cycles((float)p);
        }
        double white = aero_uniform(&m->rng);
        m->noise_state[0] += a_hi * (white - m->noise_state[0]);
        m->noise_state[1] += a_lo * (m->noise_state[0] - m->noise_state[1]);
        s += noise_scale * (m->noise_state[0] - m->noise_state[1]);
        double un = exponent == 2.0 ? (double)u[i] * u[i] : pow(u[i], exponent);
        out[i] = (float)(s * un);
    }
    memcpy(m->mode_gain, gain_end, sizeof(gain_end));
    for (int k = 0; k < 2; k++)
        if (fabs(m->noise_state[k]) < 1e-20)
            m->noise_state[k] = 0; /* no denormals */
}

/* Texture mode: the texture coordinate advances by (v/v0)(L0/L) (Dobashi et
 * al. 2003 eq. 3: the shear-layer modes sit at St_L = f L / v, so the pitch
 * follows the cavity's length as an aeolian texture's follows d0/d), amplitude
 * (v/v0)^n (g = dF/dt per unit width: F ~ v^2 L, f ~ v/L), Curle dipole
 * p = (x . g) W / (4 pi c0 r^2). */
static void process_texture(aero_cavity_model *m, const float *u, float *out,
                            int n)
{
    const aero_texture *t = m->texture;
    const double *e = m->ctl + AERO_CAV_EAR;
    double l = m->ctl[AERO_CAV_LENGTH], w = m->ctl[AERO_CAV_WIDTH];
    double r = listener_distance(m, sqrt(l * w));
    double radiation = w / (4.0 * AERO_PI * AERO_C0 * r * r) *
                       m->ctl[AERO_CAV_GAIN];
    double cx = e[0] * radiation, cy = e[1] * radiation;
    double step = t->rate / m->sample_rate / m->texture_v0 *
                  (m->texture_length > 0.0 ? m->texture_length / l : 1.0);
    for (int i = 0; i < n; i++) {
        double v = u[i] / m->texture_v0;
        long k = (long)m->texture_pos;
        double frac = m->texture_pos - k;
        double gx = aero_texture_sample(t, k, 0, 0) * (1 - frac) +
                    aero_texture_sample(t, k + 1, 0, 0) * frac;
        double gy = aero_texture_sample(t, k, 0, 1) * (1 - frac) +
                    aero_texture_sample(t, k + 1, 0, 1) * frac;
        double scale = m->exponent == 2.0 ? v * v : pow(v, m->exponent);
        out[i] = (float)((cx * gx + cy * gy) * scale);
        m->texture_pos += u[i] * step;
        if (m->texture_pos >= t->frames)
            m->texture_pos -= t->frames * floor(m->texture_pos / t->frames);
    }
}

int aero_cavity_model_process(aero_cavity_model *m, const float *speed,
                              float *const *outs, int n)
{
    float *out = outs[0];
    enum { CHUNK = 64 };
    const float limit = (float)(AERO_MACH_LIMIT * AERO_C0);
    int clamped = 0;
    float u[CHUNK];
    for (int start = 0; start < n; start += CHUNK) {
        int len = n - start < CHUNK ? n - start : CHUNK;
        for (int i = 0; i < len; i++) {
            float x = speed[start + i];
            float v = x == x ? fabsf(x) : 0.0f;
            if (v > limit)
                v = limit, clamped = 1;
            u[i] = v;
        }
        advance_ramps(m, len);
        if (m->texture)
            process_texture(m, u, out + start, len);
        else
            process_model(m, u, out + start, len, u[len - 1]);
        m->primed = 1;
    }
    return clamped;
}
