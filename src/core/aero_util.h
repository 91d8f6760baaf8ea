/* aero: small helpers shared by the core modules (header-only, no state). */
#ifndef AERO_UTIL_H
#define AERO_UTIL_H

#include <stdint.h>

/* xorshift32 (Marsaglia 2003); the state must never be 0 */
static inline uint32_t aero_xorshift32(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return *state = x;
}

/* uniform on [-1, 1) */
static inline double aero_uniform(uint32_t *state)
{
    return (double)(int32_t)aero_xorshift32(state) * (1.0 / 2147483648.0);
}

/* neither NaN nor infinite (works without isfinite's C99 math macros) */
static inline int aero_is_finite(double v)
{
    return v == v && v < 1e300 && v > -1e300;
}

#endif
