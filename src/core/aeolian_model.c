/* aero: aeolian tone of a circular cylinder, Strouhal/Reynolds model mode
 * (see aeolian_model.h for the physics). */
#include "aeolian_model.h"

#include "aero_air.h"
#include "strouhal.h"

#include <math.h>
#include <string.h>

/* Sectional rms lift coefficient in the subcritical range 5e3 < Re < 1e5:
 * C_L' ~ 0.45 (Norberg 2003, "Fluctuating lift on a circular cylinder:
 * review and new measurements", J. Fluids Struct. 17). */
#define LIFT_RMS 0.45
/* The fluctuating drag is about an order of magnitude weaker (DESIGN.md). */
#define DRAG_TO_LIFT 0.1
/* Spanwise correlation length, in diameters (paper 000, point-source
 * spacing of Dobashi et al. 2003). */
#define CORRELATION_DIAMETERS 3.0
/* Width of the shedding peak, relative to f (full width at half maximum):
 * nearly a pure tone in the laminar wake, a few percent once turbulent. */
#define PEAK_WIDTH_LAMINAR 0.004
#define PEAK_WIDTH_TURBULENT 0.06
/* Depth of the random envelope of a turbulent wake (rms, relative). */
#define ENVELOPE_DEPTH 0.35
/* Variance of a uniform random number on [-1, 1). */
#define UNIFORM_VARIANCE (1.0 / 3.0)

static const double default_ears[AERO_AEOLIAN_MAX_EARS][3] = {
    {-0.1, 1.0, 0.0}, {0.1, 1.0, 0.0}};

static uint32_t xorshift32(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return *state = x;
}

static int is_finite(double v)
{
    return v == v && v < 1e300 && v > -1e300;
}

/* sin(2 pi p) for p in [0, 1): reflect into a quarter period, then the
 * Taylor series to t^9 (error < 4e-6, harmonics below -100 dB). */
static float sin_cycles(float p)
{
    const float two_pi = 6.28318530717958647f;
    float x = p - 0.5f; /* sin(2 pi p) = -sin(2 pi x) */
    float a = fabsf(x);
    float b = fminf(a, 0.5f - a);
    float t = two_pi * b, t2 = t * t;
    float s = t * (1.0f + t2 * (-1.0f / 6 + t2 * (1.0f / 120 +
              t2 * (-1.0f / 5040 + t2 * (1.0f / 362880)))));
    return copysignf(s, -x);
}

void aero_aeolian_model_init(aero_aeolian_model *m, double sample_rate,
                             int n_ears, uint32_t seed)
{
    memset(m, 0, sizeof(*m));
    m->sample_rate = sample_rate > 0 ? sample_rate : 44100.0;
    m->n_ears = n_ears == 2 ? 2 : 1;
    m->ctl_target[AERO_CTL_DIAMETER] = 0.01;
    m->ctl_target[AERO_CTL_LENGTH] = 0.5;
    m->ctl_target[AERO_CTL_GAIN] = 1.0;
    for (int e = 0; e < AERO_AEOLIAN_MAX_EARS; e++)
        for (int k = 0; k < 3; k++)
            m->ctl_target[AERO_CTL_EAR + 3 * e + k] =
                m->n_ears == 1 ? (k == 1 ? 1.0 : 0.0) : default_ears[e][k];
    memcpy(m->ctl, m->ctl_target, sizeof(m->ctl));
    m->geometry_dirty = 1;
    aero_aeolian_model_set_ramp_ms(m, 20.0);
    aero_aeolian_model_set_seed(m, seed);
    m->phase = 0.0;
}

void aero_aeolian_model_set_seed(aero_aeolian_model *m, uint32_t seed)
{
    /* scramble so that neighbouring seeds give unrelated streams; the state
     * of xorshift must never be 0 */
    uint32_t s = seed * 2654435761u + 0x9e3779b9u;
    s ^= s >> 16;
    m->rng = s ? s : 0x12345678u;
    m->phase = (double)(xorshift32(&m->rng) >> 8) / 16777216.0;
    m->envelope = 0.0;
}

/* Start ramping the controls to their (new) targets. Before the first
 * block, values are taken at once: creation arguments do not glide. */
