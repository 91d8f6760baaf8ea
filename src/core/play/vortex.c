/* aero: real-time vortex sound from a texture Q(u, t) (see
 * vortex.h). */
#include "vortex.h"

#include "aero_air.h"
#include "aero_util.h"
#include "aero_ramp.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PAD_BEFORE 1
#define PAD_AFTER 3

static void randomise_offsets(aero_vortex *m, int from)
{
    for (int i = from; i < m->n; i++)
        /* uniform over the loop; scaled to frames when a texture arrives */
        m->pos[i] = 0.5 + 0.5 * aero_uniform(&m->rng);
    if (m->frames > 0)
        for (int i = from; i < m->n; i++)
            m->pos[i] *= m->frames;
}

int aero_vortex_init(aero_vortex *m, double sample_rate, int n_ears,
                     uint32_t seed)
{
    memset(m, 0, sizeof *m);
    int sr_ok = sample_rate > 0.0 && aero_is_finite(sample_rate);
    m->sample_rate = sr_ok ? sample_rate : AERO_SAMPLE_RATE_FALLBACK;
    m->stereo = n_ears == 2;
    m->rng = seed ? seed : 1;
    m->gain = m->gain_target = pow(10.0, AERO_GAIN_DB_DEFAULT / 20.0);
    m->clip = AERO_VORTEX_CLIP_DEFAULT;
    m->r_min = 0.05;
    m->falloff = AERO_VORTEX_FALLOFF_DEFAULT;
    aero_vortex_set_ramp_ms(m, AERO_RAMP_MS_DEFAULT);
    m->ear[0] = m->ear_target[0] = m->stereo ? -AERO_EAR_HALF_SPACING : 0.0;
    m->ear[1] = m->ear_target[1] = 1.0;
    m->ear[3] = m->ear_target[3] = AERO_EAR_HALF_SPACING;
    m->ear[4] = m->ear_target[4] = 1.0;
    /* out of memory: no sources and no flame, silent (process reads n 0) */
    if (aero_combustion_init(&m->combustion, m->sample_rate,
                             m->rng ^ 0x9e3779b9u) ||
        aero_vortex_set_count(m, AERO_VORTEX_SOURCES_DEFAULT))
        return -1;
    return sr_ok ? 0 : -1;
}

void aero_vortex_free(aero_vortex *m)
{
    if (m->texture) {
        aero_texture_free(m->texture);
        free(m->texture);
    }
    free(m->tab);
    free(m->pos);
    free(m->speed);
    free(m->speed_target);
    free(m->xyz);
    free(m->xyz_target);
    free(m->dist);
    free(m->rd);
    aero_combustion_free(&m->combustion);
    memset(m, 0, sizeof *m);
}

int aero_vortex_set_sample_rate(aero_vortex *m, double sr)
{
    if (!(sr >= 1000.0 && sr <= 1e6))
        return -1;
    if (aero_combustion_set_sample_rate(&m->combustion, sr))
        return -1;
    if (sr != m->sample_rate) {
        double ms = m->ramp_samples / m->sample_rate * 1000.0;
        m->sample_rate = sr;
        aero_vortex_set_ramp_ms(m, ms);
    }
    return 0;
}

/* grows a double array to n entries, keeping the first `old` */
static int grow(double **a, int old, int n, double fill)
{
    double *b = realloc(*a, sizeof(double) * (size_t)n);
    if (!b)
        return -1;
    for (int i = old; i < n; i++)
        b[i] = fill;
    *a = b;
    return 0;
}

int aero_vortex_set_count(aero_vortex *m, int n)
{
    int old = m->n;
    if (n < AERO_VORTEX_MIN_SOURCES || n > AERO_VORTEX_MAX_SOURCES)
        return -1;
    if (n > old) {
        if (grow(&m->pos, old, n, 0.0) || grow(&m->speed, old, n, 0.0) ||
            grow(&m->speed_target, old, n, 0.0) ||
            grow(&m->xyz, 3 * old, 3 * n, 0.0) ||
            grow(&m->xyz_target, 3 * old, 3 * n, 0.0) ||
            grow(&m->dist, 2 * old, 2 * n, -1.0) ||
            grow(&m->rd, 2 * old, 2 * n, 0.0))
            return -1;
        m->n = n;
        randomise_offsets(m, old);
    } else {
        m->n = n;
    }
    return 0;
}

