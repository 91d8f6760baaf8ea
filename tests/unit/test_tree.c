/* unit tests of src/core/common/tree.c: the .tree parser (bad lines reported with
 * their numbers and skipped), save/load round trip, the generator. */
#include "../../src/core/common/tree.h"
#include "unit.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct {
    int count;
    int lines[32];
    char last[256];
} reports;

static void collect(void *ctx, int line, const char *message)
{
    reports *r = ctx;
    if (r->count < 32)
        r->lines[r->count] = line;
    r->count++;
    snprintf(r->last, sizeof r->last, "%s", message);
}

static int reported(const reports *r, int line)
{
    int i;
    for (i = 0; i < r->count && i < 32; i++)
        if (r->lines[i] == line)
            return 1;
    return 0;
}

UNIT_TEST(parse_good)
{
    const char *text =
        "# a trunk and two branches\n"
        "\n"
        "branch 10 -1  0 0 0  0 0 2  0.2 0.15   # trunk\n"
        "branch 11 10  0 0 2  1 0 3  0.05 0.04\n"
        "\tbranch 12 10 0 0 2 -1 0 3 0.05 0.04\r\n"
        "leaf 11  0.5 0 2.5  0.5 0.05 2.55  0.08 0.05\n"
        "leaf 12 -1 0 3 -1 0 3.05 0.1 0.06";
    aero_tree t;
    reports r = {0};
    char err[256] = "";
    int rc = aero_tree_parse(text, &t, collect, &r, err, sizeof err);
    UNIT_CHECK(rc == 0, "a good tree parses (rc %d, %s)", rc, err);
    UNIT_CHECK(r.count == 0, "no line reported (%d)", r.count);
    UNIT_CHECK(t.nbranches == 3 && t.nleaves == 2,
               "3 branches, 2 leaves (got %d, %d)", t.nbranches, t.nleaves);
    UNIT_CHECK(t.branches[0].parent == -1 && t.branches[1].parent == 0
                   && t.branches[2].parent == 0,
               "parents are indices (%d %d %d)", t.branches[0].parent,
               t.branches[1].parent, t.branches[2].parent);
    UNIT_CHECK(t.branches[2].id == 12 && t.branches[2].b[0] == -1.0
                   && t.branches[2].d1 == 0.04,
               "fields of branch 12 (id %d, bx %g, d1 %g)", t.branches[2].id,
               t.branches[2].b[0], t.branches[2].d1);
    UNIT_CHECK(t.leaves[0].branch == 1 && t.leaves[1].branch == 2,
               "leaves refer to branch indices (%d %d)", t.leaves[0].branch,
               t.leaves[1].branch);
    UNIT_NEAR_REL(t.leaves[0].along, 0.5, 1e-9, "leaf 0 along its branch");
    UNIT_NEAR_REL(t.leaves[1].along, 1.0, 1e-9, "leaf 1 at its branch tip");
    UNIT_CHECK(t.leaves[1].length == 0.1 && t.leaves[1].width == 0.06,
               "leaf blade size (%g x %g)", t.leaves[1].length,
               t.leaves[1].width);
    aero_tree_free(&t);
}

