/* aero: wind-driven branch motion (see tree_motion.h; Matsuyama et al. 2005,
 * section "Branch Movement", eqs. 1-4).
 *
 * Per branch i, with rest axis e_i and two perpendicular axes x_i, y_i:
 *   load    P_i(t) = F_i(t) + P_B,i N_i(t)                        (eqs. 3-4)
 * F_i is the drag of the wind on the branch and everything it carries (its
 * subtree and their leaves), 0.5 rho Cd A |U_perp| U_perp, projected on the
 * plane x_i, y_i; N_i is 1/f^beta noise of unit rms per axis, and
 * P_B,i = G 0.5 rho Cd A |U|^2 with a gust intensity G = 0.3 (so a still
 * tree does not move). Matsuyama et al.'s static spring delta = P / k
 * (eqs. 1-2) is the equilibrium of a damped spring
 *   theta'' = omega^2 (P / k - theta) - 2 zeta omega theta',
 * with the cantilever's flexibility 1/k = l^2 / (2 E I) (tip rotation under
 * a tip load) and omega^2 = (E I / l) / J (the rotational spring of a
 * cantilever over the inertia J of everything it carries about its start;
 * 3 E I / (m l^3) for a bare rod), so branches sway at their own rate
 * instead of following the noise instantly. Deflections are soft-limited to
 * 0.3 rad (tanh), since a real crown reconfigures (streamlines) instead of
 * bending further. Rotation vectors are accumulated from the root (Fig. 6) and
 * every branch is moved rigidly by its accumulated rotation about its own
 * start point, which itself moves with the parent. */
#include "tree_motion.h"
#include "aero_air.h"
#include "aero_util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NOISE_POLES 9          /* one-pole relaxations, an octave apart */
#define NOISE_F_LOW 0.05       /* Hz, lowest corner (9 octaves to 12.8 Hz) */
#define WOOD_E 1.0e10          /* Pa, Young's modulus of green wood (~5-12 GPa) */
#define WOOD_RHO 800.0         /* kg/m^3, green wood */
#define LEAF_MASS_AREA 0.2     /* kg/m^2, fresh leaf blade with stalk */
#define CD_BRANCH 1.2          /* drag coefficient of a cylinder, Re 1e3-1e5 */
#define CD_LEAF 0.5            /* a flat leaf broadside, at low speed */
/* Above ~3 m/s broad leaves roll up and streamline: their drag grows about
   as U instead of U^2 (Vogel 1989, "Drag and reconfiguration of broad
   leaves in high winds", Vogel number ~ -1) */
#define LEAF_RECONFIGURE_SPEED 3.0
#define GUST_INTENSITY 0.3     /* rms load fluctuation / mean load */
#define DAMPING 0.15           /* zeta: structural + aerodynamic damping */
#define MAX_ANGLE 0.3          /* rad, soft limit of a branch's deflection */
#define OMEGA_MIN (2.0 * AERO_PI * 0.2) /* rad/s, slowest sway */

typedef struct {
    double e[3], x[3], y[3]; /* rest axis and its perpendiculars */
    double area_branch, area_leaf; /* own projected areas, m^2 */
    double flex;             /* static rotation per newton, rad/N */
    double omega;            /* rad/s at stiffness 1 */
    double theta[2], theta_vel[2]; /* deflection along x, y, and its rate */
    double noise[2][NOISE_POLES];
    uint32_t rng;
} motion_branch;

struct aero_tree_motion_state {
    int n;
    long step;               /* snapshot 0 is at step / RATE */
    double pole[NOISE_POLES], pole_gain[NOISE_POLES];
    double weight[NOISE_POLES]; /* amplitude weights for 1/f^beta, unit rms */
    motion_branch *br;
    double *force;           /* scratch: subtree loads, 3 per branch */
    double *rotvec;          /* scratch: accumulated rotation vectors */
    /* two snapshots: start point (3) and rotation matrix (9) per branch */
    double *origin[2], *rot[2];
};

/* rotation matrix (row-major) of the rotation vector r (Rodrigues) */
static void rodrigues(const double r[3], double m[9])
{
    double phi = sqrt(aero_dot3(r, r)), k[3];
    if (phi < 1e-12) {
        /* first order: I + [r]x */
        m[0] = 1.0;   m[1] = -r[2]; m[2] = r[1];
        m[3] = r[2];  m[4] = 1.0;   m[5] = -r[0];
        m[6] = -r[1]; m[7] = r[0];  m[8] = 1.0;
        return;
    }
    k[0] = r[0] / phi;
    k[1] = r[1] / phi;
    k[2] = r[2] / phi;
    aero_rotation3(k, cos(phi), sin(phi), m);
}

