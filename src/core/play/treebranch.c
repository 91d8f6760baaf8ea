/* aero: branch sound of a tree in the wind (see treebranch.h). */
#include "treebranch.h"
#include "aero_air.h"
#include "aero_ramp.h"
#include "aero_util.h"
#include "strouhal.h"

#include "aero_fftw.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Sectional rms lift coefficient of a circular cylinder, subcritical range
   (Norberg 2003), held at this one value for every branch (aeolian_model.c
   follows C_L'(Re), aero_lift_rms) */
#define LIFT_RMS 0.45
/* power of the high-frequency tail relative to the tone, as the spectral
   density at the tone's frequency times f_0: with alpha 2 the whole tail
   holds TAIL_LEVEL / (alpha - 1) = 1/4 of the tone's power (-6 dB). The
   paper (Matsuyama et al. 2005) gives no value; this keeps the Strouhal
   tone on top. */
#define TAIL_LEVEL 0.25
#define FRAME_SECONDS 0.08     /* FFT size: the power of 2 at or above this */
#define MAX_DISTANCE 1000.0    /* m, longest delay kept */
#define MIN_DISTANCE 0.1       /* m, closer than this the 1/r law is held */
#define MAX_GROUP 64           /* points per frequency group */
#define CHUNK 1024             /* samples per internal step */
#define PHASES 1024            /* table of unit phasors */

struct aero_treebranch_fft {
    aero_fftw_c2r c2r;
    float phase_cos[PHASES], phase_sin[PHASES];
};

static int finite3(const double v[3])
{
    return aero_is_finite(v[0]) && aero_is_finite(v[1])
        && aero_is_finite(v[2]);
}

static void free_buffers(aero_treebranch *tb)
{
    free(tb->power);
    free(tb->tail_start);
    free(tb->tail_shape);
    free(tb->window);
    free(tb->ola);
    free(tb->ring);
    if (tb->fft) {
        aero_fftw_c2r_free(&tb->fft->c2r);
        free(tb->fft);
    }
    tb->power = tb->tail_start = tb->tail_shape = NULL;
    tb->window = tb->ola = tb->ring = NULL;
    tb->fft = NULL;
}

static void update_tail_shape(aero_treebranch *tb)
{
    int k;
    if (!tb->tail_shape)
        return;
    tb->tail_shape[0] = 0.0;
    for (k = 1; k < tb->nbins; k++)
        tb->tail_shape[k] = pow(k * tb->bin_hz, -tb->alpha);
}

/* (re)allocates everything that depends on the sample rate; the FFTW plan
   is made here, never in process */
static int make_buffers(aero_treebranch *tb)
{
    int n = 256, k;
    double sigma;
    free_buffers(tb);
    while (n < FRAME_SECONDS * tb->sample_rate && n < (1 << 16))
        n *= 2;
    tb->fft_size = n;
    tb->hop = n / 8;
    tb->nbins = n / 2 + 1;
    tb->bin_hz = tb->sample_rate / n;
    tb->power = calloc((size_t)tb->nbins, sizeof(double));
    tb->tail_start = calloc((size_t)tb->nbins, sizeof(double));
    tb->tail_shape = calloc((size_t)tb->nbins, sizeof(double));
    tb->window = calloc((size_t)n, sizeof(float));
    tb->ola = calloc((size_t)n, sizeof(float));
    tb->ring_len = (long)(MAX_DISTANCE / AERO_C0 * tb->sample_rate) + CHUNK
        + n + 16;
    tb->ring = calloc((size_t)tb->ring_len, sizeof(float));
    tb->fft = calloc(1, sizeof *tb->fft);
    if (!tb->power || !tb->tail_start || !tb->tail_shape || !tb->window
        || !tb->ola || !tb->ring || !tb->fft)
        goto fail;
    if (aero_fftw_c2r_make(&tb->fft->c2r, n))
        goto fail;
    for (k = 0; k < PHASES; k++) {
        tb->fft->phase_cos[k] = (float)cos(2.0 * AERO_PI * k / PHASES);
        tb->fft->phase_sin[k] = (float)sin(2.0 * AERO_PI * k / PHASES);
    }
    /* Gaussian window, sigma = N/8 = hop: the squared windows of
       independent frames sum to sigma sqrt(pi) / hop = sqrt(pi) (Poisson
       summation: ripple 2 exp(-pi^2) ~ 1e-4), so scale by pi^-1/4 to keep
       the power; at the frame's ends the window is exp(-8) = 3e-4 */
    sigma = n / 8.0;
    for (k = 0; k < n; k++) {
        double x = (k - n / 2) / sigma;
        tb->window[k] = (float)(exp(-0.5 * x * x) * pow(AERO_PI, -0.25));
    }
    update_tail_shape(tb);
    tb->written = tb->now = 0;
    tb->frames = 0;
    return 0;
fail:
    free_buffers(tb);
    return -1;
}

int aero_treebranch_init(aero_treebranch *tb, double sample_rate,
                         uint32_t seed)
{
    memset(tb, 0, sizeof *tb);
    tb->sample_rate = sample_rate > 1000.0 && sample_rate < 1e6
        ? sample_rate : 44100.0;
    tb->seed = seed;
    tb->rng = seed ? seed : 0x2545f491u;
    tb->speed_dir[0] = 1.0;
    tb->alpha = AERO_TREEBRANCH_ALPHA_DEFAULT;
    tb->mic_k = AERO_TREEBRANCH_MIC_K_DEFAULT;
    tb->gain = pow(10.0, AERO_GAIN_DB_DEFAULT / 20.0);
    tb->ramp_samples = AERO_RAMP_MS_DEFAULT / 1000.0 * tb->sample_rate;
    tb->ear_target[0][0] = 0.0;
    tb->ear_target[0][1] = -10.0;
    tb->ear_target[0][2] = 1.7;
    memcpy(tb->ear_target[1], tb->ear_target[0], sizeof tb->ear_target[1]);
    tb->ear_target[0][0] -= 0.09;
    tb->ear_target[1][0] += 0.09;
    memcpy(tb->ear, tb->ear_target, sizeof tb->ear);
    tb->motion.stiffness = AERO_TREE_STIFFNESS_DEFAULT;
    tb->motion.beta = AERO_TREE_BETA_DEFAULT;
    return make_buffers(tb);
}

/* drops the tree and its motion: silent */
static void clear_tree(aero_treebranch *tb)
{
    if (tb->has_tree) {
        aero_tree_motion_free(&tb->motion);
        aero_tree_free(&tb->tree);
    }
    tb->has_tree = 0;
}

void aero_treebranch_free(aero_treebranch *tb)
{
    free_buffers(tb);
    clear_tree(tb);
}

/* the motion restarts from tb->seed with the current parameters */
static int restart_motion(aero_treebranch *tb)
{
    double stiffness = tb->motion.stiffness, beta = tb->motion.beta;
    if (tb->motion.state)
        aero_tree_motion_free(&tb->motion);
    if (aero_tree_motion_init(&tb->motion, &tb->tree, tb->seed))
        return -1;
    aero_tree_motion_set_stiffness(&tb->motion, stiffness);
    aero_tree_motion_set_beta(&tb->motion, beta);
    aero_tree_motion_set_wind(&tb->motion, tb->wind);
    return 0;
}

int aero_treebranch_set_tree(aero_treebranch *tb, aero_tree *t)
{
    const aero_branch *root;
    int k;
    clear_tree(tb);
    if (!t || t->nbranches < 1) {
        if (t)
            aero_tree_free(t);
        return -1;
    }
    tb->tree = *t;
    memset(t, 0, sizeof *t);
    if (restart_motion(tb)) {
        aero_tree_free(&tb->tree);
        return -1;
    }
    /* the parser and the generator put a root first */
    root = &tb->tree.branches[0];
    for (k = 0; k < 3; k++)
        tb->source[k] = 0.5 * (root->a[k] + root->b[k]);
    tb->has_tree = 1;
    return 0;
}

int aero_treebranch_set_sample_rate(aero_treebranch *tb, double sr)
{
    if (!(sr > 1000.0 && sr < 1e6))
        return -1;
    if (sr == tb->sample_rate && tb->ring)
        return 0;
    tb->ramp_samples *= sr / tb->sample_rate;
    tb->sample_rate = sr;
    return make_buffers(tb);
}

int aero_treebranch_set_wind(aero_treebranch *tb, const double w[3])
{
    double speed, limit = AERO_MACH_LIMIT * AERO_C0;
    int clamped = 0, k;
    if (!finite3(w))
        return -1;
    speed = sqrt(aero_dot3(w, w));
    for (k = 0; k < 3; k++)
        tb->wind[k] = speed > limit ? w[k] * limit / speed : w[k];
    if (speed > limit)
        clamped = 1;
    if (tb->has_tree)
        aero_tree_motion_set_wind(&tb->motion, tb->wind);
    return clamped;
}

int aero_treebranch_set_speed(aero_treebranch *tb, double speed)
{
    double w[3];
    if (!aero_is_finite(speed))
        return -1;
    for (int k = 0; k < 3; k++)
        w[k] = tb->speed_dir[k] * speed;
    tb->speed = speed;
    return aero_treebranch_set_wind(tb, w);
}

int aero_treebranch_set_direction(aero_treebranch *tb, const double d[3])
{
    double u[3];
    if (!finite3(d))
        return -1;
    for (int k = 0; k < 3; k++)
        u[k] = d[k];
    if (!(aero_normalise3(u) > 0.0))
        return -1;
    for (int k = 0; k < 3; k++)
        tb->speed_dir[k] = u[k];
    return 0;
}

int aero_treebranch_set_alpha(aero_treebranch *tb, double alpha)
{
    if (aero_set_within(&tb->alpha, alpha, AERO_TREEBRANCH_ALPHA_MIN,
                        AERO_TREEBRANCH_ALPHA_MAX))
        return -1;
    update_tail_shape(tb);
    return 0;
}

int aero_treebranch_set_stiffness(aero_treebranch *tb, double s)
{
    if (aero_set_within(&tb->motion.stiffness, s, AERO_TREE_STIFFNESS_MIN,
                        AERO_TREE_STIFFNESS_MAX))
        return -1;
    if (tb->has_tree)
        aero_tree_motion_set_stiffness(&tb->motion, s);
    return 0;
}

int aero_treebranch_set_beta(aero_treebranch *tb, double beta)
{
    if (!aero_is_finite(beta) || beta < AERO_TREE_BETA_MIN ||
        beta > AERO_TREE_BETA_MAX)
        return -1;
    if (tb->has_tree)
        aero_tree_motion_set_beta(&tb->motion, beta);
    else
        tb->motion.beta = beta;
    return 0;
}

int aero_treebranch_set_gain_db(aero_treebranch *tb, double db)
{
    return aero_set_gain_db(&tb->gain, db);
}

int aero_treebranch_set_ramp_ms(aero_treebranch *tb, double ms)
{
    return aero_set_ramp_ms(&tb->ramp_samples, ms, tb->sample_rate);
}

int aero_treebranch_set_mic(aero_treebranch *tb, const double dir[3])
{
    double n;
    int k;
    if (!finite3(dir))
        return -1;
    n = sqrt(aero_dot3(dir, dir));
    for (k = 0; k < 3; k++)
        tb->mic_dir[k] = n > 0.0 ? dir[k] / n : 0.0;
    return 0;
}

int aero_treebranch_set_mic_k(aero_treebranch *tb, double k)
{
    return aero_set_within(&tb->mic_k, k, AERO_TREEBRANCH_MIC_K_MIN,
                           AERO_TREEBRANCH_MIC_K_MAX);
}

static int valid_point(const double p[3])
{
    return finite3(p) && fabs(p[0]) < 1e5 && fabs(p[1]) < 1e5
        && fabs(p[2]) < 1e5;
}

/* one listener: in stereo the head moves there, the ears keep their
   spacing */
static int set_listener(aero_treebranch *tb, const double p[3])
{
    int k;
    if (!valid_point(p))
        return -1;
    if (tb->stereo) { /* move both ears, keeping their spacing */
        for (k = 0; k < 3; k++) {
            double mid = 0.5 * (tb->ear_target[0][k] + tb->ear_target[1][k]);
            tb->ear_target[0][k] += p[k] - mid;
            tb->ear_target[1][k] += p[k] - mid;
        }
    } else {
        memcpy(tb->ear_target[0], p, sizeof tb->ear_target[0]);
    }
    tb->ramp_left = tb->ramp_samples;
    return 0;
}

static int set_two_ears(aero_treebranch *tb, const double l[3],
                        const double r[3])
{
    if (!valid_point(l) || !valid_point(r))
        return -1;
    memcpy(tb->ear_target[0], l, sizeof tb->ear_target[0]);
    memcpy(tb->ear_target[1], r, sizeof tb->ear_target[1]);
    tb->ramp_left = tb->ramp_samples;
    return 0;
}

int aero_treebranch_set_ears(aero_treebranch *tb, const aero_ears *e)
{
    if (!e || e->n < 1 || e->n > 2)
        return -1;
    return e->n == 1 ? set_listener(tb, e->pos[0])
                     : set_two_ears(tb, e->pos[0], e->pos[1]);
}

void aero_treebranch_set_stereo(aero_treebranch *tb, int stereo)
{
    tb->stereo = stereo != 0;
}

int aero_treebranch_set_seed(aero_treebranch *tb, uint32_t seed)
{
    tb->seed = seed;
    tb->rng = seed ? seed : 0x2545f491u;
    if (!tb->has_tree)
        return 0;
    if (restart_motion(tb)) {
        clear_tree(tb);
        return -1;
    }
    return 0;
}

/* ---- one synthesis frame ------------------------------------------------ */

/* a line of power P at f, split between the two nearest bins (their
   Gaussian frames overlap, so the peak lands between them) */
static void add_line(aero_treebranch *tb, double f, double p)
{
    double x = f / tb->bin_hz, a;
    int k;
    if (!(x >= 1.0) || x >= tb->nbins - 2) /* below ~12 Hz, or aliasing */
        return;
    k = (int)x;
    a = x - k;
    tb->power[k] += (1.0 - a) * p;
    tb->power[k + 1] += a * p;
}

/* power per unit length (Pa^2 at 1 m, per m) and frequency at one end:
   Curle's compact dipole p = x_i dF_i/dt / (4 pi c0 r^2), dF/dt of the lift
   pi rho U^3 St C_L' per unit span, coherent over L_c, averaged over
   directions (<cos^2> = 1/3) */
static void end_source(double u, double d, double len, double *f,
                       double *density)
{
    double re = aero_reynolds(u, d), st, strength, lc, a;
    if (!(u > 0.0) || !(re > AERO_RE_ONSET)) {
        *f = 0.0;
        *density = 0.0;
        return;
    }
    st = aero_strouhal(re);
    strength = aero_shedding_strength(re);
    *f = st * u / d;
    lc = fmin(AERO_CORRELATION_DIAMETERS * d, len);
    a = AERO_RHO * u * u * u * st * LIFT_RMS * strength / (4.0 * AERO_C0);
    *density = a * a * lc / 3.0;
}

static void add_branch(aero_treebranch *tb, int i)
{
    const aero_branch *b = &tb->tree.branches[i];
    double pa[3], va[3], pb[3], vb[3], e[3], len, f[2], dens[2];
    double ptotal = 0.0, ftop;
    int k, end, m, npts;
    aero_tree_motion_point(&tb->motion, i, 0.0, pa, va);
    aero_tree_motion_point(&tb->motion, i, 1.0, pb, vb);
    for (k = 0; k < 3; k++)
        e[k] = pb[k] - pa[k];
    len = sqrt(aero_dot3(e, e));
    if (!(len > 0.0))
        return;
    for (k = 0; k < 3; k++)
        e[k] /= len;
    for (end = 0; end < 2; end++) {
        const double *v = end ? vb : va;
        double rel[3], along, u2;
        for (k = 0; k < 3; k++)
            rel[k] = tb->wind[k] - v[k];
        along = aero_dot3(rel, e);
        u2 = aero_dot3(rel, rel) - along * along; /* perpendicular part */
        end_source(u2 > 0.0 ? sqrt(u2) : 0.0, end ? b->d1 : b->d0, len,
                   &f[end], &dens[end]);
    }
    if (dens[0] <= 0.0 && dens[1] <= 0.0)
        return;
    /* an end below the shedding onset keeps the other's frequency */
    if (dens[0] <= 0.0)
        f[0] = f[1];
    if (dens[1] <= 0.0)
        f[1] = f[0];
    /* the frequency group: points spaced at most one bin apart along the
       branch, each carrying its share of the power (Matsuyama et al. 2005,
       Fig. 8) */
    /* compared before converting: a twig of 1e-30 m sheds at ~1e28 Hz,
       beyond int (undefined behaviour) */
    {
        double span = fabs(f[1] - f[0]) / tb->bin_hz;
        npts = span < MAX_GROUP ? (int)span + 1 : MAX_GROUP;
    }
    for (m = 0; m < npts; m++) {
        double s = (m + 0.5) / npts;
        double p = (dens[0] + s * (dens[1] - dens[0])) * len / npts;
        add_line(tb, f[0] + s * (f[1] - f[0]), p);
        ptotal += p;
    }
    /* the tail above the group (Matsuyama et al. 2005, eq. 8), as a density
       S(f) = TAIL_LEVEL P / f0 (f / f0)^-alpha: it enters at the first bin
       above f0 with the coefficient TAIL_LEVEL P df f0^(alpha - 1) of
       f^-alpha, and a running sum over bins adds every branch's tail */
    ftop = f[0] > f[1] ? f[0] : f[1];
    if (ftop > 0.0 && ftop / tb->bin_hz < tb->nbins - 2) {
        int k0 = (int)(ftop / tb->bin_hz) + 1;
        tb->tail_start[k0] += TAIL_LEVEL * ptotal * tb->bin_hz
            * pow(ftop, tb->alpha - 1.0);
    }
}

/* the spectrum of the current frame in tb->power (tails included) */
static void frame_spectrum(aero_treebranch *tb)
{
    double tail = 0.0;
    int i, k;
    memset(tb->power, 0, sizeof(double) * tb->nbins);
    memset(tb->tail_start, 0, sizeof(double) * tb->nbins);
    for (i = 0; i < tb->tree.nbranches; i++)
        add_branch(tb, i);
    for (k = 0; k < tb->nbins; k++) {
        tail += tb->tail_start[k];
        tb->power[k] += tail * tb->tail_shape[k];
    }
    tb->power[0] = tb->power[tb->nbins - 1] = 0.0;
}

int aero_treebranch_frame_power(aero_treebranch *tb, double *power,
                                int max_bins)
{
    if (!tb->has_tree || !tb->power || max_bins < tb->nbins)
        return -1;
    frame_spectrum(tb);
    memcpy(power, tb->power, sizeof(double) * tb->nbins);
    return tb->nbins;
}

/* one frame: spectrum, random phases, inverse FFT, window, overlap-add;
   the first hop of the accumulator is then final and goes to the ring */
static void synth_frame(aero_treebranch *tb)
{
    aero_treebranch_fft *fft = tb->fft;
    int n = tb->fft_size, k;
    long long w;
    frame_spectrum(tb);
    for (k = 0; k < tb->nbins; k++) {
        double p = tb->power[k];
        /* the c2r transform makes 2 |X| cos(...): mean square 2 |X|^2 */
        float amp = p > 0.0 && p < 1e30 ? (float)sqrt(0.5 * p) : 0.0f;
        uint32_t r = aero_xorshift32(&tb->rng) >> 22; /* 10 bits */
        fft->c2r.spectrum[k][0] = amp * fft->phase_cos[r];
        fft->c2r.spectrum[k][1] = amp * fft->phase_sin[r];
    }
    fftwf_execute(fft->c2r.plan);
    for (k = 0; k < n; k++)
        tb->ola[k] += tb->window[k] * fft->c2r.signal[k];
    w = tb->written;
    for (k = 0; k < tb->hop; k++) {
        float v = tb->ola[k];
        tb->ring[(w + k) % tb->ring_len] = aero_is_finite(v) ? v : 0.0f;
    }
    memmove(tb->ola, tb->ola + tb->hop, sizeof(float) * (n - tb->hop));
    memset(tb->ola + n - tb->hop, 0, sizeof(float) * tb->hop);
    tb->written += tb->hop;
    tb->frames++;
}

/* ---- rendering ----------------------------------------------------------- */

static float ring_at(const aero_treebranch *tb, long long k)
{
    return k < 0 ? 0.0f : tb->ring[k % tb->ring_len];
}

/* 4-point cubic Hermite (Catmull-Rom) read at fractional sample pos */
static double ring_read(const aero_treebranch *tb, double pos)
{
    long long k = (long long)floor(pos);
    double t = pos - (double)k;
    double y0 = ring_at(tb, k - 1), y1 = ring_at(tb, k), y2 = ring_at(tb, k + 1),
           y3 = ring_at(tb, k + 2);
    double c1 = 0.5 * (y2 - y0);
    double c2 = y0 - 2.5 * y1 + 2.0 * y2 - 0.5 * y3;
    double c3 = 0.5 * (y3 - y0) + 1.5 * (y1 - y2);
    return ((c3 * t + c2) * t + c1) * t + y1;
}

/* delay (samples) and factor (gain / r times the mic) for an ear */
static void ear_path(aero_treebranch *tb, const double p[3],
                     double *delay, double *level)
{
    double to_tree[3], r, cosmu = 1.0, s = 1.0;
    int k;
    for (k = 0; k < 3; k++)
        to_tree[k] = tb->source[k] - p[k];
    r = sqrt(aero_dot3(to_tree, to_tree));
    if (aero_dot3(tb->mic_dir, tb->mic_dir) > 0.0 && r > 0.0)
        cosmu = aero_dot3(tb->mic_dir, to_tree) / r;
    if (r < MIN_DISTANCE) { /* the near-field policy (aero_near_field) */
        aero_near_seen(&tb->near, MIN_DISTANCE);
        r = MIN_DISTANCE;
    }
    if (r > MAX_DISTANCE)
        r = MAX_DISTANCE;
    *delay = r / AERO_C0 * tb->sample_rate;
    if (*delay < 2.0)
        *delay = 2.0;
    if (tb->mic_k > 0.0) {
        double c = 0.5 * (1.0 + cosmu);
        s = c > 0.0 ? pow(c, tb->mic_k) : 0.0;
    }
    *level = tb->gain * s / r; /* pressure at 1 m times 1 m / r */
}

static void process_chunk(aero_treebranch *tb, float *out0, float *out1,
                          int n)
{
    double delay_end[2], level_end[2];
    int nears = out1 && tb->stereo ? 2 : 1, e, i;
    aero_tree_motion_advance(&tb->motion, n / tb->sample_rate);
    /* the ears glide to their targets over `ramp` */
    aero_glide_values(&tb->ear[0][0], &tb->ear_target[0][0], 6,
                      aero_glide_fraction(&tb->ramp_left, n));
    for (e = 0; e < nears; e++)
        ear_path(tb, tb->ear[e], &delay_end[e], &level_end[e]);
    if (tb->now == 0 && tb->written == 0)
        for (e = 0; e < 2; e++) { /* first block: start where we are */
            tb->delay[e] = delay_end[e < nears ? e : 0];
            tb->level[e] = level_end[e < nears ? e : 0];
        }
    while (tb->written < tb->now + n)
        synth_frame(tb);
    for (e = 0; e < nears; e++) {
        float *out = e ? out1 : out0;
        double d0 = tb->delay[e], l0 = tb->level[e];
        double dd = (delay_end[e] - d0) / n, dl = (level_end[e] - l0) / n;
        for (i = 0; i < n; i++) {
            double d = d0 + dd * (i + 1), l = l0 + dl * (i + 1);
            double v = l * ring_read(tb, (double)(tb->now + i) - d);
            out[i] = aero_is_finite(v) ? (float)v : 0.0f;
        }
        tb->delay[e] = delay_end[e];
        tb->level[e] = level_end[e];
    }
    if (out1 && nears == 1)
        memcpy(out1, out0, sizeof(float) * n);
    tb->now += n;
}

void aero_treebranch_process(aero_treebranch *tb, float *out0, float *out1,
                             int n)
{
    int done = 0;
    if (!tb->has_tree || !tb->ring || !tb->fft) {
        if (n > 0) {
            memset(out0, 0, sizeof(float) * n);
            if (out1)
                memset(out1, 0, sizeof(float) * n);
        }
        return;
    }
    while (done < n) {
        int m = n - done > CHUNK ? CHUNK : n - done;
        process_chunk(tb, out0 + done, out1 ? out1 + done : NULL, m);
        done += m;
    }
}

/* the mean of a block of speeds, each as aero_speed_in takes it */
static double block_mean(const float *in, int n, int *clamped)
{
    double sum = 0.0;
    for (int i = 0; i < n; i++)
        sum += aero_speed_in(in[i], clamped);
    return sum / n;
}

int aero_treebranch_process_speed(aero_treebranch *tb, const float *speed,
                                  float *out0, float *out1, int n)
{
    int clamped = 0;
    /* frames are ~10 ms apart: one speed a block is enough */
    if (speed && n > 0) {
        double u = block_mean(speed, n, &clamped);
        if (u != tb->speed && aero_treebranch_set_speed(tb, u) == 1)
            clamped = 1;
    }
    aero_treebranch_process(tb, out0, out1, n);
    return clamped;
}

/* ---- loading in a worker, swapping in Pd's thread ------------------------ */

int aero_treebranch_copy_settings(aero_treebranch *dst,
                                  const aero_treebranch *src)
{
    int r = 0;
    memcpy(dst->speed_dir, src->speed_dir, sizeof dst->speed_dir);
    dst->speed = src->speed;
    if (dst->alpha != src->alpha)
        aero_treebranch_set_alpha(dst, src->alpha);
    dst->mic_k = src->mic_k;
    memcpy(dst->mic_dir, src->mic_dir, sizeof dst->mic_dir);
    dst->gain = src->gain;
    dst->ramp_samples = src->ramp_samples * dst->sample_rate
        / src->sample_rate;
    dst->stereo = src->stereo;
    memcpy(dst->ear_target, src->ear_target, sizeof dst->ear_target);
    memcpy(dst->ear, src->ear, sizeof dst->ear);
    dst->ramp_left = src->ramp_left;
    aero_treebranch_set_stiffness(dst, src->motion.stiffness);
    aero_treebranch_set_beta(dst, src->motion.beta);
    aero_treebranch_set_wind(dst, src->wind);
    return r;
}

void aero_treebranch_move(aero_treebranch *dst, aero_treebranch *src)
{
    *dst = *src;
    dst->motion.tree = &dst->tree; /* the motion points into its owner */
    memset(src, 0, sizeof *src);
}
