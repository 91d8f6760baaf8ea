/* aerotex tree: generates a .tree file (src/core/common/tree.h) for [treebranch~]
 * and [leafwave~], or checks one. */
#include "aerotex.h"
#include "tree.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const char *file;
    int bad; /* lines skipped */
} tree_report;

static void print_report(void *ctx, int line, const char *message)
{
    tree_report *r = ctx;
    r->bad++;
    fprintf(stderr, "aerotex: %s:%d: %s (line skipped)\n", r->file, line,
            message);
}

static void describe(const aero_tree *t)
{
    double lo[3] = {1e30, 1e30, 1e30}, hi[3] = {-1e30, -1e30, -1e30};
    double dmin = 1e30, dmax = 0.0;
    int i, k;
    for (i = 0; i < t->nbranches; i++) {
        const aero_branch *b = &t->branches[i];
        for (k = 0; k < 3; k++) {
            double p = b->a[k], q = b->b[k];
            if (p < lo[k]) lo[k] = p;
            if (q < lo[k]) lo[k] = q;
            if (p > hi[k]) hi[k] = p;
            if (q > hi[k]) hi[k] = q;
        }
        if (b->d1 < dmin) dmin = b->d1;
        if (b->d0 < dmin) dmin = b->d0;
        if (b->d0 > dmax) dmax = b->d0;
        if (b->d1 > dmax) dmax = b->d1;
    }
    printf("branches=%d\nleaves=%d\n", t->nbranches, t->nleaves);
    printf("extent_m=%.3g %.3g %.3g\n", hi[0] - lo[0], hi[1] - lo[1],
           hi[2] - lo[2]);
    printf("diameters_m=%.3g..%.3g\n", dmin, dmax);
}

typedef struct {
    aero_tree_shape shape;
    const char *out, *check;
    int quiet;
} tree_job;

#define AT(field) offsetof(tree_job, field)
static const aerotex_option tree_options[] = {
    {"--depth", AEROTEX_WHOLE, "N", 4.0, 0.0, 8.0, AT(shape.depth),
     "levels of branching (depth 6: ~1160 branches)", NULL, NULL},
    {"--leaves", AEROTEX_WHOLE, "N", 2000.0, 0.0, 1e6, AT(shape.leaves),
     "leaves over the outermost branches", NULL, NULL},
    {"--seed", AEROTEX_SEED, "n", 1.0, 0, 0, AT(shape.seed), "the tree's seed",
     NULL, NULL},
    {"--height", AEROTEX_POSITIVE, "m", 2.0, 0.0,
     AERO_TREE_GENERATE_HEIGHT_MAX, AT(shape.height),
     "trunk height", NULL, NULL},
    {"--diameter", AEROTEX_POSITIVE, "m", 0.2, 0.0, AERO_TREE_DIAMETER_MAX,
     AT(shape.diameter), "trunk diameter at the base", NULL, NULL},
    {"--leaf-length", AEROTEX_POSITIVE, "m", 0.08, 0.0, AERO_TREE_LEAF_MAX,
     AT(shape.leaf_length), "leaf length", NULL, NULL},
    {"--leaf-width", AEROTEX_POSITIVE, "m", 0.05, 0.0, AERO_TREE_LEAF_MAX,
     AT(shape.leaf_width), "leaf width", NULL, NULL},
    {"--check", AEROTEX_TEXT, "FILE.tree", NAN, 0, 0, AT(check),
     "instead: reads a tree, reports bad lines with\ntheir numbers, prints "
     "its size", NULL, NULL},
    {"-q", AEROTEX_SWITCH, NULL, NAN, 1, 0, AT(quiet), "no report", NULL,
     NULL},
    {"-o", AEROTEX_TEXT, "FILE.tree", NAN, 0, 0, AT(out), "the tree", NULL,
     NULL},
    {NULL, 0, NULL, 0, 0, 0, 0, NULL, NULL, NULL}};

/* --check FILE: the exit status, 1 when a line was skipped (what
   [treebranch~] and [leafwave~] would report) */
static int check_tree(const char *file)
{
    aero_tree t;
    char err[512];
    tree_report r = {file, 0};
    if (aero_tree_load(file, &t, print_report, &r, err, sizeof err)) {
        aerotex_error("%s", err);
        return 1;
    }
    describe(&t);
    printf("bad_lines=%d\n", r.bad);
    aero_tree_free(&t);
    return r.bad ? 1 : 0;
}

static int tree_run(int argc, char **argv)
{
    tree_job j;
    aero_tree t;
    char err[512];
    aerotex_defaults(&aerotex_tree_command, &j);
    if (aerotex_parse(&aerotex_tree_command, &j, argc, argv))
        return 2;
    if (j.check)
        return check_tree(j.check);
    if (!j.out) {
        aerotex_error("tree: -o FILE.tree is required");
        return 2;
    }
    if (aero_tree_generate(&t, &j.shape)) {
        aerotex_error("tree: can't generate this tree (out of memory?)");
        return 1;
    }
    if (aero_tree_save(j.out, &t, err, sizeof err)) {
        aerotex_error("%s", err);
        aero_tree_free(&t);
        return 1;
    }
    if (!j.quiet) {
        printf("file=%s\n", j.out);
        describe(&t);
    }
    aero_tree_free(&t);
    return 0;
}

const aerotex_command aerotex_tree_command = {
    "tree", "-o FILE.tree [options] | --check FILE.tree",
    "a tree for [treebranch~] and [leafwave~]: a vertical trunk forking\n"
    "2-4 ways for N levels, leaves spread over the outermost branches",
    tree_options, sizeof(tree_job), NULL, tree_run};