/* one-pole relaxation processes with corners an octave apart, summed with
   variance weights f_j^(1 - beta), have a spectrum ~ 1/f^beta between the
   lowest and highest corner for 0 < beta < 2 (each contributes a
   Lorentzian (1/f_j) / (1 + (f/f_j)^2); integrating over log f_j gives
   f^-beta) */
static void set_noise_weights(aero_tree_motion_state *st, double beta)
{
    double sum = 0.0, c[NOISE_POLES];
    int j;
    for (j = 0; j < NOISE_POLES; j++) {
        double fj = NOISE_F_LOW * pow(2.0, j);
        c[j] = pow(fj, 1.0 - beta);
        sum += c[j];
    }
    for (j = 0; j < NOISE_POLES; j++)
        st->weight[j] = sqrt(c[j] / sum);
}

/* computes snapshot `which` (0 or 1) from the current rotations */
static void place_branches(const aero_tree_motion *m, int which)
{
    aero_tree_motion_state *st = m->state;
    const aero_tree *t = m->tree;
    int i, k;
    for (i = 0; i < st->n; i++) {
        const aero_branch *b = &t->branches[i];
        const motion_branch *mb = &st->br[i];
        double *r = &st->rotvec[3 * i], *o = &st->origin[which][3 * i];
        double *rm = &st->rot[which][9 * i];
        /* this branch's rotation: tip moved along x by theta[0], along y
           by theta[1]: rotation vector theta0 (e x x) + theta1 (e x y) =
           theta0 y - theta1 x */
        for (k = 0; k < 3; k++)
            r[k] = mb->theta[0] * mb->y[k] - mb->theta[1] * mb->x[k];
        if (b->parent >= 0) {
            const aero_branch *p = &t->branches[b->parent];
            double rel[3], moved[3];
            for (k = 0; k < 3; k++) {
                r[k] += st->rotvec[3 * b->parent + k];
                rel[k] = b->a[k] - p->a[k];
            }
            aero_mat3_apply(&st->rot[which][9 * b->parent], rel, moved);
            for (k = 0; k < 3; k++)
                o[k] = st->origin[which][3 * b->parent + k] + moved[k];
        } else {
            for (k = 0; k < 3; k++)
                o[k] = b->a[k];
        }
        rodrigues(r, rm);
    }
}

