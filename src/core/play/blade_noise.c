/* aero: a blade's turbulent boundary-layer noise above its texture's band
 * limit (Brooks et al. 1989); see blade_noise.h. */
#include "blade_noise.h"

#include <math.h>
#include <string.h>

#include "aero_air.h"
#include "aero_util.h"
#include "band_limit.h"

#define EDGE 1.1224620483093730         /* 2^(1/6): a band's edge */
#define LEAK_POINTS 48                  /* per band, in log frequency */
/* each band is two identical band-pass biquads in cascade (skirts of
   12 dB an octave: one section's 6 dB let a band's power into bands two
   octaves up at -24 dB, above the model's own fall of up to 8 dB a third
   there), each section's bandwidth set so that the pair is -3 dB at the
   third octave's edges: a section at -1.5 dB there, 0.517 octave wide */
#define SECTION_OCTAVES 0.517
#define SOLVE_ROUNDS 12
/* the model's level is computed again when the speed moves by this
   fraction or the angle by this much (the spectrum moves by ~0.05 dB) */
#define SPEED_STEP 0.01
#define ALPHA_STEP_DEG 0.5
/* a band whose share is quieter than this (dB SPL at 1 m) or this far
   under the loudest is not run (after the gains are solved, so that
   leaving it out moves its neighbours by less than 0.01 dB; 40 dB under
   the loudest is where the filters' skirts leave their floor anyway) */
#define FLOOR_DB (-20.0)
#define RANGE_DB 40.0
#define P_REF 2e-5

/* |H(f)|^2 of band j's biquad at f Hz */
static double response2(const aero_blade_noise *b, int j, double f)
{
    double w = 2.0 * AERO_PI * f / b->sample_rate;
    double c1 = cos(w), s1 = sin(w), c2 = cos(2 * w), s2 = sin(2 * w);
    double nr = b->b0[j] * (1 - c2), ni = b->b0[j] * s2;
    double dr = 1 + b->a1[j] * c1 + b->a2[j] * c2;
    double di = -(b->a1[j] * s1 + b->a2[j] * s2);
    double h2 = (nr * nr + ni * ni) / (dr * dr + di * di);
    return h2 * h2; /* the two sections */
}

/* power in band k of band j's filter output for unit-variance white noise
   (one-sided density 2 / sample rate): the leak of j into k */
static double leak(const aero_blade_noise *b, int j, int k)
{
    double lo = b->hz[k] / EDGE, hi = b->hz[k] * EDGE, sum = 0;
    double nyquist = 0.5 * b->sample_rate;
    double step = log(hi / lo) / LEAK_POINTS;
    for (int i = 0; i < LEAK_POINTS; i++) {
        double f = lo * exp((i + 0.5) * step);
        if (f < nyquist)
            sum += response2(b, j, f) * f * step; /* df = f dln f */
    }
    return sum * 2.0 / b->sample_rate;
}

/* one-third-octave band-pass filters (a constant 0 dB peak, the bandwidth
   prewarped) at the standard centres below 0.46 of the rate */
