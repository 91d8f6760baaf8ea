/* aero: leaves in the wind (see leafwave.h; Matsuyama et al. 2005, sections
 * "Generation of Leaf Sound" and "Sound Rendering"; the equations and
 * figures cited below are theirs). */
#include "leafwave.h"
#include "aero_air.h"
#include "aero_util.h"

#include "aero_fftw.h"
#include "aero_ramp.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WIND_REF 8.0          /* m/s: leaves reach ~tanh(1) of their sway */
#define FLUTTER_WIND 5.0      /* m/s: flutter rate doubles by this speed */
#define FLUTTER_DAMPING 0.3   /* zeta of a leaf's resonance */
#define SWAY_Y 0.7            /* longitudinal / lateral amplitude */
#define SWAY_R 0.5            /* free torsion / lateral amplitude */
#define DROOP 0.5             /* blade droop: tan of its angle below the stalk */
#define CONTACT_DEPTH 0.3     /* contact ellipsoid depth / blade half width */
#define RUB_SPEED_REF 0.5     /* m/s of sliding that plays a table at 1x */
#define RATE_MIN 0.25
#define RATE_MAX 2.0          /* tables hold content up to 0.45 fs / RATE_MAX */
#define HIT_ATTACK_S 0.001
#define HIT_DECAY_S 0.015
#define RELEASE_S 0.06        /* key off: slow decay (fig. 13) */
#define SILENT_PA 1e-7        /* a voice below this at 1 m is done */
#define DRY_CHUNK 256
#define STEAL_LOOK 8          /* voices looked at when all are busy */
#define BAND_OCTAVES_FACTOR 8.0 /* tables roll off above 8 f_i */
#define MIN_DISTANCE 0.1      /* m: 1/r is held below this */

static double clampd(double v, double lo, double hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* ---- wave tables: pink noise from f_i up, by an inverse FFT ------------- */

/* two new arrays in place of *a and *b (the old ones freed, nothing
   copied); -1, both kept, when out of memory */
static int replace_arrays(void **a, size_t a_bytes, void **b, size_t b_bytes)
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
static int make_fft(aero_leafwave *lw)
{
    lw->fft = calloc(1, sizeof *lw->fft);
    return lw->fft ? aero_fftw_c2r_make(lw->fft, AERO_LEAF_TABLE_LEN) : -1;
}

static void free_fft(aero_leafwave *lw)
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
    double f = AERO_LEAF_PITCH_HZ_M / size;
    int i = (int)floor(lw->tables_per_octave * log2(f / lw->fm) + 0.5);
    return i < 0 ? 0 : i >= lw->ntables ? lw->ntables - 1 : i;
}

const float *aero_leafwave_table(const aero_leafwave *lw, int i)
{
    if (!lw->tables || i < 0 || i >= lw->ntables)
        return NULL;
    return lw->tables + (size_t)i * (AERO_LEAF_TABLE_LEN + 1);
}

/* each table's zero crossings: of the two samples around a sign change,
   the one nearer zero; notes start there. Counted, then listed. */
static int find_crossings(aero_leafwave *lw)
{
    const int n = AERO_LEAF_TABLE_LEN;
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
        else if (replace_arrays((void **)&lw->crossings,
                                sizeof(int) * (c + 1),
                                (void **)&lw->crossing_start,
                                sizeof(int) * (count + 1)))
            return -1;
    }
    return 0;
}

/* Table i: one loop of AERO_LEAF_TABLE_LEN samples at TABLE_RATE, its
   spectrum pink (power ~ 1/f) from the basic frequency f_i over about
   three octaves, rolling off as f^-4 in power above 8 f_i, cut at
   0.45 TABLE_RATE / RATE_MAX (no aliasing when friction plays it at up to
   RATE_MAX) and nothing below f_i; random phases; unit rms. The sample
   after the end repeats the first (interpolation). */
static int make_tables(aero_leafwave *lw)
{
    const int n = AERO_LEAF_TABLE_LEN;
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
    double df = AERO_LEAF_TABLE_RATE / n;
    double f_top = 0.45 * AERO_LEAF_TABLE_RATE / RATE_MAX;
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

/* ---- leaves ------------------------------------------------------------- */

/* sine and cosine on [-pi/2, pi/2] by their Taylor series (errors 1.6e-4
   and 2.4e-5 at the ends: far below what a leaf's angle means); the leaf
   angles are limited to that range (a blade does not swing or twist
   beyond a right angle about its stalk). With libm, the three per leaf
   per frame cost a sixth of the frame. */
static double limit_angle(double x)
{
    return x < -1.5707963 ? -1.5707963 : x > 1.5707963 ? 1.5707963 : x;
}

static double sin_small(double x)
{
    double x2 = x * x;
    return x * (1.0 - x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0)));
}

static double cos_small(double x)
{
    double x2 = x * x;
    return 1.0 - x2 / 2.0 * (1.0 - x2 / 12.0 * (1.0 - x2 / 30.0 *
                                                  (1.0 - x2 / 56.0)));
}

/* AR(2) resonator x[n] = c1 x[n-1] + c2 x[n-2] + g w[n] at frequency f,
   damping zeta, frame rate fr; g makes x unit-rms for w uniform on [-1,1)
   (variance 1/3): gamma0 = (1 - c2) s2 / ((1 + c2)((1 - c2)^2 - c1^2)) */
static void resonator(double f, double fr, double coef[3])
{
    double w = 2.0 * AERO_PI * f / fr;
    if (w > 2.5)
        w = 2.5; /* below the frame Nyquist */
    double r = exp(-FLUTTER_DAMPING * w);
    double c1 = 2.0 * r * cos(w * sqrt(1.0 - FLUTTER_DAMPING * FLUTTER_DAMPING));
    double c2 = -r * r;
    double var = (1.0 - c2) / ((1.0 + c2) * ((1.0 - c2) * (1.0 - c2) - c1 * c1))
        / 3.0;
    coef[0] = c1;
    coef[1] = c2;
    coef[2] = 1.0 / sqrt(var);
}

static void free_leaves(aero_leafwave *lw)
{
    free(lw->leaves);
    free(lw->pairs);
    lw->leaves = NULL;
    lw->pairs = NULL;
    lw->nleaves = lw->npairs = 0;
}

/* rest geometry of every leaf (fig. 10): the blade hangs from the
   stalk end, drooping; the leaf swings rigidly about the stalk start */