/* one step of 1 / AERO_TREE_MOTION_RATE seconds */
static void motion_step(aero_tree_motion *m)
{
    aero_tree_motion_state *st = m->state;
    const aero_tree *t = m->tree;
    const double dt = 1.0 / AERO_TREE_MOTION_RATE;
    const double *u = m->wind;
    double speed2 = aero_dot3(u, u), speed = sqrt(speed2);
    double sqrt_stiff = sqrt(m->stiffness);
    double cd_leaf = speed > LEAF_RECONFIGURE_SPEED
        ? CD_LEAF * LEAF_RECONFIGURE_SPEED / speed : CD_LEAF;
    int i, j, k;

    /* own loads: mean drag plus noise (eqs. 3-4) */
    for (i = 0; i < st->n; i++) {
        motion_branch *mb = &st->br[i];
        double *f = &st->force[3 * i], along = aero_dot3(u, mb->e), uperp[3];
        double nperp, q, pb, nx = 0.0, ny = 0.0;
        for (k = 0; k < 3; k++)
            uperp[k] = u[k] - along * mb->e[k];
        nperp = sqrt(aero_dot3(uperp, uperp));
        q = 0.5 * AERO_RHO;
        for (k = 0; k < 3; k++)
            f[k] = q * (CD_BRANCH * mb->area_branch * nperp * uperp[k]
                        + cd_leaf * mb->area_leaf * speed * u[k]);
        for (j = 0; j < NOISE_POLES; j++) {
            double w0 = 1.7320508075688772 * aero_uniform(&mb->rng);
            double w1 = 1.7320508075688772 * aero_uniform(&mb->rng);
            mb->noise[0][j] = st->pole[j] * mb->noise[0][j]
                + st->pole_gain[j] * w0;
            mb->noise[1][j] = st->pole[j] * mb->noise[1][j]
                + st->pole_gain[j] * w1;
            nx += st->weight[j] * mb->noise[0][j];
            ny += st->weight[j] * mb->noise[1][j];
        }
        pb = GUST_INTENSITY * q
            * (CD_BRANCH * mb->area_branch + cd_leaf * mb->area_leaf) * speed2;
        for (k = 0; k < 3; k++)
            f[k] += pb * (nx * mb->x[k] + ny * mb->y[k]);
    }
    /* a branch bears the loads of everything it carries; parents come
       before their children, so one backward pass sums the subtrees */
    for (i = st->n - 1; i > 0; i--) {
        int p = t->branches[i].parent;
        if (p >= 0)
            for (k = 0; k < 3; k++)
                st->force[3 * p + k] += st->force[3 * i + k];
    }
    /* the damped cantilever springs */
    for (i = 0; i < st->n; i++) {
        motion_branch *mb = &st->br[i];
        double *f = &st->force[3 * i], target[2], mag, omega;
        target[0] = mb->flex / m->stiffness * aero_dot3(f, mb->x);
        target[1] = mb->flex / m->stiffness * aero_dot3(f, mb->y);
        mag = sqrt(target[0] * target[0] + target[1] * target[1]);
        if (mag > 1e-12) {
            double lim = MAX_ANGLE * tanh(mag / MAX_ANGLE) / mag;
            target[0] *= lim;
            target[1] *= lim;
        }
        omega = mb->omega * sqrt_stiff;
        if (omega > AERO_TREE_MOTION_RATE) /* keeps omega dt <= 1: stable */
            omega = AERO_TREE_MOTION_RATE;
        for (k = 0; k < 2; k++) {
            /* semi-implicit Euler */
            mb->theta_vel[k] += dt * (omega * omega * (target[k] - mb->theta[k])
                                      - 2.0 * DAMPING * omega
                                            * mb->theta_vel[k]);
            mb->theta[k] += dt * mb->theta_vel[k];
            if (!aero_is_finite(mb->theta[k])) {
                mb->theta[k] = 0.0;
                mb->theta_vel[k] = 0.0;
            }
        }
    }
}

/* the state's arrays for n branches, zeroed; 0 or -1 */
static int alloc_state(aero_tree_motion_state *st, int n)
{
    int k;
    st->n = n;
    st->br = calloc((size_t)n, sizeof *st->br);
    st->force = calloc((size_t)n * 3, sizeof(double));
    st->rotvec = calloc((size_t)n * 3, sizeof(double));
    for (k = 0; k < 2; k++) {
        st->origin[k] = calloc((size_t)n * 3, sizeof(double));
        st->rot[k] = calloc((size_t)n * 9, sizeof(double));
    }
    return st->br && st->force && st->rotvec && st->origin[0]
        && st->origin[1] && st->rot[0] && st->rot[1] ? 0 : -1;
}

/* the noise's one-pole relaxations, an octave apart from NOISE_F_LOW */
static void set_noise_poles(aero_tree_motion_state *st)
{
    int j;
    for (j = 0; j < NOISE_POLES; j++) {
        double fj = NOISE_F_LOW * pow(2.0, j);
        st->pole[j] = exp(-2.0 * AERO_PI * fj / AERO_TREE_MOTION_RATE);
        st->pole_gain[j] = sqrt(1.0 - st->pole[j] * st->pole[j]);
    }
}

/* branch i at rest: its axis and frame, projected area and flexibility
   (tip rotation of a cantilever under a tip load, l^2 / (2 E I)); its
   wood's mass is added to *mass; its own random stream from (seed, i),
   the noise started in its stationary state (no start-up transient) */