UNIT_TEST(parse_bad_lines)
{
    /* every line from 3 on is wrong in its own way, except 4, 13 and 17 */
    const char *text =
        "# bad lines\n"                                          /* 1 */
        "branch 0 -1 0 0 0 0 0 1 0.1 0.1\n"                      /* 2 ok */
        "branch 1 0 0 0 1 1 0 1\n"                               /* 3 fields */
        "branch 2 0 0 0 1 0 1 2 0.02 0.02\n"                     /* 4 ok */
        "branch 3 7 0 0 1 0 1 2 0.02 0.02\n"                     /* 5 parent */
        "branch 2 0 0 0 1 0 1 2 0.02 0.02\n"                     /* 6 dup id */
        "branch 4 0 0 0 1 0 1 2 0 0.02\n"                        /* 7 d0 = 0 */
        "branch 5 0 0 0 1 0 nan 2 0.02 0.02\n"                   /* 8 NaN */
        "branch 6 0 0 0 1 0 0 1 0.02 0.02\n"                     /* 9 length 0 */
        "twig 7 0 0 0 1 0 1 2 0.02 0.02\n"                       /* 10 record */
        "leaf 9 0 0 1 0 0.1 1 0.05 0.03\n"                       /* 11 branch */
        "leaf 2 0 0 1 0 0.1 1 -0.05 0.03\n"                      /* 12 size */
        "leaf 2 0 0.5 1.5 0 0.6 1.5 0.05 0.03\n"                 /* 13 ok */
        "leaf 2 0 0 1 0 0 1 0.05 0.03\n"                         /* 14 stalk 0 */
        "branch x 0 0 0 1 0 1 2 0.02 0.02\n"                     /* 15 id */
        "branch 8 0 0 0 1 0 1 2 0.02 0.02 9\n"                   /* 16 fields */
        "branch 9 2 0 1 2 0 1 3 1e-3 1e-3\n"                     /* 17 ok */
        "branch 10 0 0 0 1 0 1 2 0.02 inf\n"                     /* 18 inf */
        "branch 11 0 0 0 1 0 1 2 0.02 0.02x\n";                  /* 19 junk */
    int bad[] = {3, 5, 6, 7, 8, 9, 10, 11, 12, 14, 15, 16, 18, 19};
    int good[] = {1, 2, 4, 13, 17};
    int nbad = (int)(sizeof bad / sizeof bad[0]), i, all = 1, none = 1;
    aero_tree t;
    reports r = {0};
    char err[256] = "";
    int rc = aero_tree_parse(text, &t, collect, &r, err, sizeof err);
    UNIT_CHECK(rc == 0, "a file with bad lines still loads (rc %d)", rc);
    UNIT_CHECK(r.count == nbad, "%d bad lines reported (got %d)", nbad,
               r.count);
    for (i = 0; i < nbad; i++)
        if (!reported(&r, bad[i])) {
            all = 0;
            printf("        line %d not reported\n", bad[i]);
        }
    UNIT_CHECK(all, "each bad line reported with its own line number");
    for (i = 0; i < (int)(sizeof good / sizeof good[0]); i++)
        if (reported(&r, good[i]))
            none = 0;
    UNIT_CHECK(none, "no good line reported (negative control)");
    UNIT_CHECK(t.nbranches == 3 && t.nleaves == 1,
               "the good records are kept: 3 branches, 1 leaf (got %d, %d)",
               t.nbranches, t.nleaves);
    UNIT_CHECK(t.branches[2].id == 9 && t.branches[2].parent == 1,
               "branch 9's parent is branch 2 at index 1 (got %d)",
               t.branches[2].parent);
    aero_tree_free(&t);

    /* no report callback: must not crash either */
    rc = aero_tree_parse(text, &t, NULL, NULL, NULL, 0);
    UNIT_CHECK(rc == 0 && t.nbranches == 3, "parsing without a callback");
    aero_tree_free(&t);
}

UNIT_TEST(parse_empty)
{
    aero_tree t;
    char err[256] = "";
    reports r = {0};
    int rc = aero_tree_parse("# nothing\nleaf 0 0 0 0 0 0 1 1 1\n", &t,
                             collect, &r, err, sizeof err);
    UNIT_CHECK(rc == -1 && err[0], "no valid branch: -1 with a message (%s)",
               err);
    UNIT_CHECK(t.nbranches == 0 && t.branches == NULL,
               "and an empty tree (%d)", t.nbranches);
    UNIT_CHECK(r.count == 1 && r.lines[0] == 2,
               "the orphan leaf is reported on line 2");
    rc = aero_tree_parse("", &t, NULL, NULL, err, sizeof err);
    UNIT_CHECK(rc == -1, "an empty text is refused");
    rc = aero_tree_load("/nonexistent/dir/x.tree", &t, NULL, NULL, err,
                        sizeof err);
    UNIT_CHECK(rc == -1 && strstr(err, "x.tree"),
               "a missing file: -1 naming it (%s)", err);
    {
        /* a binary file is not a tree */
        char path[] = "/tmp/aero-tree-binXXXXXX";
        int fd = mkstemp(path);
        const char bin[] = "branch 0 -1 0 0 0 0 0 1 1 1\n\0\1\2";
        if (fd >= 0) {
            if (write(fd, bin, sizeof bin) < 0)
                perror("write");
            close(fd);
        }
        rc = aero_tree_load(path, &t, NULL, NULL, err, sizeof err);
        UNIT_CHECK(rc == -1, "a file with NUL bytes is refused (%s)", err);
        unlink(path);
    }
}

