/* aero: four lanes of floats, the small vector the real-time players run
 * their per-sample recursions on (four samples at once): GCC's vector
 * extension where the compiler has it (GCC, clang), else a plain array
 * (the portable reference, also built with -DAERO_PORTABLE_LANES). The
 * short names (lane4, l4_*) keep the inner loops readable; everything is
 * static inline, so nothing is exported. */
#ifndef AERO_LANES_H
#define AERO_LANES_H

#include "aero_util.h"

#include <stdint.h>

#define AERO_LANES 4

/* cos and sin of 2 pi p[i], 0 <= p[i] < 2^30, for count arguments at once
 * (independent, so they overlap): reduced to +-1/8 cycle around the
 * nearest quarter k, Taylor to x^12 (error below 1e-11), the quarter
 * applied without a branch */
static inline void aero_cis_cycles(const double *p, double *c, double *s,
                                   int count)
{
    for (int i = 0; i < count; i++) {
        double q = 4.0 * (p[i] - (double)(int)p[i]); /* [0, 4) quarters */
        int k = (int)(q + 0.5);
        double x = (q - k) * (0.5 * AERO_PI), x2 = x * x;
        double sn = x * (1.0 - x2 * (1.0 / 6) * (1.0 - x2 * (1.0 / 20) *
                    (1.0 - x2 * (1.0 / 42) * (1.0 - x2 * (1.0 / 72) *
                    (1.0 - x2 * (1.0 / 110))))));
        double cs = 1.0 - x2 * 0.5 * (1.0 - x2 * (1.0 / 12) * (1.0 - x2 * (1.0 / 30) *
                    (1.0 - x2 * (1.0 / 56) * (1.0 - x2 * (1.0 / 90) *
                    (1.0 - x2 * (1.0 / 132))))));
        /* e^{i k pi / 2} (cs + i sn): k odd swaps, k 1, 2 negate the
           cosine, k 2, 3 the sine */
        double odd = (double)(k & 1);
        double a = cs + odd * (sn - cs), b = sn + odd * (cs - sn);
        c[i] = a * (double)(1 - ((k + 1) & 2));
        s[i] = b * (double)(1 - (k & 2));
    }
}

#if defined(__GNUC__) && !defined(AERO_PORTABLE_LANES)
typedef float lane4 __attribute__((vector_size(16)));
typedef uint32_t lane4u __attribute__((vector_size(16)));
static inline lane4 l4_add(lane4 a, lane4 b) { return a + b; }
static inline lane4 l4_sub(lane4 a, lane4 b) { return a - b; }
static inline lane4 l4_mul(lane4 a, lane4 b) { return a * b; }
static inline lane4 l4_splat(float x) { return (lane4){x, x, x, x}; }
static inline float l4_get(lane4 a, int j) { return a[j]; }
static inline void l4_set(lane4 *a, int j, float x) { (*a)[j] = x; }
/* xorshift32 on each lane; the new words as uniform floats on [-1, 1) */
static inline lane4 l4_uniform(lane4u *state)
{
    lane4u x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    typedef int32_t lane4i __attribute__((vector_size(16)));
    return __builtin_convertvector((lane4i)x, lane4) * (1.0f / 2147483648.0f);
}
/* cos and sin of 2 pi p on each lane, 0 <= p < 2^20, to float precision:
   as aero_cis_cycles, Taylor to x^8, the quarter applied by bit masks */
static inline void l4_cis(lane4 p, lane4 *c, lane4 *s)
{
    typedef int32_t lane4i __attribute__((vector_size(16)));
    lane4 q = 4.0f * (p - __builtin_convertvector(
                              __builtin_convertvector(p, lane4i), lane4));
    lane4i k = __builtin_convertvector(q + 0.5f, lane4i);
    lane4 x = (q - __builtin_convertvector(k, lane4)) * (float)(0.5 * AERO_PI);
    lane4 x2 = x * x;
    lane4 sn = x * (1.0f - x2 * (1.0f / 6) * (1.0f - x2 * (1.0f / 20) *
                    (1.0f - x2 * (1.0f / 42))));
    lane4 cs = 1.0f - x2 * 0.5f * (1.0f - x2 * (1.0f / 12) *
                    (1.0f - x2 * (1.0f / 30) * (1.0f - x2 * (1.0f / 56))));
    lane4i odd = -(k & 1), a = (lane4i)cs, b = (lane4i)sn;
    lane4i ca = (a & ~odd) | (b & odd), sa = (b & ~odd) | (a & odd);
    *c = (lane4)(ca ^ (((k + 1) & 2) << 30));
    *s = (lane4)(sa ^ ((k & 2) << 30));
}
#else
typedef struct { float v[AERO_LANES]; } lane4;
typedef struct { uint32_t v[AERO_LANES]; } lane4u;
#define L4_EACH(expr)                                                     \
    { lane4 r; for (int j = 0; j < AERO_LANES; j++) r.v[j] = (expr); return r; }
static inline lane4 l4_add(lane4 a, lane4 b) L4_EACH(a.v[j] + b.v[j])
static inline lane4 l4_sub(lane4 a, lane4 b) L4_EACH(a.v[j] - b.v[j])
static inline lane4 l4_mul(lane4 a, lane4 b) L4_EACH(a.v[j] * b.v[j])
static inline lane4 l4_splat(float x) L4_EACH(x)
#undef L4_EACH
static inline float l4_get(lane4 a, int j) { return a.v[j]; }
static inline void l4_set(lane4 *a, int j, float x) { a->v[j] = x; }
static inline lane4 l4_uniform(lane4u *state)
{
    lane4 r;
    for (int j = 0; j < AERO_LANES; j++) {
        uint32_t x = state->v[j];
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        state->v[j] = x;
        r.v[j] = (float)(int32_t)x * (1.0f / 2147483648.0f);
    }
    return r;
}
static inline void l4_cis(lane4 p, lane4 *c, lane4 *s)
{
    double pd[AERO_LANES], cd[AERO_LANES], sd[AERO_LANES];
    for (int j = 0; j < AERO_LANES; j++)
        pd[j] = p.v[j];
    aero_cis_cycles(pd, cd, sd, AERO_LANES);
    for (int j = 0; j < AERO_LANES; j++)
        c->v[j] = (float)cd[j], s->v[j] = (float)sd[j];
}
#endif

#endif
