/* aero: arrival rings, one per ear: moving point sources add each sample
 * at its fractional arrival time (emission time + r/c0), so the Doppler
 * of any motion and the interaural delay come for free, and any number of
 * sources costs one ring per ear, not a delay line each. Shared by the
 * texture players ([aeolian~]'s texture mode, [body~]). No globals. */
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

/* adds v spread evenly over the span [at, at + step) that the sample
   occupies in arrival time (step: this sample's arrival minus the last
   one's, 1 for a source at rest), scaled by 1/step. The spans of a moving
   source tile the ring, so every sample gets the same total weight 1/step
   (the Doppler compression) whatever the fractions; splitting each sample
   linearly at its point (aero_arrivals_add) gave every 1/|1 - step|-th
   sample one contribution too many or too few: a comb of one-sample
   spikes of |1 - step| times the signal. For step 1 both are the same;
   steps outside 0.25..4 (a jump, not a motion) fall back to the point. */
static inline void aero_arrivals_add_density(float *r, long mask, double at,
                                             double step, float density);
static inline void aero_arrivals_add_span(float *r, long mask, double at,
                                          double step, float v)
{
    if (!(step > 0.25 && step < 4.0)) {
        aero_arrivals_add(r, mask, at, v);
        return;
    }
    aero_arrivals_add_density(r, mask, at, step, (float)(v / step));
}

/* As aero_arrivals_add_span, the span's density given (a step within
   0.25..4). A player whose delay is linear over each chunk steps the
   Doppler compression 1/step where one chunk's step meets the next; it
   glides the density from one chunk's step to the next instead (a sword
   stopping at 19 m/s stepped it by 0.6 % in one sample: a click, issue
   48), the spans still tiling the ring. */
static inline void aero_arrivals_add_density(float *r, long mask, double at,
                                             double step, float density)
{
    const double end = at + step;
    long k = (long)at;
    double lo = at, hi = (double)(k + 1);
    /* the whole cells the span crosses, then the part of the last */
    while (hi < end) {
        r[k & mask] += density * (float)(hi - lo);
        lo = hi;
        hi += 1.0; /* (double)(k + 1), exactly */
        k++;
    }
    if (lo < end)
        r[k & mask] += density * (float)(end - lo);
}

/* sample j of a chunk of m whose samples each span `step` (the last
   chunk's: step_last, 0 when there was none): its density glides from
   1/step_last to 1/step over the chunk (aero_arrivals_add_density) */
static inline void aero_arrivals_add_chunk(float *r, long mask, double at,
                                           double step, double step_last,
                                           int j, int m, float v)
{
    if (step_last == step || !(step_last > 0.25 && step_last < 4.0) ||
        !(step > 0.25 && step < 4.0)) {
        aero_arrivals_add_span(r, mask, at, step, v);
        return;
    }
    double glide = step_last + (step - step_last) * ((j + 0.5) / m);
    aero_arrivals_add_density(r, mask, at, step, (float)(v / glide));
}

/* moves m arrived samples of every ear to out[e] + offset (NaN/Inf/huge
   as 0), clears them for reuse and advances the head */
void aero_arrivals_take(aero_arrivals *a, float *const *out, int offset,
                        int m);

#endif