static void start_ramp(aero_aeolian_model *m)
{
    if (!m->primed) {
        memcpy(m->ctl, m->ctl_target, sizeof(m->ctl));
        m->ramp_left = 0;
    } else
        m->ramp_left = m->ramp_samples;
    m->geometry_dirty = 1;
}

int aero_aeolian_model_set_sample_rate(aero_aeolian_model *m, double sr)
{
    if (!is_finite(sr) || sr < 1.0 || sr > 1e7)
        return -1;
    double ramp_ms = 1000.0 * m->ramp_samples / m->sample_rate;
    m->sample_rate = sr;
    m->primed = 0; /* coefficients depend on sr: take new ones at once */
    return aero_aeolian_model_set_ramp_ms(m, ramp_ms);
}

int aero_aeolian_model_set_diameter(aero_aeolian_model *m, double d)
{
    if (!is_finite(d) || d < 1e-5 || d > 10.0)
        return -1;
    m->ctl_target[AERO_CTL_DIAMETER] = d;
    start_ramp(m);
    return 0;
}

int aero_aeolian_model_set_length(aero_aeolian_model *m, double l)
{
    if (!is_finite(l) || l < 1e-5 || l > 1000.0)
        return -1;
    m->ctl_target[AERO_CTL_LENGTH] = l;
    start_ramp(m);
    return 0;
}

int aero_aeolian_model_set_gain_db(aero_aeolian_model *m, double db)
{
    if (!is_finite(db) || db < -200.0 || db > 120.0)
        return -1;
    m->ctl_target[AERO_CTL_GAIN] = pow(10.0, db / 20.0);
    start_ramp(m);
    return 0;
}

int aero_aeolian_model_set_ramp_ms(aero_aeolian_model *m, double ms)
{
    if (!is_finite(ms) || ms < 0.0 || ms > 600000.0)
        return -1;
    m->ramp_samples = ms * 0.001 * m->sample_rate;
    if (m->ramp_samples < 1.0)
        m->ramp_samples = 1.0; /* at least over one block */
    return 0;
}

int aero_aeolian_model_set_ear(aero_aeolian_model *m, int ear, double x,
                               double y, double z)
{
    const double far = 1e5;
    if (ear < 0 || ear >= m->n_ears)
        return -1;
    if (!is_finite(x) || !is_finite(y) || !is_finite(z) || fabs(x) > far ||
        fabs(y) > far || fabs(z) > far)
        return -1;
    double *p = m->ctl_target + AERO_CTL_EAR + 3 * ear;
    p[0] = x, p[1] = y, p[2] = z;
    start_ramp(m);
    return 0;
}

static void advance_ramps(aero_aeolian_model *m, int n)
{
    if (m->ramp_left <= 0)
        return;
    if (m->ramp_left <= n) {
        memcpy(m->ctl, m->ctl_target, sizeof(m->ctl));
        m->ramp_left = 0;
    } else {
        double step = n / m->ramp_left;
        for (int k = 0; k < AERO_CTL_COUNT; k++)
            m->ctl[k] += (m->ctl_target[k] - m->ctl[k]) * step;
        m->ramp_left -= n;
    }
    m->geometry_dirty = 1;
}

/* Radiation of the incoherent span segments to each ear. A segment at z_j
 * radiates p ~ (x_i / r^2) dF_i/dt (Curle); the powers of ~l/(3d) segments
 * add, integrated over at most AERO_AEOLIAN_MAX_POINTS points. */
static void update_geometry(aero_aeolian_model *m)
{
    double d = m->ctl[AERO_CTL_DIAMETER], l = m->ctl[AERO_CTL_LENGTH];
    double segment = fmin(CORRELATION_DIAMETERS * d, l);
    double n_segments = l / segment;
    int points = (int)ceil(n_segments);
    if (points > AERO_AEOLIAN_MAX_POINTS)
        points = AERO_AEOLIAN_MAX_POINTS;
    if (points < 1)
        points = 1;
    double r_min = fmax(d, 0.01); /* the compact-source law fails closer */
    double distance_sum = 0;
    for (int e = 0; e < m->n_ears; e++) {
        const double *ear = m->ctl + AERO_CTL_EAR + 3 * e;
        double lift = 0, drag = 0;
        for (int j = 0; j < points; j++) {
            double z = ((j + 0.5) / points - 0.5) * l;
            double dz = ear[2] - z;
            double r2 = ear[0] * ear[0] + ear[1] * ear[1] + dz * dz;
            if (r2 < r_min * r_min)
                r2 = r_min * r_min;
            lift += (ear[1] / r2) * (ear[1] / r2);
            drag += (ear[0] / r2) * (ear[0] / r2);
        }
        m->lift_geometry[e] = sqrt(lift * n_segments / points);
        m->drag_geometry[e] = sqrt(drag * n_segments / points);
        distance_sum += sqrt(ear[0] * ear[0] + ear[1] * ear[1] +
                             ear[2] * ear[2]);
    }
    m->centre_distance = distance_sum / m->n_ears;
    m->geometry_dirty = 0;
}

