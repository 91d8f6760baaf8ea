/* aero-analyze: measures a rendered sound file and asserts on the result.
 * Used by tests/run.sh on the WAV files Pd writes in batch mode.
 *
 *   aero-analyze peak FILE      spectral peak (Welch PSD, FFTW), Hz
 *   aero-analyze peakratio A B  peak(B) / peak(A)
 *   aero-analyze width FILE     full width at half power of the highest
 *                               peak, relative to its frequency
 *   aero-analyze level FILE     rms level, dB SPL (1 Pa = 94 dB)
 *   aero-analyze leveldiff A B  level(B) - level(A), dB
 *   aero-analyze band FILE F1 F2  level of the band F1..F2 Hz, dB SPL
 *   aero-analyze banddiff FILE F1 F2 F3 F4  band F3..F4 minus band F1..F2, dB
 *   aero-analyze finite FILE    no NaN/Inf (nor their 1e9 markers), |x|
 *                               below --max (default 1e4)
 *   aero-analyze centroid FILE  spectral centroid (power-weighted mean
 *                               frequency within --fmin..--fmax), Hz
 *   aero-analyze centroidratio A B  centroid(B) / centroid(A) (a Doppler
 *                               shift of a broadband sound)
 *   aero-analyze clicks FILE    worst local jump of the 2nd difference
 *                               against its neighbourhood (a ratio);
 *                               with --play INC a texture channel as a
 *                               source plays it: looped, read at INC
 *                               frames per sample by linear interpolation
 *                               (as [aeolian~]), 12 loops at --rate SR
 *                               (default 48000)
 *   aero-analyze onsetdiff FILE time (ms) at which channel 1 first reaches
 *                               10 % of its own maximum, minus the same for
 *                               channel 0 (an interaural delay)
 *   aero-analyze scaleratio A B  the factor s by which B's spectrum is A's
 *                               stretched in frequency (B(f) ~ A(f / s)):
 *                               the scan of s in 0.7..1.4 (steps of 0.05 %)
 *                               that best matches the two log spectra over
 *                               [fmin, fmax], each level removed (a Doppler
 *                               shift of a broadband sound, which moves a
 *                               centroid in a fixed band by less)
 *   aero-analyze specdist A B   rms difference of the two log spectra over
 *                               [fmin, fmax], each smoothed by --smooth, dB
 *   aero-analyze onset FILE     time of the first sample with |x| > 1e-3
 *                               of the file's peak, seconds (after --skip)
 *   aero-analyze same A B       largest |b - a| over every sample of every
 *                               channel, relative to A's largest |a| (the
 *                               same render on two platforms); files of
 *                               other lengths, channels or rates differ (1)
 * options: --ch K (channel, default 0)  --skip S (seconds ignored at the
 * start)  --dur S (seconds analysed after the skip; default all)
 * --skip2 S (B's own skip, for two windows of one file; default --skip)
 * --every T --count K (with --dur: K windows of --dur seconds, starting at
 * the skip and every T seconds after it, e.g. the same phase of K turns of
 * a whirl; spectra average over the windows, no segment spans two)
 * --fmin F --fmax F (peak search range)  --nfft N
 * --smooth HZ (moving average of the spectrum before the peak search)
 *   --expect V --tol T   pass if |value - V| <= T (relative for peak,
 *                        absolute dB otherwise)
 *   --min V --max V      pass if value >= V / <= V
 * Prints one line "ok ..." or "FAIL ..."; exit status 0 pass, 1 fail,
 * 2 unreadable file or bad usage. */
#include <fftw3.h>
#include <math.h>
#include <sndfile.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TWO_PI 6.28318530717958647692

typedef struct {
    int channel;
    double skip, skip2, dur, fmin, fmax, smooth, every;
    int nfft, count;
    int has_expect, has_tol, has_min, has_max, has_skip2;
    double expect, tol, min, max;
    double play, rate; /* clicks --play INC --rate SR */
} options;