static void build_leaves(aero_leafwave *lw)
{
    const aero_tree *t = &lw->tree;
    const double up[3] = {0.0, 0.0, 1.0};
    double crown[3] = {0.0, 0.0, 0.0};
    uint32_t rng = lw->seed * 2654435761u + 0x9e3779b9u;
    if (!rng)
        rng = 1;
    for (int i = 0; i < lw->nleaves; i++) {
        const aero_leaf *l = &t->leaves[i];
        aero_leaf_state *s = &lw->leaves[i];
        const aero_branch *b = &t->branches[l->branch];
        double stalk[3], blade[3], centre[3], z[3], x[3], y[3];
        for (int k = 0; k < 3; k++)
            stalk[k] = l->e[k] - l->s[k];
        double ls = aero_normalise3(stalk);
        if (!(ls > 0.0)) {
            stalk[0] = 1.0;
            stalk[1] = stalk[2] = 0.0;
        }
        for (int k = 0; k < 3; k++)
            blade[k] = stalk[k] - DROOP * up[k];
        if (!(aero_normalise3(blade) > 1e-6))
            for (int k = 0; k < 3; k++)
                blade[k] = stalk[k];
        for (int k = 0; k < 3; k++) {
            centre[k] = l->e[k] + 0.5 * l->length * blade[k];
            z[k] = centre[k] - l->s[k];
        }
        double reach = aero_normalise3(z);
        if (!(reach > 0.0)) {
            z[0] = 1.0;
            z[1] = z[2] = 0.0;
        }
        aero_cross3(z, up, x);
        if (aero_normalise3(x) < 1e-6) {
            const double ex[3] = {1.0, 0.0, 0.0};
            aero_cross3(z, ex, x);
            aero_normalise3(x);
        }
        aero_cross3(z, x, y);
        for (int k = 0; k < 3; k++) {
            s->base[k] = (float)l->s[k];
            s->branch_rest[k] = (float)(b->a[k] + l->along * (b->b[k] - b->a[k]));
            s->x[k] = (float)x[k];
            s->y[k] = (float)y[k];
            s->z[k] = (float)z[k];
            s->p[k] = (float)centre[k];
            s->t[k] = (float)z[k];
            s->u[k] = (float)x[k];
            s->n[k] = (float)y[k];
            crown[k] += centre[k];
        }
        s->reach = (float)reach;
        s->half_len = (float)(0.5 * l->length);
        s->half_wid = (float)(0.5 * l->width);
        s->table = aero_leafwave_table_for(lw, l->length, l->width);
        s->flutter_class = (int)(aero_xorshift32(&rng) %
                                 AERO_LEAF_FLUTTER_CLASSES);
        /* noises start in a random state of the right size */
        s->nx[0] = (float)aero_uniform(&rng);
        s->nx[1] = (float)aero_uniform(&rng);
        s->ny[0] = (float)aero_uniform(&rng);
        s->ny[1] = (float)aero_uniform(&rng);
        s->nr[0] = (float)aero_uniform(&rng);
        s->nr[1] = (float)aero_uniform(&rng);
    }
    for (int k = 0; k < 3; k++)
        lw->crown[k] = lw->nleaves ? crown[k] / lw->nleaves : 0.0;
    lw->rng = rng;
}

/* ---- neighbour lists by spatial hashing --------------------------------- */

typedef struct {
    int key;
    int leaf;
} hash_entry;

static int cmp_hash(const void *a, const void *b)
{
    const hash_entry *x = a, *y = b;
    return x->key != y->key ? (x->key < y->key ? -1 : 1)
                            : (x->leaf < y->leaf ? -1 : x->leaf > y->leaf);
}

static int cmp_pair(const void *a, const void *b)
{
    const aero_leaf_pair *x = a, *y = b;
    if (x->i != y->i)
        return x->i < y->i ? -1 : 1;
    return x->j < y->j ? -1 : x->j > y->j;
}

static unsigned cell_hash(long cx, long cy, long cz, unsigned mask)
{
    return ((unsigned)cx * 73856093u ^ (unsigned)cy * 19349663u ^
            (unsigned)cz * 83492791u) & mask;
}

/* the spatial hash of the rest blade centres: each leaf's cell (cells, 3
   per leaf), the leaves sorted by the hash of their cell (entries), and
   where each hash's leaves start in that order (start, mask + 2 values) */
typedef struct {
    double cell;
    unsigned mask;
    long *cells;
    hash_entry *entries;
    int *start;
} leaf_hash;

static void free_hash(leaf_hash *h)
{
    free(h->entries);
    free(h->start);
    free(h->cells);
}

static int make_hash(const aero_leafwave *lw, leaf_hash *h)
{
    int n = lw->nleaves;
    double rmax = 0.0;
    for (int i = 0; i < n; i++)
        if (lw->leaves[i].reach > rmax)
            rmax = lw->leaves[i].reach;
    h->cell = 2.0 * lw->reach * rmax;
    if (!(h->cell > 1e-6))
        h->cell = 1e-6;
    unsigned size = 1;
    while (size < 2u * (unsigned)n)
        size <<= 1;
    h->mask = size - 1;
    h->entries = malloc(sizeof(hash_entry) * n);
    h->start = malloc(sizeof(int) * (size + 1));
    h->cells = malloc(sizeof(long) * 3 * n);
    if (!h->entries || !h->start || !h->cells) {
        free_hash(h);
        return -1;
    }
    for (int i = 0; i < n; i++) {
        long *c = h->cells + 3 * i;
        for (int k = 0; k < 3; k++)
            c[k] = (long)floor(lw->leaves[i].p[k] / h->cell);
        h->entries[i].key = (int)cell_hash(c[0], c[1], c[2], h->mask);
        h->entries[i].leaf = i;
    }
    qsort(h->entries, n, sizeof(hash_entry), cmp_hash);
    for (unsigned k = 0, e = 0; k <= size; k++) {
        while (e < (unsigned)n && (unsigned)h->entries[e].key < k)
            e++;
        h->start[k] = (int)e;
    }
    return 0;
}

/* j into the list of leaf i's nearest (best, by squared distance bestd,
   nb of them so far), if it is among the nearest
   AERO_LEAF_MAX_NEIGHBOURS */
