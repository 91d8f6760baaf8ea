/* aero: two instances of each core, run interleaved block by
 * block with different settings, give exactly (bit for bit) what each
 * gives alone: no state is shared through globals or statics. A new core
 * joins with one line in `cores` below.
 * Negative control: a "core" whose state hides in a static variable must
 * fail the same comparison. */
#include "unit.h"

#include <stdlib.h>
#include <string.h>

#include "aeolian.h"
#include "body_texture.h"
#include "cavity_model.h"
#include "field_render.h"
#include "field_volume.h"
#include "leafwave.h"
#include "treebranch.h"
#include "vortex_player.h"

#define BLOCK 64
#define BLOCKS 200

/* an instance: make(variant) -> state, run(state, speed, out, n), drop */
typedef struct {
    const char *name;
    void *(*make)(int variant);
    void (*run)(void *state, const float *speed, float *out, int n);
    void (*drop)(void *state);
} core_api;

/* --- [aeolian~] model and texture mode --- */
static void *aeolian_make(int variant)
{
    aero_aeolian *m = calloc(1, sizeof(*m));
    aero_aeolian_init(m, 44100.0, 1, 11u + variant);
    aero_aeolian_set_diameter(m, variant ? 0.004 : 0.01);
    return m;
}
static void aeolian_run(void *s, const float *speed, float *out, int n)
{
    float *outs[1] = {out};
    aero_aeolian_process(s, speed, outs, n);
}
static void aeolian_drop(void *s)
{
    aero_aeolian_free(s);
    free(s);
}
static void plain_drop(void *s) { free(s); }

/* --- [cavity~] model and texture mode --- */
static aero_texture *synthetic_texture(const char *kind, int dirs)
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
static void *cavity_make_mode(int variant, int textured)
{
    char err[128];
    aero_cavity *m = calloc(1, sizeof(*m));
    aero_cavity_init(m, 44100.0, 5u + variant);
    aero_cavity_set_length(m, variant ? 0.05 : 0.02);
    if (textured)
        aero_cavity_set_texture(m, synthetic_texture("cavity", 1), err,
                                      sizeof(err));
    return m;
}
static void *cavity_make(int variant) { return cavity_make_mode(variant, 0); }
static void *cavity_tex_make(int variant) { return cavity_make_mode(variant, 1); }
static void cavity_run(void *s, const float *speed, float *out, int n)
{
    aero_cavity_process(s, speed, (float *[]){out}, n);
}
static void cavity_drop(void *s)
{
    aero_cavity_free(s);
    free(s);
}

/* --- [aeolian~] texture mode: a moving stick --- */
static void *stick_make(int variant)
{
    char err[128];
    aero_aeolian *s = calloc(1, sizeof(*s));
    aero_aeolian_init(s, 44100.0, 1, 3u + variant);
    aero_aeolian_set_texture(s, synthetic_texture("aeolian", 2), err,
                             sizeof(err));
    double wind[3] = {variant ? 7.0 : 12.0, 1.0, 0.0};
    aero_aeolian_set_wind(s, wind);
    aero_aeolian_set_sources(s, variant ? 3 : 5);
    return s;
}

/* --- [body~]: a synthetic object texture, 2 directions x 3 regions --- */
static void *body_make(int variant)
{
    char err[128];
    aero_body *s = calloc(1, sizeof(*s));
    aero_texture *t = calloc(1, sizeof(*t));
    double wind[3] = {variant ? 7.0 : 12.0, 1.0, 0.5};
    double pos[3] = {0.1 * variant, 0.0, 0.0}, q[4] = {0.9, 0.1, 0.2, 0.3};
    aero_texture_init_regions(t, 512, 2, 3, 16000.0);
    for (int n = 0; n < 512 * t->channels; n++)
        t->data[n] = (float)sin(0.05 * n) * (float)cos(0.0031 * n);
    aero_texture_set(t, "kind", "object");
    aero_texture_set(t, "v0", "10");
    aero_texture_set(t, "diameter", "0.05");
    aero_texture_set(t, "symmetry", "axis");
    aero_texture_set(t, "centres", "0,0,0;0,0,0.2;0,0,0.4");
    t->angles[0] = 0.0;
    t->angles[1] = 90.0;
    aero_body_init(s, 44100.0, 1, 5u + variant);
    aero_body_set_texture(s, t, err, sizeof(err));
    aero_body_set_wind(s, wind);
    aero_body_set_pose(s, pos, q, -1.0);
    return s;
}
static void body_run(void *s, const float *speed, float *out, int n)
{
    float *outs[1] = {out};
    aero_body_process(s, speed, outs, n);
}
static void body_drop(void *s)
{
    aero_body_free(s);
    free(s);
}

