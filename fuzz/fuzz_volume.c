/* fuzz: the volume header parser and frame reader (src/core/common/field_volume.c,
 * the volume directories of [fieldsound~]). The input is the text of
 * volume.txt, then a NUL byte, then the bytes of the frame files (frame k
 * gets the k-th slice of the frame size; a short slice makes a truncated
 * file). Invariants of a header that parsed: dims 2..1024, at least one
 * frame, spacing, rate and origin finite and in range, one or four fields,
 * a frame file pattern without '/' that names a file; a frame file of the
 * wrong size is refused. A small volume that parsed is preprocessed and
 * rendered through the core of [fieldsound~] (field_sound): the output
 * stays finite, whatever the frames hold (NaN, Inf, huge).
 * The files go to a private temporary directory (a volume is a directory,
 * which a memory-backed file cannot be). Seeds: fuzz/seeds/volume/. */
#include "fuzz.h"

#include "fieldsound.h"
#include "field_volume.h"

#include <sys/stat.h>

static char dir[64]; /* the harness's own directory, made once */

static int write_file(const char *path, const uint8_t *p, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    size_t done = n ? fwrite(p, 1, n, f) : 0;
    return fclose(f) || done != n ? -1 : 0;
}

#define N 256
#define MAX_VALUES 4096 /* fields * vertices of a volume rendered */
#define MAX_FRAMES 8

static void render(const aero_volume_info *v)
{
    aero_field_params par;
    aero_field_sources src;
    aero_fieldsound r;
    static float out[N];
    char err[512];
    aero_field_params_default(&par);
    if (aero_field_prepare(v, NULL, &par, &src, NULL, NULL, err,
                           sizeof(err))) {
        FUZZ_REQUIRE(err[0] != 0, "prepare refused without a message");
        return;
    }
    aero_fieldsound_init(&r, 22050.0, 1, 0);
    aero_ears start = aero_ears_at(v->origin[0] + 0.3, v->origin[1] + 0.1,
                                   v->origin[2]);
    aero_fieldsound_place_ears(&r, &start);
    if (!aero_fieldsound_set_sources(&r, &src)) {
        aero_fieldsound_play(&r);
        for (int b = 0; b < 16; b++) {
            aero_fieldsound_process(&r, out, N);
            FUZZ_REQUIRE(fuzz_finite(out, N), "non-finite output");
        }
    }
    aero_fieldsound_free(&r);
    aero_field_sources_free(&src);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[256], err[512];
    aero_volume_info v;
    if (!dir[0]) {
        snprintf(dir, sizeof(dir), "/tmp/aero-fuzz-volume-XXXXXX");
        if (!mkdtemp(dir)) {
            dir[0] = 0;
            return 0;
        }
    }
    const uint8_t *nul = memchr(data, 0, size);
    size_t hlen = nul ? (size_t)(nul - data) : size;
    const uint8_t *frames = nul ? nul + 1 : data + size;
    size_t flen = (size_t)(data + size - frames);
    snprintf(path, sizeof(path), "%s/" AERO_VOLUME_HEADER, dir);
    if (write_file(path, data, hlen))
        return 0;
    if (aero_volume_read_header(dir, &v, err, sizeof(err))) {
        FUZZ_REQUIRE(err[0] != 0, "header refused without a message");
        return 0;
    }
    FUZZ_REQUIRE(v.nx >= 2 && v.ny >= 2 && v.nz >= 2 &&
                     v.nx <= AERO_VOLUME_MAX_DIM &&
                     v.ny <= AERO_VOLUME_MAX_DIM &&
                     v.nz <= AERO_VOLUME_MAX_DIM,
                 "dims %d %d %d", v.nx, v.ny, v.nz);
    FUZZ_REQUIRE(v.frames >= 1, "frames %d", v.frames);
    FUZZ_REQUIRE(v.fields == 1 || v.fields == 4, "fields %d", v.fields);
    for (int a = 0; a < 3; a++)
        FUZZ_REQUIRE(isfinite(v.spacing[a]) && v.spacing[a] > 0 &&
                         isfinite(v.origin[a]),
                     "spacing or origin %d", a);
    FUZZ_REQUIRE(isfinite(v.rate) && v.rate > 0, "rate %g", v.rate);
    FUZZ_REQUIRE(memchr(v.pattern, 0, sizeof(v.pattern)) &&
                     !strchr(v.pattern, '/'),
                 "pattern '%.64s'", v.pattern);
    size_t values = aero_volume_count(&v) * (size_t)v.fields;
    if (values > MAX_VALUES || v.frames > MAX_FRAMES)
        return 0;
    /* the frame files: slices of the rest of the input */
    size_t fsize = values * sizeof(float);
    char name[128];
    int written = 0, complete = 1;
    for (int k = 0; k < v.frames; k++) {
        size_t at = (size_t)k * fsize, n = 0;
        if (at < flen)
            n = flen - at < fsize ? flen - at : fsize;
        snprintf(name, sizeof(name), v.pattern, k);
        snprintf(path, sizeof(path), "%s/%s", dir, name);
        if (n && write_file(path, frames + at, n)) {
            complete = 0;
            break;
        }
        written = k + 1;
        if (n < fsize) {
            /* a short or missing frame must be refused */
            static float buf[MAX_VALUES];
            FUZZ_REQUIRE(aero_volume_read_frame(&v, k, buf, err,
                                                sizeof(err)) != 0,
                         "frame %d of %zu bytes (want %zu) accepted", k, n,
                         fsize);
            complete = 0;
            break;
        }
    }
    if (complete)
        render(&v);
    for (int k = 0; k < written; k++) {
        snprintf(name, sizeof(name), v.pattern, k);
        snprintf(path, sizeof(path), "%s/%s", dir, name);
        unlink(path);
    }
    return 0;
}