static void init_branch(motion_branch *mb, const aero_branch *b, int i,
                        uint32_t seed, double *mass)
{
    double len, dm = 0.5 * (b->d0 + b->d1), area_moment;
    uint32_t rng;
    int j, k;
    for (k = 0; k < 3; k++)
        mb->e[k] = b->b[k] - b->a[k];
    len = sqrt(aero_dot3(mb->e, mb->e));
    if (!(len > 0.0))
        len = 1e-6; /* the parser refuses these; stay finite anyway */
    for (k = 0; k < 3; k++)
        mb->e[k] /= len;
    aero_tree_perpendiculars(mb->e, mb->x, mb->y);
    mb->area_branch = dm * len;
    /* frustum volume pi l (d0^2 + d0 d1 + d1^2) / 12 */
    *mass += WOOD_RHO * AERO_PI * len
        * (b->d0 * b->d0 + b->d0 * b->d1 + b->d1 * b->d1) / 12.0;
    area_moment = AERO_PI * pow(b->d0, 4.0) / 64.0; /* m^4 */
    mb->flex = len * len / (2.0 * WOOD_E * area_moment);
    rng = (seed * 2654435761u) ^ ((uint32_t)(i + 1) * 0x85ebca6bu);
    if (!rng)
        rng = 0x6d2b79f5u;
    for (k = 0; k < 3; k++)
        aero_xorshift32(&rng);
    mb->rng = rng;
    for (k = 0; k < 2; k++)
        for (j = 0; j < NOISE_POLES; j++)
            mb->noise[k][j] = 1.7320508075688772 * aero_uniform(&mb->rng);
}

/* the leaves' area and mass, each on its own branch */
static void add_leaves(aero_tree_motion_state *st, const aero_tree *t,
                       double *mass)
{
    int i;
    for (i = 0; i < t->nleaves; i++) {
        int bi = t->leaves[i].branch;
        if (bi >= 0 && bi < st->n) {
            double area = t->leaves[i].length * t->leaves[i].width;
            st->br[bi].area_leaf += area;
            mass[bi] += LEAF_MASS_AREA * area;
        }
    }
}

/* each branch's sway rate: the rotational spring of a cantilever bent by
   a tip moment, E I / l, over the rotational inertia of everything it
   carries about its start (own mass as a rod about its end, m l^2 / 3,
   each descendant's mass at its midpoint, m |c - a|^2). The descendants'
   moments are gathered in one backward pass (children come after their
   parents), each subtree's moments about its own start moved to the
   parent's start by the parallel-axis theorem: O(n) for any shape, where
   walking every branch's ancestors was O(n depth), quadratic for a long
   chain. mom is scratch of 5 n values (mass, first moment, second
   moment, all about the branch's start), zeroed. */
static void set_sway_rates(aero_tree_motion_state *st, const aero_tree *t,
                           const double *mass, double *mom)
{
    int i, k, n = st->n;
    for (i = n - 1; i >= 0; i--) {
        const aero_branch *b = &t->branches[i];
        double *m = &mom[5 * i], h[3], l2 = 0.0, len, ei, inertia, omega;
        for (k = 0; k < 3; k++) {
            h[k] = 0.5 * (b->b[k] - b->a[k]);
            l2 += (b->b[k] - b->a[k]) * (b->b[k] - b->a[k]);
        }
        /* m[4] holds the descendants' second moment about a */
        inertia = mass[i] * l2 / 3.0 + m[4];
        len = sqrt(l2);
        ei = WOOD_E * AERO_PI * pow(b->d0, 4.0) / 64.0;
        omega = sqrt(ei / (len * inertia));
        if (!(omega > OMEGA_MIN))
            omega = OMEGA_MIN;
        st->br[i].omega = omega;
        if (b->parent >= 0 && b->parent < i) {
            double *pm = &mom[5 * b->parent], d[3], s1d = 0.0, d2 = 0.0;
            /* this subtree (own midpoint included) about a ... */
            m[0] += mass[i];
            for (k = 0; k < 3; k++)
                m[1 + k] += mass[i] * h[k];
            m[4] += mass[i] * 0.25 * l2;
            /* ... then about the parent's start, a_p = a - d */
            for (k = 0; k < 3; k++) {
                d[k] = b->a[k] - t->branches[b->parent].a[k];
                s1d += m[1 + k] * d[k];
                d2 += d[k] * d[k];
            }
            pm[0] += m[0];
            for (k = 0; k < 3; k++)
                pm[1 + k] += m[1 + k] + m[0] * d[k];
            pm[4] += m[4] + 2.0 * s1d + m[0] * d2;
        }
    }
}