/* --- [vortex~]: a synthetic vortex texture of 3 speeds, 4 sources --- */
static void *vortex_make(int variant)
{
    char err[128];
    double speeds[3] = {5.0, 10.0, 20.0}, pos[12];
    aero_vortex *m = calloc(1, sizeof(*m));
    aero_texture *t = calloc(1, sizeof(*t));
    aero_vortex_init(m, 44100.0, 0, 7u + variant);
    aero_texture_init_speeds(t, 2048, 3, speeds, 8000.0);
    for (int n = 0; n < 2048 * 3; n++)
        t->data[n] = (float)sin(0.05 * n) * (float)cos(0.0031 * n);
    aero_vortex_set_texture(m, t, err, sizeof(err));
    aero_vortex_set_count(m, 4);
    for (int i = 0; i < 12; i++)
        pos[i] = 0.1 * i * (variant ? -1 : 1);
    aero_vortex_set_positions(m, pos, 4);
    return m;
}
static void vortex_run(void *s, const float *speed, float *out, int n)
{
    float *outs[1] = {out};
    aero_vortex_process(s, speed, outs, n);
}
static void vortex_drop(void *s)
{
    aero_vortex_free(s);
    free(s);
}

/* a small generated tree for [treebranch~] and [leafwave~] */
static void small_tree(aero_tree *t, int variant)
{
    aero_tree_shape sh = {2, 80, 1.0, 0.05, 0.06, 0.04, 3u + variant};
    aero_tree_generate(t, &sh);
}
/* the speed as the wrappers take it: the block's mean along +x */
static double block_mean(const float *speed, int n)
{
    double sum = 0.0;
    for (int i = 0; i < n; i++)
        sum += speed[i];
    return sum / n;
}

/* --- [treebranch~] --- */
static void *treebranch_make(int variant)
{
    aero_tree t;
    double ear[3] = {0.0, variant ? -2.0 : -4.0, 1.5};
    aero_treebranch *tb = calloc(1, sizeof(*tb));
    aero_treebranch_init(tb, 44100.0, 9u + variant);
    small_tree(&t, variant);
    aero_treebranch_set_tree(tb, &t);
    aero_treebranch_set_ears(tb,
                             &(aero_ears){1, {{ear[0], ear[1], ear[2]}}});
    return tb;
}
static void treebranch_run(void *s, const float *speed, float *out, int n)
{
    double w[3] = {block_mean(speed, n), 0.0, 0.0};
    aero_treebranch_set_wind(s, w);
    aero_treebranch_process(s, out, NULL, n);
}
static void treebranch_drop(void *s)
{
    aero_treebranch_free(s);
    free(s);
}

/* --- [leafwave~] --- */
static void *leafwave_make(int variant)
{
    char err[128];
    aero_tree t;
    aero_leafwave *lw = calloc(1, sizeof(*lw));
    aero_leafwave_init(lw, 44100.0, 1, 13u + variant);
    aero_leafwave_set_tables(lw, 400.0, 4, 3);
    small_tree(&t, variant);
    aero_leafwave_set_tree(lw, &t, err, sizeof(err));
    aero_leafwave_set_ears(lw, &(aero_ears){1, {{0.0, variant ? -1.0 : -2.0,
                                                 1.5}}});
    return lw;
}
static void leafwave_run(void *s, const float *speed, float *out, int n)
{
    float *outs[1] = {out};
    aero_leafwave_set_wind(s, 1.0, 0.0, 0.0);
    aero_leafwave_process(s, speed, outs, n);
}
static void leafwave_drop(void *s)
{
    aero_leafwave_free(s);
    free(s);
}

/* --- [fieldsound~]: the demo burst, preprocessed, played slowly --- */
typedef struct {
    aero_field_sources src;
    aero_fieldsound r;
} field_state;
static void *field_make(int variant)
{
    char err[256];
    aero_field_demo d;
    aero_volume_info info;
    aero_field_params par;
    field_state *f = calloc(1, sizeof(*f));
    aero_field_demo_default(&d);
    d.size = 12;
    d.spacing = 1.28 / d.size;
    d.seed = 1u + variant;
    aero_field_demo_info(&d, &info);
    aero_field_params_default(&par);
    aero_field_prepare(&info, &d, &par, &f->src, NULL, NULL, err, sizeof(err));
    aero_fieldsound_init(&f->r, 44100.0);
    aero_fieldsound_set_sources(&f->r, &f->src);
    aero_fieldsound_place_ears(&f->r,
            &(aero_ears){1, {{variant ? 0.5 : 0.8, 0.1, 0.0}}});
    aero_fieldsound_set_speed(&f->r, 100.0);
    aero_fieldsound_play(&f->r);
    return f;
}
static void field_run(void *s, const float *speed, float *out, int n)
{
    (void)speed;
    aero_fieldsound_process(&((field_state *)s)->r, out, n);
}
static void field_drop(void *s)
{
    field_state *f = s;
    aero_fieldsound_free(&f->r);
    aero_field_sources_free(&f->src);
    free(f);
}

