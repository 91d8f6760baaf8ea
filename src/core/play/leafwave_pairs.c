/* aero: [leafwave~]'s neighbour pairs: which blades can touch, found in
 * a k-d tree of their rest centres; see leafwave.c. */
#include "leafwave_internal.h"
#include "aero_air.h"
#include "aero_util.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- neighbour lists from a k-d tree ---------------------------------------
 *
 * A k-d tree (Bentley 1975) of the rest blade centres, split at the median
 * of the widest axis down to buckets of KD_BUCKET leaves, so it is
 * log2(n / KD_BUCKET) deep whatever the geometry; each node keeps the tight
 * box of its leaves. A leaf's search visits the nearer child first and
 * skips a box farther than its largest possible reach or, once it holds
 * AERO_LEAFWAVE_MAX_NEIGHBOURS, not nearer than the farthest of them. Building
 * is O(n log n) (a randomised selection per level); a search O(log n) for
 * any arrangement, including every leaf at one spot, where a spatial hash
 * put them all in one cell and each leaf compared itself with all the
 * others (O(n^2): 1,000,000 leaves did not load in 300 s). Ties in distance
 * at the last place are broken by the search's order (deterministic). */

#define KD_BUCKET 8


typedef struct {
    float lo[3], hi[3]; /* box of the node's leaves */
    int start, end;     /* its leaves: order[start..end) */
    int child;          /* first of two children (adjacent), -1 in a bucket */
} kd_node;

typedef struct {
    const aero_leafwave *lw;
    int *order;
    kd_node *node;
    int nnodes;
    uint32_t rng;
} kd_tree;

static void kd_box(kd_tree *kd, kd_node *nd)
{
    for (int k = 0; k < 3; k++) {
        nd->lo[k] = 1e30f;
        nd->hi[k] = -1e30f;
    }
    for (int e = nd->start; e < nd->end; e++) {
        const float *p = kd->lw->leaves[kd->order[e]].p;
        for (int k = 0; k < 3; k++) {
            if (p[k] < nd->lo[k])
                nd->lo[k] = p[k];
            if (p[k] > nd->hi[k])
                nd->hi[k] = p[k];
        }
    }
}

/* order[lo..hi) rearranged so that order[mid] has the value it would
   have sorted by axis k, no larger one before it and no smaller one after
   (selection with a random pivot and a three-way partition: linear on
   average for any input, equal values included) */
static void kd_select(kd_tree *kd, int lo, int hi, int mid, int k)
{
    const aero_leaf_state *lv = kd->lw->leaves;
    int *o = kd->order;
    while (hi - lo > 1) {
        float pivot = lv[o[lo + (int)(aero_xorshift32(&kd->rng)
                                     % (uint32_t)(hi - lo))]].p[k];
        int lt = lo, i = lo, gt = hi;
        while (i < gt) {
            float v = lv[o[i]].p[k];
            if (v < pivot) {
                int tmp = o[lt];
                o[lt++] = o[i];
                o[i++] = tmp;
            } else if (v > pivot) {
                int tmp = o[--gt];
                o[gt] = o[i];
                o[i] = tmp;
            } else {
                i++;
            }
        }
        if (mid < lt)
            hi = lt;
        else if (mid >= gt)
            lo = gt;
        else
            return;
    }
}

static void kd_build(kd_tree *kd, int ni)
{
    kd_node *nd = &kd->node[ni];
    kd_box(kd, nd);
    nd->child = -1;
    if (nd->end - nd->start <= KD_BUCKET)
        return;
    int axis = 0;
    for (int k = 1; k < 3; k++)
        if ((double)nd->hi[k] - nd->lo[k] > (double)nd->hi[axis] - nd->lo[axis])
            axis = k;
    int mid = nd->start + (nd->end - nd->start) / 2;
    kd_select(kd, nd->start, nd->end, mid, axis);
    int c = kd->nnodes;
    kd->nnodes += 2;
    nd->child = c;
    kd->node[c].start = nd->start;
    kd->node[c].end = mid;
    kd->node[c + 1].start = mid;
    kd->node[c + 1].end = nd->end;
    kd_build(kd, c);
    kd_build(kd, c + 1);
}