static void start_ramp(aero_vortex *m)
{
    m->ramp_left = m->ramp_samples;
}

int aero_vortex_set_speeds(aero_vortex *m, const double *u,
                           int count)
{
    if (count < 1 || count > m->n)
        return -1;
    for (int i = 0; i < count; i++)
        if (!(u[i] >= AERO_VORTEX_SPEED_MIN && u[i] <= AERO_VORTEX_SPEED_MAX))
            return -1;
    for (int i = 0; i < count; i++)
        m->speed_target[i] = u[i];
    start_ramp(m);
    return 0;
}

int aero_vortex_set_positions(aero_vortex *m,
                              const double *xyz, int count)
{
    if (count < 1 || count > m->n ||
        !aero_finite_within(xyz, 3 * count, AERO_POSITION_LIMIT))
        return -1;
    memcpy(m->xyz_target, xyz, sizeof(double) * 3 * (size_t)count);
    if (!m->started) /* nothing heard yet: the scene is set, not moved */
        memcpy(m->xyz, xyz, sizeof(double) * 3 * (size_t)count);
    start_ramp(m);
    return 0;
}

int aero_vortex_set_ears(aero_vortex *m, const aero_ears *e)
{
    if (!aero_ears_ok(e, 2))
        return -1;
    for (int k = 0; k < 2; k++) /* one listener: both ears there */
        memcpy(m->ear_target + 3 * k, e->pos[e->n == 2 ? k : 0],
               sizeof(double) * 3);
    if (!m->started) /* nothing heard yet: the ears start there (gliding
                        from the default, they crossed the sources) */
        memcpy(m->ear, m->ear_target, sizeof(double) * 6);
    start_ramp(m);
    return 0;
}

int aero_vortex_set_gain_db(aero_vortex *m, double db)
{
    if (!(db >= AERO_GAIN_DB_MIN && db <= AERO_VORTEX_GAIN_DB_MAX))
        return -1;
    m->gain_target = pow(10.0, db / 20.0);
    start_ramp(m);
    return 0;
}

int aero_vortex_set_clip(aero_vortex *m, double pa)
{
    if (!(pa >= AERO_VORTEX_CLIP_MIN && pa <= AERO_VORTEX_CLIP_MAX))
        return -1;
    m->clip = pa;
    return 0;
}

int aero_vortex_set_ramp_ms(aero_vortex *m, double ms)
{
    if (!(ms >= AERO_RAMP_MS_MIN && ms <= AERO_RAMP_MS_MAX))
        return -1;
    m->ramp_samples = ms * 0.001 * m->sample_rate;
    if (m->ramp_samples < 1.0)
        m->ramp_samples = 1.0;
    return 0;
}

int aero_vortex_set_falloff(aero_vortex *m, int exponent)
{
    if (exponent != AERO_VORTEX_FALLOFF_MIN &&
        exponent != AERO_VORTEX_FALLOFF_MAX)
        return -1;
    m->falloff = exponent;
    return 0;
}

int aero_vortex_set_power_kw(aero_vortex *m, double kw)
{
    return aero_combustion_set_power_kw(&m->combustion, kw);
}

int aero_vortex_set_flame_length(aero_vortex *m, double l)
{
    return aero_combustion_set_length(&m->combustion, l);
}

int aero_vortex_set_strouhal(aero_vortex *m, double st)
{
    return aero_combustion_set_strouhal(&m->combustion, st);
}

int aero_vortex_set_fluctuation(aero_vortex *m, double eps)
{
    return aero_combustion_set_fluctuation(&m->combustion, eps);
}

int aero_vortex_set_seed(aero_vortex *m, uint32_t seed)
{
    m->rng = seed ? seed : 1;
    aero_combustion_set_seed(&m->combustion, m->rng ^ 0x9e3779b9u);
    randomise_offsets(m, 0);
    for (int i = 0; i < 2 * m->n; i++)
        m->dist[i] = -1.0; /* read positions restart from the offsets */
    return 0;
}

