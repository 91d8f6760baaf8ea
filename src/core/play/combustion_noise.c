/* aero: combustion noise of a flame, a monopole of the unsteady heat
 * release (see combustion_noise.h). */
#include "combustion_noise.h"
#include "aero_air.h"
#include "aero_util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* the tilt's pole-zero pairs in x = f / f_p: poles at TILT_START 10^k,
   zeros a quarter decade above (an average slope of -0.25 in amplitude,
   -0.5 in power, over each decade) */
#define TILT_START 1.5
#define TILT_RATIO 1.7782794100389228 /* 10^0.25 */

/* |H(x)|^2 of the analogue prototype: Butterworth 1 / (1 + x^4) times the
   tilt pairs (1 + (x/z)^2) / (1 + (x/p)^2) */
static double prototype_power(double x)
{
    double x2 = x * x, h = 1.0 / (1.0 + x2 * x2), p = TILT_START;
    for (int k = 0; k < AERO_COMBUSTION_TILTS; k++, p *= 10.0) {
        double z = p * TILT_RATIO;
        h *= (1.0 + x2 / (z * z)) / (1.0 + x2 / (p * p));
    }
    return h;
}

/* INT x^m |H(x)|^2 dx over 1e-4..1e6 (log-spaced trapezoids) */
static double prototype_moment(int m)
{
    const int per_decade = 200, decades = 10;
    double sum = 0.0, prev = 0.0, xprev = 0.0;
    for (int i = 0; i <= per_decade * decades; i++) {
        double x = pow(10.0, -4.0 + (double)i / per_decade);
        double v = (m == 2 ? x * x : 1.0) * prototype_power(x);
        if (i > 0)
            sum += 0.5 * (v + prev) * (x - xprev);
        prev = v;
        xprev = x;
    }
    return sum;
}

double aero_combustion_kappa(void)
{
    return sqrt(prototype_moment(2) / prototype_moment(0));
}

double aero_combustion_monopole(double dqdt, double r)
{
    return (AERO_COMBUSTION_GAMMA - 1.0) * dqdt /
           (4.0 * AERO_PI * AERO_C0 * AERO_C0 * r);
}

double aero_combustion_peak_hz(const aero_combustion *m, double u)
{
    double f = m->strouhal * fabs(u) / m->length;
    double fmax = 0.2 * m->sample_rate;
    if (!(f >= 1.0)) f = 1.0; /* also NaN */
    if (f > fmax) f = fmax;
    return f;
}

double aero_combustion_rms_law(const aero_combustion *m, double u, double r)
{
    double fp = aero_combustion_peak_hz(m, u);
    return aero_combustion_monopole(m->fluctuation * m->power * 2.0 * AERO_PI *
                                        fp * aero_combustion_kappa(),
                                    r);
}

static int alloc_line(aero_combustion *m, double sr)
{
    int len = (int)ceil(sr) + 8192; /* 1 s plus a block */
    float *line = calloc((size_t)len, sizeof(float));
    if (!line)
        return -1;
    free(m->line);
    m->line = line;
    m->line_len = len;
    m->line_pos = 0;
    m->dist[0] = m->dist[1] = -1.0;
    return 0;
}

int aero_combustion_init(aero_combustion *m, double sample_rate,
                         uint32_t seed)
{
    memset(m, 0, sizeof *m);
    m->sample_rate = sample_rate >= 1000.0 && sample_rate <= 1e6 ? sample_rate
                                                                  : 44100.0;
    m->power = AERO_COMBUSTION_POWER_KW_DEFAULT;
    m->length = AERO_COMBUSTION_LENGTH_DEFAULT;
    m->strouhal = AERO_COMBUSTION_ST_DEFAULT;
    m->fluctuation = AERO_COMBUSTION_FLUCTUATION_DEFAULT;
    m->rng = seed ? seed : 1;
    m->dist[0] = m->dist[1] = -1.0;
    m->shape_i0 = prototype_moment(0);
    return alloc_line(m, m->sample_rate);
}