UNIT_TEST(long_line)
{
    size_t n = 5000;
    char *text = malloc(n + 100);
    aero_tree t;
    reports r = {0};
    int rc;
    size_t head;
    strcpy(text, "branch 0 -1 0 0 0 0 0 1 0.1 0.1\nbranch 1 0 ");
    head = strlen(text);
    memset(text + head, '1', n);
    strcpy(text + head + n, "\nbranch 2 0 0 0 1 0 1 2 0.01 0.01\n");
    rc = aero_tree_parse(text, &t, collect, &r, NULL, 0);
    UNIT_CHECK(rc == 0 && t.nbranches == 2 && r.count == 1
                   && r.lines[0] == 2,
               "an over-long line is reported (line %d) and skipped, the "
               "next line still read (%d branches)",
               r.count ? r.lines[0] : -1, t.nbranches);
    aero_tree_free(&t);
    free(text);
}

/* field by field: the struct has padding after `branch` */
static int same_leaves(const aero_tree *a, const aero_tree *b)
{
    int i, k;
    if (a->nleaves != b->nleaves)
        return 0;
    for (i = 0; i < a->nleaves; i++) {
        const aero_leaf *p = &a->leaves[i], *q = &b->leaves[i];
        if (p->branch != q->branch || p->length != q->length
            || p->width != q->width || p->along != q->along)
            return 0;
        for (k = 0; k < 3; k++)
            if (p->s[k] != q->s[k] || p->e[k] != q->e[k])
                return 0;
    }
    return 1;
}

UNIT_TEST(round_trip_and_generator)
{
    aero_tree_shape shape = {6, 16380, 3.0, 0.3, 0.08, 0.05, 7};
    aero_tree t, u, v;
    char path[] = "/tmp/aero-tree-XXXXXX";
    char err[256] = "";
    int fd, rc, i, worst_parent = 1, connected = 1, ids = 1;
    double maxdiff = 0.0, mind = 1e9, maxd = 0.0;
    rc = aero_tree_generate(&t, &shape);
    UNIT_CHECK(rc == 0, "generate depth 6, 16380 leaves");
    /* mean 3.05 children per fork: sum_{L=0..6} 3.05^L = 1196 on
       average; the first forks multiply everything after them, so one
       seed may land some 25 % off; accept 900..1700 */
    UNIT_CHECK(t.nbranches > 900 && t.nbranches < 1700,
               "about 1160 branches (paper's large tree): %d", t.nbranches);
    UNIT_CHECK(t.nleaves == 16380, "16380 leaves: %d", t.nleaves);
    for (i = 0; i < t.nbranches; i++) {
        const aero_branch *b = &t.branches[i];
        if (b->parent >= i)
            worst_parent = 0;
        if (b->parent >= 0) {
            const aero_branch *p = &t.branches[b->parent];
            double d = fabs(p->b[0] - b->a[0]) + fabs(p->b[1] - b->a[1])
                + fabs(p->b[2] - b->a[2]);
            if (d > 1e-9)
                connected = 0;
        }
        if (b->id != i)
            ids = 0;
        if (b->d1 < mind)
            mind = b->d1;
        if (b->d0 > maxd)
            maxd = b->d0;
    }
    UNIT_CHECK(worst_parent, "every parent comes before its children");
    UNIT_CHECK(connected, "every child starts at its parent's end");
    UNIT_CHECK(ids, "ids are the indices");
    UNIT_CHECK(maxd == 0.3 && mind > 0.001 && mind < 0.01,
               "diameters from the 0.3 m trunk down to twigs of a few mm "
               "(thinnest %g m)", mind);
    rc = aero_tree_generate(&u, &shape);
    UNIT_CHECK(rc == 0 && u.nbranches == t.nbranches
                   && memcmp(u.branches, t.branches,
                             sizeof *t.branches * t.nbranches) == 0
                   && same_leaves(&u, &t),
               "the same seed gives the same tree");
    aero_tree_free(&u);
    shape.seed = 8;
    rc = aero_tree_generate(&u, &shape);
    UNIT_CHECK(rc == 0 && (u.nbranches != t.nbranches
                           || memcmp(u.branches, t.branches,
                                     sizeof *t.branches * t.nbranches)),
               "another seed gives another tree (negative control)");
    aero_tree_free(&u);

    fd = mkstemp(path);
    if (fd >= 0)
        close(fd);
    rc = aero_tree_save(path, &t, err, sizeof err);
    UNIT_CHECK(rc == 0, "save (%s)", err);
    rc = aero_tree_load(path, &v, NULL, NULL, err, sizeof err);
    UNIT_CHECK(rc == 0 && v.nbranches == t.nbranches
                   && v.nleaves == t.nleaves,
               "load it back (%d branches, %d leaves)", v.nbranches,
               v.nleaves);
    if (rc == 0) {
        for (i = 0; i < t.nbranches; i++) {
            int k;
            for (k = 0; k < 3; k++) {
                double d = fabs(v.branches[i].b[k] - t.branches[i].b[k]);
                if (d > maxdiff)
                    maxdiff = d;
            }
            if (v.branches[i].parent != t.branches[i].parent)
                maxdiff = 1.0;
        }
        for (i = 0; i < t.nleaves; i++)
            if (v.leaves[i].branch != t.leaves[i].branch
                || fabs(v.leaves[i].width - t.leaves[i].width) > 1e-6)
                maxdiff = 1.0;
        /* %.7g keeps 7 significant digits: < 1e-5 m on a ~10 m tree */
        UNIT_CHECK(maxdiff < 1e-5, "round trip within 7 digits (%g m)",
                   maxdiff);
        aero_tree_free(&v);
    }
    unlink(path);
    aero_tree_free(&t);

    {
        aero_tree_shape bad = {3, 10, -1.0, 0.1, 0.05, 0.03, 1};
        UNIT_CHECK(aero_tree_generate(&u, &bad) == -1 && u.nbranches == 0,
                   "a negative height is refused");
        bad.height = 2.0;
        bad.depth = 0;
        bad.leaves = 5;
        rc = aero_tree_generate(&u, &bad);
        UNIT_CHECK(rc == 0 && u.nbranches == 1 && u.nleaves == 5
                       && u.leaves[0].branch == 0,
                   "depth 0: a trunk carrying the leaves");
        aero_tree_free(&u);
    }
}

