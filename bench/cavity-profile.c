/* aero: a driver for profiling [cavity~]'s core without Pd (BENCHMARKS.md,
 * issue 42): N models (or [aeolian~]'s, for a ratio) render S seconds at
 * 48 kHz in 64-sample blocks of a speed ramping over 10-12 m/s; prints
 * the CPU time per source-sample. Not built by make; from the repository
 * root after `make`:
 *   cc -std=c99 -O3 -g -Isrc/core/common -Isrc/core/solve -Isrc/core/play \
 *       bench/cavity-profile.c build/libaero_core.a -lsndfile -lm -fopenmp \
 *       -o build/cavity-profile
 *   build/cavity-profile c 10          (a for [aeolian~])
 *   valgrind --tool=callgrind --dump-instr=yes build/cavity-profile c 1 */
#define _POSIX_C_SOURCE 200809L
#include "aeolian.h"
#include "cavity.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

enum { N = 50 };

static double cpu_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

int main(int argc, char **argv)
{
    char mode = argc > 1 ? argv[1][0] : 'c';
    double seconds = argc > 2 ? atof(argv[2]) : 10.0;
    static aero_cavity cavity[N];
    static aero_aeolian aeolian[N];
    for (int k = 0; k < N; k++) {
        aero_cavity_init(&cavity[k], 48000, 1, k + 1);
        aero_aeolian_init(&aeolian[k], 48000, 1, k + 1);
    }
    float in[64], out[64];
    double check = 0, t0 = cpu_seconds();
    long blocks = (long)(48000 * seconds / 64);
    for (long b = 0; b < blocks; b++) {
        for (int i = 0; i < 64; i++)
            in[i] = 10.0f + 2.0f * (float)((b * 64 + i) % 100000) * 1e-5f;
        for (int k = 0; k < N; k++) {
            if (mode == 'a')
                aero_aeolian_process(&aeolian[k], in, (float *[]){out}, 64);
            else
                aero_cavity_process(&cavity[k], in, (float *[]){out}, 64);
            check += out[7];
        }
    }
    double t = cpu_seconds() - t0;
    printf("%s: %.2f ns per source-sample (%d sources, %g s; check %g)\n",
           mode == 'a' ? "[aeolian~]" : "[cavity~]",
           1e9 * t / (blocks * 64.0 * N), N, seconds, check);
    for (int k = 0; k < N; k++) {
        aero_cavity_free(&cavity[k]);
        aero_aeolian_free(&aeolian[k]);
    }
    return 0;
}