static void kd_free(kd_tree *kd)
{
    free(kd->order);
    free(kd->node);
}

static int kd_make(const aero_leafwave *lw, kd_tree *kd)
{
    int n = lw->nleaves;
    kd->lw = lw;
    kd->rng = 0x2545f491u;
    kd->order = malloc(sizeof(int) * (size_t)n);
    /* fewer than 2 n / KD_BUCKET nodes (halves of more than a bucket
       end in buckets of at least KD_BUCKET / 2 leaves) */
    kd->node = malloc(sizeof(kd_node) * (2 * (size_t)n / (KD_BUCKET / 2) + 1));
    if (!kd->order || !kd->node) {
        kd_free(kd);
        return -1;
    }
    for (int i = 0; i < n; i++)
        kd->order[i] = i;
    kd->nnodes = 1;
    kd->node[0].start = 0;
    kd->node[0].end = n;
    kd_build(kd, 0);
    return 0;
}

/* squared distance from q to the node's box: no larger than the distance
   to any leaf in it, in floating point too (each term is a rounded square
   of an exact difference no larger than the leaf's) */
static double kd_box_d2(const kd_node *nd, const float q[3])
{
    double d2 = 0.0;
    for (int k = 0; k < 3; k++) {
        double d = 0.0;
        if (q[k] < nd->lo[k])
            d = (double)nd->lo[k] - q[k];
        else if (q[k] > nd->hi[k])
            d = (double)q[k] - nd->hi[k];
        d2 += d * d;
    }
    return d2;
}

/* j into the list of leaf i's nearest (best, by squared distance bestd,
   nb of them so far), if it is among the nearest
   AERO_LEAFWAVE_MAX_NEIGHBOURS */
static void keep_nearest(int *best, double *bestd, int *nb, int j, double d2)
{
    int pos = *nb;
    while (pos > 0 && bestd[pos - 1] > d2)
        pos--;
    if (pos >= AERO_LEAFWAVE_MAX_NEIGHBOURS)
        return;
    int last = *nb < AERO_LEAFWAVE_MAX_NEIGHBOURS ? *nb
                                              : AERO_LEAFWAVE_MAX_NEIGHBOURS - 1;
    for (int m = last; m > pos; m--) {
        best[m] = best[m - 1];
        bestd[m] = bestd[m - 1];
    }
    best[pos] = j;
    bestd[pos] = d2;
    if (*nb < AERO_LEAFWAVE_MAX_NEIGHBOURS)
        (*nb)++;
}

/* leaf i's search below node ni: best/bestd/nb as in keep_nearest; far2
   the square of the largest distance a neighbour may have */
static void kd_search(const kd_tree *kd, int ni, int i, double far2,
                      int *best, double *bestd, int *nb)
{
    const aero_leafwave *lw = kd->lw;
    const kd_node *nd = &kd->node[ni];
    const aero_leaf_state *a = &lw->leaves[i];
    if (nd->child < 0) {
        for (int e = nd->start; e < nd->end; e++) {
            int j = kd->order[e];
            if (j == i)
                continue;
            const aero_leaf_state *b = &lw->leaves[j];
            double d2 = 0.0;
            for (int k = 0; k < 3; k++) {
                double d = (double)b->p[k] - a->p[k];
                d2 += d * d;
            }
            double lim = lw->reach * (a->reach + b->reach);
            if (!(d2 > lim * lim))
                keep_nearest(best, bestd, nb, j, d2);
        }
        return;
    }
    double d[2];
    d[0] = kd_box_d2(&kd->node[nd->child], a->p);
    d[1] = kd_box_d2(&kd->node[nd->child + 1], a->p);
    int first = d[1] < d[0];
    for (int c = 0; c < 2; c++) {
        int w = c ? !first : first;
        if (d[w] > far2 ||
            (*nb == AERO_LEAFWAVE_MAX_NEIGHBOURS &&
             d[w] >= bestd[AERO_LEAFWAVE_MAX_NEIGHBOURS - 1]))
            continue;
        kd_search(kd, nd->child + w, i, far2, best, bestd, nb);
    }
}