static void keep_nearest(int *best, double *bestd, int *nb, int j, double d2)
{
    int pos = *nb;
    while (pos > 0 && bestd[pos - 1] > d2)
        pos--;
    if (pos >= AERO_LEAF_MAX_NEIGHBOURS)
        return;
    int last = *nb < AERO_LEAF_MAX_NEIGHBOURS ? *nb
                                              : AERO_LEAF_MAX_NEIGHBOURS - 1;
    for (int m = last; m > pos; m--) {
        best[m] = best[m - 1];
        bestd[m] = bestd[m - 1];
    }
    best[pos] = j;
    bestd[pos] = d2;
    if (*nb < AERO_LEAF_MAX_NEIGHBOURS)
        (*nb)++;
}

/* leaf i's nearest neighbours within reach, from the 27 cells around its
   own, nearest first; returns how many */
static int neighbours(const aero_leafwave *lw, const leaf_hash *h, int i,
                      int best[AERO_LEAF_MAX_NEIGHBOURS])
{
    const aero_leaf_state *a = &lw->leaves[i];
    const long *ci = h->cells + 3 * i;
    double bestd[AERO_LEAF_MAX_NEIGHBOURS];
    int nb = 0;
    for (int dx = -1; dx <= 1; dx++)
        for (int dy = -1; dy <= 1; dy++)
            for (int dz = -1; dz <= 1; dz++) {
                long cx = ci[0] + dx, cy = ci[1] + dy, cz = ci[2] + dz;
                unsigned key = cell_hash(cx, cy, cz, h->mask);
                for (int e = h->start[key]; e < h->start[key + 1]; e++) {
                    int j = h->entries[e].leaf;
                    const long *cj = h->cells + 3 * j;
                    /* another cell with the same hash: not this one */
                    if (j == i || cj[0] != cx || cj[1] != cy || cj[2] != cz)
                        continue;
                    const aero_leaf_state *b = &lw->leaves[j];
                    double d2 = 0.0;
                    for (int k = 0; k < 3; k++) {
                        double d = (double)b->p[k] - a->p[k];
                        d2 += d * d;
                    }
                    double lim = lw->reach * (a->reach + b->reach);
                    if (!(d2 > lim * lim))
                        keep_nearest(best, bestd, &nb, j, d2);
                }
            }
    return nb;
}

/* Candidate pairs: rest blade centres closer than reach (r_i + r_j), r the
   leaf's swing radius; each leaf keeps its nearest MAX_NEIGHBOURS. Cells of
   the largest such distance, hashed: each leaf looks at 27 cells, so the
   cost is O(n) for a tree of even density. */
static int build_pairs(aero_leafwave *lw)
{
    int n = lw->nleaves;
    free(lw->pairs);
    lw->pairs = NULL;
    lw->npairs = 0;
    if (n < 2)
        return 0;
    leaf_hash h;
    aero_leaf_pair *pairs = malloc(sizeof(aero_leaf_pair) * (size_t)n *
                                   AERO_LEAF_MAX_NEIGHBOURS);
    if (!pairs || make_hash(lw, &h)) {
        free(pairs);
        return -1;
    }
    int np = 0;
    for (int i = 0; i < n; i++) {
        int best[AERO_LEAF_MAX_NEIGHBOURS];
        int nb = neighbours(lw, &h, i, best);
        for (int m = 0; m < nb; m++) {
            aero_leaf_pair *p = &pairs[np++];
            memset(p, 0, sizeof(*p));
            p->i = i < best[m] ? i : best[m];
            p->j = i < best[m] ? best[m] : i;
        }
    }
    free_hash(&h);
    /* a pair found from both sides is kept once */
    qsort(pairs, np, sizeof(aero_leaf_pair), cmp_pair);
    int unique = 0;
    for (int k = 0; k < np; k++)
        if (!unique || pairs[k].i != pairs[unique - 1].i ||
            pairs[k].j != pairs[unique - 1].j)
            pairs[unique++] = pairs[k];
    for (int k = 0; k < unique; k++) {
        pairs[k].state = AERO_PAIR_INITIAL;
        pairs[k].voice = -1;
        pairs[k].q = 1e30f;
    }
    lw->pairs = pairs;
    lw->npairs = unique;
    return 0;
}

/* ---- voices --------------------------------------------------------------- */

static void reset_voices(aero_leafwave *lw)
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
    v->inc = AERO_LEAF_TABLE_RATE / lw->sample_rate;
    v->hit_decay = (float)exp(-1.0 / (HIT_DECAY_S * lw->sample_rate));
    v->rel_decay = (float)exp(-1.0 / (RELEASE_S * lw->sample_rate));
    pr->voice = best;
    return best;
}

/* raise the collision envelope of pair p's voice to `peak` (Pa at 1 m) */
static void key_on(aero_leafwave *lw, aero_leaf_pair *pr, int p, double frac,
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
    double target = AERO_LEAF_TABLE_RATE / lw->sample_rate;
    v->inc_step = (target - v->inc) / lw->frame_samples;
    v->rub_step = (float)(-v->rub / lw->frame_samples);
}

/* contact: friction at level and table speed set by the sliding speed */
static void rub(aero_leafwave *lw, aero_leaf_pair *pr, int p, double vt)
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
    double target = rate * AERO_LEAF_TABLE_RATE / lw->sample_rate;
    v->inc_step = (target - v->inc) / lw->frame_samples;
    v->rub_step = (float)((level - v->rub) / lw->frame_samples);
}

static void key_off(aero_leafwave *lw, aero_leaf_pair *pr)
{
    if (pr->voice < 0)
        return;
    aero_leaf_voice *v = &lw->voices[pr->voice];
    v->releasing = 1;
    v->rub_step = 0.0f;
    v->inc_step = 0.0;
}

/* ---- one leaf frame ------------------------------------------------------- */

/* each branch's rotation now: the smallest rotation taking its rest axis
   to its moved axis (from the moved end points; the twist about the axis
   is not in the motion's interface). Leaves turn with it. */
