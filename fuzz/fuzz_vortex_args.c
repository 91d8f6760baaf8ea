/* fuzz: [vortex~]'s creation flags and messages (n, speeds, positions,
 * listener, ears, gain, clip, ramp, seed, texture), through the core
 * setters src/pd/vortex~.c routes them to (vortex.h), in any order,
 * with any numbers (NaN, infinities, denormals, huge), between blocks of
 * any size 1..1024 with any speed signal, mono and stereo, on a small
 * synthetic vortex texture of 1..4 speeds. Invariant: the output stays
 * finite. No seeds: every byte string is a valid program. */
/* aero-fuzz: object vortex~ */
#include "fuzz.h"

#include "vortex.h"

#define MAXN 1024
#define MAXV 64 /* values in a speeds or positions list */

static aero_texture *synthetic_texture(int nspeeds, int frames)
{
    double speeds[4] = {2.0, 5.0, 10.0, 20.0};
    aero_texture *t = calloc(1, sizeof(*t));
    if (!t || aero_texture_init_speeds(t, frames, nspeeds, speeds, 8000.0)) {
        free(t);
        return NULL;
    }
    for (int n = 0; n < frames * nspeeds; n++)
        t->data[n] = (float)sin(0.37 * n);
    return t;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_stream in = {data, size};
    int stereo = fuzz_byte(&in) & 1;
    static float speed[MAXN], l[MAXN], r[MAXN];
    float *out[2] = {l, r};
    double v[MAXV];
    char err[256];
    aero_vortex m;
    if (aero_vortex_init(&m, 44100.0, stereo ? 2 : 1, 1))
        return 0;
    while (in.left) {
        unsigned op = fuzz_byte(&in) % 14;
        double a = fuzz_number(&in);
        switch (op) {
        case 0: /* n: as the wrapper, whole numbers 1..4096 only */
            aero_vortex_set_count(&m, (int)(fuzz_byte(&in) << 4 |
                                                   fuzz_byte(&in)) - 8);
            break;
        case 1:
        case 2: { /* speeds, positions: 1..MAXV values */
            int count = 1 + (int)(fuzz_byte(&in) % (op == 1 ? MAXV : MAXV / 3));
            for (int i = 0; i < count * (op == 1 ? 1 : 3); i++)
                v[i] = fuzz_number(&in);
            if (op == 1)
                aero_vortex_set_speeds(&m, v, count);
            else
                aero_vortex_set_positions(&m, v, count);
            break;
        }
        case 3: {
            aero_ears e = {1, {{a}}};
            e.pos[0][1] = fuzz_number(&in), e.pos[0][2] = fuzz_number(&in);
            aero_vortex_set_ears(&m, &e);
            break;
        }
        case 4: {
            aero_ears e = {2, {{0}}};
            for (int i = 0; i < 6; i++)
                e.pos[i / 3][i % 3] = fuzz_number(&in);
            aero_vortex_set_ears(&m, &e);
            break;
        }
        case 5: aero_vortex_set_gain_db(&m, a); break;
        case 6: aero_vortex_set_clip(&m, a); break;
        case 7: aero_vortex_set_ramp_ms(&m, a); break;
        case 8: aero_vortex_set_seed(&m, (uint32_t)fuzz_byte(&in) * 2654435761u); break;
        case 9: aero_vortex_set_sample_rate(&m, a); break;
        case 10: { /* texture: a new one, or none */
            aero_texture *t = NULL;
            if (fuzz_byte(&in) & 1)
                t = synthetic_texture(1 + (int)(fuzz_byte(&in) % 4),
                                      1 + (int)(fuzz_byte(&in) % 64));
            if (aero_vortex_set_texture(&m, t, err, sizeof(err)) && t) {
                aero_texture_free(t);
                free(t);
            }
            break;
        }
        default: { /* a block of any size with any speeds */
            int n = 1 + (int)((fuzz_byte(&in) << 2 | fuzz_byte(&in)) % MAXN);
            double b = fuzz_number(&in);
            for (int i = 0; i < n; i++)
                speed[i] = (float)(i & 1 ? a : b);
            aero_vortex_process(&m, speed, out, n);
            for (int e = 0; e <= stereo; e++)
                FUZZ_REQUIRE(fuzz_finite(out[e], n), "non-finite output");
        }
        }
    }
    aero_vortex_free(&m);
    return 0;
}
