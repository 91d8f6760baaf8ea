/* glue.c: the C side of a page that embeds aero through libpd in
 * WebAssembly (docs/web.md, "Linking aero into your own libpd module"):
 * Pd started with aero registered, a patch opened from the module's file
 * system, and one output buffer the AudioWorklet reads. */
#include "z_libpd.h"
#include "aero.h"

#include <emscripten.h>

static float out[2 * 2 * 64]; /* two Pd blocks of stereo: one 128-frame quantum */

/* FFTW for wasm is built without threads: this module runs one Pd in one
 * thread, so the planner lock aero asks for has nothing to serialise */
void fftwf_make_planner_thread_safe(void) {}

EMSCRIPTEN_KEEPALIVE int embed_init(int rate)
{
    if (libpd_init() != 0)
        return -1;
    aero_setup();                        /* every aero class, once */
    aero_set_data_path("/aero");         /* textures/ and trees/ under it */
    libpd_add_to_search_path("/aero/abstractions");
    if (libpd_init_audio(0, 2, rate) != 0)
        return -1;
    libpd_start_message(1);              /* ; pd dsp 1 */
    libpd_add_float(1);
    libpd_finish_message("pd", "dsp");
    return 0;
}

EMSCRIPTEN_KEEPALIVE int embed_open(const char *name, const char *dir)
{
    return libpd_openfile(name, dir) != 0;
}

/* one 128-frame quantum: two Pd blocks, interleaved stereo */
EMSCRIPTEN_KEEPALIVE float *embed_process(void)
{
    libpd_process_float(2, 0, out);
    return out;
}