/* ids that are not the indices (each a multiple of 2^20, the last of a
   20,000-branch chain first in no order): every parent, leaf and repeat
   found by id (the parser looks ids up in a table, not by a search per
   record: a 200,000-branch chain took a minute) */
UNIT_TEST(parse_any_ids)
{
    const int n = 20000;
    size_t cap = (size_t)n * 80 + 200, len = 0;
    char *text = malloc(cap);
    aero_tree t;
    reports r = {0};
    char err[256] = "";
    int i, wrong = 0;
    UNIT_CHECK(text != NULL, "memory");
    if (!text)
        return;
    for (i = 0; i < n; i++) {
        long id = (long)(n - i) * 1048576L % 2147483647L;
        long parent = i ? (long)(n - i + 1) * 1048576L % 2147483647L : -1;
        len += (size_t)snprintf(text + len, cap - len,
                                "branch %ld %ld 0 0 %g 0 0 %g 0.1 0.1\n", id,
                                parent, i * 0.005, (i + 1) * 0.005);
    }
    len += (size_t)snprintf(text + len, cap - len,
                            "leaf %ld 0 0 0.5 0 0.1 0.5 0.1 0.05\n"
                            "branch %ld -1 0 0 0 0 0 1 0.1 0.1\n",
                            (long)n * 1048576L % 2147483647L,
                            (long)5 * 1048576L % 2147483647L);
    int rc = aero_tree_parse(text, &t, collect, &r, err, sizeof err);
    UNIT_CHECK(rc == 0 && t.nbranches == n && t.nleaves == 1,
               "a %d-branch chain with ids k 2^20 parses (rc %d, %d branches, "
               "%d leaves)", n, rc, t.nbranches, t.nleaves);
    for (i = 1; rc == 0 && i < n; i++)
        if (t.branches[i].parent != i - 1)
            wrong++;
    UNIT_CHECK(rc == 0 && wrong == 0 && t.branches[0].parent == -1,
               "every parent is the branch before (%d wrong)", wrong);
    UNIT_CHECK(rc == 0 && t.leaves[0].branch == 0,
               "the leaf is on the branch its id names (%d)",
               rc == 0 ? t.leaves[0].branch : -1);
    UNIT_CHECK(r.count == 1 && reported(&r, n + 2) &&
                   strstr(r.last, "used twice") != NULL,
               "a repeated id is reported on its line (%d reports, last: %s)",
               r.count, r.last);
    if (rc == 0)
        aero_tree_free(&t);
    free(text);
}

