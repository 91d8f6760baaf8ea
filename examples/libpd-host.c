/* aero in a game or app through libpd: a host program that links Pd
 * (libpd) and aero statically, registers aero's classes with aero_setup(),
 * opens a patch and drives a sword from its own "game loop" with pose
 * messages, rendering 2 s of stereo sound into a WAV file.
 *
 *   libpd-host [PATCH_DIR [DATA_DIR [OUT.wav]]]
 * defaults: examples, . (the aero folder, which holds textures/), and
 * sword-swing.wav. Build it with `make libpd-example LIBPD_DIR=...` against
 * a single-instance or a multi-instance (MULTI=true) libpd: docs/libpd.md.
 * `make check` compiles it against Pd's headers
 * with -DPDINSTANCE so its use of the API stays correct; `make
 * check-libpd` builds and runs it against libpd 0.16.1, both variants.
 *
 * The patch (examples/libpd-sword.pd) holds [r pose] -> [aeolian~ -texture
 * sword -stereo] -> [dac~] and declares no path: the host tells aero where
 * its data is with aero_set_data_path(), so the sword texture is found in
 * DATA_DIR/textures/ (a patch also finds textures next to itself, in its
 * [declare -path] folders, on Pd's search path and in $AERO_DATA). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#ifdef HAVE_LIBPD
#include "z_libpd.h"
#else
/* the part of libpd's API (z_libpd.h) this host uses */
typedef void (*t_libpd_printhook)(const char *s);
void libpd_set_printhook(const t_libpd_printhook hook);
int libpd_init(void);
int libpd_init_audio(int in_channels, int out_channels, int sample_rate);
void *libpd_openfile(const char *name, const char *dir);
void libpd_closefile(void *p);
int libpd_blocksize(void);
int libpd_process_float(const int ticks, const float *in, float *out);
int libpd_start_message(int max_length);
void libpd_add_float(float x);
int libpd_finish_message(const char *recv, const char *msg);
#endif
#include "aero.h" /* aero_setup(), aero_set_data_path() (src/pd) */

#include <sndfile.h>

#define RATE 48000
#define SECONDS 2

/* a pose message to the patch's [r pose]: the blade sweeping an arc */
static void send_pose(double t)
{
    double s = t < 0.3 ? t / 0.3 : 1.0; /* a 300 ms swing */
    double th = (20.0 + 140.0 * (1.0 - cos(3.14159265 * s)) / 2.0) *
                3.14159265 / 180.0;
    double a[3] = {0.2 * cos(th), 0.3 + 0.2 * sin(th), 1.3};
    double b[3] = {1.0 * cos(th), 0.3 + 1.0 * sin(th), 1.3};
    libpd_start_message(9);
    for (int i = 0; i < 3; i++)
        libpd_add_float((float)a[i]);
    for (int i = 0; i < 3; i++)
        libpd_add_float((float)b[i]);
    libpd_add_float((float)-sin(th)); /* the chord leads: edge first */
    libpd_add_float((float)cos(th));
    libpd_add_float(0.0f);
    libpd_finish_message("pose", "pose");
}

/* Pd's messages (aero's errors among them) */
static void print_to_stderr(const char *s)
{
    fputs(s, stderr);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "examples";
    const char *data = argc > 2 ? argv[2] : ".";
    const char *wav = argc > 3 ? argv[3] : "sword-swing.wav";
    libpd_set_printhook(print_to_stderr);
    libpd_init();
    aero_setup();
    aero_set_data_path(data);
    libpd_init_audio(0, 2, RATE);
    void *patch = libpd_openfile("libpd-sword.pd", dir);
    if (!patch) {
        fprintf(stderr, "cannot open %s/libpd-sword.pd\n", dir);
        return 1;
    }
    libpd_start_message(1);
    libpd_add_float(1.0f);
    libpd_finish_message("pd", "dsp");

    int block = libpd_blocksize();
    int frames = RATE * SECONDS;
    float *out = calloc((size_t)frames * 2, sizeof(float));
    /* the game loop: a pose every 4 blocks (~5 ms), then audio */
    for (int done = 0; done + 4 * block <= frames; done += 4 * block) {
        send_pose((double)done / RATE);
        libpd_process_float(4, NULL, out + 2 * done);
    }
    libpd_closefile(patch);
    SF_INFO info = {.samplerate = RATE, .channels = 2,
                    .format = SF_FORMAT_WAV | SF_FORMAT_FLOAT};
    SNDFILE *f = sf_open(wav, SFM_WRITE, &info);
    if (!f) {
        fprintf(stderr, "cannot write %s\n", wav);
        return 1;
    }
    sf_writef_float(f, out, frames);
    sf_close(f);
    free(out);
    printf("wrote %s (%d s)\n", wav, SECONDS);
    return 0;
}
