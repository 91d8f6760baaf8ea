/* fuzz: [aeolian~]'s creation flags and messages, through the core
 * setters they call (src/pd/aeolian~.c routes each flag to one), in any
 * order and with any numbers (NaN, infinities, denormals, huge), between
 * blocks of any size 1..1024 with any speed signal, in model mode and in
 * texture mode (on a small synthetic texture), switching between them.
 * Invariant: the output stays finite. No seeds: every byte string is a
 * valid program. */
/* aero-fuzz: object aeolian~ */
#include "fuzz.h"

#include "aeolian.h"

#define MAXN 1024

static aero_texture *synthetic_texture(int dirs)
{
    aero_texture *t = calloc(1, sizeof(*t));
    if (!t || aero_texture_init(t, 256, dirs, 16000.0)) {
        free(t);
        return NULL;
    }
    for (int n = 0; n < 256 * t->channels; n++)
        t->data[n] = (float)sin(0.37 * n);
    aero_texture_set(t, "kind", "aeolian");
    aero_texture_set(t, "v0", "10");
    aero_texture_set(t, "diameter", "0.01");
    aero_texture_set(t, "st", "0.2");
    aero_texture_set(t, "symmetry", dirs > 1 ? "4" : "0");
    aero_texture_set(t, "mirror", "1");
    for (int k = 0; k < dirs; k++)
        t->angles[k] = 90.0 * k / dirs;
    return t;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_stream in = {data, size};
    int stereo = fuzz_byte(&in) & 1, ears = stereo ? 2 : 1;
    double sr = 44100.0;
    static float speed[MAXN], l[MAXN], r[MAXN];
    float *out[2] = {l, r};
    aero_aeolian x;
    aero_aeolian_init(&x, sr, ears, 1);
    char err[256];
    while (in.left) {
        unsigned op = fuzz_byte(&in) % 20;
        double a = fuzz_number(&in), b = fuzz_number(&in),
               c = fuzz_number(&in);
        double v[6] = {a, b, c, fuzz_number(&in), fuzz_number(&in),
                       fuzz_number(&in)};
        switch (op) {
        case 0: aero_aeolian_set_diameter(&x, a); break;
        case 1: aero_aeolian_set_length(&x, a); break;
        case 2: aero_aeolian_set_gain_db(&x, a); break;
        case 3: aero_aeolian_set_ramp_ms(&x, a); break;
        case 4: {
            aero_ears e = {1 + (int)(b > 0), {{a, b, c}, {a, b, c}}};
            aero_aeolian_set_ears(&x, &e);
            break;
        }
        case 5: aero_aeolian_set_seed(&x, (uint32_t)fuzz_byte(&in));
                (void)fuzz_byte(&in);
                break;
        case 6: aero_aeolian_set_sample_rate(&x, a); break;
        case 7: aero_aeolian_set_sources(&x, (int)fuzz_byte(&in) - 8);
                break;
        case 8: aero_aeolian_set_exponent(&x, a); break;
        case 9: aero_aeolian_set_roll_deg(&x, a); break;
        case 10: aero_aeolian_set_wind(&x, v); break;
        case 11: aero_aeolian_set_pose(&x, v, v + 3, fuzz_number(&in));
                 break;
        case 12: aero_aeolian_set_reference(&x, v); break;
        case 13: { /* texture / model messages */
            aero_texture *t = NULL;
            if (fuzz_byte(&in) & 1)
                t = synthetic_texture(1 + (int)(fuzz_byte(&in) % 5));
            if (aero_aeolian_set_texture(&x, t, err, sizeof(err)) && t) {
                aero_texture_free(t);
                free(t);
            }
            break;
        }
        default: { /* a block of any size with any speeds */
            int n = 1 + (int)((fuzz_byte(&in) << 2 | fuzz_byte(&in)) % MAXN);
            for (int i = 0; i < n; i++)
                speed[i] = (float)(i & 1 ? a : b);
            aero_aeolian_process(&x, speed, out, n);
            for (int e = 0; e < ears; e++)
                FUZZ_REQUIRE(fuzz_finite(out[e], n),
                             "%s mode: non-finite output",
                             aero_aeolian_texture_mode(&x) ? "texture"
                                                           : "model");
        }
        }
    }
    aero_aeolian_free(&x);
    return 0;
}