static int make_bank(aero_blade_noise *b, double sr)
{
    double hz[AERO_BLADE_BANDS_MAX], top = fmin(20000.0, 0.46 * sr);
    int n = 0;
    /* band b's centre is 10^(b / 10) Hz: 200 Hz is band 23 */
    for (int band = 23; n < AERO_BLADE_BANDS_MAX; band++) {
        double f = pow(10.0, band / 10.0);
        if (f > top * 1.0001)
            break;
        hz[n++] = f;
    }
    if (n < 1)
        return -1;
    b->n_bands = n;
    b->sample_rate = sr;
    for (int k = 0; k < n; k++) {
        double w0 = 2.0 * AERO_PI * hz[k] / sr, sn = sin(w0);
        /* RBJ's cookbook band-pass, its bandwidth prewarped */
        double al = sn * sinh(0.5 * log(2.0) * SECTION_OCTAVES * w0 / sn);
        b->hz[k] = hz[k];
        b->b0[k] = (float)(al / (1 + al));
        b->a1[k] = (float)(-2 * cos(w0) / (1 + al));
        b->a2[k] = (float)((1 - al) / (1 + al));
    }
    for (int k = 0; k < n; k++)
        for (int j = 0; j < n; j++)
            b->leak[k][j] = leak(b, j, k);
    /* The arrival ring (arrivals.h) splits each sample linearly between
       its two neighbours at the arrival's fraction f of a sample, a
       fractional-delay filter of power (1 - f)^2 + f^2 + 2 f (1 - f)
       cos w: 2/3 + cos(w) / 3 over the fractions of sources at all
       distances (-1.5 dB at 10 kHz, -4.6 dB at 20 kHz at 44.1 kHz). The
       texture's band lies far below where that matters; the noise's is
       made up for it. */
    for (int k = 0; k < n; k++)
        b->ring_loss[k] = 2.0 / 3.0 + cos(2.0 * AERO_PI * hz[k] / sr) / 3.0;
    return 0;
}

int aero_blade_noise_init(aero_blade_noise *b, const aero_airfoil *section,
                          double v0, double f_pass, double f_stop,
                          double sample_rate)
{
    if (!b || !section || !(v0 > 0 && v0 < 1e3) || !(f_pass > 0) ||
        !(f_stop > f_pass) || !isfinite(f_stop) ||
        !(section->chord > 0 && section->chord < 100) ||
        !(section->te_thickness >= 0 && section->te_thickness < 1) ||
        !isfinite(section->te_angle_deg))
        return -1;
    memset(b, 0, sizeof(*b));
    b->section = *section;
    b->section.tip = AERO_AIRFOIL_NO_TIP;
    b->v0 = v0;
    b->f_pass = f_pass;
    b->f_stop = f_stop;
    if (aero_blade_noise_set_rate(b, sample_rate) != 0)
        return -1;
    return 0;
}

int aero_blade_noise_set_rate(aero_blade_noise *b, double sample_rate)
{
    if (!(sample_rate >= 1000 && sample_rate <= 1e6))
        return -1;
    if (sample_rate == b->sample_rate && b->n_bands > 0)
        return 0;
    return make_bank(b, sample_rate);
}

/* band k's generator from the voice's seed: the run seed scrambled
   (Murmur3's finaliser) so that neighbouring bands start far apart in the
   xorshift cycle */
static uint32_t band_seed(uint32_t seed, int k)
{
    return aero_scramble32(aero_run_seed(seed, k));
}

void aero_blade_voice_reset(aero_blade_voice *v, uint32_t seed)
{
    memset(v, 0, sizeof(*v));
    for (int k = 0; k < AERO_BLADE_BANDS_MAX; k++)
        v->rng[k] = band_seed(seed ? seed : 1, k);
}

/* the band gains whose outputs, leaking into their neighbours, give each
   band the power p[k]: x = g^2 >= 0 solving leak x = p by the
   multiplicative (Richardson-Lucy) iteration, which keeps x >= 0, over
   the bands the model fills and two either side (the leak two bands off
   is 25 dB down). x holds the last solution on entry (a warm start: the
   speed moved by a percent), or zeros. */
