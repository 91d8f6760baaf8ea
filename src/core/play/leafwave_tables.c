/* aero: [leafwave~]'s wave tables (pink noise from each blade's f_i up,
 * by an inverse FFT, eq. 14) and its voices (the hits and rubs they play,
 * figs. 12-13); see leafwave.c. */
#include "leafwave_internal.h"
#include "aero_air.h"
#include "aero_fftw.h"
#include "aero_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- wave tables: pink noise from f_i up, by an inverse FFT ------------- */

/* two new arrays in place of *a and *b (the old ones freed, nothing
   copied); -1, both kept, when out of memory */
int leafwave_replace_arrays(void **a, size_t a_bytes, void **b,
                            size_t b_bytes)
{
    void *na = malloc(a_bytes), *nb = malloc(b_bytes);
    if (!na || !nb) {
        free(na);
        free(nb);
        return -1;
    }
    free(*a);
    free(*b);
    *a = na;
    *b = nb;
    return 0;
}

/* the tables' inverse FFT: planned at init, never in process */
int leafwave_make_fft(aero_leafwave *lw)
{
    lw->fft = calloc(1, sizeof *lw->fft);
    return lw->fft ? aero_fftw_c2r_make(lw->fft, AERO_LEAFWAVE_TABLE_LEN) : -1;
}

void leafwave_free_fft(aero_leafwave *lw)
{
    if (lw->fft)
        aero_fftw_c2r_free(lw->fft);
    free(lw->fft);
    lw->fft = NULL;
}

double aero_leafwave_table_hz(const aero_leafwave *lw, int i)
{
    return lw->fm * pow(2.0, (double)i / lw->tables_per_octave); /* eq. 14 */
}

int aero_leafwave_table_for(const aero_leafwave *lw, double length,
                            double width)
{
    double size = sqrt(length * width);
    if (!(size > 0.0) || !aero_is_finite(size))
        return 0;
    double f = AERO_LEAFWAVE_PITCH_HZ_M / size;
    int i = (int)floor(lw->tables_per_octave * log2(f / lw->fm) + 0.5);
    return i < 0 ? 0 : i >= lw->ntables ? lw->ntables - 1 : i;
}

const float *aero_leafwave_table(const aero_leafwave *lw, int i)
{
    if (!lw->tables || i < 0 || i >= lw->ntables)
        return NULL;
    return lw->tables + (size_t)i * (AERO_LEAFWAVE_TABLE_LEN + 1);
}

/* each table's zero crossings: of the two samples around a sign change,
   the one nearer zero; notes start there. Counted, then listed. */
static int find_crossings(aero_leafwave *lw)
{
    const int n = AERO_LEAFWAVE_TABLE_LEN;
    int count = lw->ntables;
    for (int pass = 0; pass < 2; pass++) {
        int c = 0;
        for (int t = 0; t < count; t++) {
            const float *tab = lw->tables + (size_t)t * (n + 1);
            if (pass)
                lw->crossing_start[t] = c;
            for (int s = 0; s < n; s++) {
                if ((tab[s] < 0.0f) == (tab[s + 1] < 0.0f))
                    continue;
                if (pass)
                    lw->crossings[c] = fabsf(tab[s]) <= fabsf(tab[s + 1])
                                           ? s
                                           : (s + 1) % n;
                c++;
            }
        }
        if (pass)
            lw->crossing_start[count] = c;
        else if (leafwave_replace_arrays((void **)&lw->crossings,
                                sizeof(int) * (c + 1),
                                (void **)&lw->crossing_start,
                                sizeof(int) * (count + 1)))
            return -1;
    }
    return 0;
}

/* Table i: one loop of AERO_LEAFWAVE_TABLE_LEN samples at TABLE_RATE, its
   spectrum pink (power ~ 1/f) from the basic frequency f_i over about
   three octaves, rolling off as f^-4 in power above 8 f_i, cut at
   0.45 TABLE_RATE / RATE_MAX (no aliasing when friction plays it at up to
   RATE_MAX) and nothing below f_i; random phases; unit rms. The sample
   after the end repeats the first (interpolation). */
