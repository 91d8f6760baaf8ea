/* aero: wind-driven branch motion of a tree (Matsuyama et al. 2005, section
 * 3.1): each branch is a cantilever spring loaded by the directional wind load
 * plus 1/f^beta noise; its deflection angle is accumulated from the root,
 * so a child moves with its parent.
 *
 * The motion is a deterministic function of (tree, seed, wind history,
 * parameters) and of time only: it steps internally at a fixed rate
 * (AERO_TREE_MOTION_RATE, independent of sample rate and block size) and
 * interpolates between steps. So [treebranch~] and [leafwave~] loading the
 * same tree with the same seed and wind stay in step while each runs its
 * own copy. */
#ifndef AERO_TREE_MOTION_H
#define AERO_TREE_MOTION_H
#include "tree.h"

/* the stiffness scale [leafwave~] and [treebranch~] take */
#define AERO_TREE_STIFFNESS_MIN 1e-3
#define AERO_TREE_STIFFNESS_MAX 1e3
/* the tree motion's exponent beta (Matsuyama et al. 2005) */
#define AERO_TREE_BETA_MIN 0.0
#define AERO_TREE_BETA_MAX 2.0
/* their defaults: every spring as the tree file states it, Kolmogorov's
   5/3 */
#define AERO_TREE_STIFFNESS_DEFAULT 1.0
#define AERO_TREE_BETA_DEFAULT (5.0 / 3.0)

#define AERO_TREE_MOTION_RATE 200.0 /* steps per second */

typedef struct aero_tree_motion_state aero_tree_motion_state;

typedef struct {
    const aero_tree *tree;
    double wind[3];     /* m/s, world frame */
    double stiffness;   /* scales every branch's spring constant, 1 = default */
    double beta;        /* exponent of the 1/f^beta noise loads */
    double time;        /* seconds since init */
    aero_tree_motion_state *state; /* private */
} aero_tree_motion;

/* 0 or -1 (allocation); the tree must outlive the motion */
int aero_tree_motion_init(aero_tree_motion *m, const aero_tree *t,
                          uint32_t seed);
void aero_tree_motion_set_wind(aero_tree_motion *m, const double wind[3]);
void aero_tree_motion_set_stiffness(aero_tree_motion *m, double stiffness);
void aero_tree_motion_set_beta(aero_tree_motion *m, double beta);
/* moves time forward by dt seconds (any dt >= 0) */
void aero_tree_motion_advance(aero_tree_motion *m, double dt);
/* position and velocity (m, m/s) of the point at fraction u (0 = a,
   1 = b) along branch i, now */
void aero_tree_motion_point(const aero_tree_motion *m, int i, double u,
                            double pos[3], double vel[3]);
void aero_tree_motion_free(aero_tree_motion *m);

#endif