int aero_vortex_set_texture(aero_vortex *m, aero_texture *t,
                            char *err, size_t errlen)
{
    float *tab = NULL;
    if (t) {
        int F = t->frames, ns = t->channels;
        if (aero_texture_wrong_kind(t, "vortex", err, errlen))
            return -1;
        if (!t->speeds) {
            snprintf(err, errlen, "a vortex texture without speeds");
            return -1;
        }
        if (F < 4 || ns < 1 || !(t->rate > 0.0)) {
            snprintf(err, errlen, "texture too short or without a rate");
            return -1;
        }
        tab = malloc(sizeof(float) * (size_t)ns * (F + PAD_BEFORE + PAD_AFTER));
        if (!tab) {
            snprintf(err, errlen, "out of memory");
            return -1;
        }
        for (int c = 0; c < ns; c++) {
            float *d = tab + (size_t)c * (F + PAD_BEFORE + PAD_AFTER);
            for (int k = -PAD_BEFORE; k < F + PAD_AFTER; k++) {
                int src = ((k % F) + F) % F;
                d[k + PAD_BEFORE] = t->data[(size_t)src * ns + c];
            }
        }
    }
    if (m->texture) {
        aero_texture_free(m->texture);
        free(m->texture);
    }
    free(m->tab);
    m->texture = t;
    m->tab = tab;
    if (t) {
        /* keep each source's phase within the loop */
        double old = m->frames > 0 ? m->frames : 1.0;
        for (int i = 0; i < m->n; i++)
            m->pos[i] = fmod(fabs(m->pos[i]) / old, 1.0) * t->frames;
        for (int i = 0; i < 2 * m->n; i++)
            m->rd[i] = fmod(fabs(m->rd[i]) / old, 1.0) * t->frames;
        m->frames = t->frames;
        m->nspeeds = t->channels;
        m->speeds = t->speeds;
        m->rate = t->rate;
    } else {
        for (int i = 0; i < m->n; i++)
            m->pos[i] = m->frames > 0 ? m->pos[i] / m->frames : m->pos[i];
        m->frames = 0;
        m->nspeeds = 0;
        m->speeds = NULL;
        m->rate = 0.0;
    }
    return 0;
}

/* the channel pair and weights of speed u: value = wa Q_c + wb Q_c+1 */
static void speed_weights(const aero_vortex *m, double u, int c,
                          double *wa, double *wb)
{
    const double *s = m->speeds;
    const int ns = m->nspeeds;
    if (u <= s[0] && c == 0) {
        double q = u / s[0];
        q *= q;
        *wa = q * q; /* quadrupole: p ~ u^4 */
        *wb = 0.0;
        return;
    }
    if (ns == 1) {
        *wa = 1.0;
        *wb = 0.0;
        return;
    }
    {
        double f = (u - s[c]) / (s[c + 1] - s[c]);
        if (f < 0.0) f = 0.0;
        if (f > 1.0) f = 1.0;
        *wa = 1.0 - f;
        *wb = f;
    }
}

/* index c of the pair (c, c+1) holding u (0 below, ns-2 above) */
static int speed_pair(const aero_vortex *m, double u)
{
    int c = 0;
    if (m->nspeeds < 2)
        return 0;
    while (c < m->nspeeds - 2 && u >= m->speeds[c + 1])
        c++;
    return c;
}

static double clean_speed(double u, int *clamped)
{
    if (!(u == u)) return 0.0;
    u = fabs(u);
    if (u > AERO_MACH_LIMIT * AERO_C0) {
        *clamped = 1;
        u = AERO_MACH_LIMIT * AERO_C0;
    }
    return u;
}

