/* fuzz: [cavity~]'s creation flags and messages through the core setters
 * (src/pd/cavity~.c), in any order with any numbers, between blocks of any
 * size and speed signal, in model and texture mode (a small synthetic
 * cavity texture). Invariant: finite output. No seeds needed. */
/* aero-fuzz: object cavity~ */
#include "fuzz.h"

#include "cavity.h"

#define MAXN 1024

static aero_texture *cavity_texture(void)
{
    aero_texture *t = calloc(1, sizeof(*t));
    if (!t || aero_texture_init(t, 128, 1, 16000.0)) {
        free(t);
        return NULL;
    }
    for (int n = 0; n < 128 * 3; n++)
        t->data[n] = (float)cos(0.21 * n);
    aero_texture_set(t, "kind", "cavity");
    aero_texture_set(t, "v0", "10");
    return t;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_stream in = {data, size};
    static float speed[MAXN], out[MAXN];
    char err[256];
    aero_cavity m;
    aero_cavity_init(&m, 44100.0, 1, 1);
    while (in.left) {
        unsigned op = fuzz_byte(&in) % 14;
        double a = fuzz_number(&in), b = fuzz_number(&in),
               c = fuzz_number(&in);
        switch (op) {
        case 0: aero_cavity_set_length(&m, a); break;
        case 1: aero_cavity_set_depth(&m, a); break;
        case 2: aero_cavity_set_width(&m, a); break;
        case 3: aero_cavity_set_gain_db(&m, a); break;
        case 4: aero_cavity_set_ramp_ms(&m, a); break;
        case 5: aero_cavity_set_exponent(&m, a); break;
        case 6: {
            aero_ears e = aero_ears_at(a, b, c);
            aero_cavity_set_ears(&m, &e);
            break;
        }
        case 7: aero_cavity_set_seed(&m, (uint32_t)fuzz_byte(&in)); break;
        case 8: aero_cavity_set_sample_rate(&m, a); break;
        case 9: {
            aero_texture *t = (fuzz_byte(&in) & 1) ? cavity_texture() : NULL;
            if (aero_cavity_set_texture(&m, t, err, sizeof(err)) && t) {
                aero_texture_free(t);
                free(t);
            }
            break;
        }
        default: {
            int n = 1 + (int)((fuzz_byte(&in) << 2 | fuzz_byte(&in)) % MAXN);
            for (int i = 0; i < n; i++)
                speed[i] = (float)(i & 1 ? a : b);
            aero_cavity_process(&m, speed, (float *[]){out}, n);
            FUZZ_REQUIRE(fuzz_finite(out, n), "non-finite output");
        }
        }
    }
    aero_cavity_free(&m);
    return 0;
}
