/* fuzz: [treebranch~]'s creation flags and messages (wind, listener, ears,
 * mic, k, gain, ramp, stiffness, beta, alpha, seed, open), through the
 * core setters src/pd/treebranch~.c routes them to (treebranch), in any
 * order, with any numbers (NaN, infinities, denormals, huge), between
 * blocks of any size 1..1024, mono and stereo, on a small generated tree
 * (aero_tree_generate, as `aerotex tree` makes them) or none. Invariant:
 * the output stays finite. No seeds: every byte string is a valid
 * program. */
/* aero-fuzz: object treebranch~ */
#include "fuzz.h"

#include "treebranch.h"

#define MAXN 1024

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_stream in = {data, size};
    int stereo = fuzz_byte(&in) & 1;
    static float l[MAXN], r[MAXN];
    double v[6];
    aero_treebranch tb;
    if (aero_treebranch_init(&tb, 44100.0, 1))
        return 0;
    aero_treebranch_set_stereo(&tb, stereo);
    while (in.left) {
        unsigned op = fuzz_byte(&in) % 18;
        for (int i = 0; i < 6; i++)
            v[i] = fuzz_number(&in);
        switch (op) {
        case 0: aero_treebranch_set_wind(&tb, v); break;
        case 1: {
            aero_ears e = aero_ears_at(v[0], v[1], v[2]);
            aero_treebranch_set_ears(&tb, &e);
            break;
        }
        case 2: {
            aero_ears e = {2, {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}}};
            aero_treebranch_set_ears(&tb, &e);
            break;
        }
        case 3: aero_treebranch_set_mic(&tb, v); break;
        case 4: aero_treebranch_set_mic_k(&tb, v[0]); break;
        case 5: aero_treebranch_set_gain_db(&tb, v[0]); break;
        case 6: aero_treebranch_set_ramp_ms(&tb, v[0]); break;
        case 7: aero_treebranch_set_stiffness(&tb, v[0]); break;
        case 8: aero_treebranch_set_beta(&tb, v[0]); break;
        case 9: aero_treebranch_set_alpha(&tb, v[0]); break;
        case 10: aero_treebranch_set_seed(&tb, (uint32_t)fuzz_byte(&in)); break;
        case 11: aero_treebranch_set_sample_rate(&tb, v[0]); break;
        case 12: { /* open: a small tree, or a failed open (silence) */
            aero_tree t;
            aero_tree_shape sh = {1 + (int)(fuzz_byte(&in) % 3),
                                  (int)(fuzz_byte(&in) % 40), 0.5,
                                  0.05, 0.05, 0.03, fuzz_byte(&in)};
            if ((fuzz_byte(&in) & 3) == 0) {
                aero_treebranch_set_tree(&tb, NULL);
            } else if (!aero_tree_generate(&t, &sh) &&
                       aero_treebranch_set_tree(&tb, &t)) {
                aero_tree_free(&t);
            }
            break;
        }
        default: { /* a block of any size */
            int n = 1 + (int)((fuzz_byte(&in) << 2 | fuzz_byte(&in)) % MAXN);
            aero_treebranch_process(&tb, l, stereo ? r : NULL, n);
            FUZZ_REQUIRE(fuzz_finite(l, n), "non-finite output (left)");
            if (stereo)
                FUZZ_REQUIRE(fuzz_finite(r, n), "non-finite output (right)");
        }
        }
    }
    aero_treebranch_free(&tb);
    return 0;
}
