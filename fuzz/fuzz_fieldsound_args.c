/* fuzz: [fieldsound~]'s creation flags and messages (demo, threshold, map,
 * zero, vscale, log, velocity, listener, speed, gain, ramp, play, stop),
 * through the core calls src/pd/fieldsound~.c makes (field_sound), in any
 * order, with any numbers (NaN, infinities, denormals, huge), between
 * blocks of any size 1..1024: the parameters checked as the wrapper checks
 * them, the synthetic burst preprocessed at 4..8 vertices a side and
 * swapped in, the renderer driven. Invariant: the output stays finite. No
 * seeds: every byte string is a valid program. */
/* aero-fuzz: object fieldsound~ */
#include "fuzz.h"

#include "fieldsound.h"
#include "field_volume.h"

#define MAXN 1024

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_stream in = {data, size};
    static float out[MAXN];
    char err[512];
    aero_field_params par;
    aero_field_sources src;
    aero_fieldsound r;
    memset(&src, 0, sizeof(src));
    aero_field_params_default(&par);
    aero_fieldsound_init(&r, 44100.0, 1, 0);
    aero_ears start = aero_ears_at(1, 0, 0);
    aero_fieldsound_place_ears(&r, &start);
    while (in.left) {
        unsigned op = fuzz_byte(&in) % 16;
        double v[4];
        for (int i = 0; i < 4; i++)
            v[i] = fuzz_number(&in);
        aero_field_params p = par;
        switch (op) {
        case 0: p.threshold[fuzz_byte(&in) % 3] = v[0]; break;
        case 1: p.in_lo = v[0], p.in_hi = v[1], p.rho_lo = v[2],
                p.rho_hi = v[3]; break;
        case 2: p.zero = v[0]; break;
        case 3: p.vscale = v[0]; break;
        case 4: p.log_input = fuzz_byte(&in) & 1; break;
        case 5: p.use_velocity = fuzz_byte(&in) & 1; break;
        case 6: {
            aero_ears e = aero_ears_at(v[0], v[1], v[2]);
            aero_fieldsound_set_ears(&r, &e);
            break;
        }
        case 7: aero_fieldsound_set_speed(&r, v[0]); break;
        case 8: aero_fieldsound_set_gain_db(&r, v[0]); break;
        case 9: aero_fieldsound_set_ramp_ms(&r, v[0]); break;
        case 10: aero_fieldsound_play(&r); break;
        case 11: aero_fieldsound_stop(&r); break;
        case 12: aero_fieldsound_set_sample_rate(&r, v[0]); break;
        case 13: { /* demo N: preprocess and swap in, as the wrapper does */
            aero_field_demo d;
            aero_volume_info info;
            aero_field_sources fresh;
            aero_field_demo_default(&d);
            d.size = 4 + (int)(fuzz_byte(&in) % 5);
            d.frames = 2 + (int)(fuzz_byte(&in) % 10);
            d.velocity = fuzz_byte(&in) & 1;
            d.seed = fuzz_byte(&in);
            d.spacing = 1.28 / d.size;
            aero_field_demo_info(&d, &info);
            if (aero_field_prepare(&info, &d, &par, &fresh, NULL, NULL, err,
                                   sizeof(err)))
                break;
            /* the renderer keeps a pointer to the sources: swap them
               into `src` first, as the wrapper does into x_sources */
            aero_field_sources old = src;
            src = fresh;
            if (aero_fieldsound_set_sources(&r, &src)) {
                aero_field_sources_free(&src);
                aero_fieldsound_set_sources(&r, NULL);
            }
            aero_field_sources_free(&old);
            break;
        }
        default: { /* a block of any size */
            int n = 1 + (int)((fuzz_byte(&in) << 2 | fuzz_byte(&in)) % MAXN);
            aero_fieldsound_process(&r, out, n);
            FUZZ_REQUIRE(fuzz_finite(out, n), "non-finite output");
        }
        }
        /* a parameter message: kept only if it passes the check */
        if (op <= 5 && !aero_field_params_check(&p, err, sizeof(err)))
            par = p;
    }
    aero_fieldsound_free(&r);
    aero_field_sources_free(&src);
    return 0;
}
