/* aero_web: the few C entry points the page calls in the WebAssembly module
 * (libpd 0.16.1 + aero, built by `make web`). libpd's own API
 * (libpd_start_message, libpd_finish_message, ...) is exported as it is;
 * this file adds what needs C: Pd's print hook, aero's registration with
 * one aero_setup(), its data folder in the module's file system, and one
 * output buffer the page reads after each call.
 *
 * The module's file system (MEMFS) is laid out like aero's checkout:
 * /aero/abstractions, /aero/textures, /aero/trees, /aero/scenes. */
#include "z_libpd.h"
#include "aero.h"

#include <emscripten.h>
#include <stdio.h>
#include <stdlib.h>

#define AERO_WEB_MAX_TICKS 64

/* interleaved stereo output of up to AERO_WEB_MAX_TICKS Pd blocks; the
 * module has one Pd, so one buffer */
static float out_buffer[AERO_WEB_MAX_TICKS * 64 * 2];

static void print_hook(const char *s)
{
    fputs(s, stderr); /* the page's printErr: Pd's errors reach the console */
}

/* once per module instance: Pd at RATE with two output channels, aero
 * registered, its data and abstractions found under /aero, DSP on */
EMSCRIPTEN_KEEPALIVE int aero_web_init(int rate)
{
    libpd_set_printhook(print_hook);
    if (libpd_init() != 0)
        return -1;
    aero_setup();
    aero_set_data_path("/aero");
    libpd_add_to_search_path("/aero/abstractions");
    if (libpd_init_audio(0, 2, rate) != 0)
        return -1;
    libpd_start_message(1);
    libpd_add_float(1.0f);
    libpd_finish_message("pd", "dsp");
    return libpd_blocksize();
}

EMSCRIPTEN_KEEPALIVE void *aero_web_open(const char *name, const char *dir)
{
    return libpd_openfile(name, dir);
}

EMSCRIPTEN_KEEPALIVE void aero_web_close(void *patch)
{
    if (patch)
        libpd_closefile(patch);
}

/* runs TICKS Pd blocks (64 samples each) with no input; returns the
 * interleaved stereo output (TICKS * 128 floats), NULL when TICKS is out
 * of range */
EMSCRIPTEN_KEEPALIVE float *aero_web_process(int ticks)
{
    if (ticks < 1 || ticks > AERO_WEB_MAX_TICKS)
        return NULL;
    if (libpd_process_float(ticks, NULL, out_buffer) != 0)
        return NULL;
    return out_buffer;
}

/* FFTW for wasm is built without threads (platforms/wasm-deps.sh): this
 * module runs one Pd in one thread, so the planner lock aero asks for
 * before planning (src/core/common/aero_fftw.h) has nothing to serialise */
void fftwf_make_planner_thread_safe(void)
{
}