/* The physical ceiling (tree.c): finite sizes no tree has are refused line
   by line, against the largest trees measured (the tallest ~116 m, Koch et
   al. 2004; the widest trunk ~11 m, Van Pelt 2001), while the biggest real
   tree still loads, and so do the shipped trees and the generator's
   largest. */
UNIT_TEST(physical_ceiling)
{
    const char *text =
        "branch 0 -1 0 0 0 0 0 1 0.05 0.04\n"                    /* 1 ok */
        "branch 1 0 0 0 1 1e30 1e30 1e30 0.02 0.02\n"            /* 2 far */
        "branch 2 1 0 0 1 0 1 2 0.02 0.02\n"                     /* 3 parent */
        "branch 3 0 0 0 1 0 0 10001 0.05 0.04\n"                 /* 4 long */
        "branch 4 0 0 0 1 0 1 2 30 0.02\n"                       /* 5 wide */
        "leaf 0 0 0 0.5 0.1 0 0.5 40 0.03\n"                     /* 6 blade */
        "leaf 0 0 0 0.5 -250 0 0.5 0.05 0.03\n"                  /* 7 far */
        /* a General Sherman: 84 m, 11 m at the foot; a 25 m leaf */
        "branch 5 -1 10 0 0 10 0 84 11 1\n"                      /* 8 ok */
        "leaf 5 10 0 50 12 0 50 25 2\n";                         /* 9 ok */
    int bad[] = {2, 3, 4, 5, 6, 7};
    aero_tree t;
    reports r = {0};
    char err[256] = "";
    printf("physical ceiling\n");
    UNIT_CHECK(aero_tree_parse(text, &t, collect, &r, err, sizeof err) == 0,
               "loads: %s", err);
    UNIT_CHECK(r.count == 6, "6 lines refused (got %d; last: %s)", r.count,
               r.last);
    for (int i = 0; i < 6; i++)
        UNIT_CHECK(reported(&r, bad[i]), "line %d refused", bad[i]);
    UNIT_CHECK(!reported(&r, 8) && !reported(&r, 9),
               "the largest real tree and leaf load");
    UNIT_CHECK(t.nbranches == 2 && t.nleaves == 1,
               "2 branches and 1 leaf kept (got %d, %d)", t.nbranches,
               t.nleaves);
    aero_tree_free(&t);
    static const char *shipped[] = {"trees/small.tree", "trees/medium.tree",
                                    "trees/large.tree"};
    for (int i = 0; i < 3; i++) {
        reports s = {0};
        UNIT_CHECK(aero_tree_load(shipped[i], &t, collect, &s, err,
                                  sizeof err) == 0 && s.count == 0,
                   "%s: no line refused (%d)", shipped[i], s.count);
        aero_tree_free(&t);
    }
    /* the generator's largest tree, on a few seeds */
    for (uint32_t seed = 1; seed <= 4; seed++) {
        aero_tree_shape sh = {8, 2000, AERO_TREE_GENERATE_HEIGHT_MAX, 1.0,
                              0.1, 0.05, seed};
        double far = 0.0;
        UNIT_CHECK(aero_tree_generate(&t, &sh) == 0, "generated");
        for (int b = 0; b < t.nbranches; b++)
            for (int k = 0; k < 3; k++) {
                far = fabs(t.branches[b].a[k]) > far ? fabs(t.branches[b].a[k])
                                                     : far;
                far = fabs(t.branches[b].b[k]) > far ? fabs(t.branches[b].b[k])
                                                     : far;
            }
        UNIT_CHECK(far <= AERO_TREE_REACH_MAX,
                   "seed %u: the generator's farthest point %g m <= %d m",
                   (unsigned)seed, far, AERO_TREE_REACH_MAX);
        aero_tree_free(&t);
    }
}

UNIT_MAIN(UNIT_CASE(parse_any_ids), UNIT_CASE(parse_good), UNIT_CASE(parse_bad_lines), UNIT_CASE(parse_empty), UNIT_CASE(long_line), UNIT_CASE(round_trip_and_generator),
          UNIT_CASE(physical_ceiling))