static float sanitize_speed(float u, float limit, int *clamped)
{
    if (!(u == u))
        return 0.0f;
    u = fabsf(u);
    if (u > limit) {
        *clamped = 1;
        return limit;
    }
    return u;
}

/* The per-sample coefficients for the state at the end of a block. */
typedef struct {
    double freq, lift[AERO_AEOLIAN_MAX_EARS], drag[AERO_AEOLIAN_MAX_EARS];
    double jitter, am_alpha, am_scale;
} block_coefs;

static void compute_coefs(const aero_aeolian_model *m, double speed,
                          double doppler, block_coefs *c)
{
    double d = m->ctl[AERO_CTL_DIAMETER], l = m->ctl[AERO_CTL_LENGTH];
    double sr = m->sample_rate;
    double re = aero_reynolds(speed, d);
    double st = aero_strouhal(re);
    double strength = aero_shedding_strength(re);
    double turbulence = aero_wake_turbulence(re);
    double depth = ENVELOPE_DEPTH * turbulence;
    double segment = fmin(CORRELATION_DIAMETERS * d, l);

    /* p_rms per segment = (x_i/r^2) rho U^3 St C' L_seg / (4 c0): Curle with
     * dF/dt = 2 pi f F', F' = 1/2 rho U^2 d L_seg C', f = St U / d. sqrt(2)
     * turns rms into the sine's amplitude; the envelope's power is removed. */
    double source = AERO_RHO * st * strength * segment / (4.0 * AERO_C0) *
                    sqrt(2.0) / sqrt(1.0 + depth * depth) *
                    m->ctl[AERO_CTL_GAIN];
    for (int e = 0; e < m->n_ears; e++) {
        c->lift[e] = source * LIFT_RMS * m->lift_geometry[e];
        /* drag at 2f: twice the rate, C_D' = 0.1 C_L' */
        c->drag[e] = source * 2.0 * DRAG_TO_LIFT * LIFT_RMS *
                     m->drag_geometry[e];
    }
    c->freq = st / d / sr * doppler;

    /* Phase diffusion D (rad^2/s) gives a Lorentzian line of full width
     * B = D / (2 pi) Hz: per sample a step of variance 2 pi B / sr rad^2,
     * i.e. B / (2 pi sr) cycles^2, drawn uniform on [-w, w], var w^2/3. */
    double f = st * speed / d;
    double width = (PEAK_WIDTH_LAMINAR +
                    (PEAK_WIDTH_TURBULENT - PEAK_WIDTH_LAMINAR) * turbulence) *
                   f;
    c->jitter = sqrt(width / (2.0 * AERO_PI * sr) / UNIFORM_VARIANCE);
    /* envelope: one-pole low-passed noise with the same bandwidth */
    double alpha = 1.0 - exp(-2.0 * AERO_PI * width / sr);
    if (alpha < 1e-7)
        alpha = 1e-7;
    double variance = UNIFORM_VARIANCE * alpha / (2.0 - alpha);
    c->am_alpha = alpha;
    c->am_scale = depth / sqrt(variance);
}

double aero_aeolian_model_tone_hz(const aero_aeolian_model *m, double speed)
{
    double d = m->ctl_target[AERO_CTL_DIAMETER];
    double re = aero_reynolds(speed, d);
    if (aero_shedding_strength(re) <= 0)
        return 0;
    return aero_strouhal(re) * fabs(speed) / d;
}