void aero_combustion_free(aero_combustion *m)
{
    free(m->line);
    memset(m, 0, sizeof *m);
}

int aero_combustion_set_sample_rate(aero_combustion *m, double sr)
{
    if (!(sr >= 1000.0 && sr <= 1e6))
        return -1;
    if (sr == m->sample_rate && m->line)
        return 0;
    if (alloc_line(m, sr))
        return -1;
    m->sample_rate = sr;
    m->peak = 0.0; /* re-make the filter */
    return 0;
}

int aero_combustion_set_power_kw(aero_combustion *m, double kw)
{
    if (!(kw >= AERO_COMBUSTION_POWER_KW_MIN &&
          kw <= AERO_COMBUSTION_POWER_KW_MAX))
        return -1;
    m->power = kw * 1000.0;
    return 0;
}

int aero_combustion_set_length(aero_combustion *m, double l)
{
    if (!(l >= AERO_COMBUSTION_LENGTH_MIN && l <= AERO_COMBUSTION_LENGTH_MAX))
        return -1;
    m->length = l;
    return 0;
}

int aero_combustion_set_strouhal(aero_combustion *m, double st)
{
    if (!(st >= AERO_COMBUSTION_ST_MIN && st <= AERO_COMBUSTION_ST_MAX))
        return -1;
    m->strouhal = st;
    return 0;
}

int aero_combustion_set_fluctuation(aero_combustion *m, double eps)
{
    if (!(eps >= AERO_COMBUSTION_FLUCTUATION_MIN &&
          eps <= AERO_COMBUSTION_FLUCTUATION_MAX))
        return -1;
    m->fluctuation = eps;
    return 0;
}

int aero_combustion_set_seed(aero_combustion *m, uint32_t seed)
{
    m->rng = seed ? seed : 1;
    return 0;
}

/* the digital filter for peak fp (bilinear transform, each corner
   pre-warped); the state is kept, so a gliding peak does not click */
static void make_filter(aero_combustion *m, double fp)
{
    const double sr = m->sample_rate, c = 2.0 * sr;
    double K = tan(AERO_PI * fp / sr), norm = 1.0 / (1.0 + sqrt(2.0) * K + K * K);
    double p = TILT_START * fp;
    /* (s / w_p) times the Butterworth low-pass: its output is
       (dxi/dt) / w_p, so no difference of samples multiplies a filter's
       glitch by the sample rate */
    m->b[0][0] = K * norm;
    m->b[0][1] = 0.0;
    m->b[0][2] = -K * norm;
    m->a[0][0] = 2.0 * (K * K - 1.0) * norm;
    m->a[0][1] = (1.0 - sqrt(2.0) * K + K * K) * norm;
    m->nsec = 1;
    for (int k = 0; k < AERO_COMBUSTION_TILTS; k++, p *= 10.0) {
        double z = p * TILT_RATIO, wp, wz, d0;
        int s = m->nsec;
        double pk = p;
        /* corners above the band are held just below Nyquist rather than
           dropped, so that a gliding peak never adds or removes a section
           (a section joining with an empty state clicks) */
        if (pk > 0.47 * sr) pk = 0.47 * sr;
        if (z > 0.49 * sr) z = 0.49 * sr;
        wp = c * tan(AERO_PI * pk / sr);
        wz = c * tan(AERO_PI * z / sr);
        d0 = 1.0 + c / wp;
        m->b[s][0] = (1.0 + c / wz) / d0;
        m->b[s][1] = (1.0 - c / wz) / d0;
        m->b[s][2] = 0.0;
        m->a[s][0] = (1.0 - c / wp) / d0;
        m->a[s][1] = 0.0;
        m->nsec++;
    }
    /* white noise of variance v through H has variance 2 v fp I0 / sr */
    m->noise_scale = sqrt(sr / (2.0 * fp * m->shape_i0));
    m->peak = fp;
}

