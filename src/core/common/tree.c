/* aero: .tree files (parser, writer) and the tree generator of
 * `aerotex tree` (see tree.h). */
#include "tree.h"
#include "aero_air.h"
#include "aero_util.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TREE_MAX_FIELDS 12
#define TREE_MAX_FILE (256L * 1024 * 1024) /* refuse absurd files */

static void set_err(char *err, size_t errlen, const char *msg, const char *arg)
{
    if (err && errlen)
        snprintf(err, errlen, msg, arg ? arg : "");
}

/* ---- growing arrays ---------------------------------------------------- */

static int grow(void **p, int *cap, int need, size_t elem)
{
    void *q;
    int n = *cap;
    if (need <= n)
        return 0;
    while (n < need)
        n = n ? 2 * n : 64;
    q = realloc(*p, (size_t)n * elem);
    if (!q)
        return -1;
    *p = q;
    *cap = n;
    return 0;
}

/* ---- branch ids -> indices --------------------------------------------- */

/* Ids are any non-negative integers, so a parser finds a branch by its id
   in an open-addressing hash table (slot = index + 1, 0 empty), kept at
   most half full: O(1) expected per lookup, so a file of n branches and
   leaves parses in O(n) whatever its ids (a linear search per record made a
   200,000-branch chain take a minute). */
typedef struct {
    int *slot;
    unsigned mask; /* table size - 1, a power of two; 0 before the first */
    int count;
} id_index;

/* Murmur3's finaliser (aero_scramble32): every bit of the id moves every
   bit of the slot, so regular ids (multiples of a power of two, a chain
   counting by 1000) spread like any others */
static unsigned id_hash(long id, unsigned mask)
{
    return aero_scramble32((uint32_t)id) & mask;
}

/* index of the branch with this id, or -1 */
static int find_branch(const aero_tree *t, const id_index *ix, long id)
{
    unsigned h;
    if (!ix->mask)
        return -1;
    for (h = id_hash(id, ix->mask); ix->slot[h]; h = (h + 1) & ix->mask) {
        int i = ix->slot[h] - 1;
        if (t->branches[i].id == id)
            return i;
    }
    return -1;
}

static void id_put(const aero_tree *t, id_index *ix, int i)
{
    unsigned h = id_hash(t->branches[i].id, ix->mask);
    while (ix->slot[h])
        h = (h + 1) & ix->mask;
    ix->slot[h] = i + 1;
}

/* branch i (already in t) into the index; 0 or -1 (out of memory) */
static int id_add(const aero_tree *t, id_index *ix, int i)
{
    if (2u * (unsigned)(ix->count + 1) > ix->mask) {
        unsigned size = ix->mask ? 2u * (ix->mask + 1) : 64u, k;
        int *old = ix->slot;
        unsigned oldsize = ix->mask ? ix->mask + 1 : 0;
        int *slot = calloc(size, sizeof *slot);
        if (!slot)
            return -1;
        ix->slot = slot;
        ix->mask = size - 1;
        for (k = 0; k < oldsize; k++)
            if (old[k])
                id_put(t, ix, old[k] - 1);
        free(old);
    }
    id_put(t, ix, i);
    ix->count++;
    return 0;
}

/* ---- parsing ------------------------------------------------------------ */

static int parse_double(const char *s, double *v)
{
    char *end;
    errno = 0;
    *v = strtod(s, &end);
    return end != s && *end == '\0' && aero_is_finite(*v) && errno != ERANGE
        ? 0 : -1;
}

static int parse_long(const char *s, long *v)
{
    char *end;
    errno = 0;
    *v = strtol(s, &end, 10);
    return end != s && *end == '\0' && errno != ERANGE ? 0 : -1;
}

static void report_line(aero_tree_report report, void *ctx, int line,
                        const char *fmt, const char *arg)
{
    char msg[256];
    if (!report)
        return;
    snprintf(msg, sizeof msg, fmt, arg);
    report(ctx, line, msg);
}