static void branch_rotations(aero_leafwave *lw)
{
    const aero_tree *t = &lw->tree;
    for (int b = 0; b < t->nbranches; b++) {
        double *r = lw->branch_rot + 9 * b;
        double pa[3], pb[3], v[3], rest[3], now[3], axis[3];
        aero_tree_motion_point(&lw->motion, b, 0.0, pa, v);
        aero_tree_motion_point(&lw->motion, b, 1.0, pb, v);
        for (int k = 0; k < 3; k++) {
            rest[k] = t->branches[b].b[k] - t->branches[b].a[k];
            now[k] = pb[k] - pa[k];
        }
        aero_normalise3(rest);
        aero_normalise3(now);
        aero_cross3(rest, now, axis);
        double sn = aero_normalise3(axis), cs = aero_dot3(rest, now);
        if (!(sn > 1e-12)) {
            for (int k = 0; k < 9; k++)
                r[k] = k % 4 == 0 ? 1.0 : 0.0;
            continue;
        }
        aero_rotation3(axis, cs, sn, r);
    }
}

/* eqs. 9-13: the leaf's three unit-rms noises N_x, N_y, N_r, each white
   noise through a damped leaf resonance, stepped one frame; its angles
   theta_x, theta_y and theta_r (with the x-r coupling) from amp = W_x,
   W_y, W_r */
static void leaf_angles(aero_leafwave *lw, aero_leaf_state *s,
                        const double amp[3], double angle[3])
{
    const double *c = lw->flutter_coef[s->flutter_class];
    double e0 = aero_uniform(&lw->rng), e1 = aero_uniform(&lw->rng),
           e2 = aero_uniform(&lw->rng);
    double nx = c[0] * s->nx[0] + c[1] * s->nx[1] + c[2] * e0;
    double ny = c[0] * s->ny[0] + c[1] * s->ny[1] + c[2] * e1;
    double nr = c[0] * s->nr[0] + c[1] * s->nr[1] + c[2] * e2;
    s->nx[1] = s->nx[0];
    s->nx[0] = (float)nx;
    s->ny[1] = s->ny[0];
    s->ny[0] = (float)ny;
    s->nr[1] = s->nr[0];
    s->nr[0] = (float)nr;
    angle[0] = limit_angle(amp[0] * nx);
    angle[1] = limit_angle(amp[1] * ny);
    angle[2] = limit_angle(amp[2] * nr + lw->coupling * angle[0]);
}

/* leaf i's pose this frame: its own swing by the angles, turned with its
   branch, from the branch point it rides on; then the blade frame (along
   d, across = the turned rest x made perpendicular to d, normal = d x
   across, then the torsion) */
static void pose_leaf(aero_leafwave *lw, int i, const double angle[3])
{
    aero_leaf_state *s = &lw->leaves[i];
    double sx = sin_small(angle[0]), sy = sin_small(angle[1]);
    double cz = cos_small(angle[0]) * cos_small(angle[1]);
    double d[3], base[3], u[3], nn[3], local[3], off[3], xr[3];
    double bp[3] = {0.0, 0.0, 0.0}, bv[3];
    int bi = lw->tree.leaves[i].branch;
    if (lw->has_motion)
        aero_tree_motion_point(&lw->motion, bi, lw->tree.leaves[i].along, bp,
                               bv);
    else
        for (int k = 0; k < 3; k++)
            bp[k] = s->branch_rest[k];
    for (int k = 0; k < 3; k++) {
        local[k] = s->z[k] * cz + s->x[k] * sx + s->y[k] * sy;
        off[k] = (double)s->base[k] - s->branch_rest[k];
        xr[k] = s->x[k];
    }
    if (lw->has_motion) {
        const double *r = lw->branch_rot + 9 * bi;
        double tmp[3];
        aero_mat3_apply(r, local, d);
        aero_mat3_apply(r, off, tmp);
        for (int k = 0; k < 3; k++)
            off[k] = tmp[k];
        aero_mat3_apply(r, xr, tmp);
        for (int k = 0; k < 3; k++)
            xr[k] = tmp[k];
    } else
        for (int k = 0; k < 3; k++)
            d[k] = local[k];
    for (int k = 0; k < 3; k++)
        base[k] = bp[k] + off[k];
    aero_normalise3(d);
    double xd = aero_dot3(xr, d);
    for (int k = 0; k < 3; k++)
        u[k] = xr[k] - xd * d[k];
    aero_normalise3(u);
    aero_cross3(d, u, nn);
    double cr = cos_small(angle[2]), sr = sin_small(angle[2]);
    for (int k = 0; k < 3; k++) {
        s->p[k] = (float)(base[k] + s->reach * d[k]);
        s->t[k] = (float)d[k];
        s->n[k] = (float)(cr * nn[k] + sr * u[k]);
        s->u[k] = (float)(cr * u[k] - sr * nn[k]);
    }
}

/* eq. 15: P_j - P_i (dv) in the blade frame of leaf i, measured against
   the ellipsoid of the two blades' half sizes (thin across the blade):
   q <= 1 is inside, "A" of fig. 12 */
static float pair_measure(const aero_leaf_state *a, const aero_leaf_state *b,
                          float dv[3])
{
    for (int k = 0; k < 3; k++)
        dv[k] = b->p[k] - a->p[k];
    float lt = dv[0] * a->t[0] + dv[1] * a->t[1] + dv[2] * a->t[2];
    float lu = dv[0] * a->u[0] + dv[1] * a->u[1] + dv[2] * a->u[2];
    float ln = dv[0] * a->n[0] + dv[1] * a->n[1] + dv[2] * a->n[2];
    float hl = a->half_len + b->half_len, hw = a->half_wid + b->half_wid;
    float hn = CONTACT_DEPTH * hw;
    return (lt * lt) / (hl * hl) + (lu * lu) / (hw * hw) +
           (ln * ln) / (hn * hn);
}

/* the blades' relative speed over the last frame (vrel), its part normal
   to blade i (vn) and the sliding part (returned) */
static double pair_speeds(const aero_leaf_pair *pr, const aero_leaf_state *a,
                          const float dv[3], double frame_dt, double *vrel)
{
    float dd[3];
    for (int k = 0; k < 3; k++)
        dd[k] = dv[k] - pr->d[k];
    float dn = dd[0] * a->n[0] + dd[1] * a->n[1] + dd[2] * a->n[2];
    *vrel = sqrt((double)dd[0] * dd[0] + (double)dd[1] * dd[1] +
                 (double)dd[2] * dd[2]) / frame_dt;
    double vn = fabs((double)dn) / frame_dt;
    return sqrt(*vrel * *vrel > vn * vn ? *vrel * *vrel - vn * vn : 0.0);
}

