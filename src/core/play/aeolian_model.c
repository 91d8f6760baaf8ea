/* aero: [aeolian~]'s model mode, the Strouhal/Reynolds model of a
 * circular cylinder (see aeolian.h for the physics). It reads the object's
 * settings; its state is a->model. */
#include "aeolian_internal.h"

#include "aero_air.h"
#include "aero_util.h"
#include "aero_ramp.h"
#include "strouhal.h"

#include <math.h>
#include <string.h>

/* The fluctuating drag is about an order of magnitude weaker than the
 * lift. */
#define DRAG_TO_LIFT 0.1
/* Depth of the random envelope of a turbulent wake (rms, relative). */
#define ENVELOPE_DEPTH 0.35
/* Variance of a uniform random number on [-1, 1). */
#define UNIFORM_VARIANCE (1.0 / 3.0)

void aero_aeolian_model_seed(aero_aeolian *a)
{
    aero_aeolian_model *m = &a->model;
    /* scramble so that neighbouring seeds give unrelated streams; the state
     * of xorshift must never be 0 */
    uint32_t s = a->seed * 2654435761u + 0x9e3779b9u;
    s ^= s >> 16;
    m->rng = s ? s : 0x12345678u;
    double phase = (double)(aero_xorshift32(&m->rng) >> 8) / 16777216.0;
    m->phasor.re = cos(2.0 * AERO_PI * phase);
    m->phasor.im = sin(2.0 * AERO_PI * phase);
    m->envelope = m->envelope_lp = 0.0;
    m->levels_dirty = 1; /* no laws cached yet */
}

/* Start gliding to the (new) targets. Before the first block, values are
 * taken at once: creation arguments do not glide. */
void aero_aeolian_model_retarget(aero_aeolian *a)
{
    aero_aeolian_model *m = &a->model;
    if (!m->primed) {
        memcpy(m->ctl, a->target, sizeof(m->ctl));
        m->ramp_left = 0;
    } else {
        /* at least over one block */
        m->ramp_left = fmax(a->ramp_ms * 0.001 * a->sample_rate, 1.0);
    }
    m->geometry_dirty = 1;
}

void aero_aeolian_model_unprime(aero_aeolian *a)
{
    a->model.primed = 0; /* coefficients depend on sr: take new ones at once */
}

static void advance_ramps(aero_aeolian *a, int n)
{
    aero_aeolian_model *m = &a->model;
    if (m->ramp_left <= 0)
        return;
    aero_glide_values(m->ctl, a->target, AERO_AEO_COUNT,
                      aero_glide_fraction(&m->ramp_left, n));
    m->geometry_dirty = 1;
}

/* Radiation of the incoherent span segments to each ear. A segment at z_j
 * radiates p ~ (x_i / r^2) dF_i/dt (Curle); the powers of ~l/(3d) segments
 * add, integrated over at most AERO_AEOLIAN_MAX_POINTS points. */
static void update_geometry(aero_aeolian *a)
{
    aero_aeolian_model *m = &a->model;
    double d = m->ctl[AERO_AEO_DIAMETER], l = m->ctl[AERO_AEO_LENGTH];
    double segment = fmin(AERO_CORRELATION_DIAMETERS * d, l);
    double n_segments = l / segment;
    int points = (int)ceil(n_segments);
    if (points > AERO_AEOLIAN_MAX_POINTS)
        points = AERO_AEOLIAN_MAX_POINTS;
    if (points < 1)
        points = 1;
    /* the compact-source law fails closer (the near-field policy,
       aero_near_field): exactly at a segment, heard along +y, its lift */
    double r_min = fmax(d, AERO_AEOLIAN_NEAR_MIN);
    const double lift_dir[3] = {0.0, 1.0, 0.0};
    double distance_sum = 0;
    for (int e = 0; e < a->n_ears; e++) {
        const double *ear = m->ctl + AERO_AEO_EAR + 3 * e;
        double lift = 0, drag = 0;
        for (int j = 0; j < points; j++) {
            double z = ((j + 0.5) / points - 0.5) * l;
            double r[3] = {ear[0], ear[1], ear[2] - z};
            aero_near_field(r, r_min, lift_dir, &a->near);
            double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
            lift += (r[1] / r2) * (r[1] / r2);
            drag += (r[0] / r2) * (r[0] / r2);
        }
        m->lift_geometry[e] = sqrt(lift * n_segments / points);
        m->drag_geometry[e] = sqrt(drag * n_segments / points);
        distance_sum += sqrt(ear[0] * ear[0] + ear[1] * ear[1] +
                             ear[2] * ear[2]);
    }
    m->centre_distance = distance_sum / a->n_ears;
    m->geometry_dirty = 0;
    m->levels_dirty = 1;
}