static double dist3(const double p[3], const double q[3])
{
    double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

/* fraction 0..1 of segment a-b where p projects */
static double project_along(const double a[3], const double b[3],
                            const double p[3])
{
    double ab[3], ap[3], l2 = 0.0, dot = 0.0, u;
    int k;
    for (k = 0; k < 3; k++) {
        ab[k] = b[k] - a[k];
        ap[k] = p[k] - a[k];
        l2 += ab[k] * ab[k];
        dot += ab[k] * ap[k];
    }
    u = l2 > 0.0 ? dot / l2 : 0.0;
    return u < 0.0 ? 0.0 : u > 1.0 ? 1.0 : u;
}

typedef struct {
    aero_tree *t;
    int bcap, lcap;
    id_index ids;
    aero_tree_report report;
    void *ctx;
} parser;

/* the 8 numbers of a record from f[0] on: two points and two sizes; the
   sizes must be positive (else `sizes` is reported) and the points apart
   (else `zero`); 0, or -1 reported */
static int parse_geometry(parser *p, int line, char **f, double v[8],
                          const char *sizes, const char *zero)
{
    int k;
    for (k = 0; k < 8; k++)
        if (parse_double(f[k], &v[k])) {
            report_line(p->report, p->ctx, line,
                        "'%s' is not a finite number", f[k]);
            return -1;
        }
    if (!(v[6] > 0.0) || !(v[7] > 0.0)) {
        report_line(p->report, p->ctx, line, sizes, "");
        return -1;
    }
    if (!(dist3(v, v + 3) > 0.0)) {
        report_line(p->report, p->ctx, line, zero, "");
        return -1;
    }
    return 0;
}

/* --- the physical ceiling of a tree's geometry -----------------------------
 * Finite numbers no tree has (a corrupt or hostile file: a branch ending at
 * 1e30 m) are refused line by line, like any bad record, against the sizes
 * of the largest trees measured, with a margin (tree.h states the limits):
 * the tallest trees, coast redwoods, reach about 116 m and cannot grow
 * beyond 122-130 m (Koch et al. 2004), so every point lies within
 * AERO_TREE_REACH_MAX of the origin (the tree's foot) and no branch is
 * longer; the widest trunks measure about 11 m across at the ground
 * (General Sherman; Van Pelt 2001); the longest leaves known, of raffia
 * palms, are commonly given as about 25 m (no survey at hand to cite).
 * 0, or -1 reported. */
static int tree_physical_bounds(parser *p, int line, const double v[8],
                                int leaf)
{
    for (int k = 0; k < 6; k++)
        if (!(fabs(v[k]) <= AERO_TREE_REACH_MAX)) {
            char num[64];
            snprintf(num, sizeof num, "%g", v[k]);
            report_line(p->report, p->ctx, line,
                        "coordinate %s m is farther from the tree's foot than "
                        "any tree reaches (at most " AERO_TREE_STR(
                            AERO_TREE_REACH_MAX) " m)", num);
            return -1;
        }
    double len = dist3(v, v + 3);
    double size_max = leaf ? AERO_TREE_LEAF_MAX : AERO_TREE_DIAMETER_MAX;
    if (!(len <= AERO_TREE_REACH_MAX) || !(v[6] <= size_max) ||
        !(v[7] <= size_max)) {
        char num[128];
        snprintf(num, sizeof num, leaf ? "with a stalk of %g m and a blade of "
                 "%g x %g m" : "of %g m, %g to %g m across", len, v[6], v[7]);
        report_line(p->report, p->ctx, line,
                    leaf ? "leaf %s: larger than any leaf (a stalk of at most "
                           AERO_TREE_STR(AERO_TREE_REACH_MAX) " m, a blade "
                           "of at most " AERO_TREE_STR(AERO_TREE_LEAF_MAX)
                           " m)"
                         : "branch %s: larger than any tree's (at most "
                           AERO_TREE_STR(AERO_TREE_REACH_MAX) " m long, "
                           AERO_TREE_STR(AERO_TREE_DIAMETER_MAX)
                           " m across)", num);
        return -1;
    }
    return 0;
}

/* branch <id> <parent id or -1> <ax ay az> <bx by bz> <d0> <d1> */
static int parse_branch(parser *p, int line, char **f, int nf)
{
    aero_tree *t = p->t;
    aero_branch *b;
    double v[8];
    long id, ref;
    int parent = -1;
    if (nf != 11) {
        report_line(p->report, p->ctx, line,
                    "branch needs 10 numbers (id parent ax ay az bx by bz "
                    "d0 d1)%s", "");
        return -1;
    }
    if (parse_long(f[1], &id) || id < 0 || id > 2147483647L) {
        report_line(p->report, p->ctx, line,
                    "bad branch id '%s' (a non-negative integer)", f[1]);
        return -1;
    }
    if (parse_long(f[2], &ref) || ref < -1 || ref > 2147483647L) {
        report_line(p->report, p->ctx, line,
                    "bad parent '%s' (an earlier branch id, or -1)", f[2]);
        return -1;
    }
    if (parse_geometry(p, line, f + 3, v,
                       "branch diameters must be positive%s",
                       "branch has zero length (start = end)%s") ||
        tree_physical_bounds(p, line, v, 0))
        return -1;
    if (find_branch(t, &p->ids, id) >= 0) {
        report_line(p->report, p->ctx, line, "branch id %s used twice", f[1]);
        return -1;
    }
    if (ref >= 0 && (parent = find_branch(t, &p->ids, ref)) < 0) {
        report_line(p->report, p->ctx, line,
                    "parent %s is not an earlier branch", f[2]);
        return -1;
    }
    if (grow((void **)&t->branches, &p->bcap, t->nbranches + 1,
             sizeof *t->branches))
        return -2;
    b = &t->branches[t->nbranches++];
    b->id = (int)id;
    b->parent = parent;
    memcpy(b->a, v, sizeof b->a);
    memcpy(b->b, v + 3, sizeof b->b);
    b->d0 = v[6];
    b->d1 = v[7];
    if (id_add(t, &p->ids, t->nbranches - 1)) {
        t->nbranches--;
        return -2;
    }
    return 0;
}

/* leaf <branch id> <sx sy sz> <ex ey ez> <length> <width> */
static int parse_leaf(parser *p, int line, char **f, int nf)
{
    aero_tree *t = p->t;
    aero_leaf *l;
    double v[8];
    long ref;
    int bi;
    if (nf != 10) {
        report_line(p->report, p->ctx, line,
                    "leaf needs 9 numbers (branch sx sy sz ex ey ez length "
                    "width)%s", "");
        return -1;
    }
    if (parse_long(f[1], &ref) || ref < 0 || ref > 2147483647L
        || (bi = find_branch(t, &p->ids, ref)) < 0) {
        report_line(p->report, p->ctx, line,
                    "leaf on unknown branch '%s' (a branch id given above)",
                    f[1]);
        return -1;
    }
    if (parse_geometry(p, line, f + 2, v,
                       "leaf length and width must be positive%s",
                       "leaf stalk has zero length (start = end)%s") ||
        tree_physical_bounds(p, line, v, 1))
        return -1;
    if (grow((void **)&t->leaves, &p->lcap, t->nleaves + 1,
             sizeof *t->leaves))
        return -2;
    l = &t->leaves[t->nleaves++];
    l->branch = bi;
    memcpy(l->s, v, sizeof l->s);
    memcpy(l->e, v + 3, sizeof l->e);
    l->length = v[6];
    l->width = v[7];
    l->along = project_along(t->branches[bi].a, t->branches[bi].b, l->s);
    return 0;
}

/* one record; 0 accepted, -1 reported and skipped, -2 out of memory */
static int parse_record(parser *p, int line, char **f, int nf)
{
    if (strcmp(f[0], "branch") == 0)
        return parse_branch(p, line, f, nf);
    if (strcmp(f[0], "leaf") == 0)
        return parse_leaf(p, line, f, nf);
    report_line(p->report, p->ctx, line,
                "unknown record '%s' (branch or leaf)", f[0]);
    return -1;
}

int aero_tree_parse(const char *text, aero_tree *t, aero_tree_report report,
                    void *ctx, char *err, size_t errlen)
{
    parser p;
    char linebuf[1024];
    const char *s = text ? text : "";
    int line = 0;
    memset(t, 0, sizeof *t);
    memset(&p, 0, sizeof p);
    p.t = t;
    p.report = report;
    p.ctx = ctx;
    while (*s) {
        const char *eol = s;
        size_t len;
        char *f[TREE_MAX_FIELDS + 1], *c, *hash;
        int nf = 0, toolong = 0;
        while (*eol && *eol != '\n')
            eol++;
        line++;
        len = (size_t)(eol - s);
        if (len >= sizeof linebuf) {
            toolong = 1;
            len = sizeof linebuf - 1;
        }
        memcpy(linebuf, s, len);
        linebuf[len] = '\0';
        s = *eol ? eol + 1 : eol;
        if ((hash = strchr(linebuf, '#')))
            *hash = '\0';
        for (c = linebuf; *c;) {
            while (*c == ' ' || *c == '\t' || *c == '\r')
                *c++ = '\0';
            if (!*c)
                break;
            if (nf <= TREE_MAX_FIELDS)
                f[nf++] = c;
            while (*c && *c != ' ' && *c != '\t' && *c != '\r')
                c++;
        }
        if (nf == 0 && !toolong)
            continue;
        if (toolong) {
            report_line(report, ctx, line, "line longer than %s characters",
                        "1023");
            continue;
        }
        if (nf > TREE_MAX_FIELDS) {
            report_line(report, ctx, line, "too many fields%s", "");
            continue;
        }
        if (parse_record(&p, line, f, nf) == -2) {
            free(p.ids.slot);
            aero_tree_free(t);
            set_err(err, errlen, "out of memory%s", NULL);
            return -1;
        }
    }
    free(p.ids.slot);
    if (t->nbranches == 0) {
        aero_tree_free(t);
        set_err(err, errlen, "no valid branch in the tree%s", NULL);
        return -1;
    }
    return 0;
}

int aero_tree_load(const char *path, aero_tree *t, aero_tree_report report,
                   void *ctx, char *err, size_t errlen)
{
    FILE *fp;
    char *text;
    long size;
    size_t got;
    int r;
    memset(t, 0, sizeof *t);
    fp = fopen(path, "rb");
    if (!fp) {
        if (err && errlen)
            snprintf(err, errlen, "can't open tree %s: %s", path,
                     strerror(errno));
        return -1;
    }
    if (fseek(fp, 0, SEEK_END) || (size = ftell(fp)) < 0
        || size > TREE_MAX_FILE || fseek(fp, 0, SEEK_SET)) {
        fclose(fp);
        set_err(err, errlen, "can't read tree %s (not a regular file, or "
                "too large)", path);
        return -1;
    }
    text = malloc((size_t)size + 1);
    if (!text) {
        fclose(fp);
        set_err(err, errlen, "out of memory reading %s", path);
        return -1;
    }
    got = fread(text, 1, (size_t)size, fp);
    fclose(fp);
    text[got] = '\0';
    if (memchr(text, '\0', got)) {
        free(text);
        set_err(err, errlen, "%s is not a text file", path);
        return -1;
    }
    r = aero_tree_parse(text, t, report, ctx, err, errlen);
    free(text);
    if (r && err && errlen) {
        char inner[200];
        snprintf(inner, sizeof inner, "%s", err);
        snprintf(err, errlen, "%s: %s", path, inner);
    }
    return r;
}

int aero_tree_save(const char *path, const aero_tree *t, char *err,
                   size_t errlen)
{
    FILE *fp = fopen(path, "w");
    int i, ok;
    if (!fp) {
        if (err && errlen)
            snprintf(err, errlen, "can't write %s: %s", path, strerror(errno));
        return -1;
    }
    fprintf(fp, "# aero tree: %d branches, %d leaves (metres)\n",
            t->nbranches, t->nleaves);
    fprintf(fp, "# branch <id> <parent id or -1> <ax ay az> <bx by bz> "
            "<d0> <d1>\n");
    fprintf(fp, "# leaf <branch id> <stalk start sx sy sz> <stalk end ex ey "
            "ez> <length> <width>\n");
    for (i = 0; i < t->nbranches; i++) {
        const aero_branch *b = &t->branches[i];
        fprintf(fp, "branch %d %d %.7g %.7g %.7g %.7g %.7g %.7g %.7g %.7g\n",
                b->id, b->parent >= 0 ? t->branches[b->parent].id : -1,
                b->a[0], b->a[1], b->a[2], b->b[0], b->b[1], b->b[2], b->d0,
                b->d1);
    }
    for (i = 0; i < t->nleaves; i++) {
        const aero_leaf *l = &t->leaves[i];
        fprintf(fp, "leaf %d %.7g %.7g %.7g %.7g %.7g %.7g %.7g %.7g\n",
                t->branches[l->branch].id, l->s[0], l->s[1], l->s[2], l->e[0],
                l->e[1], l->e[2], l->length, l->width);
    }
    ok = !ferror(fp);
    if (fclose(fp) || !ok) {
        set_err(err, errlen, "error writing %s", path);
        return -1;
    }
    return 0;
}

void aero_tree_free(aero_tree *t)
{
    free(t->branches);
    free(t->leaves);
    memset(t, 0, sizeof *t);
}

/* ---- the generator ------------------------------------------------------ */

void aero_tree_perpendiculars(const double e[3], double x[3], double y[3])
{
    double up[3] = {0.0, 0.0, 1.0};
    if (fabs(e[2]) > 0.9) {
        up[0] = 1.0;
        up[2] = 0.0;
    }
    aero_cross3(e, up, x);
    aero_normalise3(x);
    aero_cross3(e, x, y);
}

/* unit direction at polar angle `tilt` from axis e, azimuth `azim` */
static void tilted(const double e[3], double tilt, double azim, double d[3])
{
    double x[3], y[3];
    int k;
    aero_tree_perpendiculars(e, x, y);
    for (k = 0; k < 3; k++)
        d[k] = cos(tilt) * e[k]
            + sin(tilt) * (cos(azim) * x[k] + sin(azim) * y[k]);
    aero_normalise3(d);
}

static double uniform01(uint32_t *rng)
{
    return 0.5 * (aero_uniform(rng) + 1.0);
}

/* Growth rules (a simple self-similar tree; the numbers are the choices of
   this generator, not measurements): every branch above the last level
   forks into 2, 3 or 4 children (probabilities 0.2, 0.55, 0.25: mean 3.05,
   so depth 6 gives about 1160 internodes, the large tree of Matsuyama et
   al. 2005); one child continues the parent's direction within 15 deg, the
   others leave at 30..60 deg, spread around the axis by the golden angle;
   each child is 0.72..0.82 as long as its parent; diameters follow the pipe
   model (Leonardo's rule: the squared diameters of the children add up to
   the parent's squared end diameter) and taper by 0.92 along each
   internode. */
#define GEN_TAPER 0.92
#define GEN_GOLDEN 2.39996322972865332 /* rad, pi (3 - sqrt 5) */

/* the children of branch i (one growth step of the rules above) */
static int grow_children(aero_tree *t, int *bcap, int i, uint32_t *rng)
{
    double r = uniform01(rng), e[3], len;
    int nchild = r < 0.2 ? 2 : r < 0.75 ? 3 : 4, c, k;
    double azim0 = 2.0 * AERO_PI * uniform01(rng);
    aero_branch par = t->branches[i]; /* copy: realloc below */
    for (k = 0; k < 3; k++)
        e[k] = par.b[k] - par.a[k];
    len = dist3(par.a, par.b);
    aero_normalise3(e);
    if (grow((void **)&t->branches, bcap, t->nbranches + nchild,
             sizeof *t->branches))
        return -1;
    for (c = 0; c < nchild; c++) {
        aero_branch *b = &t->branches[t->nbranches];
        double dir[3], tilt, clen, share;
        if (c == 0) { /* the leader */
            tilt = (15.0 * AERO_PI / 180.0) * uniform01(rng);
            share = 1.6;
        } else {
            tilt = (30.0 + 30.0 * uniform01(rng)) * AERO_PI / 180.0;
            share = 1.0;
        }
        tilted(e, tilt, azim0 + c * GEN_GOLDEN, dir);
        clen = len * (0.72 + 0.10 * uniform01(rng));
        b->id = t->nbranches;
        b->parent = i;
        for (k = 0; k < 3; k++) {
            b->a[k] = par.b[k];
            b->b[k] = par.b[k] + clen * dir[k];
        }
        /* pipe model: sum of d^2 over children = parent's d1^2, the
           leader taking a larger share */
        b->d0 = par.d1 * sqrt(share / (nchild - 1 + 1.6));
        b->d1 = b->d0 * GEN_TAPER;
        t->nbranches++;
    }
    return 0;
}

/* leaf i of `count` on the branches from first_terminal on: spread
   evenly, stalks leaving the twig by the golden angle and pointing
   somewhat outward/upward */
static void place_leaf(aero_tree *t, const aero_tree_shape *sh, int i,
                       int first_terminal, uint32_t *rng)
{
    int nterminal = t->nbranches - first_terminal, k;
    int bi = first_terminal + (int)((long long)i * nterminal / sh->leaves);
    const aero_branch *b = &t->branches[bi];
    aero_leaf *l = &t->leaves[t->nleaves++];
    double e[3], dir[3], u, size, stalk;
    for (k = 0; k < 3; k++)
        e[k] = b->b[k] - b->a[k];
    aero_normalise3(e);
    u = 0.15 + 0.85 * uniform01(rng);
    tilted(e, (40.0 + 30.0 * uniform01(rng)) * AERO_PI / 180.0,
           i * GEN_GOLDEN + 0.3 * aero_uniform(rng), dir);
    size = 0.8 + 0.4 * uniform01(rng); /* +-20 % leaf size */
    stalk = 0.3 * sh->leaf_length * size; /* blade ~ stalk, as theirs */
    l->branch = bi;
    for (k = 0; k < 3; k++) {
        l->s[k] = b->a[k] + u * (b->b[k] - b->a[k]);
        l->e[k] = l->s[k] + stalk * dir[k];
    }
    l->length = sh->leaf_length * size;
    l->width = sh->leaf_width * size;
    l->along = u;
}

static int valid_shape(const aero_tree_shape *sh)
{
    return sh->depth >= 0 && sh->depth <= 12 && sh->leaves >= 0
        && sh->leaves <= 10000000 && sh->height > 0.0 && sh->diameter > 0.0
        && sh->leaf_length > 0.0 && sh->leaf_width > 0.0
        && sh->height <= AERO_TREE_GENERATE_HEIGHT_MAX
        && sh->diameter <= AERO_TREE_DIAMETER_MAX
        && sh->leaf_length <= AERO_TREE_LEAF_MAX
        && sh->leaf_width <= AERO_TREE_LEAF_MAX
        && aero_is_finite(sh->height) && aero_is_finite(sh->diameter)
        && aero_is_finite(sh->leaf_length) && aero_is_finite(sh->leaf_width);
}

int aero_tree_generate(aero_tree *t, const aero_tree_shape *shape)
{
    aero_tree_shape sh = *shape;
    uint32_t rng = shape->seed ? shape->seed : 0x9e3779b9u;
    int bcap = 0, lcap = 0, level_start = 0, level_end, level, i;
    memset(t, 0, sizeof *t);
    if (!valid_shape(&sh))
        return -1;
    for (i = 0; i < 4; i++) /* decorrelate nearby seeds */
        aero_xorshift32(&rng);

    if (grow((void **)&t->branches, &bcap, 1, sizeof *t->branches))
        return -1;
    t->nbranches = 1;
    t->branches[0].id = 0;
    t->branches[0].parent = -1;
    memset(t->branches[0].a, 0, sizeof t->branches[0].a);
    t->branches[0].b[0] = 0.0;
    t->branches[0].b[1] = 0.0;
    t->branches[0].b[2] = sh.height;
    t->branches[0].d0 = sh.diameter;
    t->branches[0].d1 = sh.diameter * GEN_TAPER;

    for (level = 0; level < sh.depth; level++) {
        level_end = t->nbranches;
        for (i = level_start; i < level_end; i++)
            if (grow_children(t, &bcap, i, &rng))
                goto oom;
        level_start = level_end;
    }

    /* leaves on the outermost level */
    if (sh.leaves > 0
        && grow((void **)&t->leaves, &lcap, sh.leaves, sizeof *t->leaves))
        goto oom;
    for (i = 0; i < sh.leaves; i++)
        place_leaf(t, &sh, i, level_start, &rng);
    return 0;
oom:
    aero_tree_free(t);
    return -1;
}

int aero_tree_copy(aero_tree *dst, const aero_tree *src)
{
    memset(dst, 0, sizeof *dst);
    if (src->nbranches > 0) {
        dst->branches = malloc(sizeof *dst->branches * (size_t)src->nbranches);
        if (!dst->branches)
            return -1;
        memcpy(dst->branches, src->branches,
               sizeof *dst->branches * (size_t)src->nbranches);
    }
    if (src->nleaves > 0) {
        dst->leaves = malloc(sizeof *dst->leaves * (size_t)src->nleaves);
        if (!dst->leaves) {
            aero_tree_free(dst);
            return -1;
        }
        memcpy(dst->leaves, src->leaves,
               sizeof *dst->leaves * (size_t)src->nleaves);
    }
    dst->nbranches = src->nbranches;
    dst->nleaves = src->nleaves;
    return 0;
}
