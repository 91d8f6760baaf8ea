/* aero: small helpers shared by the core modules (header-only, no state). */
#ifndef AERO_UTIL_H
#define AERO_UTIL_H

#include "aero_air.h"
#include "aero_ranges.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

/* writes a message to err (of errlen bytes) when the caller gave one */
static inline void aero_say(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    if (!err || !errlen)
        return;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}

/* releases each of n pointers with `release` (free, fftwf_free, ...) */
static inline void aero_release_each(void (*release)(void *),
                                     void *const *p, size_t n)
{
    for (size_t i = 0; i < n; i++)
        release(p[i]);
}

/* AERO_FREE_ALL(s->a, s->b, ...) frees every array of a module in one line;
 * AERO_RELEASE_ALL(fftwf_free, s->u, s->v) the same with another release */
#define AERO_RELEASE_ALL(release, ...)                                        \
    aero_release_each((release), (void *const[]){__VA_ARGS__},                \
                      sizeof((void *const[]){__VA_ARGS__}) / sizeof(void *))
#define AERO_FREE_ALL(...) AERO_RELEASE_ALL(free, __VA_ARGS__)

/* makes room for item n of `size` bytes in buf (capacity *cap items, doubled
 * from 64 when full); returns the buffer to keep, or NULL (buf untouched) */
static inline void *aero_grow(void *buf, int n, int *cap, size_t size)
{
    int more;
    void *bigger;
    if (n < *cap)
        return buf;
    more = *cap ? 2 * *cap : 64;
    if (!(bigger = realloc(buf, size * (size_t)more)))
        return NULL;
    *cap = more;
    return bigger;
}

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

/* h scrambled (Murmur3's 32-bit finaliser), never 0: a generator started
   from it lies far in the xorshift cycle from one started at h */
static inline uint32_t aero_scramble32(uint32_t h)
{
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    h *= 0xc2b2ae35u;
    h ^= h >> 16;
    return h ? h : 1;
}

/* the seed of run k (0, 1, ...) of several independent runs made from one
   user seed, such as a texture's directions or speeds: the seed scrambled
   by 2^32 over the golden ratio, then a prime step per run, so that
   neighbouring seeds and runs start far apart */
static inline uint32_t aero_run_seed(uint32_t seed, int k)
{
    return seed * 2654435761u + 7919u * (uint32_t)(k + 1);
}

/* neither NaN nor infinite (works without isfinite's C99 math macros) */
/* A speed from a signal inlet, the one policy of every player: NaN is 0;
   a speed beyond Mach 0.3 (1e30, an infinity included) is clamped to it
   and *clamped set, for the player's one report (never silence for a
   loud input). */
static inline float aero_speed_in(float v, int *clamped)
{
    const float lim = (float)(AERO_MACH_LIMIT * AERO_C0);
    if (!(v == v))
        return 0.0f;
    if (v > lim || v < -lim) {
        *clamped = 1;
        return v > 0.0f ? lim : -lim;
    }
    return v;
}

/* The one near-field policy (CONTRIBUTING.md, "One policy per kind of
 * input"). The compact far-field laws (Curle 1955: p ~ r.g / r^2) do not
 * hold closer to a source than about its size, `limit` m (each object
 * states its own). A listener closer is heard as at `limit` along its own
 * direction from the source: only the magnitude of r is clamped, so the
 * level is the same on both sides of the source and continuous across the
 * limit, and nothing changes for a listener at or beyond it. Exactly at the
 * source (|r| below 1e-9 of the limit) the direction is undefined and
 * `dir` (a unit vector: the source's lift, or, for a cavity, the wall's
 * normal) is taken: the loudest way of a lift dipole, so that a listener at a
 * sounding source is never silent.
 * r is the source-to-listener vector, changed in place; returns 1 when the
 * policy acted (the object reports it once, `near` below). */
typedef struct {
    int hit;      /* a listener was within the limit */
    double limit; /* the limit then, m */
} aero_near;

/* records the first time a listener came within `limit` (an object that
   holds its 1/r law at the limit and has no direction to keep) */
static inline void aero_near_seen(aero_near *near, double limit)
{
    if (!near->hit) {
        near->hit = 1;
        near->limit = limit;
    }
}

static inline int aero_near_field(double *r, double limit,
                                  const double *dir, aero_near *near)
{
    double d2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    if (!(d2 < limit * limit))
        return 0;
    double d = sqrt(d2), k;
    if (d < 1e-9 * limit) {
        r[0] = dir[0] * limit;
        r[1] = dir[1] * limit;
        r[2] = dir[2] * limit;
    } else {
        k = limit / d;
        r[0] *= k;
        r[1] *= k;
        r[2] *= k;
    }
    aero_near_seen(near, limit);
    return 1;
}

static inline int aero_is_finite(double v)
{
    return v == v && v < 1e300 && v > -1e300;
}