/* Everything that depends on Re, the geometry and the chunk length,
 * recomputed only when one of them moves (the speed by more than 0.1 %,
 * which shifts St by far less than that): the per-chunk cost stays a few
 * multiplications under a gusting wind. */
static void update_chunk_laws(aero_aeolian *a, double speed, int n)
{
    aero_aeolian_model *m = &a->model;
    double d = m->ctl[AERO_AEO_DIAMETER], l = m->ctl[AERO_AEO_LENGTH];
    if (!m->levels_dirty && n == m->cached_n && d == m->cached_diameter &&
        fabs(speed - m->cached_speed) <= 1e-3 * m->cached_speed)
        return;
    double re = aero_reynolds(speed, d);
    m->st = aero_strouhal(re);
    /* sectional C_L'(Re), Norberg (2003): it already rises from 0 at onset */
    double lift_rms = aero_lift_rms(re);
    double turbulence = aero_wake_turbulence(re);
    double depth = ENVELOPE_DEPTH * turbulence;

    /* p_rms per segment = (x_i/r^2) rho U^3 St C' L_seg / (4 c0): Curle with
     * dF/dt = 2 pi f F', F' = 1/2 rho U^2 d L_seg C', f = St U / d. sqrt(2)
     * turns rms into the sine's amplitude; the envelope's power is divided
     * out. */
    double segment = fmin(AERO_CORRELATION_DIAMETERS * d, l);
    double source = AERO_RHO * m->st * segment / (4.0 * AERO_C0) *
                    sqrt(2.0) / sqrt(1.0 + depth * depth) * m->ctl[AERO_AEO_GAIN];
    for (int e = 0; e < a->n_ears; e++) {
        m->lift_level[e] = source * lift_rms * m->lift_geometry[e];
        /* drag at 2f: twice the rate, C_D' = 0.1 C_L' */
        m->drag_level[e] = source * 2.0 * DRAG_TO_LIFT * lift_rms *
                           m->drag_geometry[e];
    }

    /* Phase diffusion D (rad^2/s) gives a Lorentzian line of full width
     * B = D / (2 pi) Hz: over n samples the phase wanders by a step of
     * variance B n / (2 pi sr) cycles^2 (uniform on [-1, 1) has var 1/3). */
    double sr = a->sample_rate;
    double width = aero_shedding_line_width(re) * m->st * speed / d;
    m->phase_jitter = sqrt(3.0 * width * n / (2.0 * AERO_PI * sr));
    /* envelope: noise through two one-pole low-passes (bandwidth ~ the
     * line's), so its path is smooth between chunks; scaled by its standard
     * deviation, var = alpha^4 (1 + p^2) / (1 - p^2)^3 var_in, p = 1 - alpha */
    double x = 2.0 * AERO_PI * width * n / sr;
    double alpha = x / (1.0 + x) + 1e-6;
    double p = 1.0 - alpha, p2 = p * p;
    double variance = UNIFORM_VARIANCE * alpha * alpha * alpha * alpha *
                      (1.0 + p2) / ((1.0 - p2) * (1.0 - p2) * (1.0 - p2));
    m->envelope_alpha = alpha;
    m->envelope_scale = depth / sqrt(variance);

    m->cached_speed = speed;
    m->cached_diameter = d;
    m->cached_n = n;
    m->levels_dirty = 0;
}

double aero_aeolian_model_tone_hz(const aero_aeolian *a, double speed)
{
    double d = a->target[AERO_AEO_DIAMETER];
    double re = aero_reynolds(speed, d);
    if (aero_shedding_strength(re) <= 0)
        return 0;
    return aero_strouhal(re) * fabs(speed) / d;
}