typedef struct {
    double *x;
    long n;
    double sr;
    long gate; /* samples per window of --every (0: one stretch) */
} signal_t;

static int load(const char *path, const options *o, signal_t *s)
{
    SF_INFO info;
    memset(&info, 0, sizeof(info));
    SNDFILE *f = sf_open(path, SFM_READ, &info);
    if (!f) {
        printf("FAIL cannot read %s: %s\n", path, sf_strerror(NULL));
        return -1;
    }
    if (o->channel < 0 || o->channel >= info.channels) {
        printf("FAIL %s has %d channel(s), no channel %d\n", path,
               info.channels, o->channel);
        sf_close(f);
        return -1;
    }
    double *all = malloc(sizeof(double) * info.frames * info.channels + 1);
    sf_count_t got = sf_readf_double(f, all, info.frames);
    sf_close(f);
    long skip = (long)(o->skip * info.samplerate);
    if (skip > got)
        skip = got;
    s->sr = info.samplerate;
    s->gate = 0;
    if (o->every > 0.0 && o->count > 0 && o->dur > 0.0) {
        /* K windows, each whole inside the file, laid end to end */
        long len = (long)(o->dur * info.samplerate), k = 0;
        s->x = malloc(sizeof(double) * ((size_t)len * o->count + 1));
        for (; k < o->count; k++) {
            long at = skip + (long)(k * o->every * info.samplerate);
            if (at + len > got)
                break;
            for (long i = 0; i < len; i++)
                s->x[k * len + i] = all[(at + i) * info.channels + o->channel];
        }
        s->n = k * len;
        s->gate = len;
        if (k < o->count) {
            printf("FAIL %s: window %ld of %d ends after the file\n", path,
                   k + 1, o->count);
            free(all);
            free(s->x);
            return -1;
        }
    } else {
        s->n = got - skip;
        if (o->dur > 0.0 && (long)(o->dur * info.samplerate) < s->n)
            s->n = (long)(o->dur * info.samplerate);
        s->x = malloc(sizeof(double) * (s->n + 1));
        for (long i = 0; i < s->n; i++)
            s->x[i] = all[(i + skip) * info.channels + o->channel];
    }
    free(all);
    if (s->n < 16) {
        printf("FAIL %s: only %ld frames after --skip\n", path, s->n);
        free(s->x);
        return -1;
    }
    return 0;
}

static double level_db(const signal_t *s)
{
    double sum = 0;
    for (long i = 0; i < s->n; i++)
        sum += s->x[i] * s->x[i];
    double rms = sqrt(sum / s->n);
    return 20.0 * log10(rms / 20e-6 + 1e-30);
}

/* Welch power spectrum (Hann window, 75 % overlap); psd has nfft/2+1 bins */
static double *welch(const signal_t *s, int *nfft_io)
{
    int nfft = *nfft_io;
    long block = s->gate > 0 ? s->gate : s->n;
    while (nfft > block && nfft > 64)
        nfft /= 2;
    *nfft_io = nfft;
    double *in = fftw_malloc(sizeof(double) * nfft);
    fftw_complex *out = fftw_malloc(sizeof(fftw_complex) * (nfft / 2 + 1));
    fftw_plan plan = fftw_plan_dft_r2c_1d(nfft, in, out, FFTW_ESTIMATE);
    double *psd = calloc(nfft / 2 + 1, sizeof(double));
    double *window = malloc(sizeof(double) * nfft);
    for (int i = 0; i < nfft; i++)
        window[i] = 0.5 - 0.5 * cos(TWO_PI * i / nfft);
    int hop = nfft / 4, segments = 0;
    for (long from = 0; from + block <= s->n; from += block)
        for (long start = from; start + nfft <= from + block; start += hop) {
            for (int i = 0; i < nfft; i++)
                in[i] = s->x[start + i] * window[i];
            fftw_execute(plan);
            for (int k = 0; k <= nfft / 2; k++)
                psd[k] += out[k][0] * out[k][0] + out[k][1] * out[k][1];
            segments++;
        }
    for (int k = 0; k <= nfft / 2 && segments; k++)
        psd[k] /= segments;
    fftw_destroy_plan(plan);
    fftw_free(in);
    fftw_free(out);
    free(window);
    return psd;
}

