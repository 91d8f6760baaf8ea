/* aerotex tree: generates a .tree file (src/core/tree.h) for [treebranch~]
 * and [leafwave~], or checks one. */
#include "aerotex.h"
#include "tree.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int number_arg(int argc, char **argv, int *i, double *v)
{
    char *end;
    if (*i + 1 >= argc) {
        aerotex_error("tree: %s needs a value", argv[*i]);
        return -1;
    }
    errno = 0;
    *v = strtod(argv[*i + 1], &end);
    if (end == argv[*i + 1] || *end || errno || !(*v == *v)) {
        aerotex_error("tree: %s: '%s' is not a number", argv[*i],
                      argv[*i + 1]);
        return -1;
    }
    (*i)++;
    return 0;
}

static void print_report(void *ctx, int line, const char *message)
{
    fprintf(stderr, "aerotex: %s:%d: %s (line skipped)\n", (const char *)ctx,
            line, message);
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

int aerotex_tree(int argc, char **argv)
{
    aero_tree_shape shape;
    aero_tree t;
    const char *out = NULL, *check = NULL;
    char err[512];
    int i, quiet = 0;
    shape.depth = 4;
    shape.leaves = 2000;
    shape.height = 2.0;
    shape.diameter = 0.2;
    shape.leaf_length = 0.08;
    shape.leaf_width = 0.05;
    shape.seed = 1;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        double v;
        if (!strcmp(a, "-o") || !strcmp(a, "--check")) {
            if (i + 1 >= argc) {
                aerotex_error("tree: %s needs a file", a);
                return 2;
            }
            if (!strcmp(a, "-o"))
                out = argv[++i];
            else
                check = argv[++i];
            continue;
        }
        if (!strcmp(a, "-q")) {
            quiet = 1;
            continue;
        }
        if (!strcmp(a, "--depth") || !strcmp(a, "--leaves")
            || !strcmp(a, "--seed") || !strcmp(a, "--height")
            || !strcmp(a, "--diameter") || !strcmp(a, "--leaf-length")
            || !strcmp(a, "--leaf-width")) {
            if (number_arg(argc, argv, &i, &v))
                return 2;
            if (!strcmp(a, "--depth")) {
                if (v < 0 || v > 8 || v != (int)v) {
                    aerotex_error("tree: --depth %g: an integer 0..8", v);
                    return 2;
                }
                shape.depth = (int)v;
            } else if (!strcmp(a, "--leaves")) {
                if (v < 0 || v > 1e6 || v != (int)v) {
                    aerotex_error("tree: --leaves %g: an integer 0..1000000",
                                  v);
                    return 2;
                }
                shape.leaves = (int)v;
            } else if (!strcmp(a, "--seed")) {
                if (v < 0 || v > 4294967295.0 || v != (double)(long long)v) {
                    aerotex_error("tree: --seed %g: an integer 0..2^32-1", v);
                    return 2;
                }
                shape.seed = (uint32_t)(long long)v;
            } else {
                if (!(v > 0.0) || v > 1000.0) {
                    aerotex_error("tree: %s %g: a positive length in metres",
                                  a, v);
                    return 2;
                }
                if (!strcmp(a, "--height"))
                    shape.height = v;
                else if (!strcmp(a, "--diameter"))
                    shape.diameter = v;
                else if (!strcmp(a, "--leaf-length"))
                    shape.leaf_length = v;
                else
                    shape.leaf_width = v;
            }
            continue;
        }
        aerotex_error("tree: unknown option '%s' (try 'aerotex help')", a);
        return 2;
    }
    if (check) {
        if (aero_tree_load(check, &t, print_report, (void *)check, err,
                           sizeof err)) {
            aerotex_error("%s", err);
            return 1;
        }
        describe(&t);
        aero_tree_free(&t);
        return 0;
    }
    if (!out) {
        aerotex_error("tree: -o FILE.tree is required");
        return 2;
    }
    if (aero_tree_generate(&t, &shape)) {
        aerotex_error("tree: can't generate this tree (out of memory?)");
        return 1;
    }
    if (aero_tree_save(out, &t, err, sizeof err)) {
        aerotex_error("%s", err);
        aero_tree_free(&t);
        return 1;
    }
    if (!quiet) {
        printf("file=%s\n", out);
        describe(&t);
    }
    aero_tree_free(&t);
    return 0;
}