int aero_tree_motion_init(aero_tree_motion *m, const aero_tree *t,
                          uint32_t seed)
{
    aero_tree_motion_state *st;
    int n = t ? t->nbranches : 0, i;
    double *mass, *moments;
    memset(m, 0, sizeof *m);
    m->tree = t;
    m->stiffness = 1.0;
    m->beta = 5.0 / 3.0; /* Kolmogorov's inertial-range spectrum of wind */
    if (!t || n < 1)
        return -1;
    st = calloc(1, sizeof *st);
    if (!st)
        return -1;
    m->state = st;
    mass = calloc((size_t)n, sizeof(double));
    moments = calloc((size_t)n * 5, sizeof(double));
    if (!mass || !moments || alloc_state(st, n)) {
        free(mass);
        free(moments);
        aero_tree_motion_free(m);
        return -1;
    }
    set_noise_poles(st);
    set_noise_weights(st, m->beta);
    for (i = 0; i < n; i++)
        init_branch(&st->br[i], &t->branches[i], i, seed, &mass[i]);
    add_leaves(st, t, mass);
    set_sway_rates(st, t, mass, moments);
    free(moments);
    free(mass);
    place_branches(m, 0);
    place_branches(m, 1); /* the tree stands still until wind arrives */
    return 0;
}

void aero_tree_motion_set_wind(aero_tree_motion *m, const double wind[3])
{
    int k;
    for (k = 0; k < 3; k++)
        if (!aero_is_finite(wind[k]))
            return;
    for (k = 0; k < 3; k++)
        m->wind[k] = wind[k];
}

void aero_tree_motion_set_stiffness(aero_tree_motion *m, double stiffness)
{
    if (aero_is_finite(stiffness) && stiffness > 0.0)
        m->stiffness = stiffness < 1e-3 ? 1e-3 : stiffness > 1e3 ? 1e3
            : stiffness;
}

void aero_tree_motion_set_beta(aero_tree_motion *m, double beta)
{
    if (!aero_is_finite(beta))
        return;
    m->beta = beta < 0.0 ? 0.0 : beta > 2.0 ? 2.0 : beta;
    if (m->state)
        set_noise_weights(m->state, m->beta);
}

void aero_tree_motion_advance(aero_tree_motion *m, double dt)
{
    aero_tree_motion_state *st = m->state;
    if (!st || !aero_is_finite(dt) || dt <= 0.0)
        return;
    m->time += dt;
    /* snapshot 0 at step k, snapshot 1 at step k + 1; keep
       k / RATE <= time < (k + 1) / RATE */
    while (m->time * AERO_TREE_MOTION_RATE >= (double)(st->step + 1)) {
        double *o = st->origin[0], *r = st->rot[0];
        st->origin[0] = st->origin[1];
        st->rot[0] = st->rot[1];
        st->origin[1] = o;
        st->rot[1] = r;
        motion_step(m);
        place_branches(m, 1);
        st->step++;
    }
}

void aero_tree_motion_point(const aero_tree_motion *m, int i, double u,
                            double pos[3], double vel[3])
{
    const aero_tree_motion_state *st = m->state;
    const aero_branch *b;
    double rest[3], p[2][3], frac;
    int k, s;
    if (!st || !m->tree || i < 0 || i >= st->n) {
        for (k = 0; k < 3; k++)
            pos[k] = vel[k] = 0.0;
        return;
    }
    b = &m->tree->branches[i];
    if (!(u >= 0.0))
        u = 0.0;
    else if (u > 1.0)
        u = 1.0;
    for (k = 0; k < 3; k++)
        rest[k] = b->b[k] * u + b->a[k] * (1.0 - u) - b->a[k];
    for (s = 0; s < 2; s++) {
        aero_mat3_apply(&st->rot[s][9 * i], rest, p[s]);
        for (k = 0; k < 3; k++)
            p[s][k] += st->origin[s][3 * i + k];
    }
    frac = m->time * AERO_TREE_MOTION_RATE - (double)st->step;
    frac = frac < 0.0 ? 0.0 : frac > 1.0 ? 1.0 : frac;
    for (k = 0; k < 3; k++) {
        pos[k] = p[0][k] + frac * (p[1][k] - p[0][k]);
        vel[k] = (p[1][k] - p[0][k]) * AERO_TREE_MOTION_RATE;
    }
}

void aero_tree_motion_free(aero_tree_motion *m)
{
    aero_tree_motion_state *st = m->state;
    if (st) {
        free(st->br);
        free(st->force);
        free(st->rotvec);
        free(st->origin[0]);
        free(st->origin[1]);
        free(st->rot[0]);
        free(st->rot[1]);
        free(st);
    }
    m->state = NULL;
}