/* the bins of [fmin, fmax] (lo, hi) and the highest one among them */
static int highest_bin(const double *psd, int nfft, double df,
                       const options *o, int *lo, int *hi)
{
    *lo = (int)ceil(o->fmin / df), *hi = (int)floor(o->fmax / df);
    if (*lo < 1)
        *lo = 1;
    if (*hi > nfft / 2 - 1)
        *hi = nfft / 2 - 1;
    int best = *lo;
    for (int k = *lo; k <= *hi; k++)
        if (psd[k] > psd[best])
            best = k;
    return best;
}

/* the contiguous bins around best whose power is at least half of it */
static void half_power_region(const double *psd, int lo, int hi, int best,
                              int *a, int *b)
{
    double half = 0.5 * psd[best];
    *a = best, *b = best;
    while (*a > lo && psd[*a - 1] >= half)
        (*a)--;
    while (*b < hi && psd[*b + 1] >= half)
        (*b)++;
}

static double peak_hz(const signal_t *s, const options *o)
{
    int nfft = o->nfft;
    double *psd = welch(s, &nfft);
    double df = s->sr / nfft;
    /* a moving average over --smooth Hz steadies the peak of a noisy,
     * broadened line without moving it (the line is symmetric) */
    int half = (int)(0.5 * o->smooth / df);
    if (half > 0) {
        double *avg = calloc(nfft / 2 + 1, sizeof(double));
        for (int k = 0; k <= nfft / 2; k++) {
            int a = k - half < 0 ? 0 : k - half;
            int b = k + half > nfft / 2 ? nfft / 2 : k + half;
            for (int j = a; j <= b; j++)
                avg[k] += psd[j];
            avg[k] /= b - a + 1;
        }
        free(psd);
        psd = avg;
    }
    int lo, hi, best = highest_bin(psd, nfft, df, o, &lo, &hi);
    if (half > 0) {
        /* a broad line: centroid of the contiguous region above half its
         * maximum, far steadier than the highest bin of a noisy estimate */
        int a, b;
        half_power_region(psd, lo, hi, best, &a, &b);
        double sum = 0, moment = 0;
        for (int k = a; k <= b; k++)
            sum += psd[k], moment += k * psd[k];
        free(psd);
        return moment / sum * df;
    }
    /* parabolic interpolation of the log spectrum around the maximum */
    double a = log(psd[best - 1] + 1e-300), b = log(psd[best] + 1e-300),
           c = log(psd[best + 1] + 1e-300);
    double denom = a - 2 * b + c, shift = 0;
    if (denom < 0)
        shift = 0.5 * (a - c) / denom;
    free(psd);
    return (best + shift) * df;
}

static double band_db(const signal_t *s, const options *o, double f1,
                      double f2)
{
    int nfft = o->nfft;
    double *psd = welch(s, &nfft);
    double df = s->sr / nfft, sum = 0, wsum = 0;
    for (int i = 0; i < nfft; i++) {
        double w = 0.5 - 0.5 * cos(TWO_PI * i / nfft);
        wsum += w * w;
    }
    for (int k = 1; k < nfft / 2; k++)
        if (k * df >= f1 && k * df <= f2)
            sum += 2.0 * psd[k];
    free(psd);
    /* Parseval: mean square = sum |X|^2 / (nfft * sum w^2) */
    double ms = sum / (nfft * wsum);
    return 10.0 * log10(ms / (20e-6 * 20e-6) + 1e-30);
}