/* leaf i's nearest neighbours within reach, nearest first; returns how
   many. rmax: the largest leaf reach. */
static int neighbours(const kd_tree *kd, int i, float rmax,
                      int best[AERO_LEAFWAVE_MAX_NEIGHBOURS])
{
    const aero_leafwave *lw = kd->lw;
    double bestd[AERO_LEAFWAVE_MAX_NEIGHBOURS];
    /* as the pair's own limit below, with the largest partner */
    double far = lw->reach * (lw->leaves[i].reach + rmax);
    int nb = 0;
    kd_search(kd, 0, i, far * far, best, bestd, &nb);
    return nb;
}

/* Candidate pairs: rest blade centres closer than reach (r_i + r_j), r the
   leaf's swing radius; each leaf keeps its nearest MAX_NEIGHBOURS, found
   in the k-d tree above: O(n log n) for any arrangement of the leaves. */
/* keys[0..n) sorted in place (LSD radix, 11-bit digits, `bits` wide);
   tmp: scratch of n. Linear: a comparison sort of the 8 n candidate pairs
   took most of the load of a large crown. */
static void radix_sort(uint64_t *keys, uint64_t *tmp, size_t n, int bits)
{
    for (int shift = 0; shift < bits; shift += 11) {
        size_t count[2049] = {0};
        for (size_t k = 0; k < n; k++)
            count[((keys[k] >> shift) & 2047u) + 1]++;
        for (int d = 0; d < 2048; d++)
            count[d + 1] += count[d];
        for (size_t k = 0; k < n; k++)
            tmp[count[(keys[k] >> shift) & 2047u]++] = keys[k];
        memcpy(keys, tmp, sizeof(uint64_t) * n);
    }
}

int leafwave_build_pairs(aero_leafwave *lw)
{
    int n = lw->nleaves;
    free(lw->pairs);
    lw->pairs = NULL;
    lw->npairs = 0;
    if (n < 2)
        return 0;
    kd_tree kd;
    size_t cap = (size_t)n * AERO_LEAFWAVE_MAX_NEIGHBOURS;
    /* each candidate as one key, (smaller index) n + larger */
    uint64_t *keys = malloc(sizeof(uint64_t) * cap);
    uint64_t *tmp = malloc(sizeof(uint64_t) * cap);
    if (!keys || !tmp || kd_make(lw, &kd)) {
        free(keys);
        free(tmp);
        return -1;
    }
    float rmax = 0.0f;
    for (int i = 0; i < n; i++)
        if (lw->leaves[i].reach > rmax)
            rmax = lw->leaves[i].reach;
    size_t np = 0;
    for (int i = 0; i < n; i++) {
        int best[AERO_LEAFWAVE_MAX_NEIGHBOURS];
        int nb = neighbours(&kd, i, rmax, best);
        for (int m = 0; m < nb; m++) {
            int a = i < best[m] ? i : best[m], b = i < best[m] ? best[m] : i;
            keys[np++] = (uint64_t)a * (uint64_t)n + (uint64_t)b;
        }
    }
    kd_free(&kd);
    int bits = 1;
    while (bits < 64 && ((uint64_t)n * (uint64_t)n >> bits))
        bits++;
    radix_sort(keys, tmp, np, bits);
    free(tmp);
    /* a pair found from both sides is kept once */
    size_t unique = 0;
    for (size_t k = 0; k < np; k++)
        if (!unique || keys[k] != keys[unique - 1])
            keys[unique++] = keys[k];
    aero_leaf_pair *pairs = calloc(unique, sizeof(aero_leaf_pair));
    if (!pairs) {
        free(keys);
        return -1;
    }
    for (size_t k = 0; k < unique; k++) {
        pairs[k].i = (int)(keys[k] / (uint64_t)n);
        pairs[k].j = (int)(keys[k] % (uint64_t)n);
        pairs[k].state = AERO_LEAFWAVE_PAIR_INITIAL;
        pairs[k].voice = -1;
        pairs[k].q = 1e30f;
    }
    free(keys);
    lw->pairs = pairs;
    lw->npairs = (int)unique;
    return 0;
}