static void solve_gains(const aero_blade_noise *b, const double *p,
                        double *x)
{
    int n = b->n_bands, lo = n, hi = -1;
    double den[AERO_BLADE_BANDS_MAX];
    for (int k = 0; k < n; k++)
        if (p[k] > 0) {
            lo = k < lo ? k : lo;
            hi = k;
        }
    for (int j = 0; j < n; j++)
        if (j < lo || j > hi)
            x[j] = 0;
        else if (!(x[j] > 0))
            x[j] = b->leak[j][j] > 0 ? p[j] / b->leak[j][j] : 0;
    if (hi < lo)
        return;
    int klo = lo - 2 < 0 ? 0 : lo - 2, khi = hi + 2 >= n ? n - 1 : hi + 2;
    for (int j = lo; j <= hi; j++) {
        den[j] = 0;
        for (int k = klo; k <= khi; k++)
            den[j] += b->leak[k][j];
    }
    for (int round = 0; round < SOLVE_ROUNDS; round++) {
        double ratio[AERO_BLADE_BANDS_MAX];
        for (int k = klo; k <= khi; k++) {
            double got = 0;
            for (int j = lo; j <= hi; j++)
                got += b->leak[k][j] * x[j];
            ratio[k] = got > 0 ? p[k] / got : 0;
        }
        for (int j = lo; j <= hi; j++) {
            double num = 0;
            for (int k = klo; k <= khi; k++)
                num += b->leak[k][j] * ratio[k];
            x[j] = den[j] > 0 ? x[j] * num / den[j] : 0;
        }
    }
}

/* the model's power in each band, in the texture's units (N/s)^2: the
   band's SPL broadside at 1 m for this span, times (4 pi c0)^2 (Curle's
   dipole broadside at 1 m: p = g / (4 pi c0)), weighted by the power
   complement of the texture's band limit */
void aero_blade_noise_band_powers(const aero_blade_noise *b, double speed,
                                  double alpha_deg, double span,
                                  double scale, double size, double *p)
{
    aero_airfoil a = b->section;
    aero_airfoil_flow f = {(float)speed, (float)alpha_deg, (float)AERO_C0,
                           (float)AERO_NU};
    aero_airfoil_observer o = {1, 90, 90};
    float hz[AERO_BLADE_BANDS_MAX] = {0};
    float spl[AERO_BPM_MECHANISMS * AERO_BLADE_BANDS_MAX];
    float total[AERO_BLADE_BANDS_MAX];
    int n = b->n_bands;
    double to_g = 4.0 * AERO_PI * AERO_C0 * P_REF;
    a.span = (float)span;
    a.chord = (float)(a.chord * size);
    a.te_thickness = (float)(a.te_thickness * size);
    for (int k = 0; k < n; k++)
        hz[k] = (float)b->hz[k];
    if (aero_airfoil_noise_spectrum(&a, &f, &o, hz, n, spl) != 0) {
        for (int k = 0; k < n; k++)
            p[k] = 0;
        return;
    }
    aero_airfoil_noise_total(spl, n, total);
    for (int k = 0; k < n; k++) {
        double g = aero_band_limit_gain(b->hz[k] / scale, b->f_pass,
                                        b->f_stop);
        double keep = 1.0 - g * g;
        p[k] = total[k] > AERO_BPM_SILENT_DB && keep > 0
                   ? to_g * to_g * pow(10.0, total[k] / 10.0) * keep
                   : 0.0;
    }
}

/* leaves out the bands too quiet to hear or to matter beside the rest */
static void prune(const aero_blade_noise *b, double *x)
{
    const double to_g = 4.0 * AERO_PI * AERO_C0 * P_REF;
    double loudest = 0, floor_power = to_g * to_g * pow(10, FLOOR_DB / 10);
    for (int k = 0; k < b->n_bands; k++)
        if (x[k] * b->leak[k][k] > loudest)
            loudest = x[k] * b->leak[k][k];
    for (int k = 0; k < b->n_bands; k++) {
        double own = x[k] * b->leak[k][k];
        if (!(own > floor_power) || !(own > loudest * pow(10, -RANGE_DB / 10)))
            x[k] = 0;
    }
}

static int moved(const aero_blade_voice *v, double speed, double alpha,
                 double span, double scale)
{
    return !(v->law_speed > 0) ||
           fabs(speed - v->law_speed) > SPEED_STEP * v->law_speed ||
           fabs(alpha - v->law_alpha) > ALPHA_STEP_DEG ||
           span != v->law_span ||
           fabs(scale - v->law_scale) > SPEED_STEP * v->law_scale;
}

