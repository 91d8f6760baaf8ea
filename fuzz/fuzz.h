/* aero fuzz harnesses: what every harness shares.
 *
 * A harness defines LLVMFuzzerTestOneInput and is built two ways:
 *   - by fuzz/run.sh with clang -fsanitize=fuzzer,address,undefined
 *     (libFuzzer's main; a broken invariant aborts, so libFuzzer keeps the
 *     input as a crash);
 *   - by tests/objects/95-fuzz-replay.sh with -DFUZZ_REPLAY and the main()
 *     below, which replays the shipped seeds and every crash ever found
 *     (fuzz/regress/NAME/) in `make check`; a broken invariant counts as a
 *     failure there and the binary ends with `N passed, N failed`.
 * Outside data reaches the parsers through a memory-backed file
 * (memfd_create, opened by its /proc/self/fd path), as it would from disk. */
#ifndef AERO_FUZZ_H
#define AERO_FUZZ_H

#define _GNU_SOURCE
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int fuzz_broken; /* invariants broken by the current input */

/* an invariant of the code under test, whatever the input */
#define FUZZ_REQUIRE(cond, ...)                                            \
    do {                                                                   \
        if (!(cond)) {                                                     \
            fprintf(stderr, "fuzz: %s:%d: ", __FILE__, __LINE__);          \
            fprintf(stderr, __VA_ARGS__);                                  \
            fprintf(stderr, "\n");                                         \
            fuzz_broken++;                                                 \
            fuzz_stop();                                                   \
        }                                                                  \
    } while (0)

static inline void fuzz_stop(void)
{
#ifndef FUZZ_REPLAY
    abort();
#endif
}

/* a file holding data[0..size) in memory; its path goes to path (which
 * stays valid until fuzz_file_close). Returns the descriptor or -1. */
static inline int fuzz_file(const uint8_t *data, size_t size, char *path,
                            size_t len)
{
    int fd = memfd_create("aero-fuzz", 0);
    if (fd < 0)
        return -1;
    size_t done = 0;
    while (done < size) {
        ssize_t w = write(fd, data + done, size - done);
        if (w <= 0) {
            close(fd);
            return -1;
        }
        done += (size_t)w;
    }
    lseek(fd, 0, SEEK_SET);
    snprintf(path, len, "/proc/self/fd/%d", fd);
    return fd;
}

static inline void fuzz_file_close(int fd)
{
    if (fd >= 0)
        close(fd);
}

/* all n floats finite */
static inline int fuzz_finite(const float *x, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(x[i]))
            return 0;
    return 1;
}

/* reads the fuzz input as a stream of small values */
typedef struct {
    const uint8_t *p;
    size_t left;
} fuzz_stream;

static inline unsigned fuzz_byte(fuzz_stream *s)
{
    if (!s->left)
        return 0;
    s->left--;
    return *s->p++;
}

/* a number as a patch might send one: from a list of values that break
 * things (0, negatives, NaN, infinities, denormals, huge) or raw bits */
static inline double fuzz_number(fuzz_stream *s)
{
    static const double special[] = {
        0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 10.0, -10.0, 0.01, 0.001, 1e-5,
        1e-6, 100.0, 343.0, 1000.0, 1e5, 1e6, 1e30, -1e30, 1e300, 1e-300,
        4.9e-324, 1.17549435e-38, 3.4e38, 44100.0, 22050.0, 192000.0,
        NAN, INFINITY, -INFINITY, 0.3 * 343.0, 12.0, 360.0, 256.0, 257.0,
        -200.0, 120.0, 600000.0, 600001.0, 1e-5 * 0.999};
    unsigned b = fuzz_byte(s);
    if (b < 0xc0)
        return special[b % (sizeof(special) / sizeof(special[0]))];
    double x = 0.0;
    uint8_t raw[8] = {0};
    for (int i = 0; i < 8; i++)
        raw[i] = (uint8_t)fuzz_byte(s);
    memcpy(&x, raw, sizeof(x));
    return x;
}

#ifdef FUZZ_REPLAY
/* replays files (a seed or a saved crash each) */
int main(int argc, char **argv)
{
    int passed = 0, failed = 0;
    for (int i = 1; i < argc; i++) {
        FILE *f = fopen(argv[i], "rb");
        if (!f) {
            printf("  FAIL  can't read %s\n", argv[i]);
            failed++;
            continue;
        }
        size_t cap = 1 << 16, n = 0;
        uint8_t *buf = malloc(cap);
        size_t got;
        while (buf && (got = fread(buf + n, 1, cap - n, f)) > 0) {
            n += got;
            if (n == cap) {
                uint8_t *bigger = realloc(buf, cap *= 2);
                if (!bigger) {
                    free(buf);
                    buf = NULL;
                }
                buf = bigger;
            }
        }
        fclose(f);
        if (!buf) {
            printf("  FAIL  out of memory reading %s\n", argv[i]);
            failed++;
            continue;
        }
        fuzz_broken = 0;
        LLVMFuzzerTestOneInput(buf, n);
        free(buf);
        if (fuzz_broken) {
            printf("  FAIL  %s: %d invariant(s) broken\n", argv[i],
                   fuzz_broken);
            failed++;
        } else {
            printf("  ok    %s (%zu bytes) handled\n", argv[i], n);
            passed++;
        }
    }
    printf("%d passed, %d failed\n", passed, failed);
    return failed ? 1 : 0;
}
#endif

#endif