/* power-weighted mean frequency of the Welch spectrum in fmin..fmax */
static double centroid_hz(const signal_t *s, const options *o)
{
    int nfft = o->nfft;
    double *psd = welch(s, &nfft);
    double df = s->sr / nfft, sw = 0, sf = 0;
    for (int k = 1; k < nfft / 2; k++)
        if (k * df >= o->fmin && k * df <= o->fmax) {
            sw += psd[k];
            sf += psd[k] * k * df;
        }
    free(psd);
    return sw > 0 ? sf / sw : 0.0;
}

/* full width at half maximum of the highest peak in [fmin, fmax] of the
 * (optionally smoothed) power spectrum, divided by its frequency */
static double relative_width(const signal_t *s, const options *o)
{
    int nfft = o->nfft;
    double *psd = welch(s, &nfft);
    double df = s->sr / nfft;
    int lo, hi, best = highest_bin(psd, nfft, df, o, &lo, &hi);
    double half = 0.5 * psd[best];
    int a, b;
    half_power_region(psd, lo, hi, best, &a, &b);
    /* interpolate the half-power crossings between bins */
    double left = a - (psd[a] - half) / (psd[a] - psd[a - 1] + 1e-300);
    double right = b + (psd[b] - half) / (psd[b] - psd[b + 1] + 1e-300);
    free(psd);
    return (right - left) / best;
}

/* the looped texture channel s as a source reading it at inc frames per
   sample at rate sr (linear interpolation, as the player): 12 loops, so
   that a window at the 2 ms scale of the output sees what an ear would
   hear from one source; 0, or -1 out of memory */
static int play_texture(signal_t *s, double inc, double sr)
{
    long n = (long)(12.0 * s->n / inc);
    double *y = malloc(sizeof(double) * (size_t)(n > 0 ? n : 1));
    if (!y)
        return -1;
    for (long k = 0; k < n; k++) {
        double pos = fmod(k * inc, (double)s->n);
        long i0 = (long)pos, i1 = i0 + 1 < s->n ? i0 + 1 : 0;
        double fr = pos - i0;
        y[k] = s->x[i0] + fr * (s->x[i1] - s->x[i0]);
    }
    free(s->x);
    s->x = y;
    s->n = n;
    s->sr = sr;
    return 0;
}

static double click_ratio(const signal_t *s)
{
    long w = (long)(0.002 * s->sr); /* 2 ms windows */
    if (w < 8)
        w = 8;
    long windows = s->n / w;
    double *peak = calloc(windows + 1, sizeof(double));
    double global = 0;
    for (long k = 0; k < windows; k++) {
        for (long i = k * w; i < (k + 1) * w; i++) {
            if (i < 2)
                continue;
            double d2 = fabs(s->x[i] - 2 * s->x[i - 1] + s->x[i - 2]);
            if (d2 > peak[k])
                peak[k] = d2;
        }
        if (peak[k] > global)
            global = peak[k];
    }
    double worst = 1.0;
    for (long k = 3; k + 3 < windows; k++) {
        double around = 0;
        for (long j = k - 3; j <= k + 3; j++)
            if (j != k && peak[j] > around)
                around = peak[j];
        if (around < 1e-6 * global)
            around = 1e-6 * global;
        if (around <= 0)
            continue;
        double r = peak[k] / around;
        if (r > worst)
            worst = r;
    }
    free(peak);
    return worst;
}

/* judge a value against the options; prints the verdict line */
/* first sample reaching frac of the channel's own maximum, seconds */
static double onset_s(const signal_t *s, double frac)
{
    double biggest = 0;
    for (long i = 0; i < s->n; i++)
        if (fabs(s->x[i]) > biggest)
            biggest = fabs(s->x[i]);
    for (long i = 0; i < s->n; i++)
        if (fabs(s->x[i]) >= frac * biggest)
            return (double)i / s->sr;
    return 0;
}

