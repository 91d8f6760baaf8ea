/* aero bench: N [aeolian~] model-mode sources in src/core alone, for an
 * instruction count on each architecture (bench/arm/count.sh).
 *   aeolian-core N SECONDS
 * renders N sources, one ear each, in Pd's 64-sample blocks at 48 kHz,
 * all driven by the gusting speed of bench/run.sh (12 + 4 sin(0.013 k)
 * + 3 sin(0.031 k) m/s, k counting 10 ms steps, ramped linearly over each
 * step as [line~] does), and sums them into one buffer as [throw~] would.
 * Prints a checksum of the sum so the work cannot be left out, and so two
 * architectures can be seen to compute the same sound. */
#include "aeolian.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define RATE 48000.0
#define BLOCK 64

static double gust(long step)
{
    return 12.0 + 4.0 * sin(0.013 * (double)step) + 3.0 * sin(0.031 * (double)step);
}

int main(int argc, char **argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 1;
    double seconds = argc > 2 ? atof(argv[2]) : 1.0;
    if (n < 0 || n > 100000 || !(seconds > 0 && seconds < 3600)) {
        fprintf(stderr, "usage: aeolian-core N SECONDS\n");
        return 2;
    }
    aero_aeolian *m = calloc(n > 0 ? (size_t)n : 1, sizeof(*m));
    if (!m) return 1;
    for (int i = 0; i < n; i++)
        aero_aeolian_init(&m[i], RATE, 1, (uint32_t)i + 1);

    long blocks = (long)(seconds * RATE / BLOCK);
    long step_samples = (long)(RATE / 100); /* 10 ms */
    float speed[BLOCK], out[BLOCK], sum[BLOCK];
    float *outs[1] = {out};
    double check = 0, from = gust(0), to = gust(1);
    long t = 0;
    for (long b = 0; b < blocks; b++) {
        for (int i = 0; i < BLOCK; i++, t++) {
            long phase = t % step_samples;
            if (phase == 0 && t > 0) {
                from = to;
                to = gust(t / step_samples + 1);
            }
            speed[i] = (float)(from + (to - from) * (double)phase / (double)step_samples);
            sum[i] = 0;
        }
        for (int s = 0; s < n; s++) {
            aero_aeolian_process(&m[s], speed, outs, BLOCK);
            for (int i = 0; i < BLOCK; i++) sum[i] += out[i];
        }
        for (int i = 0; i < BLOCK; i++) check += (double)sum[i] * sum[i];
    }
    printf("aeolian-core: %d sources, %ld samples, sum of squares %.9g\n", n,
           blocks * BLOCK, check);
    for (int i = 0; i < n; i++)
        aero_aeolian_free(&m[i]);
    free(m);
    return 0;
}

/* Model mode never makes the texture part, which would free a texture;
 * texture.c needs libsndfile, which the cross toolchains lack, so this
 * stands in for it here (texture.h's contract: NULL or a loaded texture). */
void aero_texture_free(aero_texture *t)
{
    (void)t;
}
