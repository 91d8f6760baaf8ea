# --- a new object joins in two places: CONTRIBUTING.md's walk-through,
# followed for real ---------------------------------------------------------
# In a copy of the tree, [gust~] is added as the walk-through says: its core
# module (src/core/play/gust.{c,h}), its wrapper (src/pd/gust~.c) and one
# word in src/pd/aero.c's AERO_OBJECTS. Nothing else is edited: the build
# finds the new files by itself. The test builds the copy, loads [gust~] in
# Pd as an external and from the single binary, checks its tone (St U / d)
# and that a refused value is worded from its table.
section "a new object from CONTRIBUTING.md: its own files and one registration line"

NEW="$ROOT/$OUT/new-object"
rm -rf "$NEW"
mkdir -p "$NEW"
# the tree as git tracks it, with the times kept (so the built core, copied
# too, is not rebuilt), and the built core objects
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    git ls-files -z | xargs -0 cp -p --parents -t "$NEW"
else # an unpacked source archive: all of it but the build
    tar -cf - --exclude=./build --exclude='./*.pd_linux' --exclude='./*-64.so' . | tar -xpf - -C "$NEW"
fi
mkdir -p "$NEW/build"
cp -pR build/core "$NEW/build/"
cp -p build/libaero_core.a "$NEW/build/"

# 1. the core module
cat >"$NEW/src/core/play/gust.h" <<'EOF'
/* aero: [gust~], the tone of a 1 cm gap in a wind (Strouhal 0.2), the
 * throwaway object of tests/objects/98-new-object.sh */
#ifndef AERO_GUST_H
#define AERO_GUST_H
#include <stdint.h>
#include "aero_ears.h"
#include "aero_ranges.h"

typedef struct {
    double sample_rate, phase, gain;
} aero_gust;

int aero_gust_init(aero_gust *g, double sample_rate, int n_ears,
                   uint32_t seed);
int aero_gust_set_gain_db(aero_gust *g, double db);
int aero_gust_set_ears(aero_gust *g, const aero_ears *e);
int aero_gust_process(aero_gust *g, const float *speed, float *const *out,
                      int n);
void aero_gust_free(aero_gust *g);
#endif
EOF
cat >"$NEW/src/core/play/gust.c" <<'EOF'
#include "gust.h"
#include <math.h>

#define TWO_PI 6.283185307179586

int aero_gust_init(aero_gust *g, double sample_rate, int n_ears,
                   uint32_t seed)
{
    (void)n_ears;
    (void)seed;
    g->sample_rate = sample_rate > 0.0 ? sample_rate : 44100.0;
    g->phase = 0.0;
    g->gain = pow(10.0, AERO_GAIN_DB_DEFAULT / 20.0);
    return sample_rate > 0.0 ? 0 : -1;
}

int aero_gust_set_gain_db(aero_gust *g, double db)
{
    if (!(db >= AERO_GAIN_DB_MIN && db <= AERO_GAIN_DB_MAX))
        return -1;
    g->gain = pow(10.0, db / 20.0);
    return 0;
}

int aero_gust_set_ears(aero_gust *g, const aero_ears *e)
{
    (void)g;
    return aero_ears_ok(e, 1) ? 0 : -1;
}

int aero_gust_process(aero_gust *g, const float *speed, float *const *out,
                      int n)
{
    for (int i = 0; i < n; i++) {
        double u = speed && speed[i] > 0.0f && speed[i] < 100.0f ? speed[i]
                                                                 : 0.0;
        g->phase += TWO_PI * 0.2 * u / 0.01 / g->sample_rate;
        if (g->phase > TWO_PI)
            g->phase -= TWO_PI;
        out[0][i] = (float)(g->gain * 0.01 * u * sin(g->phase));
    }
    return 0;
}

void aero_gust_free(aero_gust *g)
{
    (void)g;
}
EOF

# 2. the wrapper
cat >"$NEW/src/pd/gust~.c" <<'EOF'
/* [gust~]: the throwaway object of tests/objects/98-new-object.sh */
#include "aero_pd.h"

#include "gust.h"

static t_class *gust_tilde_class;

typedef struct _gust_tilde {
    t_object x_obj;
    t_float x_f;
    aero_pd_base x_base;
    aero_gust x_core;
} t_gust_tilde;

static int gust_tilde_process(void *obj, const float *in, float *const *out,
                              int n)
{
    t_gust_tilde *x = obj;
    return aero_gust_process(&x->x_core, in, out, n);
}

static void gust_tilde_dsp(t_gust_tilde *x, t_signal **sp)
{
    aero_gust_init(&x->x_core, sp[0]->s_sr, 1, 0);
    aero_pd_dsp(&x->x_base, sp, 1, gust_tilde_process);
}

AERO_PD_SETTER(gust_tilde, t_gust_tilde, gain, x_core, aero_gust_set_gain_db)

static void gust_tilde_listener(t_gust_tilde *x, t_symbol *s, int argc,
                                t_atom *argv)
{
    aero_ears e;
    if (aero_pd_ears(&x->x_base, s, argc, argv, &e) &&
        aero_gust_set_ears(&x->x_core, &e))
        aero_pd_bad_ears(&x->x_base, e.n);
}

static const aero_pd_method gust_tilde_methods[] = {
    {"gain", AERO_PD_FLOAT, 0, (t_method)gust_tilde_gain, 0, AERO_PD_GAIN},
    {"listener", AERO_PD_LIST, 3, (t_method)gust_tilde_listener, 0,
     AERO_PD_NO_RULE},
};