/* log power of a Welch spectrum at frequency f (linear between bins) */
static double log_power_at(const double *psd, int nfft, double df, double f)
{
    double k = f / df;
    int i = (int)k;
    if (i < 0 || i + 1 > nfft / 2)
        return log(1e-300);
    double p = psd[i] + (k - i) * (psd[i + 1] - psd[i]);
    return log(p > 1e-300 ? p : 1e-300);
}

/* B's spectrum as A's stretched by s: the s in 0.7..1.4 whose log spectra
 * over [fmin, fmax] (B's band; 64 points per octave), each with its mean
 * removed, differ least; -1 when the spectra cannot be compared */
static double scale_ratio(const signal_t *a, const signal_t *b,
                          const options *o)
{
    int na = o->nfft, nb = o->nfft;
    double *pa = welch(a, &na), *pb = welch(b, &nb);
    double best = -1.0, best_err = 1e300;
    if (na == nb && a->sr == b->sr && o->fmin > 0 && o->fmax > o->fmin) {
        double df = a->sr / na;
        int n = (int)(64.0 * log2(o->fmax / o->fmin)) + 1;
        double *lb = malloc(sizeof(double) * n), *la = malloc(sizeof(double) * n);
        double *f = malloc(sizeof(double) * n);
        double mb = 0;
        for (int j = 0; j < n; j++) {
            f[j] = o->fmin * pow(2.0, j / 64.0);
            lb[j] = log_power_at(pb, nb, df, f[j]);
            mb += lb[j] / n;
        }
        for (double sc = 0.7; sc <= 1.4; sc *= 1.0005) {
            double ma = 0, err = 0;
            for (int j = 0; j < n; j++) {
                la[j] = log_power_at(pa, na, df, f[j] / sc);
                ma += la[j] / n;
            }
            for (int j = 0; j < n; j++) {
                double d = (lb[j] - mb) - (la[j] - ma);
                err += d * d;
            }
            if (err < best_err)
                best_err = err, best = sc;
        }
        free(f);
        free(lb);
        free(la);
    }
    free(pa);
    free(pb);
    return best;
}

/* rms distance of two smoothed log power spectra over [fmin, fmax], dB */
static double spectral_distance(const signal_t *a, const signal_t *b,
                                const options *o)
{
    int na = o->nfft, nb = o->nfft;
    double *pa = welch(a, &na), *pb = welch(b, &nb);
    if (na != nb || a->sr != b->sr) {
        free(pa);
        free(pb);
        return 1e9;
    }
    double df = a->sr / na;
    int half = (int)(o->smooth / df / 2);
    double sum = 0;
    int count = 0;
    for (int k = 1; k < na / 2; k++) {
        if (k * df < o->fmin || (o->fmax > 0 && k * df > o->fmax))
            continue;
        double sa = 0, sb = 0;
        int m = 0;
        for (int j = k - half; j <= k + half; j++)
            if (j >= 1 && j < na / 2)
                sa += pa[j], sb += pb[j], m++;
        double d = 10.0 * log10((sb + 1e-300) / (sa + 1e-300));
        sum += d * d;
        count++;
    }
    free(pa);
    free(pb);
    return count ? sqrt(sum / count) : 1e9;
}

/* every sample of every channel of PATH (NULL if unreadable), its shape */
static float *read_all(const char *path, SF_INFO *info)
{
    memset(info, 0, sizeof(*info));
    SNDFILE *f = sf_open(path, SFM_READ, info);
    if (!f)
        return NULL;
    size_t n = (size_t)info->frames * (size_t)info->channels;
    float *x = malloc(sizeof(float) * (n + 1));
    if (x && sf_readf_float(f, x, info->frames) != info->frames) {
        free(x);
        x = NULL;
    }
    sf_close(f);
    return x;
}

static int verdict(const char *what, double value, const char *unit,
                   const options *o, int relative_tol);

