/* aero: a tree of branches and leaves (Matsuyama et al. 2005), read
 * from a plain-text .tree file, shared by [treebranch~], [leafwave~] and
 * `aerotex tree`.
 *
 * File format (one record per line, '#' starts a comment, blank lines ok):
 *   branch <id> <parent> <ax> <ay> <az> <bx> <by> <bz> <d0> <d1>
 *       an internode from start point a to end point b (metres) with the
 *       diameters d0 at a and d1 at b (metres); parent is the id of an
 *       earlier branch, or -1 for a root (the trunk)
 *   leaf <branch> <sx> <sy> <sz> <ex> <ey> <ez> <length> <width>
 *       a leaf on branch <branch>: its stalk runs from s (on the branch) to
 *       e, where the blade of length x width (metres) is attached
 * Ids are any non-negative integers, unique; a parent must appear before
 * its children. A bad line (unknown record, wrong field count, non-finite
 * or non-positive size, unknown parent or branch) is reported with its
 * line number through the report callback and skipped; the rest loads.
 * So is a record beyond the sizes of the largest trees measured (tree.c
 * says whose): a point farther than AERO_TREE_REACH_MAX from the origin
 * (the tree's foot), a branch or stalk longer than that, a branch wider
 * than AERO_TREE_DIAMETER_MAX, a blade longer or wider than
 * AERO_TREE_LEAF_MAX. */
#ifndef AERO_TREE_H
#define AERO_TREE_H
#include <stddef.h>
#include <stdint.h>

#define AERO_TREE_HEIGHT_MAX 130   /* m: the tallest a tree can grow */
#define AERO_TREE_REACH_MAX 200    /* m: 1.5 x that, for crowns and slopes */
#define AERO_TREE_DIAMETER_MAX 20  /* m: ~2 x the widest trunk */
#define AERO_TREE_LEAF_MAX 30      /* m: 1.2 x the longest leaf */
/* the generator's crown spreads up to ~4.5 trunk heights from the foot
   (measured over depths 0..8): a trunk of at most 40 m keeps every point
   within AERO_TREE_REACH_MAX */
#define AERO_TREE_GENERATE_HEIGHT_MAX 40
#define AERO_TREE_STR_(x) #x
#define AERO_TREE_STR(x) AERO_TREE_STR_(x)

typedef struct {
    int id;
    int parent;       /* index into branches[] (not the id), -1 for a root */
    double a[3], b[3]; /* start and end point, m */
    double d0, d1;    /* diameter at a and at b, m */
} aero_branch;

typedef struct {
    int branch;       /* index into branches[] */
    double s[3], e[3]; /* stalk start (on the branch) and end, m */
    double length, width; /* blade, m */
    double along;     /* fraction 0..1 of the branch where s projects */
} aero_leaf;

typedef struct {
    int nbranches, nleaves;
    aero_branch *branches;
    aero_leaf *leaves;
} aero_tree;

/* called once per skipped line; ctx is passed through */
typedef void (*aero_tree_report)(void *ctx, int line, const char *message);

/* reads a .tree file: 0, or -1 (file unreadable, or no valid branch) with a
   message in err; report may be NULL */
int aero_tree_load(const char *path, aero_tree *t, aero_tree_report report,
                   void *ctx, char *err, size_t errlen);
/* the same from a string in memory (tests, fuzzing) */
int aero_tree_parse(const char *text, aero_tree *t, aero_tree_report report,
                    void *ctx, char *err, size_t errlen);
int aero_tree_save(const char *path, const aero_tree *t, char *err,
                   size_t errlen);
void aero_tree_free(aero_tree *t);
/* dst a copy of src (its own arrays); 0 or -1 (out of memory, dst empty) */
int aero_tree_copy(aero_tree *dst, const aero_tree *src);

/* a branch's frame: two unit vectors perpendicular to its unit axis e and
   to each other (the generator's and the motion's); x is horizontal
   unless e is within ~25 deg of vertical */
void aero_tree_perpendiculars(const double e[3], double x[3], double y[3]);

/* a generated tree (aerotex tree): recursive branching from a vertical
   trunk of height `height` (at most AERO_TREE_GENERATE_HEIGHT_MAX) and base
   diameter `diameter` (at most AERO_TREE_DIAMETER_MAX; leaves at most
   AERO_TREE_LEAF_MAX), `depth` levels of
   branching, about `leaves` leaves spread over the outermost branches,
   reproducible from seed; 0 or -1 */
typedef struct {
    int depth;
    int leaves;
    double height, diameter;
    double leaf_length, leaf_width;
    uint32_t seed;
} aero_tree_shape;
int aero_tree_generate(aero_tree *t, const aero_tree_shape *shape);

#endif
