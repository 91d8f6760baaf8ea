/* aero: the multi-instance check, one case in each object's unit test:
 * two instances of a core, run interleaved block by block with different
 * settings, must give exactly (bit for bit) what each gives alone, so no
 * state is shared through globals or statics (libpd runs several Pd
 * instances in one process). An object's test file adds
 *
 *     UNIT_TEST(multi_instance)
 *     {
 *         unit_multi_instance("cavity~", "model", make, run, drop);
 *     }
 *
 * with make(variant) -> state (variant 0 or 1: two different settings),
 * run(state, speed, out, n) one block of the first outlet, drop(state).
 * tests/robust/registered.sh finds the object by the first argument:
 * every object of AERO_OBJECTS (src/pd/aero.c) needs such a case.
 * test_multi_instance.c holds the negative control (a core whose state
 * hides in a static must fail the same comparison). */
#ifndef AERO_MULTI_INSTANCE_H
#define AERO_MULTI_INSTANCE_H

#include "unit.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "texture.h"
#include "tree.h"

#define UNIT_MI_BLOCK 64
#define UNIT_MI_BLOCKS 200

typedef struct {
    void *(*make)(int variant);
    void (*run)(void *state, const float *speed, float *out, int n);
    void (*drop)(void *state);
} unit_mi_core;

/* a gusting speed, different for the two instances */
static inline void unit_mi_speed(int variant, int b, float *speed)
{
    for (int i = 0; i < UNIT_MI_BLOCK; i++) {
        double t = (b * UNIT_MI_BLOCK + i) / 44100.0;
        speed[i] = (float)(8.0 + 4.0 * variant + 3.0 * sin(6.0 * t + variant));
    }
}

/* alone: instance `variant` for UNIT_MI_BLOCKS blocks */
static inline void unit_mi_alone(const unit_mi_core *c, int variant,
                                 float *out)
{
    float speed[UNIT_MI_BLOCK];
    void *s = c->make(variant);
    for (int b = 0; b < UNIT_MI_BLOCKS; b++) {
        unit_mi_speed(variant, b, speed);
        c->run(s, speed, out + b * UNIT_MI_BLOCK, UNIT_MI_BLOCK);
    }
    c->drop(s);
}

/* the number of samples where the interleaved run differs from the lone
   one; checks that the instances make sound at all */
static inline int unit_mi_differences(const char *label, unit_mi_core c)
{
    enum { N = UNIT_MI_BLOCK * UNIT_MI_BLOCKS };
    static float alone[2][N], together[2][N];
    float speed[UNIT_MI_BLOCK];
    unit_mi_alone(&c, 0, alone[0]);
    unit_mi_alone(&c, 1, alone[1]);
    void *s[2] = {c.make(0), c.make(1)};
    for (int b = 0; b < UNIT_MI_BLOCKS; b++)
        for (int v = 0; v < 2; v++) {
            unit_mi_speed(v, b, speed);
            c.run(s[v], speed, together[v] + b * UNIT_MI_BLOCK,
                  UNIT_MI_BLOCK);
        }
    c.drop(s[0]);
    c.drop(s[1]);
    int diff = 0, sound = 0;
    for (int v = 0; v < 2; v++)
        for (int i = 0; i < N; i++) {
            diff += memcmp(&alone[v][i], &together[v][i], sizeof(float)) != 0;
            sound += alone[v][i] != 0.0f;
        }
    UNIT_CHECK(sound > N / 2, "%s: the instances make sound (%d non-zero "
               "samples)", label, sound);
    return diff;
}

/* the check: OBJECT (its Pd class, "cavity~") and WHAT (which core or
   mode, "texture mode") name it */
static inline void unit_multi_instance(const char *object, const char *what,
                                       void *(*make)(int variant),
                                       void (*run)(void *state,
                                                   const float *speed,
                                                   float *out, int n),
                                       void (*drop)(void *state))
{
    char label[128];
    snprintf(label, sizeof(label), "[%s] %s", object, what);
    int diff = unit_mi_differences(label, (unit_mi_core){make, run, drop});
    UNIT_CHECK(diff == 0,
               "%s: two instances interleaved = each alone, bit for bit "
               "(%d of %d samples differ)",
               label, diff, 2 * UNIT_MI_BLOCK * UNIT_MI_BLOCKS);
}

/* --- fixtures several objects' cases share --------------------------- */

/* a synthetic texture of KIND, DIRS directions (allocated: the core that
   takes it frees it) */
static inline aero_texture *unit_mi_texture(const char *kind, int dirs)
{
    aero_texture *t = calloc(1, sizeof(*t));
    aero_texture_init(t, 512, dirs, 16000.0);
    for (int n = 0; n < 512 * t->channels; n++)
        t->data[n] = (float)sin(0.05 * n) * (float)cos(0.0031 * n);
    aero_texture_set(t, "kind", kind);
    aero_texture_set(t, "v0", "10");
    aero_texture_set(t, "diameter", "0.01");
    aero_texture_set(t, "st", "0.2");
    aero_texture_set(t, "symmetry", "0");
    aero_texture_set(t, "mirror", "1");
    for (int k = 0; k < dirs; k++)
        t->angles[k] = 45.0 * k;
    return t;
}

/* a small generated tree, different per variant */
static inline void unit_mi_tree(aero_tree *t, int variant)
{
    aero_tree_shape sh = {2, 80, 1.0, 0.05, 0.06, 0.04, 3u + (unsigned)variant};
    aero_tree_generate(t, &sh);
}

/* the speed as the wrappers take it for a wind: the block's mean */
static inline double unit_mi_block_mean(const float *speed, int n)
{
    double sum = 0.0;
    for (int i = 0; i < n; i++)
        sum += speed[i];
    return sum / n;
}

#endif