static double distance(const double *a, const double *b)
{
    double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

/* Catmull-Rom through p[0..3], between p[1] and p[2] */
static inline float cubic(const float *p, float f)
{
    return aero_catmull_rom(p[0], p[1], p[2], p[3], f);
}

/* the speed inlet at the block's ends (read before any output is
   written: the buffers may be shared); 1 if any sample was clamped */
static int read_inlet(const float *speed, int n, double *u_first,
                      double *u_last)
{
    int clamped = 0;
    *u_first = speed ? clean_speed(speed[0], &clamped) : 0.0;
    *u_last = speed ? clean_speed(speed[n - 1], &clamped) : 0.0;
    if (speed)
        for (int k = 1; k < n - 1; k++)
            if (fabs(speed[k]) > AERO_MACH_LIMIT * AERO_C0) clamped = 1;
    return clamped;
}

/* what one block's sources share */
typedef struct {
    int n, nout, frames, stride;
    double step;   /* texture frames per sample */
    double delay;  /* texture frames per m */
    double sound;  /* 1 / (m per sample of c0) */
    double inv_n;
    double frac;   /* of the ramps, over this block */
    double ear0[6]; /* the ears at the block's start */
} block;

/* adds n samples of texture channels qa, qb read from s0 in steps of ds,
   weights w (wa, wb at the start, then at the end) and gain g0 -> g1
   interpolated per sample, into o */
static void add_texture(const block *b, const float *qa, const float *qb,
                        double s0, double ds, const double w[4], double g0,
                        double g1, float *o)
{
    const int F = b->frames, n = b->n;
    const float dwa = (float)((w[2] - w[0]) * b->inv_n),
                dwb = (float)((w[3] - w[1]) * b->inv_n),
                dg = (float)((g1 - g0) * b->inv_n);
    float wa = (float)w[0], wb = (float)w[1], g = (float)g0;
    double s = s0;
    for (int k = 0; k < n; k++) {
        int idx;
        float f;
        if (s >= F) s -= F;
        else if (s < 0.0) s += F;
        idx = (int)s;
        if (idx >= F) idx = F - 1; /* rounding */
        f = (float)(s - idx);
        o[k] += g * (wa * cubic(qa + idx, f) + wb * cubic(qb + idx, f));
        s += ds;
        wa += dwa;
        wb += dwb;
        g += dg;
    }
}

/* source i heard at ear e: the retarded read position moves at the
   Doppler rate of both motions; adds the block into o */
static void render_ear(aero_vortex *m, const block *b, int i, int e,
                       int c, const double w[4], float *o)
{
    const int F = b->frames;
    /* r1 now; rs: had only the source moved (the ear where it was at the
       block's start) */
    double r1 = distance(m->xyz + 3 * i, m->ear + 3 * e);
    double rs = distance(m->xyz + 3 * i, b->ear0 + 3 * e);
    double r0 = m->dist[2 * i + e];
    double g0, g1, s0, ds, vs, vl;
    const float *qa = m->tab + (size_t)c * b->stride;
    const float *qb = m->nspeeds > 1 ? qa + b->stride : qa;
    if (r1 < m->r_min) { /* the near-field policy (aero_near_field) */
        aero_near_seen(&m->near, m->r_min);
        r1 = m->r_min;
    }
    if (rs < m->r_min) rs = m->r_min;
    if (r0 < 0.0) {
        /* first block: start at the source's offset, delayed by the
           distance, with no jump */
        r0 = r1;
        rs = r1;
        m->rd[2 * i + e] = m->pos[i] - r1 * b->delay;
    }
    m->dist[2 * i + e] = r1;
    /* the rates of change of r from each motion, in units of c0 (m per
       sample / (c0 / sr)) */
    vs = (rs - r0) * b->inv_n * b->sound;
    vl = (r1 - rs) * b->inv_n * b->sound;
    if (vs < -0.9) vs = -0.9; /* a jump, not a motion */
    if (vs > 10.0) vs = 10.0;
    if (vl > 0.9) vl = 0.9;
    if (vl < -10.0) vl = -10.0;
    ds = b->step * (1.0 - vl) / (1.0 + vs);
    s0 = fmod(m->rd[2 * i + e], (double)F);
    if (s0 < 0.0) s0 += F;
    m->rd[2 * i + e] = fmod(s0 + b->n * ds, (double)F);
    if (w[0] == 0.0 && w[1] == 0.0 && w[2] == 0.0 && w[3] == 0.0)
        return;
    g0 = 1.0 / r0;
    g1 = 1.0 / r1;
    if (m->falloff == 3) {
        g0 *= g0 * g0;
        g1 *= g1 * g1;
    }
    add_texture(b, qa, qb, s0, ds, w, g0, g1, o);
}

/* source i over the block: its speed's channel pair and weights at both
   ends, its position, then each ear */
static void render_source(aero_vortex *m, const block *b, int i,
                          double u_in0, double u_in1, float *const *out)
{
    double u0 = u_in0 + m->speed[i], u1, w[4];
    int c;
    aero_glide_values(m->speed + i, m->speed_target + i, 1, b->frac);
    u1 = u_in1 + m->speed[i];
    if (u1 > AERO_MACH_LIMIT * AERO_C0) u1 = AERO_MACH_LIMIT * AERO_C0;
    if (u0 > AERO_MACH_LIMIT * AERO_C0) u0 = AERO_MACH_LIMIT * AERO_C0;
    c = speed_pair(m, u1);
    speed_weights(m, u0, c, &w[0], &w[1]);
    speed_weights(m, u1, c, &w[2], &w[3]);
    aero_glide_values(m->xyz + 3 * i, m->xyz_target + 3 * i, 3, b->frac);
    for (int e = 0; e < b->nout; e++)
        render_ear(m, b, i, e, c, w, out[e]);
    m->pos[i] += b->n * b->step;
    if (m->pos[i] >= b->frames)
        m->pos[i] = fmod(m->pos[i], (double)b->frames);
}

/* the flame's roar: a monopole at the volumes' centre, at their mean
   speed */
static void add_combustion(aero_vortex *m, double u_in, int nout,
                           float *const *out, int n)
{
    double c[3] = {0.0, 0.0, 0.0}, u = 0.0;
    if (m->n < 1) /* after a failed init: no volumes, no flame */
        return;
    for (int i = 0; i < m->n; i++) {
        for (int k = 0; k < 3; k++) c[k] += m->xyz[3 * i + k];
        u += u_in + m->speed[i];
    }
    for (int k = 0; k < 3; k++) c[k] /= m->n;
    u /= m->n;
    if (u > AERO_MACH_LIMIT * AERO_C0) u = AERO_MACH_LIMIT * AERO_C0;
    aero_combustion_process(&m->combustion, u, c, m->ear, nout, out, n);
}

/* microphone limit (on the pressure), then the gain; no NaN leaves */
static void limit_and_gain(aero_vortex *m, double frac, int nout,
                           float *const *out, int n)
{
    double g1 = m->gain + (m->gain_target - m->gain) * frac;
    const float dg = (float)((g1 - m->gain) / n);
    for (int e = 0; e < nout; e++) {
        float *o = out[e];
        const float lim = (float)m->clip;
        float g = (float)m->gain;
        for (int k = 0; k < n; k++, g += dg) {
            float v = o[k];
            if (!(v == v)) v = 0.0f;
            if (lim > 0.0f) {
                if (v > lim) v = lim;
                if (v < -lim) v = -lim;
            }
            v *= g;
            if (v > 1e30f) v = 1e30f;
            if (v < -1e30f) v = -1e30f;
            o[k] = v;
        }
    }
    m->gain = g1;
}

int aero_vortex_process(aero_vortex *m, const float *speed,
                        float *const *out, int n)
{
    const int nout = m->stereo ? 2 : 1;
    double u_in0, u_in1, frac;
    if (n <= 0)
        return 0;
    m->started = 1;
    int clamped = read_inlet(speed, n, &u_in0, &u_in1);
    for (int e = 0; e < nout; e++)
        memset(out[e], 0, sizeof(float) * (size_t)n);

    /* the controls at the end of this block */
    frac = aero_glide_fraction(&m->ramp_left, n);
    if (!m->tab) {
        aero_glide_values(m->ear, m->ear_target, 6, frac);
        for (int i = 0; i < m->n; i++) {
            aero_glide_values(m->speed + i, m->speed_target + i, 1, frac);
            aero_glide_values(m->xyz + 3 * i, m->xyz_target + 3 * i, 3,
                              frac);
            m->dist[2 * i] = m->dist[2 * i + 1] = -1.0;
        }
    } else {
        block b = {n, nout, m->frames, m->frames + PAD_BEFORE + PAD_AFTER,
                   m->rate / m->sample_rate, m->rate / AERO_C0,
                   m->sample_rate / AERO_C0, 1.0 / n, frac, {0}};
        memcpy(b.ear0, m->ear, sizeof b.ear0);
        aero_glide_values(m->ear, m->ear_target, 6, frac);
        for (int i = 0; i < m->n; i++)
            render_source(m, &b, i, u_in0, u_in1, out);
    }
    add_combustion(m, u_in1, nout, out, n);
    limit_and_gain(m, frac, nout, out, n);
    return clamped;
}
