/* aero: arrival rings (see arrivals.h). */
#include "arrivals.h"

#include <math.h>
#include <stdlib.h>

int aero_arrivals_alloc(aero_arrivals *a, int n_ears, double sr,
                        double max_delay_s, long margin)
{
    long need = (long)ceil(sr * max_delay_s) + margin, len = 1;
    float *rings[AERO_ARRIVALS_MAX_EARS] = {NULL, NULL};
    if (n_ears < 1 || n_ears > AERO_ARRIVALS_MAX_EARS)
        return -1;
    while (len < need)
        len <<= 1;
    for (int e = 0; e < n_ears; e++)
        rings[e] = calloc((size_t)len, sizeof(float));
    if (!rings[0] || (n_ears > 1 && !rings[1])) {
        free(rings[0]);
        free(rings[1]);
        return -1;
    }
    for (int e = 0; e < AERO_ARRIVALS_MAX_EARS; e++) {
        free(a->ring[e]);
        a->ring[e] = rings[e];
    }
    a->n_ears = n_ears;
    a->mask = len - 1;
    a->head = 0;
    return 0;
}

void aero_arrivals_free(aero_arrivals *a)
{
    for (int e = 0; e < AERO_ARRIVALS_MAX_EARS; e++) {
        free(a->ring[e]);
        a->ring[e] = NULL;
    }
}

void aero_arrivals_take(aero_arrivals *a, float *const *out, int offset,
                        int m)
{
    for (int e = 0; e < a->n_ears; e++) {
        float *ring = a->ring[e];
        float *o = out[e] + offset;
        for (int j = 0; j < m; j++) {
            long i = (a->head + j) & a->mask;
            float v = ring[i];
            ring[i] = 0.0f;
            o[j] = v == v && v < 1e30f && v > -1e30f ? v : 0.0f;
        }
    }
    a->head = (a->head + m) & a->mask;
}
