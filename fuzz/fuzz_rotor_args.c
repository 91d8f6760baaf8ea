/* fuzz: [rotor~]'s creation flags and messages (blades, strips, radius,
 * chord, thickness, hub, thrust, torque, design, pose and place, wind,
 * listener, ears, gain, ramp), through the core setters src/pd/rotor~.c
 * routes them to (rotor), in any order, with any numbers, between blocks
 * of any size 1..1024 with any rpm signal, mono and stereo. Invariant:
 * the output stays finite. No seeds: every byte string is a valid
 * program. */
/* aero-fuzz: object rotor~ */
#include "fuzz.h"

#include "rotor.h"

#define MAXN 1024

/* setting `op` (0..9) to a */
static void set_number(aero_rotor *r, unsigned op, double a)
{
    switch (op) {
    case 0: aero_rotor_set_blades(r, a); break;
    case 1: aero_rotor_set_strips(r, a); break;
    case 2: aero_rotor_set_radius(r, a); break;
    case 3: aero_rotor_set_chord(r, a); break;
    case 4: aero_rotor_set_thickness(r, a); break;
    case 5: aero_rotor_set_hub(r, a); break;
    case 6: aero_rotor_set_thrust(r, a); break;
    case 7: aero_rotor_set_torque(r, a); break;
    case 8: aero_rotor_set_design(r, a); break;
    case 9: aero_rotor_set_gain_db(r, a); break;
    default: aero_rotor_set_ramp_ms(r, a); break;
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_stream in = {data, size};
    int stereo = fuzz_byte(&in) & 1;
    static float rpm[MAXN], l[MAXN], r[MAXN];
    float *out[2] = {l, r};
    double v[7];
    aero_rotor s;
    if (aero_rotor_init(&s, 44100.0, stereo ? 2 : 1, 1))
        return 0;
    while (in.left) {
        unsigned op = fuzz_byte(&in) % 17;
        double a = fuzz_number(&in);
        switch (op) {
        case 0: { /* pose / place: position + quaternion or rotation vector */
            for (int i = 0; i < 7; i++)
                v[i] = fuzz_number(&in);
            int offset = (int)(fuzz_byte(&in) % 200) - 20;
            if (fuzz_byte(&in) & 1) {
                double q[4];
                if (fabs(v[3]) < 1e9 && fabs(v[4]) < 1e9 && fabs(v[5]) < 1e9) {
                    aero_rotor_quaternion_from_rotvec(v + 3, q);
                    aero_rotor_set_pose_at(&s, v, q, a, offset);
                }
            } else
                aero_rotor_set_pose_at(&s, v, v + 3, a, offset);
            break;
        }
        case 1:
            v[0] = a, v[1] = fuzz_number(&in), v[2] = fuzz_number(&in);
            aero_rotor_set_wind(&s, v);
            break;
        case 2: {
            aero_ears e = {1 + (int)(fuzz_byte(&in) % 3), {{a}}};
            e.pos[0][1] = fuzz_number(&in), e.pos[0][2] = fuzz_number(&in);
            memcpy(e.pos[1], e.pos[0], sizeof e.pos[1]);
            aero_rotor_set_ears(&s, &e);
            break;
        }
        case 3: aero_rotor_set_sample_rate(&s, a); break;
        case 4: case 5: case 6: case 7: case 8: case 9:
        case 10: case 11: case 12: case 13:
            set_number(&s, fuzz_byte(&in) % 11, a);
            break;
        default: { /* a block */
            int n = 1 + (int)((fuzz_byte(&in) << 2 | fuzz_byte(&in)) % MAXN);
            for (int i = 0; i < n; i++)
                rpm[i] = (float)(a * (1.0 + 0.001 * i));
            aero_rotor_process(&s, (fuzz_byte(&in) & 1) ? rpm : NULL, out, n);
            FUZZ_REQUIRE(fuzz_finite(l, n) && (!stereo || fuzz_finite(r, n)),
                         "non-finite output");
            break;
        }
        }
    }
    aero_rotor_free(&s);
    return 0;
}