int leafwave_make_tables(aero_leafwave *lw)
{
    const int n = AERO_LEAFWAVE_TABLE_LEN;
    int count = lw->tables_per_octave * lw->octaves;
    float *tables = malloc(sizeof(float) * (size_t)count * (n + 1));
    if (!tables || !lw->fft) {
        free(tables);
        return -1;
    }
    fftwf_complex *spectrum = lw->fft->spectrum;
    const float *signal = lw->fft->signal;
    uint32_t rng = lw->seed * 747796405u + 2891336453u;
    if (!rng)
        rng = 1;
    double df = AERO_LEAFWAVE_TABLE_RATE / n;
    double f_top = 0.45 * AERO_LEAFWAVE_TABLE_RATE / RATE_MAX;
    free(lw->tables);
    lw->tables = tables;
    lw->ntables = count;
    for (int t = 0; t < count; t++) {
        double f_i = aero_leafwave_table_hz(lw, t);
        memset(spectrum, 0, sizeof(fftwf_complex) * (n / 2 + 1));
        for (int k = 1; k < n / 2; k++) {
            double f = k * df;
            if (f < f_i || f > f_top)
                continue;
            /* pink over about three octaves, then a second-order
               roll-off: the table's colour scales with f_i */
            double over = f / (BAND_OCTAVES_FACTOR * f_i);
            double amp = 1.0 / (sqrt(f) * (1.0 + over * over));
            double ph = AERO_PI * aero_uniform(&rng);
            spectrum[k][0] = (float)(amp * cos(ph));
            spectrum[k][1] = (float)(amp * sin(ph));
        }
        fftwf_execute(lw->fft->plan); /* a real signal: Hermitian spectrum */
        double sum = 0.0;
        for (int s = 0; s < n; s++)
            sum += (double)signal[s] * signal[s];
        double scale = sum > 0.0 ? 1.0 / sqrt(sum / n) : 0.0;
        float *dst = tables + (size_t)t * (n + 1);
        for (int s = 0; s < n; s++)
            dst[s] = (float)(signal[s] * scale);
        dst[n] = dst[0];
    }
    return find_crossings(lw);
}

/* ---- voices --------------------------------------------------------------- */

void leafwave_reset_voices(aero_leafwave *lw)
{
    for (int v = 0; v < lw->nvoices; v++) {
        memset(&lw->voices[v], 0, sizeof(aero_leaf_voice));
        lw->voices[v].pair = -1;
        lw->voices[v].table = -1;
        lw->free_voices[v] = lw->nvoices - 1 - v;
    }
    lw->nfree = lw->nvoices;
    lw->steal_cursor = 0;
    for (int p = 0; p < lw->npairs; p++)
        lw->pairs[p].voice = -1;
}

static double voice_level(const aero_leaf_voice *v)
{
    return (double)v->hit + v->rub;
}

/* a voice for pair p, starting `wait` samples into the next frame at a zero
   crossing of its table (no pulse at the start, as Matsuyama et al. ask): a
   free one, else the quietest of the next STEAL_LOOK voices (a rotating
   cursor: O(1) per key on, where a search of the whole pool cost O(voices))
   if it is quieter than `level`; -1 if none */
static int start_voice(aero_leafwave *lw, int p, int wait, double level)
{
    int best = -1;
    if (lw->nfree > 0)
        best = lw->free_voices[--lw->nfree];
    else {
        double quietest = level;
        for (int k = 0; k < STEAL_LOOK; k++) {
            int c = lw->steal_cursor;
            lw->steal_cursor = c + 1 == lw->nvoices ? 0 : c + 1;
            double l = voice_level(&lw->voices[c]);
            if (l < quietest) {
                quietest = l;
                best = c;
            }
        }
    }
    if (best < 0)
        return -1;
    aero_leaf_voice *v = &lw->voices[best];
    if (v->pair >= 0 && lw->pairs[v->pair].voice == best)
        lw->pairs[v->pair].voice = -1;
    aero_leaf_pair *pr = &lw->pairs[p];
    int table = lw->leaves[pr->i].table;
    /* a random one of the table's zero crossings (listed at init) */
    int first = lw->crossing_start[table];
    int count = lw->crossing_start[table + 1] - first;
    int pos = count > 0 ? lw->crossings[first + (int)(aero_xorshift32(&lw->rng) %
                                                     (uint32_t)count)]
                        : 0;
    memset(v, 0, sizeof(*v));
    v->pair = p;
    v->table = table;
    v->wait = wait;
    v->pos = pos;
    v->inc = AERO_LEAFWAVE_TABLE_RATE / lw->sample_rate;
    v->hit_decay = (float)exp(-1.0 / (HIT_DECAY_S * lw->sample_rate));
    v->rel_decay = (float)exp(-1.0 / (RELEASE_S * lw->sample_rate));
    pr->voice = best;
    return best;
}

/* raise the collision envelope of pair p's voice to `peak` (Pa at 1 m) */
void leafwave_key_on(aero_leafwave *lw, aero_leaf_pair *pr, int p, double frac,
                     double peak)
{
    lw->keyons_total++;
    if (pr->voice < 0) {
        int wait = (int)(frac * lw->frame_samples);
        if (start_voice(lw, p, wait, peak) < 0)
            return;
    }
    aero_leaf_voice *v = &lw->voices[pr->voice];
    v->releasing = 0;
    int attack = (int)(HIT_ATTACK_S * lw->sample_rate);
    if (attack < 1)
        attack = 1;
    if (peak > v->hit) {
        v->attack_left = attack;
        v->hit_step = (float)((peak - v->hit) / attack);
    }
    /* a collision plays the table at its own speed (rate 1) */
    double target = AERO_LEAFWAVE_TABLE_RATE / lw->sample_rate;
    v->inc_step = (target - v->inc) / lw->frame_samples;
    v->rub_step = (float)(-v->rub / lw->frame_samples);
}

