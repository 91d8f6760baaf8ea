/* aero-libpd-render: a libpd host for the tests (tests/libpd/run.sh): links
 * libpd and aero statically, registers aero with one aero_setup(), opens a
 * patch that drives itself (loadbang), turns DSP on and renders its two
 * [dac~] channels into a float WAV, dropping the first SETTLE seconds as
 * the Pd tests do. Built for a single-instance libpd, or a multi-instance
 * one with -DPDINSTANCE -DPDTHREADS (the main instance is used).
 *
 *   aero-libpd-render [-data DIR] [-path DIR] [-seconds S] [-settle S]
 *                     PATCH OUT.wav
 *
 * -data DIR calls aero_set_data_path(DIR), -path DIR
 * libpd_add_to_search_path(DIR). Pd's messages go to stderr. */
#include "z_libpd.h"
#include "aero.h"

#include <sndfile.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RATE 48000

static void print_to_stderr(const char *s)
{
    fputs(s, stderr);
}

int main(int argc, char **argv)
{
    const char *data = NULL, *path = NULL;
    double seconds = 2.0, settle = 0.2;
    int i = 1;
    for (; i + 1 < argc && argv[i][0] == '-'; i += 2) {
        if (!strcmp(argv[i], "-data"))
            data = argv[i + 1];
        else if (!strcmp(argv[i], "-path"))
            path = argv[i + 1];
        else if (!strcmp(argv[i], "-seconds"))
            seconds = atof(argv[i + 1]);
        else if (!strcmp(argv[i], "-settle"))
            settle = atof(argv[i + 1]);
        else
            break;
    }
    if (argc - i != 2 || !(seconds > 0 && seconds < 600) ||
        !(settle >= 0 && settle < 60)) {
        fprintf(stderr, "usage: aero-libpd-render [-data DIR] [-path DIR] "
                        "[-seconds S] [-settle S] PATCH OUT.wav\n");
        return 2;
    }
    char dir[4096];
    const char *patch = argv[i], *slash = strrchr(patch, '/');
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - patch) : 1,
             slash ? patch : ".");
    const char *name = slash ? slash + 1 : patch;

    libpd_set_printhook(print_to_stderr);
    libpd_init();
    aero_setup();
    if (data)
        aero_set_data_path(data);
    if (path)
        libpd_add_to_search_path(path);
    libpd_init_audio(0, 2, RATE);
    void *file = libpd_openfile(name, dir);
    if (!file) {
        fprintf(stderr, "cannot open %s in %s\n", name, dir);
        return 1;
    }
    libpd_start_message(1);
    libpd_add_float(1.0f);
    libpd_finish_message("pd", "dsp");

    int block = libpd_blocksize();
    int skip = (int)(settle * RATE / block), ticks = (int)(seconds * RATE / block);
    float *out = calloc((size_t)ticks * block * 2, sizeof(float));
    if (!out)
        return 1;
    for (int t = 0; t < skip; t++)
        libpd_process_float(1, NULL, out);
    libpd_process_float(ticks, NULL, out);
    libpd_closefile(file);

    SF_INFO info = {.samplerate = RATE, .channels = 2,
                    .format = SF_FORMAT_WAV | SF_FORMAT_FLOAT};
    SNDFILE *f = sf_open(argv[i + 1], SFM_WRITE, &info);
    if (!f || sf_writef_float(f, out, (sf_count_t)ticks * block) !=
                  (sf_count_t)ticks * block) {
        fprintf(stderr, "cannot write %s\n", argv[i + 1]);
        return 1;
    }
    sf_close(f);
    free(out);
    return 0;
}