/* --- negative control: state in a static, as a careless core would --- */
static double shared_phase;
static void *shared_make(int variant)
{
    double *f = calloc(1, sizeof(*f));
    *f = variant ? 0.03 : 0.01;
    shared_phase = 0.0;
    return f;
}
static void shared_run(void *s, const float *speed, float *out, int n)
{
    for (int i = 0; i < n; i++) {
        shared_phase += *(double *)s * (1.0 + speed[i]);
        out[i] = (float)sin(shared_phase);
    }
}

static const core_api cores[] = {
    {"aeolian", aeolian_make, aeolian_run, aeolian_drop},
    {"cavity_model", cavity_make, cavity_run, cavity_drop},
    {"cavity_model (texture)", cavity_tex_make, cavity_run, cavity_drop},
    {"aeolian (texture)", stick_make, aeolian_run, aeolian_drop},
    {"body_texture", body_make, body_run, body_drop},
    {"vortex_player", vortex_make, vortex_run, vortex_drop},
    {"treebranch", treebranch_make, treebranch_run, treebranch_drop},
    {"leafwave", leafwave_make, leafwave_run, leafwave_drop},
    {"field_sound", field_make, field_run, field_drop},
};
static const core_api control = {"static-state control", shared_make,
                                 shared_run, plain_drop};

/* a gusting speed, different for the two instances */
static void speed_block(int variant, int b, float *speed)
{
    for (int i = 0; i < BLOCK; i++) {
        double t = (b * BLOCK + i) / 44100.0;
        speed[i] = (float)(8.0 + 4.0 * variant + 3.0 * sin(6.0 * t + variant));
    }
}

/* alone: instance `variant` for BLOCKS blocks */
static void run_alone(const core_api *c, int variant, float *out)
{
    float speed[BLOCK];
    void *s = c->make(variant);
    for (int b = 0; b < BLOCKS; b++) {
        speed_block(variant, b, speed);
        c->run(s, speed, out + b * BLOCK, BLOCK);
    }
    c->drop(s);
}

/* number of samples where the interleaved run differs from the lone one */
static int interleaved_differences(const core_api *c)
{
    static float alone[2][BLOCK * BLOCKS], together[2][BLOCK * BLOCKS];
    float speed[BLOCK];
    run_alone(c, 0, alone[0]);
    run_alone(c, 1, alone[1]);
    void *s[2] = {c->make(0), c->make(1)};
    for (int b = 0; b < BLOCKS; b++)
        for (int v = 0; v < 2; v++) {
            speed_block(v, b, speed);
            c->run(s[v], speed, together[v] + b * BLOCK, BLOCK);
        }
    c->drop(s[0]);
    c->drop(s[1]);
    int diff = 0, sound = 0;
    for (int v = 0; v < 2; v++)
        for (int i = 0; i < BLOCK * BLOCKS; i++) {
            diff += memcmp(&alone[v][i], &together[v][i], sizeof(float)) != 0;
            sound += alone[v][i] != 0.0f;
        }
    UNIT_CHECK(sound > BLOCK * BLOCKS / 2,
               "%s: the instances make sound (%d non-zero samples)", c->name,
               sound);
    return diff;
}

UNIT_TEST(instances_independent)
{
    for (size_t k = 0; k < sizeof(cores) / sizeof(cores[0]); k++) {
        int diff = interleaved_differences(&cores[k]);
        UNIT_CHECK(diff == 0,
                   "%s: two instances interleaved = each alone, bit for bit "
                   "(%d of %d samples differ)",
                   cores[k].name, diff, 2 * BLOCK * BLOCKS);
    }
}

UNIT_TEST(negative_control)
{
    int diff = interleaved_differences(&control);
    UNIT_CHECK(diff > 0,
               "negative control: a core with static state is caught (%d "
               "samples differ)", diff);
}

UNIT_MAIN(UNIT_CASE(instances_independent), UNIT_CASE(negative_control))
