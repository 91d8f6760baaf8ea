/* aero: AERO_CLONES marks a loop-heavy function for an AVX2 clone. The
 * solvers' step loops are memory-bound sweeps that vectorise: where the
 * compiler can dispatch at load time (GCC, x86-64 ELF), an AVX2
 * clone runs on the machines that have it. AVX2 without FMA: the same IEEE
 * operations on each element as the SSE2 build, so a texture is the same
 * to the bit on either. Elsewhere it marks nothing, and under Clang too:
 * Clang 14 names a clone set's dispatcher only in the file that defines it,
 * so a call from another file (flow2d.c to turbulence2d.c) does not link. */
#ifndef AERO_CLONES_H
#define AERO_CLONES_H

#if defined(__x86_64__) && defined(__linux__) && defined(__has_attribute) && \
    !defined(__clang__)
#if __has_attribute(target_clones)
#define AERO_CLONES __attribute__((target_clones("avx2", "default")))
#endif
#endif
#ifndef AERO_CLONES
#define AERO_CLONES
#endif

#endif