typedef aero_cplx cplx;

static cplx cmul(cplx a, cplx b)
{
    cplx c = {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
    return c;
}

/* e^{i 2 pi x} */
static cplx turn(double x)
{
    cplx c = {cos(2.0 * AERO_PI * x), sin(2.0 * AERO_PI * x)};
    return c;
}

/* e^{i 2 pi x} for a small x (|2 pi x| < 0.05): Taylor series, error
 * below 1e-12, no libm call */
static cplx turn_small(double x)
{
    double t = 2.0 * AERO_PI * x, t2 = t * t;
    if (t2 > 0.0025)
        return turn(x);
    cplx c = {1.0 - t2 * (0.5 - t2 / 24.0), t * (1.0 - t2 * (1.0 / 6.0 - t2 / 120.0))};
    return c;
}

/* the state after a chunk of n samples: the phasor at sample n (lane 0's,
 * or computed for a chunk that ends inside a lane step, its last samples
 * written from the lanes' values zr, zi), renormalised against drift, and
 * the increment's turn moved on to w1 */
static void phasor_next(aero_aeolian_model *m, int i, int n, const float *zr,
                        const float *zi, double a, double b, double w0,
                        double w1)
{
    cplx z;
    if (i == n) {
        /* lane 0 now stands at sample n: the next chunk's start */
        z.re = zr[0], z.im = zi[0];
    } else {
        for (int j = 0; i < n; i++, j++) {
            m->scratch_sin[i] = zi[j];
            m->scratch_cos[i] = zr[j];
        }
        z = cmul(m->phasor, turn(a * n + b * (double)n * n));
    }
    double norm = 1.0 / sqrt(z.re * z.re + z.im * z.im); /* no drift */
    m->phasor.re = z.re * norm, m->phasor.im = z.im * norm;
    cplx next = cmul(m->increment_turn, turn_small(w1 - w0));
    norm = 1.0 / sqrt(next.re * next.re + next.im * next.im);
    m->increment_turn.re = next.re * norm, m->increment_turn.im = next.im * norm;
    m->increment = w1;
}

/* The oscillator for one chunk: sin and cos of the shedding phase into
 * scratch_sin/cos. The phase increment glides linearly from the last
 * chunk's value to w1 (cycles per sample), so frequency never steps: with
 * a = w0 + d/2, b = d/2, d = (w1 - w0)/n the phase is p0 + a i + b i^2.
 * LANES phasors take the samples i = LANES k + j; lane j advances by
 * r_j = e^{i 2 pi (a L + 2 b L j + b L^2 (2k + 1))}, i.e. r_j itself turns
 * by e^{i 2 pi 2 b L^2} per step. One libm sincos per chunk; the lanes are
 * independent, so the inner loop vectorises. */
static void render_phasors(aero_aeolian_model *m, double w1, int n)
{
    enum { L = AERO_AEOLIAN_LANES };
    if (!m->primed_phase) {
        m->increment = w1;
        m->increment_turn = turn(w1);
        m->primed_phase = 1;
    }
    const double w0 = m->increment;
    const double b = 0.5 * (w1 - w0) / n, a = w0 + b;
    /* e^{i 2 pi a} from the last increment's turn: no libm call */
    const cplx ea = cmul(m->increment_turn, turn_small(b));
    cplx eal = cmul(ea, ea); /* e^{i 2 pi a L}, L = 8, by squaring */
    eal = cmul(eal, eal);
    eal = cmul(eal, eal);

    float zr[L], zi[L], rr[L], ri[L];
    cplx z = m->phasor;
    cplx u = cmul(ea, turn_small(b)), v = turn_small(2.0 * b);
    cplx r = cmul(eal, turn_small(b * L * L)), g = turn_small(2.0 * b * L);
    for (int j = 0; j < L; j++) {
        zr[j] = (float)z.re, zi[j] = (float)z.im;
        rr[j] = (float)r.re, ri[j] = (float)r.im;
        z = cmul(z, u);
        u = cmul(u, v);
        r = cmul(r, g);
    }
    const cplx q = turn_small(2.0 * b * L * L);
    const float qr = (float)q.re, qi = (float)q.im;
    float *restrict sin_out = m->scratch_sin, *restrict cos_out = m->scratch_cos;
    int i = 0;
#if defined(__GNUC__) && AERO_AEOLIAN_LANES == 8
    /* the same recurrence on two 4-float vectors per quantity (GCC's
     * vector extension; the plain loop below is the portable reference) */
    typedef float v4 __attribute__((vector_size(16)));
    v4 zr0, zr1, zi0, zi1, rr0, rr1, ri0, ri1;
    memcpy(&zr0, zr, 16), memcpy(&zr1, zr + 4, 16);
    memcpy(&zi0, zi, 16), memcpy(&zi1, zi + 4, 16);
    memcpy(&rr0, rr, 16), memcpy(&rr1, rr + 4, 16);
    memcpy(&ri0, ri, 16), memcpy(&ri1, ri + 4, 16);
    for (; i + L <= n; i += L) {
        memcpy(sin_out + i, &zi0, 16), memcpy(sin_out + i + 4, &zi1, 16);
        memcpy(cos_out + i, &zr0, 16), memcpy(cos_out + i + 4, &zr1, 16);
        v4 t0 = zr0 * rr0 - zi0 * ri0, t1 = zr1 * rr1 - zi1 * ri1;
        zi0 = zr0 * ri0 + zi0 * rr0, zi1 = zr1 * ri1 + zi1 * rr1;
        zr0 = t0, zr1 = t1;
        t0 = rr0 * qr - ri0 * qi, t1 = rr1 * qr - ri1 * qi;
        ri0 = rr0 * qi + ri0 * qr, ri1 = rr1 * qi + ri1 * qr;
        rr0 = t0, rr1 = t1;
    }
    memcpy(zr, &zr0, 16), memcpy(zr + 4, &zr1, 16);
    memcpy(zi, &zi0, 16), memcpy(zi + 4, &zi1, 16);
#else
    for (; i + L <= n; i += L) {
        for (int j = 0; j < L; j++) {
            sin_out[i + j] = zi[j];
            cos_out[i + j] = zr[j];
        }
        for (int j = 0; j < L; j++) {
            float tr = zr[j] * rr[j] - zi[j] * ri[j];
            float ti = zr[j] * ri[j] + zi[j] * rr[j];
            float ur = rr[j] * qr - ri[j] * qi;
            float ui = rr[j] * qi + ri[j] * qr;
            zr[j] = tr, zi[j] = ti, rr[j] = ur, ri[j] = ui;
        }
    }
#endif
    phasor_next(m, i, n, zr, zi, a, b, w0, w1);
}

/* The chunk's speeds: sanitised |U| (NaN -> 0, clamped at Mach 0.3) into
 * scratch_amp as U^3, the level law; returns the mean |U|. Branch-free and
 * summed in lanes so that it vectorises; *clamped is set when a speed
 * reached the limit. */
static double speed_law(aero_aeolian_model *m, const float *speed, int n,
                        int *clamped)
{
    const float speed_limit = (float)(AERO_MACH_LIMIT * AERO_C0);
    float *restrict amp = m->scratch_amp;
    for (int i = 0; i < n; i++) {
        float x = speed[i];
        float u = x == x ? fabsf(x) : 0.0f;
        amp[i] = u < speed_limit ? u : speed_limit;
    }
    float lane_sum[AERO_AEOLIAN_LANES] = {0}, sum = 0;
    int k = 0;
    for (; k + AERO_AEOLIAN_LANES <= n; k += AERO_AEOLIAN_LANES)
        for (int j = 0; j < AERO_AEOLIAN_LANES; j++)
            lane_sum[j] += amp[k + j];
    for (; k < n; k++)
        sum += amp[k];
    for (int j = 0; j < AERO_AEOLIAN_LANES; j++)
        sum += lane_sum[j];
    for (k = 0; k < n; k++)
        amp[k] = amp[k] * amp[k] * amp[k];
    for (k = 0; k < n; k++)
        *clamped |= fabsf(speed[k]) >= speed_limit;
    return sum / n;
}

/* lift at f, drag at 2f (sin 2x = 2 sin x cos x), per ear: the level in
 * scratch_amp times the phasors, each ear's coefficients gliding to
 * lift_end and drag_end over the chunk */
static void write_ears(aero_aeolian *a, const double *lift_end,
                       const double *drag_end, float *const *out, int n)
{
    aero_aeolian_model *m = &a->model;
    const float inv_n = 1.0f / n;
    const float *restrict amp = m->scratch_amp;
    const float *restrict sines = m->scratch_sin, *restrict cosines = m->scratch_cos;
    for (int e = 0; e < a->n_ears; e++) {
        const float l0 = (float)m->lift_coef[e];
        const float dl = (float)(lift_end[e] - m->lift_coef[e]) * inv_n;
        const float k0 = 2.0f * (float)m->drag_coef[e];
        const float dk = 2.0f * (float)(drag_end[e] - m->drag_coef[e]) * inv_n;
        float *restrict o = out[e];
        for (int i = 0; i < n; i++) {
            float t = (float)(i + 1);
            o[i] = amp[i] * sines[i] * ((l0 + dl * t) + (k0 + dk * t) * cosines[i]);
        }
        m->lift_coef[e] = lift_end[e];
        m->drag_coef[e] = drag_end[e];
    }
}

/* One chunk of at most AERO_AEOLIAN_CHUNK samples. */
static int process_chunk(aero_aeolian *a, const float *speed,
                         float *const *out, int n)
{
    aero_aeolian_model *m = &a->model;
    const double sr = a->sample_rate;
    int clamped = 0;

    advance_ramps(a, n);
    if (m->geometry_dirty)
        update_geometry(a);

    /* Doppler of a moving listener: f' = f (1 - (dr/dt) / c0) */
    double doppler = 1.0;
    if (m->primed) {
        double dr_dt = (m->centre_distance - m->prev_distance) * sr / n;
        doppler = fmin(fmax(1.0 - dr_dt / AERO_C0, 0.5), 1.5);
    }
    m->prev_distance = m->centre_distance;

    float *restrict amp = m->scratch_amp;
    double mean_speed = speed_law(m, speed, n, &clamped);
    update_chunk_laws(a, mean_speed, n);
    double f = m->st * mean_speed / m->ctl[AERO_AEO_DIAMETER] * doppler;
    double step = f * n / sr + m->phase_jitter * aero_uniform(&m->rng);
    m->envelope_lp += m->envelope_alpha * (aero_uniform(&m->rng) - m->envelope_lp);
    m->envelope += m->envelope_alpha * (m->envelope_lp - m->envelope);
    double gain_end = 1.0 + m->envelope_scale * m->envelope;
    if (gain_end < 0)
        gain_end = 0;

    const double *lift_end = m->lift_level, *drag_end = m->drag_level;
    if (!m->primed) {
        for (int e = 0; e < a->n_ears; e++) {
            m->lift_coef[e] = lift_end[e];
            m->drag_coef[e] = drag_end[e];
        }
        m->envelope_gain = gain_end;
        m->primed = 1;
    }

    /* level per sample: U^3 times the interpolated envelope */
    const float inv_n = 1.0f / n;
    const float g0 = (float)m->envelope_gain;
    const float dg = (float)(gain_end - m->envelope_gain) * inv_n;
    for (int i = 0; i < n; i++)
        amp[i] *= g0 + dg * (float)(i + 1);

    render_phasors(m, step / n, n);
    write_ears(a, lift_end, drag_end, out, n);
    m->envelope_gain = gain_end;
    return clamped;
}

int aero_aeolian_model_process(aero_aeolian *a, const float *speed,
                               float *const *out, int n)
{
    int clamped = 0;
    for (int start = 0; start < n; start += AERO_AEOLIAN_CHUNK) {
        int len = n - start < AERO_AEOLIAN_CHUNK ? n - start : AERO_AEOLIAN_CHUNK;
        float *chunk_out[AERO_AEOLIAN_MAX_EARS];
        for (int e = 0; e < a->n_ears; e++)
            chunk_out[e] = out[e] + start;
        clamped |= process_chunk(a, speed + start, chunk_out, len);
    }
    return clamped;
}
