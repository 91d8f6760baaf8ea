/* aero: [cavity~]'s model mode: the Rossiter tones, their lock-in onto the
 * depth modes and the shear layer's noise, rendered in four lanes (see
 * cavity.h; the object and its settings: cavity.c). */
#include "cavity_internal.h"

#include "aero_air.h"
#include "aero_lanes.h"
#include "aero_util.h"

#include <math.h>
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

/* x - floor(x), in [0, 1): without a libm call where |x| < 2^62 (every
 * phase a control can make); beyond, where the int64 cast would overflow
 * (a hostile speed can pull a locked tone's factor that far), floor, and 0
 * for what is not finite */
static double wrap_cycles(double x)
{
    if (!(fabs(x) < 0x1p62)) {
        double f = x - floor(x);
        return f >= 0.0 && f < 1.0 ? f : 0.0;
    }
    double t = (double)(int64_t)x;
    t -= t > x;
    return x - t;
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

/* Geometry, listener and level laws, when a control or the exponent has
 * moved: the depth modes and, per Rossiter mode, the unlocked tone
 * amplitude per U^n at ear 0; each other ear hears it at its own
 * distance (1/r). */
static void update_laws(aero_cavity *m)
{
    double l = m->ctl[AERO_CAV_LENGTH], d = m->ctl[AERO_CAV_DEPTH];
    double w = m->ctl[AERO_CAV_WIDTH];
    for (int j = 0; j < AERO_CAVITY_DEPTH_MODES; j++) {
        m->depth_hz[j] = aero_cavity_depth_hz(d, l, w, j + 1);
        m->lock_scale[j] = 1.0 / (LOCK_WIDTH * m->depth_hz[j]);
    }
    double weight_sum = 0;
    for (int k = 0; k < AERO_CAVITY_MODES; k++)
        weight_sum += mode_weight[k] * mode_weight[k];
    /* p_rms = LEVEL (rho/2) U_ref^(2-n) U^n sqrt(L W) / r; the tones share
     * it by their weights (sqrt 2: rms -> amplitude) */
    double r = aero_cavity_ear_distance(m, 0, sqrt(l * w));
    m->level = LEVEL * 0.5 * AERO_RHO * pow(REFERENCE_SPEED, 2.0 - m->exponent) *
               sqrt(l * w) / r * m->ctl[AERO_CAV_GAIN];
    for (int k = 0; k < AERO_CAVITY_MODES; k++)
        m->mode_level[k] = m->level * sqrt(2.0) * mode_weight[k] / sqrt(weight_sum);
    m->ear_scale[0] = 1.0;
    for (int e = 1; e < m->n_ears; e++)
        m->ear_scale[e] = r / aero_cavity_ear_distance(m, e, sqrt(l * w));
    m->laws_dirty = 0;
}

/* A chunk is rendered as LANES lanes of T = ceil(n / LANES) consecutive
 * samples each (lane j holds samples T j .. T j + T - 1), so that every
 * per-sample recursion runs on LANES samples at once: the tones by the
 * two-term recurrence s[t+1] = 2 cos(w) s[t] - s[t-1], started per lane from
 * its exact phase, and the noise's one-pole filters from zero per lane,
 * then corrected by the true start state carried from lane to lane. */
enum { LANES = AERO_LANES, CHUNK = AERO_CAVITY_CHUNK,
       LANE_MAX = CHUNK / LANES };
/* the largest per-sample phase step (cycles, uniform amplitude) within a
   lane, where the coefficient's linear expansion (below) holds */
#define MAX_STEP 0.01

/* one chunk of model mode in lanes: the tones' recurrences (started per
 * lane from its exact phase), the per-sample phase steps, the noise band's
 * filters run from zero per lane and the start states that correct them */
typedef struct {
    int n, len, jl, tl;  /* samples, lane length T, the lane and place of
                            the chunk's last sample */
    double gain_end[AERO_CAVITY_MODES], width[AERO_CAVITY_MODES];
    double end[AERO_CAVITY_MODES]; /* each tone's phase at sample n - 1 */
    lane4 prev[AERO_CAVITY_MODES], cur[AERO_CAVITY_MODES];
    lane4 coef[AERO_CAVITY_MODES], slope[AERO_CAVITY_MODES];
    lane4 kick[AERO_CAVITY_MODES];
    lane4 e[LANE_MAX];   /* per-sample phase steps, shared by the modes */
    double noise_scale;
    lane4 z1[LANE_MAX], z2[LANE_MAX], c1, c2;
    float k1[LANE_MAX], k2[LANE_MAX];
} model_chunk;

/* The Rossiter frequencies at the chunk's end speed (Rossiter 1964), each
 * pulled onto a depth mode it comes near (lock-in) and growing there; a
 * locked tone is purer: its line narrows as it grows */
static void lock_in(aero_cavity *m, double u_end, model_chunk *ch)
{
    enum { K = AERO_CAVITY_MODES };
    const double l = m->ctl[AERO_CAV_LENGTH];
    double inv = 1.0 / (l * (u_end / AERO_C0 + 1.0 / ROSSITER_KAPPA));
    for (int k = 0; k < K; k++) {
        double factor = (k + 1 - ROSSITER_ALPHA) * inv;
        double fk = factor * u_end, lock = 0, best = 0, pulled = fk;
        for (int j = 0; j < AERO_CAVITY_DEPTH_MODES; j++) {
            double fd = m->depth_hz[j];
            double x = (fk - fd) * m->lock_scale[j], x2 = x * x;
            /* 1 / (1 + x^2) and 1 / (1 + x^4) from one division */
            double r = 1.0 / ((1.0 + x2) * (1.0 + x2 * x2));
            double near = (1.0 + x2 * x2) * r, pull = (1.0 + x2) * r;
            lock = near > lock ? near : lock;
            /* the locked tone's frequency holds on the depth mode
               (aero_cavity_locked_hz) */
            if (pull > best)
                best = pull, pulled = fk - (fk - fd) * pull;
        }
        double grow = 1.0 + LOCK_GAIN * lock;
        m->freq_factor[k] = fk > 0.0 ? factor * pulled / fk : factor;
        ch->gain_end[k] = m->mode_level[k] * grow;
        ch->width[k] = TONE_WIDTH * fk / grow;
    }
}

/* Within a lane the phase still wanders per sample: the recurrence's
 * coefficient 2 cos(2 pi w) moves by -4 pi sin(2 pi w) e_t, e_t the
 * per-sample step, so the lines keep their Lorentzian tails beyond
 * sr / (2 T). The steps (uniform) are shared by the modes, whose lines
 * lie apart, and sum to 0 over a lane (a bridge: the lane still ends
 * on its phase). A wider line's steps above MAX_STEP cycles are kept
 * only in the lane steps. The linear coefficient exceeds the exact one
 * by (2 pi x)^2 cos(2 pi w) at most (x = step e_t, |e_t| < 2), so a
 * lane of T samples can grow by at most (1 + 4 pi MAX_STEP)^T, and
 * each lane starts again from its exact phase and level. */
static void phase_steps(lane4u *rng, model_chunk *ch)
{
    const int len = ch->len;
    lane4 mean = l4_splat(0.0f);
    for (int t = 0; t < len; t++)
        mean = l4_add(mean, ch->e[t] = l4_uniform(rng));
    mean = l4_mul(mean, l4_splat(1.0f / len));
    for (int t = 0; t < len; t++)
        ch->e[t] = l4_sub(ch->e[t], mean);
}

/* The tones. Each lane j (samples T j .. T j + T - 1) has its own
 * frequency w_j = w + s_j / T, s_j the phase's random step over the
 * lane, so the phase walks at every lane boundary (a frequency noise
 * constant over T samples, whose line keeps its Lorentzian shape out
 * to sr / (2 T) from the tone). Sample T j + t sounds at phase
 * P_j + w_j (t + 1), P_j = p + sum_{j' < j} w_j' T, p the phase after
 * the last chunk (m->phasor). */
static void start_tones(aero_cavity *m, double u_mean, lane4u *rng,
                        model_chunk *ch)
{
    enum { K = AERO_CAVITY_MODES };
    const double sr = m->sample_rate;
    const int len = ch->len, n = ch->n;
    for (int k = 0; k < K; k++) {
        double w = wrap_cycles(m->freq_factor[k] * u_mean / sr);
        double sd = sqrt(0.75 * ch->width[k] * len / (2.0 * AERO_PI * sr)) /
                    len;
        /* the lanes' steps, near-Gaussian (four uniforms each) */
        lane4 g = l4_add(l4_add(l4_uniform(rng), l4_uniform(rng)),
                         l4_add(l4_uniform(rng), l4_uniform(rng)));
        double offset = 0.0;
        lane4 wl, ol;
        for (int j = 0; j < LANES; j++) {
            double wj = wrap_cycles(w + sd * l4_get(g, j));
            l4_set(&wl, j, (float)wj);
            l4_set(&ol, j, (float)offset); /* < LANES T: no wrap needed */
            if (j == ch->jl)
                ch->end[k] = offset + wj * (ch->tl + 1);
            offset += wj * len;
        }
        /* the lanes in float: each restarts from its exact phase */
        lane4 cw, sw, co, so;
        l4_cis(wl, &cw, &sw);
        l4_cis(ol, &co, &so);
        /* the gain glides from g0 to g1 over the chunk: the lanes carry
           g0, the slope (g1 - g0) / (g0 n) per sample multiplies later */
        double g0 = m->mode_gain[k], g1 = ch->gain_end[k];
        ch->slope[k] = l4_splat(g0 > 0.0 ? (float)((g1 - g0) / (g0 * n))
                                         : 0.0f);
        if (!(g0 > 0.0))
            g0 = g1;
        m->mode_gain[k] = g1;
        /* z = g0 e^{i 2 pi P_j}: sample T j - 1; one step of w_j on */
        lane4 pc = l4_splat((float)(g0 * m->phasor[k][0]));
        lane4 ps = l4_splat((float)(g0 * m->phasor[k][1]));
        lane4 zc = l4_sub(l4_mul(pc, co), l4_mul(ps, so));
        lane4 zs = l4_add(l4_mul(pc, so), l4_mul(ps, co));
        ch->prev[k] = zs;
        ch->cur[k] = l4_add(l4_mul(zc, sw), l4_mul(zs, cw));
        ch->coef[k] = l4_add(cw, cw);
        double step = sqrt(3.0 * ch->width[k] / (2.0 * AERO_PI * sr));
        step = step < MAX_STEP ? step : MAX_STEP;
        ch->kick[k] = l4_mul(sw, l4_splat((float)(-4.0 * AERO_PI * step)));
    }
}

/* the phase after this chunk, kept on the unit circle (one Newton step
   of 1 / |z|: |z| is 1 to rounding); its step from the four modes'
   float cosines and sines at once (their rounding, ~1e-5 cycles, is
   far below the phase's own random step per chunk) */
static void advance_phasors(aero_cavity *m, const double *end)
{
    enum { K = AERO_CAVITY_MODES };
    lane4 ev, cv, sv;
    for (int k = 0; k < K; k++)
        l4_set(&ev, k, (float)end[k]);
    l4_cis(ev, &cv, &sv);
    for (int k = 0; k < K; k++) {
        const double *p0 = m->phasor[k];
        double c = l4_get(cv, k), sn = l4_get(sv, k);
        double zc = p0[0] * c - p0[1] * sn, zs = p0[0] * sn + p0[1] * c;
        double norm = 1.5 - 0.5 * (zc * zc + zs * zs);
        m->phasor[k][0] = zc * norm, m->phasor[k][1] = zs * norm;
    }
}

/* the white noise of each lane through both filters from zero */
static void filter_noise_lanes(aero_cavity *m, double a1, double a2,
                               double p1, double p2, model_chunk *ch)
{
    const lane4 af1 = l4_splat((float)a1), pf1 = l4_splat((float)p1);
    const lane4 af2 = l4_splat((float)a2), pf2 = l4_splat((float)p2);
    lane4 y1 = l4_splat(0.0f), y2 = y1;
    lane4u white;
    memcpy(&white, m->noise_rng, sizeof(white));
    for (int t = 0; t < ch->len; t++) {
        y1 = l4_add(l4_mul(pf1, y1), l4_mul(af1, l4_uniform(&white)));
        y2 = l4_add(l4_mul(pf2, y2), l4_mul(af2, y1));
        ch->z1[t] = y1, ch->z2[t] = y2;
    }
    memcpy(m->noise_rng, &white, sizeof(white));
}

/* the start-state responses per t, the carries lane to lane (c1, c2),
   and the states at sample n - 1 for the next chunk */
static void carry_noise_states(aero_cavity *m, double a2, double p1,
                               double p2, model_chunk *ch)
{
    const int len = ch->len, jl = ch->jl, tl = ch->tl;
    double pw1[LANE_MAX], pw2[LANE_MAX], h[LANE_MAX];
    double q1 = 1.0, q2 = 1.0, hh = 0.0;
    for (int t = 0; t < len; t++) {
        q1 *= p1, q2 *= p2;
        hh = p2 * hh + q1;
        pw1[t] = q1, pw2[t] = q2, h[t] = hh;
        /* the band's share: y1 - y2 */
        ch->k1[t] = (float)(q1 - a2 * hh), ch->k2[t] = (float)q2;
    }
    double s1 = m->noise_state[0], s2 = m->noise_state[1];
    double e1 = pw1[len - 1], e2 = pw2[len - 1], eh = a2 * h[len - 1];
    for (int j = 0; j < LANES; j++) {
        l4_set(&ch->c1, j, (float)s1), l4_set(&ch->c2, j, (float)s2);
        double n1 = l4_get(ch->z1[len - 1], j) + e1 * s1;
        s2 = l4_get(ch->z2[len - 1], j) + eh * s1 + e2 * s2;
        s1 = n1;
    }
    double cl1 = l4_get(ch->c1, jl), cl2 = l4_get(ch->c2, jl);
    s1 = l4_get(ch->z1[tl], jl) + pw1[tl] * cl1;
    s2 = l4_get(ch->z2[tl], jl) + a2 * h[tl] * cl1 + pw2[tl] * cl2;
    m->noise_state[0] = fabs(s1) < 1e-20 ? 0.0 : s1; /* no denormals */
    m->noise_state[1] = fabs(s2) < 1e-20 ? 0.0 : s2;
}

/* Shear-layer noise: white noise between two one-pole low-passes at
 * f_1 / 2 and 4 f_4 (y1 = LP_hi(white), y2 = LP_lo(y1), the band
 * y1 - y2), scaled to NOISE_LEVEL of the tones. Each lane runs both
 * filters from zero (z1, z2, together); the true start states C1, C2
 * of a lane, carried from the one before, add p1^(t+1) C1 to y1 and
 * a2 h[t] C1 + p2^(t+1) C2 to y2, h[t] = sum_m p2^(t-m) p1^(m+1) (the
 * low filter's response to the high one's decaying start). */
static void noise_band(aero_cavity *m, double u_end, model_chunk *ch)
{
    enum { K = AERO_CAVITY_MODES };
    const double sr = m->sample_rate;
    double f_lo = 0.5 * m->freq_factor[0] * u_end,
           f_hi = 4.0 * m->freq_factor[K - 1] * u_end;
    double a1 = 1.0 - exp(-2.0 * AERO_PI * fmin(f_hi, 0.4 * sr) / sr);
    double a2 = 1.0 - exp(-2.0 * AERO_PI * fmin(f_lo, 0.4 * sr) / sr);
    double p1 = 1.0 - a1, p2 = 1.0 - a2;
    ch->noise_scale = a1 > 1e-9 ? NOISE_LEVEL * m->level /
                                      sqrt((1.0 / 3.0) * a1 / (2.0 - a1))
                                : 0.0;
    filter_noise_lanes(m, a1, a2, p1, p2, ch);
    carry_noise_states(m, a2, p1, p2, ch);
}

/* per sample: the recurrences, the gain slopes, the noise band; written
   to sum in sample order (the recurrences in locals: the stores to sum
   cannot touch them) */
static void sum_lanes(const model_chunk *ch, float *sum)
{
    enum { K = AERO_CAVITY_MODES };
    const int len = ch->len;
    lane4 prev[K], cur[K];
    memcpy(prev, ch->prev, sizeof(prev));
    memcpy(cur, ch->cur, sizeof(cur));
    const lane4 ns = l4_splat((float)ch->noise_scale);
    const lane4 c1 = l4_mul(ch->c1, ns), c2 = l4_mul(ch->c2, ns);
    lane4 index;
    for (int j = 0; j < LANES; j++)
        l4_set(&index, j, (float)(len * j + 1));
    for (int t = 0; t < len; t++) {
        lane4 s1 = l4_splat(0.0f), s2 = s1;
        for (int k = 0; k < K; k++) {
            lane4 y = cur[k];
            s1 = l4_add(s1, y);
            s2 = l4_add(s2, l4_mul(ch->slope[k], y));
            lane4 c = l4_add(ch->coef[k], l4_mul(ch->kick[k], ch->e[t]));
            cur[k] = l4_sub(l4_mul(c, y), prev[k]);
            prev[k] = y;
        }
        lane4 band = l4_add(l4_mul(ns, l4_sub(ch->z1[t], ch->z2[t])),
                            l4_sub(l4_mul(l4_splat(ch->k1[t]), c1),
                                   l4_mul(l4_splat(ch->k2[t]), c2)));
        lane4 v = l4_add(l4_add(s1, l4_mul(index, s2)), band);
        index = l4_add(index, l4_splat(1.0f));
        for (int j = 0; j < LANES; j++)
            sum[len * j + t] = l4_get(v, j);
    }
}

/* the level's speed law U^n: per sample for n = 2, else once per chunk,
   gliding linearly over it */
static void speed_law(aero_cavity *m, const float *u, const float *sum,
                      float *out, int n, double u_end)
{
    if (m->exponent == 2.0) {
        for (int i = 0; i < n; i++)
            out[i] = sum[i] * (u[i] * u[i]);
        return;
    }
    double q = pow(u_end, m->exponent);
    if (!m->primed)
        m->speed_power = q;
    const float q0 = (float)m->speed_power;
    const float dq = (float)((q - m->speed_power) / n);
    for (int i = 0; i < n; i++)
        out[i] = sum[i] * (q0 + dq * (float)(i + 1));
    m->speed_power = q;
}

/* Model mode, one chunk of n <= CHUNK samples. Per chunk: the Rossiter
 * frequencies (from the chunk's mean speed, so the phase reaches the same
 * point as with the speed per sample), the lock-in, the gains, the noise
 * filters, each tone's random phase step (a Lorentzian line of width B
 * wanders by B n / (2 pi sr) cycles^2 per chunk, drawn near-Gaussian: the
 * sum of four uniforms, as the per-sample steps it replaces add up to);
 * per sample the four recurrences, the white noise and its two filters, in
 * float. */
void aero_cavity_model_process(aero_cavity *m, const float *u,
                               float *const *out, int n, double u_mean,
                               double u_end)
{
    model_chunk ch;
    float sum[LANES * LANE_MAX];
    lane4u rng;
    if (m->laws_dirty)
        update_laws(m);
    ch.n = n;
    ch.len = (n + LANES - 1) / LANES;
    ch.jl = (n - 1) / ch.len;
    ch.tl = (n - 1) % ch.len;
    lock_in(m, u_end, &ch);
    if (!m->primed)
        memcpy(m->mode_gain, ch.gain_end, sizeof(ch.gain_end));
    memcpy(&rng, m->tone_rng, sizeof(rng));
    phase_steps(&rng, &ch);
    start_tones(m, u_mean, &rng, &ch);
    memcpy(m->tone_rng, &rng, sizeof(rng));
    advance_phasors(m, ch.end);
    noise_band(m, u_end, &ch);
    sum_lanes(&ch, sum);
    speed_law(m, u, sum, out[0], n, u_end);
    /* the other ear: the same field at its own distance */
    for (int e = 1; e < m->n_ears; e++) {
        const float scale = (float)m->ear_scale[e];
        for (int i = 0; i < n; i++)
            out[e][i] = out[0][i] * scale;
    }
}
