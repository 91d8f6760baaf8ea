/* fuzz: [leafwave~]'s creation flags and messages (wind, mic, listener,
 * ears, k, gain, ramp, stiffness, beta, sway, coupling, flutter, hit, rub,
 * reach, voices, fm, tables, octaves, seed, open), through the core
 * setters src/pd/leafwave~.c routes them to (leafwave), in any order, with
 * any numbers (NaN, infinities, denormals, huge), between blocks of any
 * size 1..1024 with any speed signal, mono and stereo, on a small
 * generated tree or none. Invariant: the output stays finite. No seeds:
 * every byte string is a valid program. */
/* aero-fuzz: object leafwave~ */
#include "fuzz.h"

#include "leafwave.h"

#define MAXN 1024

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_stream in = {data, size};
    int ears = 1 + (fuzz_byte(&in) & 1);
    static float speed[MAXN], l[MAXN], r[MAXN];
    float *outs[2] = {l, r};
    double v[3];
    char err[256];
    aero_leafwave lw;
    if (aero_leafwave_init(&lw, 44100.0, ears, 1))
        return 0;
    /* small tables keep an execution cheap; the fuzzer may grow them */
    aero_leafwave_set_tables(&lw, 400.0, 2, 2);
    while (in.left) {
        unsigned op = fuzz_byte(&in) % 26;
        for (int i = 0; i < 3; i++)
            v[i] = fuzz_number(&in);
        switch (op) {
        case 0: aero_leafwave_set_wind(&lw, v[0], v[1], v[2]); break;
        case 1: aero_leafwave_set_speed(&lw, v[0]); break;
        case 2: { /* 0..2 ears (0: refused) */
            aero_ears e = {(int)(fuzz_byte(&in) % 3),
                           {{v[0], v[1], v[2]}, {v[0], v[1], v[2]}}};
            aero_leafwave_set_ears(&lw, &e);
            break;
        }
        case 3: aero_leafwave_set_mic(&lw, v[0], v[1], v[2]); break;
        case 4: aero_leafwave_set_mic_k(&lw, v[0]); break;
        case 5: aero_leafwave_set_gain_db(&lw, v[0]); break;
        case 6: aero_leafwave_set_ramp_ms(&lw, v[0]); break;
        case 7: aero_leafwave_set_stiffness(&lw, v[0]); break;
        case 8: aero_leafwave_set_beta(&lw, v[0]); break;
        case 9: aero_leafwave_set_sway(&lw, v[0]); break;
        case 10: aero_leafwave_set_coupling(&lw, v[0]); break;
        case 11: aero_leafwave_set_flutter(&lw, v[0]); break;
        case 12: aero_leafwave_set_hit(&lw, v[0]); break;
        case 13: aero_leafwave_set_rub(&lw, v[0]); break;
        case 14: aero_leafwave_set_reach(&lw, v[0]); break;
        case 15: /* voices, as the wrapper passes them: whole numbers */
            aero_leafwave_set_voices(&lw, (int)(fuzz_byte(&in) << 4) - 16);
            break;
        case 16:
            aero_leafwave_set_tables(&lw, v[0], (int)(fuzz_byte(&in) % 20) - 2,
                                     (int)(fuzz_byte(&in) % 11) - 1);
            break;
        case 17: aero_leafwave_set_seed(&lw, (uint32_t)fuzz_byte(&in)); break;
        case 18: aero_leafwave_set_sample_rate(&lw, v[0]); break;
        case 19: { /* open: a small tree, or a failed open (cleared) */
            aero_tree t;
            aero_tree_shape sh = {1 + (int)(fuzz_byte(&in) % 3),
                                  (int)(fuzz_byte(&in) % 60), 0.5, 0.05,
                                  0.05, 0.03, fuzz_byte(&in)};
            if ((fuzz_byte(&in) & 3) == 0)
                aero_leafwave_clear_tree(&lw);
            else if (!aero_tree_generate(&t, &sh))
                aero_leafwave_set_tree(&lw, &t, err, sizeof(err));
            break;
        }
        default: { /* a block of any size with any speeds */
            int n = 1 + (int)((fuzz_byte(&in) << 2 | fuzz_byte(&in)) % MAXN);
            for (int i = 0; i < n; i++)
                speed[i] = (float)(i & 1 ? v[0] : v[1]);
            aero_leafwave_process(&lw, (fuzz_byte(&in) & 1) ? speed : NULL,
                                  outs, n);
            for (int e = 0; e < ears; e++)
                FUZZ_REQUIRE(fuzz_finite(outs[e], n), "non-finite output");
        }
        }
    }
    aero_leafwave_free(&lw);
    return 0;
}