static const aero_pd_spec gust_tilde_spec = {
    "gust~", gust_tilde_methods, AERO_PD_COUNT(gust_tilde_methods), NULL};

static void *gust_tilde_new(t_symbol *s, int argc, t_atom *argv)
{
    (void)s;
    t_gust_tilde *x = (t_gust_tilde *)pd_new(gust_tilde_class);
    aero_pd_base_init(&x->x_base, x, &gust_tilde_spec, argc, argv);
    aero_gust_init(&x->x_core, sys_getsr(), 1, aero_pd_default_seed());
    aero_pd_parse_flags(&x->x_base, argc, argv);
    aero_pd_base_outlets(&x->x_base);
    return x;
}

static void gust_tilde_free(t_gust_tilde *x)
{
    aero_pd_base_free(&x->x_base);
    aero_gust_free(&x->x_core);
}

AERO_PD_EXPORT void gust_tilde_setup(void)
{
    gust_tilde_class = aero_pd_class_new(
        &gust_tilde_spec, (t_newmethod)(t_method)gust_tilde_new,
        (t_method)gust_tilde_free, sizeof(t_gust_tilde),
        offsetof(t_gust_tilde, x_f), (t_method)gust_tilde_dsp);
}
EOF

# 3. the one registration line: a word in aero.c's AERO_OBJECTS
sed 's/^\(    X(body)\)$/\1 X(gust)/' src/pd/aero.c >"$NEW/src/pd/aero.c"
if [ "$(diff src/pd/aero.c "$NEW/src/pd/aero.c" | grep -c '^>')" -eq 1 ]; then
    pass "one line of src/pd/aero.c changed: $(diff src/pd/aero.c "$NEW/src/pd/aero.c" | grep '^>' | sed 's/^> *//')"
else
    fail "the registration in src/pd/aero.c is not one line (has AERO_OBJECTS changed?)"
fi

# build the copy: the new external and the single binary (the core's
# objects depend on every core header: the new ones get an old time, so
# that only gust.c is compiled)
touch -d 2000-01-01 "$NEW/src/core/play/gust.h" "$NEW/src/core/play/gust.c"
# the binaries of the Pd under test: a double-precision Pd (check-pd056's
# second pass) loads *.linux-amd64-64.so, made by `make double` (the
# same names 97-install.sh checks)
ext=pd_linux
[ "${PD_FLOATSIZE:-32}" = 64 ] && ext=linux-amd64-64.so
if (cd "$NEW" && nice -n 10 make -j2 "gust~.$ext" >"$NEW/build.log" 2>&1 &&
    nice -n 10 make -j2 make-lib-executable=yes "aero.$ext" \
        >>"$NEW/build.log" 2>&1); then
    if grep -q -e 'warning:' "$NEW/build.log"; then
        fail "the copy with [gust~] builds with warnings"; grep 'warning:' "$NEW/build.log" | head -5
    else
        pass "the copy with [gust~] builds warning-free"
    fi
else
    fail "the copy with [gust~] does not build"; tail -20 "$NEW/build.log"
fi

# load it: as an external (gust~.$ext in the copy), then from the
# single binary alone (-lib with its full path: Pd would find the tree's
# own aero binary in the current folder first)
mkdir -p "$NEW/lib-only"
cp "$NEW/aero.$ext" "$NEW/lib-only/"
PD_SEARCH="$NEW" pd_render new-gust-ext "gust~ -gain 900" 1 1000 "; aero-speed 10"
PD_SEARCH="$NEW/lib-only" PD_FLAGS="$PD_FLAGS -lib $NEW/lib-only/aero" \
    pd_render new-gust-lib "gust~" 1 1000 "; aero-speed 10"
for how in ext lib; do
    if [ -s "$OUT/new-gust-$how.wav" ] && ! grep -q "couldn't create" "$OUT/new-gust-$how.log"; then
        pass "[gust~] created from $(if [ $how = ext ]; then echo "its external"; else echo "-lib aero"; fi)"
        # St U / d = 0.2 * 10 / 0.01 = 200 Hz
        judge $ANALYZE peak "$OUT/new-gust-$how.wav" --expect 200 --tol 0.05 \
            --fmin 50 --fmax 1000
    else
        fail "[gust~] not created from $how"; cat "$OUT/new-gust-$how.log"
    fi
done
# negative control: the tree's own single binary, without the word, has no
# [gust~]
PD_SEARCH="$NEW/lib-only" PD_FLAGS="$PD_FLAGS -lib $ROOT/aero" \
    pd_render new-gust-unregistered "gust~" 1 200 "; aero-speed 10"
if grep -q "couldn't create" "$OUT/new-gust-unregistered.log"; then
    pass "negative control: without its word in AERO_OBJECTS, -lib aero has no [gust~]"
else
    fail "negative control: [gust~] created from a single binary that does not list it"
fi
# a refused value, worded by the skeleton from the table
want="[gust~]: gain 900 dB out of range (-200..120 dB; default 0 dB): flag -gain ignored, the default stays"
if grep -q -F "$want" "$OUT/new-gust-ext.log"; then
    pass "the table words the refusal: $want"
else
    fail "no '$want'"; cat "$OUT/new-gust-ext.log"
fi