/* 3-vectors */
static inline double aero_dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void aero_cross3(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* scales a to unit length (a zero vector stays zero); returns |a| */
static inline double aero_normalise3(double *a)
{
    double n = sqrt(aero_dot3(a, a));
    if (n > 0.0) {
        a[0] /= n;
        a[1] /= n;
        a[2] /= n;
    }
    return n;
}

/* R(q) v for a unit quaternion q = (w, x, y, z) */
static inline void aero_quat_rotate(const double *q, const double *v,
                                    double *out)
{
    double u[3] = {q[1], q[2], q[3]}, t[3], c[3];
    aero_cross3(u, v, t);
    for (int i = 0; i < 3; i++)
        t[i] *= 2.0;
    aero_cross3(u, t, c);
    for (int i = 0; i < 3; i++)
        out[i] = v[i] + q[0] * t[i] + c[i];
}

/* a rotation vector (axis times angle in degrees) as a unit quaternion */
static inline void aero_quat_from_rotvec(const double r[3], double q[4])
{
    double axis[3] = {r[0], r[1], r[2]};
    double deg = aero_normalise3(axis);
    double half = 0.5 * deg * 3.14159265358979323846 / 180.0;
    q[0] = cos(half);
    for (int i = 0; i < 3; i++)
        q[1 + i] = axis[i] * sin(half);
}

/* a looping texture's read position brought back into [0, frames): more
   than a whole texture per sample (a tiny body in a fast flow, a short
   texture) must still wrap into it, and a position that is not finite
   restarts at 0, since reading outside would overflow the texture */
static inline double aero_texture_wrap(double pos, long frames)
{
    if (pos >= frames)
        pos -= frames * floor(pos / frames);
    return pos >= 0.0 && pos < frames ? pos : 0.0;
}

/* Catmull-Rom cubic through p0..p3, read between p1 and p2 at f in [0, 1):
   a continuous slope at every sample, so a texture read between its
   samples has no corners (linear reads have one at each sample: heard
   as a sharp second difference, a click, where the content nears the
   texture's Nyquist frequency) */
static inline float aero_catmull_rom(float p0, float p1, float p2, float p3,
                                     float f)
{
    return p1 + 0.5f * f * (p2 - p0 +
                f * (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3 +
                f * (3.0f * (p1 - p2) + p3 - p0)));
}

/* out = m v, m a row-major 3x3 matrix */
static inline void aero_mat3_apply(const double *m, const double *v,
                                   double *out)
{
    out[0] = m[0] * v[0] + m[1] * v[1] + m[2] * v[2];
    out[1] = m[3] * v[0] + m[4] * v[1] + m[5] * v[2];
    out[2] = m[6] * v[0] + m[7] * v[1] + m[8] * v[2];
}

/* the rotation (row-major) by the angle of cosine c and sine s about the
   unit axis k (Rodrigues): R = c I + s [k]x + (1 - c) k k^T */
static inline void aero_rotation3(const double *k, double c, double s,
                                  double *m)
{
    double t = 1.0 - c;
    m[0] = c + t * k[0] * k[0];
    m[1] = t * k[0] * k[1] - s * k[2];
    m[2] = t * k[0] * k[2] + s * k[1];
    m[3] = t * k[1] * k[0] + s * k[2];
    m[4] = c + t * k[1] * k[1];
    m[5] = t * k[1] * k[2] - s * k[0];
    m[6] = t * k[2] * k[0] - s * k[1];
    m[7] = t * k[2] * k[1] + s * k[0];
    m[8] = c + t * k[2] * k[2];
}

/* *field = v when v is finite and within [lo, hi]: 0; else -1 (kept) */
static inline int aero_set_within(double *field, double v, double lo,
                                  double hi)
{
    if (!aero_is_finite(v) || v < lo || v > hi)
        return -1;
    *field = v;
    return 0;
}

/* the gain setters' range and law: *gain = 10^(db/20) for db within
   [AERO_GAIN_DB_MIN, AERO_GAIN_DB_MAX]: 0; else -1 (kept) */
static inline int aero_set_gain_db(double *gain, double db)
{
    if (aero_set_within(&db, db, AERO_GAIN_DB_MIN, AERO_GAIN_DB_MAX))
        return -1;
    *gain = pow(10.0, db / 20.0);
    return 0;
}

/* the ramp setters' range: *samples = ms at `rate` for ms within
   [AERO_RAMP_MS_MIN, AERO_RAMP_MS_MAX]: 0; else -1 (kept) */
static inline int aero_set_ramp_ms(double *samples, double ms, double rate)
{
    if (aero_set_within(&ms, ms, AERO_RAMP_MS_MIN, AERO_RAMP_MS_MAX))
        return -1;
    *samples = ms * 0.001 * rate;
    return 0;
}

#endif
