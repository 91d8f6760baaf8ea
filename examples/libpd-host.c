/* aero in a game or app through libpd: a host program that links Pd
 * (libpd) and aero statically, registers aero's classes with aero_setup(),
 * opens a patch and drives a sword from its own "game loop" with pose
 * messages, rendering 2 s of stereo sound into sword-swing.wav.
 *
 * Build (libpd from https://github.com/libpd/libpd, built with
 * -DPDINSTANCE for several Pd instances per process):
 *   make libpd-example LIBPD_DIR=/path/to/libpd
 * Without libpd, `make check` only compiles this file against Pd's headers
 * with -DPDINSTANCE, so its use of the API stays correct.
 *
 * The patch (examples/libpd-sword.pd) holds [r pose] -> [aeolian~ -texture
 * sword -stereo] -> [dac~]; textures are found next to the patch or in the
 * folder passed to [declare -path]. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#ifdef HAVE_LIBPD
#include "z_libpd.h"
#else
/* the part of libpd's API (z_libpd.h) this host uses */
int libpd_init(void);
int libpd_init_audio(int in_channels, int out_channels, int sample_rate);
void *libpd_openfile(const char *name, const char *dir);
int libpd_blocksize(void);
int libpd_process_float(const int ticks, const float *in, float *out);
int libpd_start_message(int max_length);
void libpd_add_float(float x);
int libpd_finish_message(const char *recv, const char *msg);
#endif
#include "m_pd.h"

#include <sndfile.h>

void aero_setup(void); /* aero's single-library setup (src/pd/aero.c) */

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

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "examples";
    libpd_init();
    aero_setup();
    libpd_init_audio(0, 2, RATE);
    if (!libpd_openfile("libpd-sword.pd", dir)) {
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
    SF_INFO info = {.samplerate = RATE, .channels = 2,
                    .format = SF_FORMAT_WAV | SF_FORMAT_FLOAT};
    SNDFILE *f = sf_open("sword-swing.wav", SFM_WRITE, &info);
    if (!f) {
        fprintf(stderr, "cannot write sword-swing.wav\n");
        return 1;
    }
    sf_writef_float(f, out, frames);
    sf_close(f);
    free(out);
    printf("wrote sword-swing.wav (%d s)\n", SECONDS);
    return 0;
}
