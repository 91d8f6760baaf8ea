/* aero: where the sound is heard: one listener (mono) or two ears (stereo),
 * the one control block every real-time player takes (set_ears). */
#ifndef AERO_EARS_H
#define AERO_EARS_H

#include "aero_util.h"

#define AERO_EARS_MAX 2
/* positions (listener, ears, sources) farther than this from the origin
   along any axis are refused, m */
#define AERO_POSITION_LIMIT 1e5
/* stereo: each ear this far from the listener's centre along x, m (a head
   about 0.2 m across) */
#define AERO_EAR_HALF_SPACING 0.1

typedef struct aero_ears {
    int n;                           /* 1: listener, 2: left and right ear */
    double pos[AERO_EARS_MAX][3];    /* m */
} aero_ears;

/* n values, each finite and within +-limit */
static inline int aero_finite_within(const double *v, int n, double limit)
{
    for (int i = 0; i < n; i++)
        if (!aero_is_finite(v[i]) || fabs(v[i]) > limit)
            return 0;
    return 1;
}

/* finite and within AERO_POSITION_LIMIT on every axis */
static inline int aero_position_ok(const double p[3])
{
    return aero_finite_within(p, 3, AERO_POSITION_LIMIT);
}

/* 1 when e holds 1..max_ears usable positions, else 0 */
static inline int aero_ears_ok(const aero_ears *e, int max_ears)
{
    if (!e || e->n < 1 || e->n > max_ears || e->n > AERO_EARS_MAX)
        return 0;
    for (int k = 0; k < e->n; k++)
        if (!aero_position_ok(e->pos[k]))
            return 0;
    return 1;
}

/* one listener at (x, y, z) */
static inline aero_ears aero_ears_at(double x, double y, double z)
{
    aero_ears e = {1, {{x, y, z}, {x, y, z}}};
    return e;
}

#endif
