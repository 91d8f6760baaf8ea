/* fuzz: the tree file parser (src/core/common/tree.c, the .tree files of
 * [treebranch~] and [leafwave~]). Invariants of a tree that loaded: at
 * least one branch; every parent index earlier than its child or -1;
 * every leaf on an existing branch; every number finite, every size > 0,
 * every branch and stalk of non-zero length, every point and size within
 * what a tree can have (what trees/README.md promises of a loaded tree). A small tree that loaded is then handed to the two
 * objects' cores and rendered for a few blocks: the output stays finite.
 * Seeds: trees/small.tree and fuzz/seeds/tree/. */
/* aero-fuzz: seeds trees/small.tree */
#include "fuzz.h"

#include "leafwave.h"
#include "tree.h"
#include "treebranch.h"

static void count_line(void *ctx, int line, const char *message)
{
    (void)line;
    (void)message;
    ++*(int *)ctx;
}

static int finite3(const double *v)
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

/* within the physical ceiling of a tree (tree.h) */
static int within3(const double *v)
{
    return fabs(v[0]) <= AERO_TREE_REACH_MAX &&
           fabs(v[1]) <= AERO_TREE_REACH_MAX &&
           fabs(v[2]) <= AERO_TREE_REACH_MAX;
}

static int same3(const double *a, const double *b)
{
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

/* copies a tree (the cores take theirs over) */
static int tree_copy(const aero_tree *t, aero_tree *c)
{
    c->nbranches = t->nbranches;
    c->nleaves = t->nleaves;
    c->branches = malloc(sizeof(aero_branch) * (size_t)t->nbranches);
    c->leaves = malloc(sizeof(aero_leaf) * (size_t)(t->nleaves + 1));
    if (!c->branches || !c->leaves) {
        free(c->branches);
        free(c->leaves);
        memset(c, 0, sizeof(*c));
        return -1;
    }
    memcpy(c->branches, t->branches, sizeof(aero_branch) * (size_t)t->nbranches);
    if (t->nleaves > 0)
        memcpy(c->leaves, t->leaves, sizeof(aero_leaf) * (size_t)t->nleaves);
    return 0;
}

#define N 256

static void render(const aero_tree *t)
{
    static float l[N], r[N];
    float *outs[2] = {l, r};
    aero_tree c;
    char err[256];
    aero_treebranch tb;
    if (!aero_treebranch_init(&tb, 22050.0, 1)) {
        double w[3] = {12.0, 3.0, 0.0}, ear[3] = {0.0, -3.0, 1.5};
        aero_treebranch_set_stereo(&tb, 1);
        aero_treebranch_set_wind(&tb, w);
        aero_ears both = {2, {{ear[0], ear[1], ear[2]},
                              {ear[0], ear[1], ear[2]}}};
        aero_treebranch_set_ears(&tb, &both);
        if (!tree_copy(t, &c) && aero_treebranch_set_tree(&tb, &c))
            aero_tree_free(&c);
        for (int b = 0; b < 12; b++) {
            aero_treebranch_process(&tb, l, r, N);
            FUZZ_REQUIRE(fuzz_finite(l, N) && fuzz_finite(r, N),
                         "treebranch: non-finite output");
        }
        aero_treebranch_free(&tb);
    }
    aero_leafwave lw;
    if (!aero_leafwave_init(&lw, 22050.0, 2, 1)) {
        aero_leafwave_set_wind(&lw, 12.0, 3.0, 0.0);
        aero_leafwave_set_tables(&lw, 400.0, 2, 2);
        if (!tree_copy(t, &c))
            aero_leafwave_set_tree(&lw, &c, err, sizeof(err));
        for (int b = 0; b < 12; b++) {
            aero_leafwave_process(&lw, NULL, outs, N);
            FUZZ_REQUIRE(fuzz_finite(l, N) && fuzz_finite(r, N),
                         "leafwave: non-finite output");
        }
        aero_leafwave_free(&lw);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[64], err[256];
    int bad = 0;
    aero_tree t;
    int fd = fuzz_file(data, size, path, sizeof(path));
    if (fd < 0)
        return 0;
    int rc = aero_tree_load(path, &t, count_line, &bad, err, sizeof(err));
    fuzz_file_close(fd);
    if (rc) {
        FUZZ_REQUIRE(err[0] != 0, "refused without a message");
        return 0;
    }
    FUZZ_REQUIRE(t.nbranches >= 1, "loaded without a branch");
    for (int i = 0; i < t.nbranches; i++) {
        const aero_branch *b = &t.branches[i];
        FUZZ_REQUIRE(b->parent >= -1 && b->parent < i,
                     "branch %d: parent %d not earlier", i, b->parent);
        FUZZ_REQUIRE(b->id >= 0, "branch %d: id %d", i, b->id);
        FUZZ_REQUIRE(finite3(b->a) && finite3(b->b) && !same3(b->a, b->b),
                     "branch %d: bad end points", i);
        FUZZ_REQUIRE(isfinite(b->d0) && isfinite(b->d1) && b->d0 > 0 &&
                         b->d1 > 0,
                     "branch %d: bad diameters", i);
        FUZZ_REQUIRE(within3(b->a) && within3(b->b) &&
                         b->d0 <= AERO_TREE_DIAMETER_MAX &&
                         b->d1 <= AERO_TREE_DIAMETER_MAX,
                     "branch %d: larger than any tree", i);
        for (int j = 0; j < i && j < 64; j++)
            FUZZ_REQUIRE(t.branches[j].id != b->id, "branch %d: id %d twice",
                         i, b->id);
    }
    for (int i = 0; i < t.nleaves; i++) {
        const aero_leaf *f = &t.leaves[i];
        FUZZ_REQUIRE(f->branch >= 0 && f->branch < t.nbranches,
                     "leaf %d: branch %d", i, f->branch);
        FUZZ_REQUIRE(finite3(f->s) && finite3(f->e) && !same3(f->s, f->e),
                     "leaf %d: bad stalk", i);
        FUZZ_REQUIRE(isfinite(f->length) && isfinite(f->width) &&
                         f->length > 0 && f->width > 0,
                     "leaf %d: bad blade", i);
        FUZZ_REQUIRE(within3(f->s) && within3(f->e) &&
                         f->length <= AERO_TREE_LEAF_MAX &&
                         f->width <= AERO_TREE_LEAF_MAX,
                     "leaf %d: larger than any leaf", i);
        FUZZ_REQUIRE(f->along >= 0 && f->along <= 1, "leaf %d: along %g", i,
                     f->along);
    }
    /* the cores on small trees only (the big ones cost seconds each) */
    if (t.nbranches <= 64 && t.nleaves <= 128)
        render(&t);
    aero_tree_free(&t);
    return 0;
}
