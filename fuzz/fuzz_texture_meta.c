/* fuzz: texture metadata (the "key=value" comment of a texture WAV: kind,
 * directions, frames, rate, angles, v0, diameter, symmetry, mirror, st).
 * The input is the comment; the harness writes a well-formed float WAV
 * around it (channels 3 x (1 + first byte % 8), 16..271 frames of a sine)
 * so every input reaches the metadata parser, then the players.
 * Seeds: fuzz/seeds/texture_meta/ (the shipped textures' metadata). */
#include "texture_play.h"

#include <sndfile.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2)
        return 0;
    int channels = 3 * (1 + data[0] % 8);
    int frames = 16 + data[1];
    char *comment = malloc(size - 1);
    if (!comment)
        return 0;
    memcpy(comment, data + 2, size - 2);
    comment[size - 2] = 0; /* libsndfile stores a C string */
    int fd = memfd_create("aero-fuzz-meta", 0);
    if (fd < 0) {
        free(comment);
        return 0;
    }
    SF_INFO info;
    memset(&info, 0, sizeof(info));
    info.samplerate = 16000;
    info.channels = channels;
    info.format = SF_FORMAT_WAV | SF_FORMAT_FLOAT;
    SNDFILE *f = sf_open_fd(fd, SFM_WRITE, &info, 0);
    if (f) {
        float *x = malloc(sizeof(float) * (size_t)frames * channels);
        if (x) {
            for (int n = 0; n < frames * channels; n++)
                x[n] = (float)sin(0.1 * n);
            sf_set_string(f, SF_STR_COMMENT, comment);
            sf_writef_float(f, x, frames);
            free(x);
        }
        sf_close(f);
        char path[64];
        snprintf(path, sizeof(path), "/proc/self/fd/%d", fd);
        fuzz_texture_check(path);
    }
    close(fd);
    free(comment);
    return 0;
}