static double distance(const double *a, const double *b)
{
    double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

/* the filter for this block's peak: the flame's time scale glides (3 %
   per 64 samples, an e-fold in ~50 ms at 44.1 kHz): a filter re-made far
   from its state rings, and dQ/dt turns the ring into a click */
static void glide_peak(aero_combustion *m, double u, int n)
{
    double fp = aero_combustion_peak_hz(m, u);
    if (m->peak > 0.0) {
        double most = pow(1.03, n / 64.0);
        if (fp > m->peak * most) fp = m->peak * most;
        if (fp < m->peak / most) fp = m->peak / most;
    }
    if (m->peak <= 0.0 || fabs(fp - m->peak) > 0.005 * m->peak)
        make_filter(m, fp);
}

/* n samples of dQ/dt = eps P dxi/dt at the flame into the line: near-
   Gaussian white noise (three uniforms) through the filter's sections */
static void write_source(aero_combustion *m, int n)
{
    const double dq_scale = m->fluctuation * m->power * 2.0 * AERO_PI * m->peak;
    for (int k = 0; k < n; k++) {
        double x = (aero_uniform(&m->rng) + aero_uniform(&m->rng) +
                    aero_uniform(&m->rng)) * m->noise_scale;
        for (int s = 0; s < m->nsec; s++) {
            /* transposed direct form II */
            double y = m->b[s][0] * x + m->z[s][0];
            m->z[s][0] = m->b[s][1] * x - m->a[s][0] * y + m->z[s][1];
            m->z[s][1] = m->b[s][2] * x - m->a[s][1] * y;
            x = y;
        }
        if (!aero_is_finite(x)) { /* never: but no NaN may leave */
            x = 0.0;
            memset(m->z, 0, sizeof m->z);
        }
        m->line[m->line_pos] = (float)(x * dq_scale);
        if (++m->line_pos == m->line_len)
            m->line_pos = 0;
    }
}

/* the line as ear e hears it, at t - r/c0 and 1/r, the delay and gain
   gliding over the block from the last block's distance; added to o */
static void hear(aero_combustion *m, const double src[3], const double *ear,
                 int e, int start, float *o, int n)
{
    const double sr = m->sample_rate;
    double r1 = distance(src, ear), r0 = m->dist[e];
    double maxd = m->line_len - n - 4.0;
    if (!(r1 >= 0.05)) r1 = 0.05; /* also NaN */
    if (r0 < 0.0) r0 = r1;
    m->dist[e] = r1;
    double d0 = r0 / AERO_C0 * sr, d1 = r1 / AERO_C0 * sr;
    double g0 = aero_combustion_monopole(1.0, r0),
           g1 = aero_combustion_monopole(1.0, r1);
    if (d0 > maxd) d0 = maxd;
    if (d1 > maxd) d1 = maxd;
    for (int k = 0; k < n; k++) {
        double f = (k + 1.0) / n;
        double d = d0 + (d1 - d0) * f, g = g0 + (g1 - g0) * f;
        double pos = start + k - d;
        int i0, i1;
        double fr, v;
        while (pos < 0.0) pos += m->line_len;
        i0 = (int)pos;
        fr = pos - i0;
        if (i0 >= m->line_len) i0 -= m->line_len;
        i1 = i0 + 1 == m->line_len ? 0 : i0 + 1;
        v = m->line[i0] + fr * (m->line[i1] - m->line[i0]);
        o[k] += (float)(g * v);
    }
}

void aero_combustion_process(aero_combustion *m, double u, const double src[3],
                             const double *ears, int nears,
                             float *const *out, int n)
{
    int start = m->line_pos;
    if (n <= 0 || !m->line || n > m->line_len / 2)
        return;
    if (nears > 2) nears = 2;
    glide_peak(m, u, n);
    if (m->power <= 0.0 || m->fluctuation <= 0.0) {
        /* silent: the line holds zeros (the filter rests) */
        for (int k = 0; k < n; k++) {
            m->line[m->line_pos] = 0.0f;
            if (++m->line_pos == m->line_len)
                m->line_pos = 0;
        }
        m->dist[0] = m->dist[1] = -1.0;
        return;
    }
    write_source(m, n);
    for (int e = 0; e < nears; e++)
        hear(m, src, ears + 3 * e, e, start, out[e], n);
}