int aero_aeolian_model_process(aero_aeolian_model *m, const float *speed,
                               float *const *out, int n)
{
    if (n <= 0)
        return 0;
    const float speed_limit = (float)(AERO_MACH_LIMIT * AERO_C0);
    int clamped = 0;

    advance_ramps(m, n);
    if (m->geometry_dirty)
        update_geometry(m);

    /* Doppler of a moving listener: f' = f (1 - (dr/dt) / c0) */
    double doppler = 1.0;
    if (m->primed) {
        double dr_dt = (m->centre_distance - m->prev_distance) *
                       m->sample_rate / n;
        doppler = fmin(fmax(1.0 - dr_dt / AERO_C0, 0.5), 1.5);
    }
    m->prev_distance = m->centre_distance;

    block_coefs end;
    compute_coefs(m, sanitize_speed(speed[n - 1], speed_limit, &clamped),
                  doppler, &end);
    if (!m->primed) {
        m->freq_coef = end.freq;
        for (int e = 0; e < m->n_ears; e++) {
            m->lift_coef[e] = end.lift[e];
            m->drag_coef[e] = end.drag[e];
        }
        m->jitter = end.jitter;
        m->am_alpha = end.am_alpha;
        m->am_scale = end.am_scale;
        m->primed = 1;
    }

    /* linear interpolation of every coefficient across the block */
    const double inv_n = 1.0 / n;
    const double freq_step = (end.freq - m->freq_coef) * inv_n;
    double freq = m->freq_coef;
    double jitter = m->jitter, am_alpha = m->am_alpha;
    double am_scale = m->am_scale;
    const double jitter_step = (end.jitter - jitter) * inv_n;
    const double alpha_step = (end.am_alpha - am_alpha) * inv_n;
    const double scale_step = (end.am_scale - am_scale) * inv_n;
    double phase = m->phase, envelope = m->envelope;
    uint32_t rng = m->rng;

    for (int start = 0; start < n; start += AERO_AEOLIAN_CHUNK) {
        int len = n - start < AERO_AEOLIAN_CHUNK ? n - start
                                                 : AERO_AEOLIAN_CHUNK;
        /* sequential part: phase with diffusion, envelope, U^3 */
        for (int i = 0; i < len; i++) {
            float u = sanitize_speed(speed[start + i], speed_limit, &clamped);
            uint32_t r = xorshift32(&rng);
            freq += freq_step;
            jitter += jitter_step;
            am_alpha += alpha_step;
            am_scale += scale_step;
            phase += freq * u +
                     jitter * (double)(int16_t)(r >> 16) * (1.0 / 32768.0);
            phase -= floor(phase);
            envelope += am_alpha *
                        ((double)(int16_t)(r & 0xffff) * (1.0 / 32768.0) -
                         envelope);
            double a = 1.0 + am_scale * envelope;
            m->scratch_phase[i] = (float)phase;
            m->scratch_amp[i] = (float)((a > 0 ? a : 0) * u * u * u);
        }
        /* vectorisable part: lift at f, drag at 2f, per ear */
        for (int e = 0; e < m->n_ears; e++) {
            const double lift_step = (end.lift[e] - m->lift_coef[e]) * inv_n;
            const double drag_step = (end.drag[e] - m->drag_coef[e]) * inv_n;
            float lift = (float)(m->lift_coef[e] + lift_step * start);
            float drag = (float)(m->drag_coef[e] + drag_step * start);
            const float lstep = (float)lift_step, dstep = (float)drag_step;
            float *o = out[e] + start;
            for (int i = 0; i < len; i++) {
                float p = m->scratch_phase[i];
                float p2 = 2.0f * p;
                p2 -= p2 >= 1.0f ? 1.0f : 0.0f;
                lift += lstep;
                drag += dstep;
                o[i] = m->scratch_amp[i] *
                       (lift * sin_cycles(p) + drag * sin_cycles(p2));
            }
        }
    }

    m->freq_coef = end.freq;
    for (int e = 0; e < m->n_ears; e++) {
        m->lift_coef[e] = end.lift[e];
        m->drag_coef[e] = end.drag[e];
    }
    m->jitter = end.jitter;
    m->am_alpha = end.am_alpha;
    m->am_scale = end.am_scale;
    m->phase = phase;
    /* no denormals in the envelope filter */
    m->envelope = fabs(envelope) < 1e-20 ? 0.0 : envelope;
    m->rng = rng;
    m->clamped |= clamped;
    return clamped;
}