void aero_blade_voice_target(const aero_blade_noise *b, aero_blade_voice *v,
                             double speed, double alpha_deg, double span,
                             double scale, double size)
{
    int n = b->n_bands;
    for (int k = 0; k < n; k++) /* the last chunk reached its targets */
        v->gain[k] = v->target[k];
    if (!(speed > 1e-3) || !(span > 0) || !(scale > 0) || !(size > 0) ||
        !isfinite(alpha_deg)) {
        for (int k = 0; k < n; k++)
            v->target[k] = 0;
        v->law_speed = 0;
    } else if (moved(v, speed, alpha_deg, span, scale)) {
        double p[AERO_BLADE_BANDS_MAX], x[AERO_BLADE_BANDS_MAX];
        for (int k = 0; k < n; k++) /* the last solution, to start from */
            x[k] = (double)v->target[k] * v->target[k];
        aero_blade_noise_band_powers(b, speed, alpha_deg, span, scale, size,
                                     p);
        for (int k = 0; k < n; k++)
            p[k] /= b->ring_loss[k];
        solve_gains(b, p, x);
        prune(b, x);
        for (int k = 0; k < n; k++)
            v->target[k] = (float)sqrt(x[k] > 0 ? x[k] : 0);
        v->law_speed = speed;
        v->law_alpha = alpha_deg;
        v->law_span = span;
        v->law_scale = scale;
    }
    /* the bands to run: those sounding now or by the chunk's end */
    int lo = n, hi = 0;
    for (int k = 0; k < n; k++)
        if (v->gain[k] > 0 || v->target[k] > 0) {
            if (k < lo)
                lo = k;
            hi = k + 1;
        }
    for (int k = 0; k < n; k++) /* a band that stops starts again at rest */
        if (k < lo || k >= hi)
            v->x1[k] = v->x2[k] = v->y1[k] = v->y2[k] = v->z1[k] =
                v->z2[k] = 0;
    v->lo = lo < hi ? lo : 0;
    v->hi = lo < hi ? hi : 0;
}

/* Each band filters noise of its own: bands driven by one noise overlap
   coherently, and between two centres their phases differ by some 280
   deg (each cascade turns -140 deg above its centre, +140 below), which
   cancelled a quarter of the power there (6 dB under the model). */
void aero_blade_voice_render(const aero_blade_noise *b, aero_blade_voice *v,
                             float *out, int m)
{
    /* uniform on [-1, 1) has variance 1/3: sqrt(3) / 2^31 per unit */
    const float unit = 1.7320508f / 2147483648.0f;
    for (int j = 0; j < m; j++)
        out[j] = 0;
    for (int k = v->lo; k < v->hi; k++) {
        const float b0 = b->b0[k], a1 = b->a1[k], a2 = b->a2[k];
        const float dg = (v->target[k] - v->gain[k]) / (float)m;
        float g = v->gain[k], x1 = v->x1[k], x2 = v->x2[k];
        float y1 = v->y1[k], y2 = v->y2[k], z1 = v->z1[k], z2 = v->z2[k];
        uint32_t r = v->rng[k];
        for (int j = 0; j < m; j++) {
            float x = unit * (float)(int32_t)aero_xorshift32(&r);
            float u = b0 * (x - x2) - a1 * y1 - a2 * y2;
            float y = b0 * (u - y2) - a1 * z1 - a2 * z2;
            x2 = x1;
            x1 = x;
            y2 = y1;
            y1 = u;
            z2 = z1;
            z1 = y;
            g += dg;
            out[j] += g * y;
        }
        v->x1[k] = x1;
        v->x2[k] = x2;
        v->y1[k] = y1;
        v->y2[k] = y2;
        v->z1[k] = z1;
        v->z2[k] = z2;
        v->rng[k] = r;
    }
}
