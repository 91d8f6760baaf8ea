/* aero: arrival rings, one per ear: moving point sources add each sample
 * at its fractional arrival time (emission time + r/c0), so the Doppler
 * of any motion and the interaural delay come for free, and any number of
 * sources costs one ring per ear, not a delay line each. Shared by the
 * texture players (stick_texture, body_texture). No globals. */
#ifndef AERO_ARRIVALS_H
#define AERO_ARRIVALS_H

#define AERO_ARRIVALS_MAX_EARS 2

typedef struct {
    float *ring[AERO_ARRIVALS_MAX_EARS];
    long mask;          /* ring length - 1 (a power of two) */
    long head;          /* ring index of the next output sample */
    int n_ears;
} aero_arrivals;

/* (re)allocates n_ears zeroed rings holding max_delay_s at sr plus margin
   samples: 0, or -1 (out of memory: the old rings stay) */
int aero_arrivals_alloc(aero_arrivals *a, int n_ears, double sr,
                        double max_delay_s, long margin);
void aero_arrivals_free(aero_arrivals *a);

/* adds v at fractional ring position `at` (from the head) of ring r,
   split linearly between its two neighbouring samples */
static inline void aero_arrivals_add(float *r, long mask, double at, float v)
{
    long ia = (long)at;
    float fa = (float)(at - (double)ia);
    r[ia & mask] += v * (1.0f - fa);
    r[(ia + 1) & mask] += v * fa;
}

/* moves m arrived samples of every ear to out[e] + offset (NaN/Inf/huge
   as 0), clears them for reuse and advances the head */
void aero_arrivals_take(aero_arrivals *a, float *const *out, int offset,
                        int m);

#endif