/* contact: friction at level and table speed set by the sliding speed */
void leafwave_rub(aero_leafwave *lw, aero_leaf_pair *pr, int p, double vt)
{
    double level = lw->rub_pa * vt;
    if (pr->voice < 0) {
        if (level < SILENT_PA)
            return;
        if (start_voice(lw, p, 0, level) < 0)
            return;
    }
    aero_leaf_voice *v = &lw->voices[pr->voice];
    v->releasing = 0;
    double rate = clampd(vt / RUB_SPEED_REF, RATE_MIN, RATE_MAX);
    double target = rate * AERO_LEAFWAVE_TABLE_RATE / lw->sample_rate;
    v->inc_step = (target - v->inc) / lw->frame_samples;
    v->rub_step = (float)((level - v->rub) / lw->frame_samples);
}

void leafwave_key_off(aero_leafwave *lw, aero_leaf_pair *pr)
{
    if (pr->voice < 0)
        return;
    aero_leaf_voice *v = &lw->voices[pr->voice];
    v->releasing = 1;
    v->rub_step = 0.0f;
    v->inc_step = 0.0;
}

/* voices that have died away go back to the free stack */
void leafwave_free_silent_voices(aero_leafwave *lw)
{
    for (int v = 0; v < lw->nvoices; v++) {
        aero_leaf_voice *vo = &lw->voices[v];
        if (vo->table < 0)
            continue;
        int sounding = vo->pair >= 0 &&
                       lw->pairs[vo->pair].voice == v &&
                       (lw->pairs[vo->pair].state == AERO_LEAFWAVE_PAIR_CONTACT ||
                        lw->pairs[vo->pair].state == AERO_LEAFWAVE_PAIR_KEYON);
        if (!sounding && vo->wait <= 0 && vo->attack_left <= 0 &&
            voice_level(vo) < SILENT_PA) {
            if (vo->pair >= 0 && lw->pairs[vo->pair].voice == v)
                lw->pairs[vo->pair].voice = -1;
            vo->pair = -1;
            vo->table = -1;
            lw->free_voices[lw->nfree++] = v;
        }
    }
}

/* samples s..e of one voice, branch-free: the envelopes follow
   hit = hit * hit_mul + hit_add and rub = rub * rub_mul + rub_add (a
   linear ramp or an exponential decay); the read position runs on
   unwrapped and is masked into the table (a power of two) */
static void play(const float *tab, float *restrict dry, int s, int e,
                 double *pos, double *inc, double inc_step, float *hit,
                 float hit_mul, float hit_add, float *rubv, float rub_mul,
                 float rub_add)
{
    double p = *pos, d = *inc;
    float h = *hit, r = *rubv;
    for (int k = s; k < e; k++) {
        long ip = (long)p;
        float frac = (float)(p - (double)ip);
        int idx = (int)(ip & (AERO_LEAFWAVE_TABLE_LEN - 1));
        float x = tab[idx] + frac * (tab[idx + 1] - tab[idx]);
        dry[k] += x * (h + r);
        p += d;
        d += inc_step;
        h = h * hit_mul + hit_add;
        r = r * rub_mul + rub_add;
    }
    *pos = fmod(p, AERO_LEAFWAVE_TABLE_LEN);
    *inc = d;
    *hit = h;
    *rubv = r;
}

/* voices -> dry pressure at 1 m, n samples */
void leafwave_render_voices(aero_leafwave *lw, float *dry, int n)
{
    memset(dry, 0, sizeof(float) * n);
    for (int vi = 0; vi < lw->nvoices; vi++) {
        aero_leaf_voice *v = &lw->voices[vi];
        if (v->table < 0)
            continue;
        const float *tab = lw->tables + (size_t)v->table *
                                            (AERO_LEAFWAVE_TABLE_LEN + 1);
        int s = 0;
        if (v->wait > 0) {
            s = v->wait < n ? v->wait : n;
            v->wait -= s;
        }
        double pos = v->pos, inc = v->inc;
        float hit = v->hit, rubv = v->rub;
        float rub_mul = v->releasing ? v->rel_decay : 1.0f;
        float rub_add = v->releasing ? 0.0f : v->rub_step;
        if (s < n && v->attack_left > 0) {
            int e = s + v->attack_left < n ? s + v->attack_left : n;
            v->attack_left -= e - s;
            play(tab, dry, s, e, &pos, &inc, v->inc_step, &hit, 1.0f,
                 v->hit_step, &rubv, rub_mul, rub_add);
            s = e;
        }
        if (s < n)
            play(tab, dry, s, n, &pos, &inc, v->inc_step, &hit,
                 v->hit_decay, 0.0f, &rubv, rub_mul, rub_add);
        /* keep the ramps within their frame's targets */
        if (inc < 0.1 * AERO_LEAFWAVE_TABLE_RATE / lw->sample_rate)
            inc = 0.1 * AERO_LEAFWAVE_TABLE_RATE / lw->sample_rate;
        v->pos = pos;
        v->inc = inc;
        v->hit = hit < 1e-20f ? 0.0f : hit;
        v->rub = rubv < 1e-20f ? 0.0f : rubv;
    }
}
