/* aero bench: a loop of exactly 4 instructions per iteration on amd64,
 * arm64 and armv7 (in each one's assembly: add, add, subtract, branch), to
 * check an instruction counter: the counts of N and 2 N iterations must
 * differ by exactly 4 N (bench/arm/count.sh). */
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 1000;
    long i = n, a = 0;
    if (n < 1) return 2;
#if defined(__aarch64__)
    __asm__ volatile("1: add %1, %1, #1\n add %1, %1, #2\n"
                     " subs %0, %0, #1\n b.ne 1b"
                     : "+r"(i), "+r"(a));
#elif defined(__arm__)
    __asm__ volatile("1: add %1, %1, #1\n add %1, %1, #2\n"
                     " subs %0, %0, #1\n bne 1b"
                     : "+r"(i), "+r"(a));
#elif defined(__x86_64__)
    __asm__ volatile("1: add $1, %1\n add $2, %1\n sub $1, %0\n jne 1b"
                     : "+r"(i), "+r"(a));
#else
#error "known-loop: amd64, arm64 or armv7"
#endif
    printf("known-loop: %ld iterations, %ld\n", n, a);
    return 0;
}
