/* aero: [leafwave~]'s leaves on the tree and their contacts: blades
 * posed on the moving branches each frame, and each neighbour pair's
 * contact state (hit, rub, release) that starts and stops voices; see
 * leafwave.c. */
#include "leafwave_internal.h"
#include "aero_air.h"
#include "aero_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

void leafwave_free_leaves(aero_leafwave *lw)
{
    free(lw->leaves);
    free(lw->pairs);
    lw->leaves = NULL;
    lw->pairs = NULL;
    lw->nleaves = lw->npairs = 0;
}

/* rest geometry of every leaf (fig. 10): the blade hangs from the
   stalk end, drooping; the leaf swings rigidly about the stalk start */
void leafwave_build_leaves(aero_leafwave *lw)
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
                                 AERO_LEAFWAVE_FLUTTER_CLASSES);
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
    if (state != AERO_LEAFWAVE_PAIR_INITIAL && (inside || q_prev <= 1.0f))
        vt = pair_speeds(pr, a, dv, frame_dt, &vrel);
    switch (state) {
    case AERO_LEAFWAVE_PAIR_INITIAL:
        state = inside ? AERO_LEAFWAVE_PAIR_CONTACT : AERO_LEAFWAVE_PAIR_NONCONTACT;
        break;
    case AERO_LEAFWAVE_PAIR_NONCONTACT:
    case AERO_LEAFWAVE_PAIR_KEYOFF:
        if (inside) {
            /* the crossing time within the last frame, from q */
            double frac = q_prev > 1.0f && q_prev - q > 0.0f
                              ? (q_prev - 1.0) / ((double)q_prev - q)
                              : 0.0;
            state = AERO_LEAFWAVE_PAIR_KEYON;
            leafwave_key_on(lw, pr, p, clampd(frac, 0.0, 1.0),
                            lw->hit_pa * vrel);
        } else {
            state = AERO_LEAFWAVE_PAIR_NONCONTACT;
            leafwave_key_off(lw, pr);
        }
        break;
    case AERO_LEAFWAVE_PAIR_KEYON:
    case AERO_LEAFWAVE_PAIR_CONTACT:
        if (inside) {
            state = AERO_LEAFWAVE_PAIR_CONTACT;
            leafwave_rub(lw, pr, p, vt);
        } else {
            state = AERO_LEAFWAVE_PAIR_KEYOFF;
            leafwave_key_off(lw, pr);
        }
        break;
    }
    pr->state = state;
    pr->q = q;
    for (int k = 0; k < 3; k++)
        pr->d[k] = dv[k];
}

/* one leaf frame: every leaf moves, every pair is tested and plays */
void leafwave_leaf_frame(aero_leafwave *lw, double sway)
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
    leafwave_free_silent_voices(lw);
    lw->frames++;
}
