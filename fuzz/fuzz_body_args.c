/* fuzz: [body~]'s creation flags and messages (pose in its three forms,
 * place, wind, listener, ears, scale, exponent, gain, ramp, seed, texture),
 * through the core setters src/pd/body~.c routes them to (body.h),
 * in any order, with any numbers, between blocks of any size 1..1024 with
 * any speed signal, mono and stereo, on small synthetic object textures
 * (sphere or axis symmetry, 1..3 directions, 1..4 regions, mirror or not).
 * Invariant: the output stays finite. No seeds: every byte string is a
 * valid program. */
/* aero-fuzz: object body~ */
#include "fuzz.h"

#include "body.h"

#define MAXN 1024

static aero_texture *synthetic_texture(fuzz_stream *in)
{
    int sphere = fuzz_byte(in) & 1;
    int dirs = sphere ? 1 : 1 + (int)(fuzz_byte(in) % 3);
    int regions = 1 + (int)(fuzz_byte(in) % 4);
    int frames = 2 + (int)(fuzz_byte(in) % 64);
    char centres[256];
    size_t used = 0;
    aero_texture *t = calloc(1, sizeof(*t));
    if (!t || aero_texture_init_regions(t, frames, dirs, regions, 4000.0)) {
        free(t);
        return NULL;
    }
    for (int n = 0; n < frames * t->channels; n++)
        t->data[n] = (float)sin(0.37 * n);
    for (int k = 0; k < dirs; k++)
        t->angles[k] = dirs > 1 ? 90.0 * k / (dirs - 1) : 90.0;
    for (int l = 0; l < regions; l++)
        used += (size_t)snprintf(centres + used, sizeof centres - used,
                                 "%s0,0,%g", l ? ";" : "", 0.1 * l);
    aero_texture_set(t, "kind", "object");
    aero_texture_set(t, "v0", "10");
    aero_texture_set(t, "diameter", "0.1");
    aero_texture_set(t, "symmetry", sphere ? "sphere" : "axis");
    aero_texture_setd(t, "mirror", fuzz_byte(in) & 1);
    aero_texture_set(t, "centres", centres);
    return t;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_stream in = {data, size};
    int stereo = fuzz_byte(&in) & 1;
    static float speed[MAXN], l[MAXN], r[MAXN];
    float *out[2] = {l, r};
    double v[7];
    char err[256];
    aero_body s;
    if (aero_body_init(&s, 44100.0, stereo ? 2 : 1, 1))
        return 0;
    while (in.left) {
        unsigned op = fuzz_byte(&in) % 13;
        double a = fuzz_number(&in);
        switch (op) {
        case 0:
        case 1: { /* pose / place: position + quaternion or rotation vector */
            for (int i = 0; i < 7; i++)
                v[i] = fuzz_number(&in);
            if (fuzz_byte(&in) & 1) {
                double q[4];
                if (fabs(v[3]) < 1e9 && fabs(v[4]) < 1e9 && fabs(v[5]) < 1e9) {
                    aero_body_quaternion_from_rotvec(v + 3, q);
                    aero_body_set_pose(&s, v, q, op ? -1.0 : a);
                }
            } else
                aero_body_set_pose(&s, v, v + 3, op ? -1.0 : a);
            break;
        }
        case 2:
            v[0] = a, v[1] = fuzz_number(&in), v[2] = fuzz_number(&in);
            aero_body_set_wind(&s, v);
            break;
        case 3: {
            aero_ears e = {1 + (int)(fuzz_byte(&in) % 3), {{a}}};
            e.pos[0][1] = fuzz_number(&in), e.pos[0][2] = fuzz_number(&in);
            memcpy(e.pos[1], e.pos[0], sizeof e.pos[1]);
            aero_body_set_ears(&s, &e);
            break;
        }
        case 4: aero_body_set_scale(&s, a); break;
        case 5: aero_body_set_exponent(&s, a); break;
        case 6: aero_body_set_gain_db(&s, a); break;
        case 7: aero_body_set_ramp_ms(&s, a); break;
        case 8: aero_body_set_seed(&s, (uint32_t)fuzz_byte(&in) * 2654435761u); break;
        case 9: aero_body_set_sample_rate(&s, a); break;
        case 10: { /* texture: a new one, or none */
            aero_texture *t = (fuzz_byte(&in) & 1) ? synthetic_texture(&in)
                                                   : NULL;
            if (aero_body_set_texture(&s, t, err, sizeof(err)) && t) {
                aero_texture_free(t);
                free(t);
            }
            break;
        }
        default: { /* a block */
            int n = 1 + (int)((fuzz_byte(&in) << 2 | fuzz_byte(&in)) % MAXN);
            for (int i = 0; i < n; i++)
                speed[i] = (float)a;
            aero_body_process(&s, (fuzz_byte(&in) & 1) ? speed : NULL,
                                      out, n);
            FUZZ_REQUIRE(fuzz_finite(l, n) && (!stereo || fuzz_finite(r, n)),
                         "non-finite output");
            break;
        }
        }
    }
    aero_body_free(&s);
    return 0;
}