static int same(const char *pa, const char *pb, const options *o)
{
    SF_INFO ia, ib;
    float *a = read_all(pa, &ia), *b = read_all(pb, &ib);
    if (!a || !b) {
        printf("FAIL cannot read %s\n", a ? pb : pa);
        free(a);
        free(b);
        return 2;
    }
    int rc;
    if (ia.frames != ib.frames || ia.channels != ib.channels ||
        ia.samplerate != ib.samplerate) {
        printf("FAIL %s (%ld frames, %d ch, %d Hz) and %s (%ld frames, %d ch,"
               " %d Hz) differ in shape\n", pa, (long)ia.frames, ia.channels,
               ia.samplerate, pb, (long)ib.frames, ib.channels, ib.samplerate);
        rc = 1;
    } else {
        size_t n = (size_t)ia.frames * (size_t)ia.channels, differ = 0;
        double top = 0, worst = 0;
        int bad = 0;
        for (size_t i = 0; i < n; i++) {
            if (!isfinite(a[i]) || !isfinite(b[i]))
                bad = 1;
            double d = fabs((double)b[i] - (double)a[i]);
            differ += a[i] != b[i];
            if (d > worst)
                worst = d;
            if (fabs(a[i]) > top)
                top = fabs(a[i]);
        }
        double rel = bad || top == 0 ? NAN : worst / top;
        /* 2^-24: a float's rounding step (half an ulp) at 1, so rel / 2^-23
         * is the difference in ulps of the peak */
        char what[1200];
        snprintf(what, sizeof(what), "difference of %s from %s (%zu of %zu "
                 "samples differ, largest %.3g = %.3g ulp of the peak %.4g)",
                 pb, pa, differ, n, worst, rel / 1.1920929e-7, top);
        rc = verdict(what, rel, "of the peak", o, 0);
    }
    free(a);
    free(b);
    return rc;
}

static int verdict(const char *what, double value, const char *unit,
                   const options *o, int relative_tol)
{
    int ok = value == value;
    char want[160] = "";
    if (o->has_expect) {
        double tol = o->has_tol ? o->tol : 0;
        double allowed = relative_tol ? tol * fabs(o->expect) : tol;
        ok = ok && fabs(value - o->expect) <= allowed;
        if (relative_tol)
            snprintf(want, sizeof(want), " (want %.4g +- %.3g%%)", o->expect,
                     100 * tol);
        else
            snprintf(want, sizeof(want), " (want %.4g +- %.3g)", o->expect,
                     tol);
    }
    if (o->has_min) {
        ok = ok && value >= o->min;
        snprintf(want + strlen(want), sizeof(want) - strlen(want),
                 " (want >= %.4g)", o->min);
    }
    if (o->has_max) {
        ok = ok && value <= o->max;
        snprintf(want + strlen(want), sizeof(want) - strlen(want),
                 " (want <= %.4g)", o->max);
    }
    printf("%s %s: %.5g %s%s\n", ok ? "ok" : "FAIL", what, value, unit, want);
    return ok ? 0 : 1;
}

static void usage(void)
{
    fprintf(stderr, "usage: aero-analyze peak|peakratio|scaleratio|width|level|leveldiff|band|finite|"
                    "centroid|centroidratio|clicks|onset|same FILE [FILE2] [F1 F2] [options]\n");
}