/* pair p's state machine (fig. 12) for this frame */
static void pair_step(aero_leafwave *lw, int p, double frame_dt)
{
    aero_leaf_pair *pr = &lw->pairs[p];
    const aero_leaf_state *a = &lw->leaves[pr->i];
    float dv[3];
    float q = pair_measure(a, &lw->leaves[pr->j], dv);
    int inside = q <= 1.0f;
    float q_prev = pr->q;
    int state = pr->state;
    double vrel = 0.0, vt = 0.0;
    if (state != AERO_PAIR_INITIAL && (inside || q_prev <= 1.0f))
        vt = pair_speeds(pr, a, dv, frame_dt, &vrel);
    switch (state) {
    case AERO_PAIR_INITIAL:
        state = inside ? AERO_PAIR_CONTACT : AERO_PAIR_NONCONTACT;
        break;
    case AERO_PAIR_NONCONTACT:
    case AERO_PAIR_KEYOFF:
        if (inside) {
            /* the crossing time within the last frame, from q */
            double frac = q_prev > 1.0f && q_prev - q > 0.0f
                              ? (q_prev - 1.0) / ((double)q_prev - q)
                              : 0.0;
            state = AERO_PAIR_KEYON;
            key_on(lw, pr, p, clampd(frac, 0.0, 1.0), lw->hit_pa * vrel);
        } else {
            state = AERO_PAIR_NONCONTACT;
            key_off(lw, pr);
        }
        break;
    case AERO_PAIR_KEYON:
    case AERO_PAIR_CONTACT:
        if (inside) {
            state = AERO_PAIR_CONTACT;
            rub(lw, pr, p, vt);
        } else {
            state = AERO_PAIR_KEYOFF;
            key_off(lw, pr);
        }
        break;
    }
    pr->state = state;
    pr->q = q;
    for (int k = 0; k < 3; k++)
        pr->d[k] = dv[k];
}

