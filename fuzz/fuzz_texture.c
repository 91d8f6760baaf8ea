/* fuzz: texture files (aero_texture_load: libsndfile's header reading and
 * our metadata checks), then both players render what loaded.
 * Seeds: the shipped textures. */
/* aero-fuzz: seeds textures/?*.wav */
#include "texture_play.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[64];
    int fd = fuzz_file(data, size, path, sizeof(path));
    if (fd < 0)
        return 0;
    fuzz_texture_check(path);
    fuzz_file_close(fd);
    return 0;
}