int main(int argc, char **argv)
{
    options o = {.fmin = 20.0, .fmax = 1e9, .nfft = 16384};
    const char *pos[6];
    int npos = 0;
    if (argc < 3) {
        usage();
        return 2;
    }
    const char *cmd = argv[1];
    for (int i = 2; i < argc; i++) {
        const char *a = argv[i];
        int more = i + 1 < argc;
        if (!strcmp(a, "--ch") && more)
            o.channel = atoi(argv[++i]);
        else if (!strcmp(a, "--skip") && more)
            o.skip = atof(argv[++i]);
        else if (!strcmp(a, "--skip2") && more)
            o.has_skip2 = 1, o.skip2 = atof(argv[++i]);
        else if (!strcmp(a, "--every") && more)
            o.every = atof(argv[++i]);
        else if (!strcmp(a, "--count") && more)
            o.count = atoi(argv[++i]);
        else if (!strcmp(a, "--dur") && more)
            o.dur = atof(argv[++i]);
        else if (!strcmp(a, "--fmin") && more)
            o.fmin = atof(argv[++i]);
        else if (!strcmp(a, "--fmax") && more)
            o.fmax = atof(argv[++i]);
        else if (!strcmp(a, "--smooth") && more)
            o.smooth = atof(argv[++i]);
        else if (!strcmp(a, "--nfft") && more)
            o.nfft = atoi(argv[++i]);
        else if (!strcmp(a, "--expect") && more)
            o.has_expect = 1, o.expect = atof(argv[++i]);
        else if (!strcmp(a, "--tol") && more)
            o.has_tol = 1, o.tol = atof(argv[++i]);
        else if (!strcmp(a, "--min") && more)
            o.has_min = 1, o.min = atof(argv[++i]);
        else if (!strcmp(a, "--max") && more)
            o.has_max = 1, o.max = atof(argv[++i]);
        else if (!strcmp(a, "--play") && more)
            o.play = atof(argv[++i]);
        else if (!strcmp(a, "--rate") && more)
            o.rate = atof(argv[++i]);
        else if (a[0] == '-' && a[1] == '-') {
            usage();
            return 2;
        } else if (npos < 6)
            pos[npos++] = a;
    }
    if (npos < 1 || o.nfft < 64) {
        usage();
        return 2;
    }
    signal_t s, s2;
    if (load(pos[0], &o, &s))
        return 2;
    int rc = 2;
    char what[600];
    if (!strcmp(cmd, "peak")) {
        snprintf(what, sizeof(what), "peak of %s", pos[0]);
        rc = verdict(what, peak_hz(&s, &o), "Hz", &o, 1);
    } else if (!strcmp(cmd, "peakratio") && npos >= 2) {
        if (load(pos[1], &o, &s2))
            return 2;
        snprintf(what, sizeof(what), "peak of %s over %s", pos[1], pos[0]);
        rc = verdict(what, peak_hz(&s2, &o) / peak_hz(&s, &o), "", &o, 1);
        free(s2.x);
    } else if (!strcmp(cmd, "scaleratio") && npos >= 2) {
        options o2 = o;
        if (o.has_skip2)
            o2.skip = o.skip2;
        if (load(pos[1], &o2, &s2))
            return 2;
        snprintf(what, sizeof(what), "spectrum of %s%s over %s", pos[1],
                 o.has_skip2 ? " (second window)" : "", pos[0]);
        rc = verdict(what, scale_ratio(&s, &s2, &o), "", &o, 1);
        free(s2.x);
    } else if (!strcmp(cmd, "width")) {
        snprintf(what, sizeof(what), "relative peak width of %s", pos[0]);
        rc = verdict(what, relative_width(&s, &o), "", &o, 0);
    } else if (!strcmp(cmd, "level")) {
        snprintf(what, sizeof(what), "level of %s", pos[0]);
        rc = verdict(what, level_db(&s), "dB SPL", &o, 0);
    } else if (!strcmp(cmd, "leveldiff") && npos >= 2) {
        if (load(pos[1], &o, &s2))
            return 2;
        snprintf(what, sizeof(what), "level of %s minus %s", pos[1], pos[0]);
        rc = verdict(what, level_db(&s2) - level_db(&s), "dB", &o, 0);
        free(s2.x);
    } else if (!strcmp(cmd, "band") && npos >= 3) {
        snprintf(what, sizeof(what), "band %s-%s Hz of %s", pos[1], pos[2],
                 pos[0]);
        rc = verdict(what, band_db(&s, &o, atof(pos[1]), atof(pos[2])),
                     "dB SPL", &o, 0);
    } else if (!strcmp(cmd, "banddiff") && npos >= 5) {
        snprintf(what, sizeof(what), "band %s-%s Hz over band %s-%s Hz of %s",
                 pos[3], pos[4], pos[1], pos[2], pos[0]);
        rc = verdict(what, band_db(&s, &o, atof(pos[3]), atof(pos[4])) -
                               band_db(&s, &o, atof(pos[1]), atof(pos[2])),
                     "dB", &o, 0);
    } else if (!strcmp(cmd, "finite")) {
        long bad = 0;
        double biggest = 0;
        for (long i = 0; i < s.n; i++) {
            /* tests/pdtest.sh marks NaN/Inf as 1e9 ([tabwrite~] zeroes them) */
            if (!isfinite(s.x[i]) || fabs(s.x[i]) >= 0.999e9)
                bad++;
            else if (fabs(s.x[i]) > biggest)
                biggest = fabs(s.x[i]);
        }
        double limit = o.has_max ? o.max : 1e4;
        rc = bad || biggest > limit;
        printf("%s finite %s: %ld NaN/Inf samples, max |x| %.4g (limit %.4g)"
               "\n", rc ? "FAIL" : "ok", pos[0], bad, biggest, limit);
    } else if (!strcmp(cmd, "onsetdiff")) {
        options o1 = o;
        o1.channel = 1;
        if (load(pos[0], &o1, &s2))
            return 2;
        snprintf(what, sizeof(what), "onset of channel 1 after channel 0 "
                 "of %s", pos[0]);
        rc = verdict(what, 1000.0 * (onset_s(&s2, 0.1) - onset_s(&s, 0.1)),
                     "ms", &o, 0);
        free(s2.x);
    } else if (!strcmp(cmd, "specdist") && npos >= 2) {
        if (load(pos[1], &o, &s2))
            return 2;
        snprintf(what, sizeof(what), "spectral distance of %s from %s",
                 pos[1], pos[0]);
        rc = verdict(what, spectral_distance(&s, &s2, &o), "dB", &o, 0);
        free(s2.x);
    } else if (!strcmp(cmd, "centroid")) {
        snprintf(what, sizeof(what), "spectral centroid of %s", pos[0]);
        rc = verdict(what, centroid_hz(&s, &o), "Hz", &o, 1);
    } else if (!strcmp(cmd, "centroidratio") && npos >= 2) {
        if (load(pos[1], &o, &s2))
            return 2;
        snprintf(what, sizeof(what), "spectral centroid of %s over %s",
                 pos[1], pos[0]);
        rc = verdict(what, centroid_hz(&s2, &o) / centroid_hz(&s, &o), "",
                     &o, 1);
        free(s2.x);
    } else if (!strcmp(cmd, "onset")) {
        /* first sound: arrival times (field auralization, retarded time) */
        double top = 0;
        long first = -1;
        for (long i = 0; i < s.n; i++)
            if (fabs(s.x[i]) > top)
                top = fabs(s.x[i]);
        for (long i = 0; i < s.n && top > 0; i++)
            if (fabs(s.x[i]) > 1e-3 * top) {
                first = i;
                break;
            }
        snprintf(what, sizeof(what), "onset of %s", pos[0]);
        rc = verdict(what, first < 0 ? NAN : first / s.sr, "s", &o, 0);
    } else if (!strcmp(cmd, "same") && npos >= 2) {
        rc = same(pos[0], pos[1], &o);
    } else if (!strcmp(cmd, "clicks")) {
        if (o.play != 0.0) {
            if (!(o.play > 0.01 && o.play < 100.0) || s.n < 2 ||
                play_texture(&s, o.play, o.rate > 0.0 ? o.rate : 48000.0)) {
                usage();
                return 2;
            }
        }
        snprintf(what, sizeof(what), "click ratio of %s%s", pos[0],
                 o.play != 0.0 ? " (played)" : "");
        rc = verdict(what, click_ratio(&s), "", &o, 0);
    } else
        usage();
    free(s.x);
    return rc;
}