/* voices that have died away go back to the free stack */
static void free_silent_voices(aero_leafwave *lw)
{
    for (int v = 0; v < lw->nvoices; v++) {
        aero_leaf_voice *vo = &lw->voices[v];
        if (vo->table < 0)
            continue;
        int sounding = vo->pair >= 0 &&
                       lw->pairs[vo->pair].voice == v &&
                       (lw->pairs[vo->pair].state == AERO_PAIR_CONTACT ||
                        lw->pairs[vo->pair].state == AERO_PAIR_KEYON);
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

/* one leaf frame: every leaf moves, every pair is tested and plays */
static void leaf_frame(aero_leafwave *lw, double sway)
{
    const double amp[3] = {sway, SWAY_Y * sway, SWAY_R * sway};
    if (lw->has_motion)
        branch_rotations(lw);
    for (int i = 0; i < lw->nleaves; i++) {
        double angle[3];
        leaf_angles(lw, &lw->leaves[i], amp, angle);
        pose_leaf(lw, i, angle);
    }
    double frame_dt = lw->frame_samples / lw->sample_rate;
    for (int p = 0; p < lw->npairs; p++)
        pair_step(lw, p, frame_dt);
    free_silent_voices(lw);
    lw->frames++;
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
        int idx = (int)(ip & (AERO_LEAF_TABLE_LEN - 1));
        float x = tab[idx] + frac * (tab[idx + 1] - tab[idx]);
        dry[k] += x * (h + r);
        p += d;
        d += inc_step;
        h = h * hit_mul + hit_add;
        r = r * rub_mul + rub_add;
    }
    *pos = fmod(p, AERO_LEAF_TABLE_LEN);
    *inc = d;
    *hit = h;
    *rubv = r;
}

/* voices -> dry pressure at 1 m, n samples */
static void render_voices(aero_leafwave *lw, float *dry, int n)
{
    memset(dry, 0, sizeof(float) * n);
    for (int vi = 0; vi < lw->nvoices; vi++) {
        aero_leaf_voice *v = &lw->voices[vi];
        if (v->table < 0)
            continue;
        const float *tab = lw->tables + (size_t)v->table *
                                            (AERO_LEAF_TABLE_LEN + 1);
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
        if (inc < 0.1 * AERO_LEAF_TABLE_RATE / lw->sample_rate)
            inc = 0.1 * AERO_LEAF_TABLE_RATE / lw->sample_rate;
        v->pos = pos;
        v->inc = inc;
        v->hit = hit < 1e-20f ? 0.0f : hit;
        v->rub = rubv < 1e-20f ? 0.0f : rubv;
    }
}

/* ---- life cycle and setters ---------------------------------------------- */

static void clear_line(aero_leafwave *lw)
{
    if (lw->line)
        memset(lw->line, 0, sizeof(float) * lw->line_len);
    lw->line_pos = 0;
}

static int alloc_line(aero_leafwave *lw, double sr)
{
    int len = (int)(AERO_LEAF_MAX_DISTANCE / AERO_C0 * sr) + 2 * DRY_CHUNK +
              8192;
    float *line = calloc((size_t)len, sizeof(float));
    if (!line)
        return -1;
    free(lw->line);
    lw->line = line;
    lw->line_len = len;
    lw->line_pos = 0;
    lw->render_primed = 0;
    return 0;
}

int aero_leafwave_init(aero_leafwave *lw, double sample_rate, int n_ears,
                       uint32_t seed)
{
    memset(lw, 0, sizeof(*lw));
    if (!(sample_rate >= 1000.0 && sample_rate <= 1e6))
        sample_rate = 44100.0;
    lw->sample_rate = sample_rate;
    lw->n_ears = n_ears == 2 ? 2 : 1;
    lw->seed = seed;
    lw->rng = seed ? seed : 1;
    lw->stiffness = 1.0;
    lw->beta = 5.0 / 3.0;
    lw->sway = 0.6;
    lw->coupling = 0.5;
    lw->flutter_hz = 2.0;
    lw->reach = 1.5;
    lw->hit_pa = 0.01;
    lw->rub_pa = 0.003;
    lw->gain = 1.0;
    lw->mic_k = 1.0;
    lw->fm = 200.0;
    lw->tables_per_octave = 12;
    lw->octaves = 4;
    lw->nvoices = 256;
    lw->frame_samples = floor(sample_rate / AERO_LEAF_FRAME_RATE + 0.5);
    lw->to_next_frame = lw->frame_samples;
    for (int e = 0; e < lw->n_ears; e++) {
        double x = lw->n_ears == 2 ? (e ? 0.1 : -0.1) : 0.0;
        lw->ear[e][0] = lw->ear_target[e][0] = x;
        lw->ear[e][1] = lw->ear_target[e][1] = -10.0;
        lw->ear[e][2] = lw->ear_target[e][2] = 1.7;
    }
    lw->ramp_samples = 0.02 * sample_rate;
    lw->voices = malloc(sizeof(aero_leaf_voice) * lw->nvoices);
    lw->free_voices = malloc(sizeof(int) * lw->nvoices);
    if (!lw->voices || !lw->free_voices || alloc_line(lw, sample_rate) ||
        make_fft(lw) || make_tables(lw)) {
        aero_leafwave_free(lw);
        return -1;
    }
    reset_voices(lw);
    return 0;
}

void aero_leafwave_clear_tree(aero_leafwave *lw)
{
    if (lw->has_motion)
        aero_tree_motion_free(&lw->motion);
    lw->has_motion = 0;
    if (lw->has_tree)
        aero_tree_free(&lw->tree);
    lw->has_tree = 0;
    free_leaves(lw);
    reset_voices(lw);
    clear_line(lw);
}

void aero_leafwave_free(aero_leafwave *lw)
{
    aero_leafwave_clear_tree(lw);
    free(lw->voices);
    free(lw->free_voices);
    free(lw->tables);
    free_fft(lw);
    free(lw->crossings);
    free(lw->crossing_start);
    lw->crossings = lw->crossing_start = NULL;
    free(lw->branch_rot);
    lw->branch_rot = NULL;
    free(lw->line);
    lw->voices = NULL;
    lw->free_voices = NULL;
    lw->tables = NULL;
    lw->line = NULL;
    lw->nvoices = 0;
}

/* (re)starts the leaves and the branch motion of the current tree */
static int restart(aero_leafwave *lw, char *err, size_t errlen)
{
    if (lw->has_motion)
        aero_tree_motion_free(&lw->motion);
    lw->has_motion = 0;
    free_leaves(lw);
    lw->frames = 0;
    lw->keyons_total = 0;
    lw->to_next_frame = lw->frame_samples;
    clear_line(lw);
    reset_voices(lw);
    if (!lw->has_tree)
        return 0;
    free(lw->branch_rot);
    lw->branch_rot = malloc(sizeof(double) * 9 * lw->tree.nbranches);
    if (lw->branch_rot &&
        aero_tree_motion_init(&lw->motion, &lw->tree, lw->seed) == 0) {
        lw->has_motion = 1;
        aero_tree_motion_set_stiffness(&lw->motion, lw->stiffness);
        aero_tree_motion_set_beta(&lw->motion, lw->beta);
    }
    /* distances are measured to the trunk, as [treebranch~] does (the
       midpoint of the first root branch): both objects' sounds arrive
       together */
    for (int k = 0; k < 3; k++)
        lw->source[k] = 0.5 * (lw->tree.branches[0].a[k] +
                               lw->tree.branches[0].b[k]);
    lw->nleaves = lw->tree.nleaves;
    if (lw->nleaves > 0) {
        lw->leaves = calloc((size_t)lw->nleaves, sizeof(aero_leaf_state));
        if (!lw->leaves) {
            lw->nleaves = 0;
            if (err)
                snprintf(err, errlen, "out of memory for %d leaves",
                         lw->tree.nleaves);
            return -1;
        }
        build_leaves(lw);
        if (build_pairs(lw)) {
            free_leaves(lw);
            if (err)
                snprintf(err, errlen, "out of memory for the neighbour lists");
            return -1;
        }
    }
    reset_voices(lw);
    return 0;
}

int aero_leafwave_set_tree(aero_leafwave *lw, aero_tree *t, char *err,
                           size_t errlen)
{
    aero_leafwave_clear_tree(lw);
    if (!t)
        return 0;
    lw->tree = *t;
    memset(t, 0, sizeof(*t));
    lw->has_tree = 1;
    for (int i = 0; i < lw->tree.nleaves; i++) {
        int b = lw->tree.leaves[i].branch;
        if (b < 0 || b >= lw->tree.nbranches) {
            if (err)
                snprintf(err, errlen, "leaf %d names no branch", i);
            aero_leafwave_clear_tree(lw);
            return -1;
        }
    }
    if (restart(lw, err, errlen)) {
        aero_leafwave_clear_tree(lw);
        return -1;
    }
    return 0;
}

int aero_leafwave_set_sample_rate(aero_leafwave *lw, double sr)
{
    if (!(sr >= 1000.0 && sr <= 1e6))
        return -1;
    if (sr == lw->sample_rate && lw->line)
        return 0;
    if (alloc_line(lw, sr))
        return -1;
    double ramp_ms = 1000.0 * lw->ramp_samples / lw->sample_rate;
    lw->sample_rate = sr;
    lw->frame_samples = floor(sr / AERO_LEAF_FRAME_RATE + 0.5);
    lw->to_next_frame = lw->frame_samples;
    aero_leafwave_set_ramp_ms(lw, ramp_ms);
    reset_voices(lw);
    return 0;
}

int aero_leafwave_set_wind(aero_leafwave *lw, double vx, double vy, double vz)
{
    if (!aero_is_finite(vx) || !aero_is_finite(vy) || !aero_is_finite(vz))
        return -1;
    double v[3] = {vx, vy, vz}, s = sqrt(aero_dot3(v, v));
    double lim = AERO_MACH_LIMIT * AERO_C0;
    if (s > lim)
        for (int k = 0; k < 3; k++)
            v[k] *= lim / s;
    for (int k = 0; k < 3; k++) {
        lw->wind[k] = v[k];
        lw->speed_dir[k] = 0.0;
    }
    return s > lim ? -1 : 0;
}

int aero_leafwave_set_speed(aero_leafwave *lw, double speed)
{
    if (!aero_is_finite(speed))
        return -1;
    lw->inlet_speed = speed;
    return fabs(speed) > AERO_MACH_LIMIT * AERO_C0;
}

int aero_leafwave_set_direction(aero_leafwave *lw, double x, double y,
                                double z)
{
    double d[3] = {x, y, z};
    if (!aero_is_finite(x) || !aero_is_finite(y) || !aero_is_finite(z) ||
        !(aero_normalise3(d) > 0.0))
        return -1;
    for (int k = 0; k < 3; k++)
        lw->speed_dir[k] = d[k];
    return 0;
}

int aero_leafwave_set_ears(aero_leafwave *lw, const aero_ears *e)
{
    if (!aero_ears_ok(e, lw->n_ears))
        return -1;
    for (int ear = 0; ear < e->n; ear++) {
        memcpy(lw->ear_target[ear], e->pos[ear], sizeof(lw->ear_target[ear]));
        lw->ramp_left = lw->render_primed ? lw->ramp_samples : 0;
        if (!lw->render_primed)
            for (int k = 0; k < 3; k++)
                lw->ear[ear][k] = lw->ear_target[ear][k];
    }
    return 0;
}

int aero_leafwave_set_gain_db(aero_leafwave *lw, double db)
{
    return aero_set_gain_db(&lw->gain, db);
}

int aero_leafwave_set_ramp_ms(aero_leafwave *lw, double ms)
{
    if (aero_set_ramp_ms(&lw->ramp_samples, ms, lw->sample_rate))
        return -1;
    if (lw->ramp_samples < 1.0)
        lw->ramp_samples = 1.0;
    return 0;
}

int aero_leafwave_set_stiffness(aero_leafwave *lw, double s)
{
    if (aero_set_within(&lw->stiffness, s, AERO_TREE_STIFFNESS_MIN,
                        AERO_TREE_STIFFNESS_MAX))
        return -1;
    if (lw->has_motion)
        aero_tree_motion_set_stiffness(&lw->motion, s);
    return 0;
}

int aero_leafwave_set_beta(aero_leafwave *lw, double beta)
{
    if (aero_set_within(&lw->beta, beta, 0.0, AERO_TREE_BETA_MAX))
        return -1;
    if (lw->has_motion)
        aero_tree_motion_set_beta(&lw->motion, beta);
    return 0;
}

int aero_leafwave_set_mic(aero_leafwave *lw, double x, double y, double z)
{
    if (!aero_is_finite(x) || !aero_is_finite(y) || !aero_is_finite(z))
        return -1;
    lw->mic[0] = x;
    lw->mic[1] = y;
    lw->mic[2] = z;
    return 0;
}

int aero_leafwave_set_mic_k(aero_leafwave *lw, double k)
{
    return aero_set_within(&lw->mic_k, k, 0.0, AERO_LEAFWAVE_MIC_K_MAX);
}

int aero_leafwave_set_sway(aero_leafwave *lw, double rad)
{
    return aero_set_within(&lw->sway, rad, 0.0, AERO_LEAFWAVE_SWAY_MAX);
}

int aero_leafwave_set_coupling(aero_leafwave *lw, double a)
{
    return aero_set_within(&lw->coupling, a, -AERO_LEAFWAVE_COUPLING_MAX,
                           AERO_LEAFWAVE_COUPLING_MAX);
}

int aero_leafwave_set_flutter(aero_leafwave *lw, double hz)
{
    return aero_set_within(&lw->flutter_hz, hz, AERO_LEAFWAVE_FLUTTER_MIN,
                           AERO_LEAFWAVE_FLUTTER_MAX);
}

int aero_leafwave_set_hit(aero_leafwave *lw, double pa)
{
    return aero_set_within(&lw->hit_pa, pa, 0.0, AERO_LEAFWAVE_PA_MAX);
}

int aero_leafwave_set_rub(aero_leafwave *lw, double pa)
{
    return aero_set_within(&lw->rub_pa, pa, 0.0, AERO_LEAFWAVE_PA_MAX);
}

int aero_leafwave_set_reach(aero_leafwave *lw, double factor)
{
    if (aero_set_within(&lw->reach, factor, AERO_LEAFWAVE_REACH_MIN,
                        AERO_LEAFWAVE_REACH_MAX))
        return -1;
    return restart(lw, NULL, 0);
}

int aero_leafwave_set_tables(aero_leafwave *lw, double fm, int per_octave,
                             int octaves)
{
    if (!aero_is_finite(fm) || fm < AERO_LEAFWAVE_FM_MIN ||
        fm > AERO_LEAFWAVE_FM_MAX || per_octave < 1 ||
        per_octave > AERO_LEAFWAVE_PER_OCTAVE_MAX || octaves < 1 ||
        octaves > AERO_LEAFWAVE_OCTAVES_MAX ||
        per_octave * octaves > AERO_LEAFWAVE_TABLES_MAX)
        return -1;
    double old_fm = lw->fm;
    int old_n = lw->tables_per_octave, old_o = lw->octaves;
    lw->fm = fm;
    lw->tables_per_octave = per_octave;
    lw->octaves = octaves;
    if (make_tables(lw)) {
        lw->fm = old_fm;
        lw->tables_per_octave = old_n;
        lw->octaves = old_o;
        return -1;
    }
    for (int i = 0; i < lw->nleaves; i++)
        lw->leaves[i].table = aero_leafwave_table_for(
            lw, lw->tree.leaves[i].length, lw->tree.leaves[i].width);
    reset_voices(lw);
    return 0;
}

int aero_leafwave_set_voices(aero_leafwave *lw, int n)
{
    if (n < 1 || n > AERO_LEAFWAVE_VOICES_MAX)
        return -1;
    if (replace_arrays((void **)&lw->voices, sizeof(aero_leaf_voice) * n,
                       (void **)&lw->free_voices, sizeof(int) * n))
        return -1;
    lw->nvoices = n;
    reset_voices(lw);
    return 0;
}

int aero_leafwave_set_seed(aero_leafwave *lw, uint32_t seed)
{
    lw->seed = seed;
    lw->rng = seed ? seed : 1;
    if (make_tables(lw))
        return -1;
    return restart(lw, NULL, 0);
}

void aero_leafwave_count_states(const aero_leafwave *lw, int counts[5])
{
    for (int s = 0; s < 5; s++)
        counts[s] = 0;
    for (int p = 0; p < lw->npairs; p++)
        counts[lw->pairs[p].state]++;
}

/* ---- process -------------------------------------------------------------- */

/* cardioid of the microphone (eq. 16, C = 0): mu between its axis and the
   direction from the ear to the trunk; no axis: facing the tree */
static double mic_factor(const aero_leafwave *lw, const double ear[3])
{
    double to[3], axis[3] = {lw->mic[0], lw->mic[1], lw->mic[2]};
    for (int k = 0; k < 3; k++)
        to[k] = lw->source[k] - ear[k];
    if (aero_normalise3(axis) <= 0.0 || aero_normalise3(to) <= 0.0 ||
        lw->mic_k == 0.0)
        return 1.0;
    double c = 0.5 * (1.0 + aero_dot3(axis, to));
    return c <= 0.0 ? 0.0 : pow(c, lw->mic_k);
}

/* the wind now: the `wind` vector plus the inlet speed (the mean of the
   block, read before any output) along the set direction, else the
   wind's (+x without one),
   clamped at Mach 0.3; returns 1 when clamped */
static int wind_now(const aero_leafwave *lw, const float *speed, int n,
                    double w[3], double *u)
{
    double u_in = lw->inlet_speed;
    if (speed && n > 0) {
        double sum = 0.0;
        for (int s = 0; s < n; s++)
            sum += speed[s] == speed[s] ? speed[s] : 0.0;
        u_in = sum / n;
        if (!aero_is_finite(u_in))
            u_in = 0.0;
    }
    double dir[3] = {lw->wind[0], lw->wind[1], lw->wind[2]};
    if (aero_dot3(lw->speed_dir, lw->speed_dir) > 0.0) {
        for (int k = 0; k < 3; k++)
            dir[k] = lw->speed_dir[k];
    } else if (aero_normalise3(dir) <= 0.0) {
        dir[0] = 1.0;
        dir[1] = dir[2] = 0.0;
    }
    for (int k = 0; k < 3; k++)
        w[k] = lw->wind[k] + u_in * dir[k];
    double lim = AERO_MACH_LIMIT * AERO_C0;
    *u = sqrt(aero_dot3(w, w));
    if (!(*u > lim))
        return 0;
    for (int k = 0; k < 3; k++)
        w[k] *= lim / *u;
    *u = lim;
    return 1;
}

/* leaf amplitudes follow the drag load U^2 (saturating), their flutter
   rate rises with the wind: the resonators of the flutter classes for
   wind speed u; returns the sway amplitude */
static double flutter_for_wind(aero_leafwave *lw, double u)
{
    double x = (u / WIND_REF) * (u / WIND_REF) / lw->stiffness;
    double f0 = lw->flutter_hz * sqrt(lw->stiffness) * (1.0 + u / FLUTTER_WIND);
    for (int c = 0; c < AERO_LEAF_FLUTTER_CLASSES; c++)
        resonator(f0 * 0.7 * pow(2.0, (double)c / (AERO_LEAF_FLUTTER_CLASSES - 1)),
                  lw->sample_rate / lw->frame_samples, lw->flutter_coef[c]);
    return lw->sway * tanh(x);
}

/* n samples of the leaves' sound, frame by frame, into the delay line */
static void render_dry(aero_leafwave *lw, double sway, int n)
{
    for (int done = 0; done < n;) {
        int seg = n - done;
        if (seg > DRY_CHUNK)
            seg = DRY_CHUNK;
        if (seg > (int)lw->to_next_frame)
            seg = (int)lw->to_next_frame;
        float dry[DRY_CHUNK];
        render_voices(lw, dry, seg);
        for (int s = 0; s < seg; s++) {
            lw->line[lw->line_pos] = dry[s];
            if (++lw->line_pos == lw->line_len)
                lw->line_pos = 0;
        }
        if (lw->has_motion)
            aero_tree_motion_advance(&lw->motion, seg / lw->sample_rate);
        lw->to_next_frame -= seg;
        if (lw->to_next_frame <= 0.0) {
            lw->to_next_frame += lw->frame_samples;
            if (lw->nleaves > 0)
                leaf_frame(lw, sway);
        }
        done += seg;
    }
}

/* the ears glide to their targets over the ramp */
static void glide_ears(aero_leafwave *lw, int n)
{
    if (!(lw->ramp_left > 0))
        return;
    aero_glide_values(&lw->ear[0][0], &lw->ear_target[0][0], 3 * lw->n_ears,
                      aero_glide_fraction(&lw->ramp_left, n));
}

/* ear e reads the line with a moving stylus: delay r / c0 interpolated
   over the block (Doppler), 1/r, the cardioid; the block was written from
   start_pos on */
static void read_ear(aero_leafwave *lw, int e, int start_pos, float *out,
                     int n)
{
    double max_delay = lw->line_len - 2.0 * DRY_CHUNK - 4096.0;
    double r = 0.0;
    for (int k = 0; k < 3; k++)
        r += (lw->ear[e][k] - lw->source[k]) * (lw->ear[e][k] - lw->source[k]);
    r = sqrt(r);
    double delay = clampd(r / AERO_C0 * lw->sample_rate, 1.0, max_delay);
    double amp = lw->gain * mic_factor(lw, lw->ear[e]) /
                 (r > MIN_DISTANCE ? r : MIN_DISTANCE);
    if (!lw->render_primed) {
        lw->delay_prev[e] = delay;
        lw->amp_prev[e] = amp;
    }
    double d0 = lw->delay_prev[e], a0 = lw->amp_prev[e];
    for (int s = 0; s < n; s++) {
        double f = (s + 1.0) / n;
        double dl = d0 + f * (delay - d0);
        double rp = start_pos + s - dl;
        while (rp < 0.0)
            rp += lw->line_len;
        int i0 = (int)rp;
        double fr = rp - i0;
        if (i0 >= lw->line_len)
            i0 -= lw->line_len;
        int i1 = i0 + 1 == lw->line_len ? 0 : i0 + 1;
        double v = lw->line[i0] + fr * (lw->line[i1] - lw->line[i0]);
        double y = v * (a0 + f * (amp - a0));
        out[s] = aero_is_finite(y) ? (float)y : 0.0f;
    }
    lw->delay_prev[e] = delay;
    lw->amp_prev[e] = amp;
}

int aero_leafwave_process(aero_leafwave *lw, const float *speed,
                          float *const *outs, int n)
{
    double w[3], u;
    int clamped = wind_now(lw, speed, n, w, &u);
    if (lw->has_motion)
        aero_tree_motion_set_wind(&lw->motion, w);
    double sway = flutter_for_wind(lw, u);
    int start_pos = lw->line_pos;
    render_dry(lw, sway, n);
    glide_ears(lw, n);
    for (int e = 0; e < lw->n_ears; e++)
        read_ear(lw, e, start_pos, outs[e], n);
    lw->render_primed = 1;
    return clamped;
}
