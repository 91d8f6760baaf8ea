/* aero: [leafwave~]'s neighbour pairs: which blades can touch, found by
 * a spatial hash of their rest centres; see leafwave.c. */
#include "leafwave_internal.h"
#include "aero_air.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
int leafwave_build_pairs(aero_leafwave *lw)
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
