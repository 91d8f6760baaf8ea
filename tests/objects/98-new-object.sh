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
sed 's/^\(    X(.*)\)$/\1 X(gust)/' src/pd/aero.c >"$NEW/src/pd/aero.c"
if [ "$(diff src/pd/aero.c "$NEW/src/pd/aero.c" | grep -c '^>')" -eq 1 ]; then
    pass "one line of src/pd/aero.c changed: $(diff src/pd/aero.c "$NEW/src/pd/aero.c" | grep '^>' | sed 's/^> *//')"
else
    fail "the registration in src/pd/aero.c is not one line (has AERO_OBJECTS changed?)"
fi

# negative control: with the object's code and its word but none of its test
# files yet, the registration check names what [gust~] lacks
if (cd "$NEW" && sh tests/robust/registered.sh) >"$NEW/registered-before.log" 2>&1; then
    fail "registration check: [gust~] without its test files passed"
elif grep -q -F "FAIL [gust~] (AERO_OBJECTS) lacks its robustness file tests/robust/objects/gust~.txt, a unit_multi_instance(\"gust~\", ...) case in tests/unit/test_*.c, a fuzz harness with /* aero-fuzz: object gust~ */, a README.md line naming [gust~] and gust~-help.pd" \
    "$NEW/registered-before.log"; then
    pass "negative control: before step 5 the registration check names the four things [gust~] lacks"
else
    fail "registration check: not the expected findings for [gust~]"; cat "$NEW/registered-before.log"
fi
gust_hostile_before=$(cd "$NEW" && sh tests/robust/object-table.sh hostile | grep -c '^gust~ ')

# 5. its tests: the unit test (a law and the multi-instance case), ...
cat >"$NEW/tests/unit/test_gust.c" <<'EOF'
/* Unit test of [gust~] (the throwaway object of 98-new-object.sh): its
 * tone at St U / d, and two instances at once. */
#include "gust.h"
#include "multi_instance.h"

UNIT_TEST(strouhal_tone)
{
    enum { N = 44100 };
    static float speed[N], out[N];
    aero_gust g;
    aero_gust_init(&g, 44100.0, 1, 0);
    for (int i = 0; i < N; i++)
        speed[i] = 10.0f;
    aero_gust_process(&g, speed, (float *[]){out}, N);
    /* St 0.2 (Roshko 1954) x 10 m/s / 0.01 m */
    UNIT_NEAR_REL(unit_zero_crossing_hz(out, N, 44100.0), 200.0, 0.01,
                  "tone at 10 m/s (Hz)");
    aero_gust_free(&g);
}

static void *mi_make(int variant)
{
    aero_gust *g = calloc(1, sizeof(*g));
    aero_gust_init(g, 44100.0, 1, 0);
    aero_gust_set_gain_db(g, variant ? -6.0 : 0.0);
    return g;
}
static void mi_run(void *s, const float *speed, float *out, int n)
{
    aero_gust_process(s, speed, (float *[]){out}, n);
}
static void mi_drop(void *s)
{
    aero_gust_free(s);
    free(s);
}

UNIT_TEST(multi_instance)
{
    unit_multi_instance("gust~", "model", mi_make, mi_run, mi_drop);
}

UNIT_MAIN(UNIT_CASE(strouhal_tone), UNIT_CASE(multi_instance))
EOF
# ... its hostile-input and long-run configurations, ...
cat >"$NEW/tests/robust/objects/gust~.txt" <<'EOF'
# [gust~]: its hostile-input configurations and long runs
# (fields: tests/robust/objects/README.md)
hostile | -gain 0 | 1 | - | -gain NAN, -gain INF, -gain 900, 1 2 3, -listener a b c | gain NAN; gain INF; gain 1e30; gain -1e9; listener NAN 0 0; listener a b c; listener 1 2
long | gust-model | -gain 0 | -
EOF
# ... and its fuzz harness
cat >"$NEW/fuzz/fuzz_gust_args.c" <<'EOF'
/* fuzz: [gust~]'s messages through the core setters, between blocks of
 * any size and speed. Invariant: finite output. No seeds needed. */
/* aero-fuzz: object gust~ */
#include "fuzz.h"

#include "gust.h"

#define MAXN 1024

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_stream in = {data, size};
    static float speed[MAXN], out[MAXN];
    aero_gust g;
    aero_gust_init(&g, 44100.0, 1, 0);
    while (in.left) {
        unsigned op = fuzz_byte(&in) % 3;
        double a = fuzz_number(&in);
        if (op == 0) {
            aero_gust_set_gain_db(&g, a);
        } else if (op == 1) {
            aero_ears e = aero_ears_at(a, a, a);
            aero_gust_set_ears(&g, &e);
        } else {
            int n = 1 + (int)(fuzz_byte(&in) % MAXN);
            for (int i = 0; i < n; i++)
                speed[i] = (float)a;
            aero_gust_process(&g, speed, (float *[]){out}, n);
            FUZZ_REQUIRE(fuzz_finite(out, n), "non-finite output");
        }
    }
    aero_gust_free(&g);
    return 0;
}
EOF
# 6. its line in the README's list of objects
awk '{ print } /^\| `\[body~\]` \|/ {
    print "| `[gust~]` | the throwaway object of tests/objects/98-new-object.sh | help/gust~-help.pd |" }' \
    README.md >"$NEW/README.md"

if (cd "$NEW" && sh tests/robust/registered.sh) >"$NEW/registered.log" 2>&1 &&
    grep -q -F "ok   [gust~]: wrapper, 1 hostile and 1 long configurations, multi-instance case, fuzz harness, README line" "$NEW/registered.log"; then
    pass "registration check: [gust~] complete with its own files"
else
    fail "registration check: [gust~] with its files does not pass"; cat "$NEW/registered.log"
fi
# the files the copy changed beside its new ones: the word and the README line
gust_changed=$(for f in src/pd/aero.c README.md $(git ls-files); do
    [ -f "$NEW/$f" ] && ! cmp -s "$f" "$NEW/$f" && echo "$f"
done | sort -u | tr '\n' ' ')
if [ "$gust_changed" = "README.md src/pd/aero.c " ]; then
    pass "beside its own new files, the copy changed only: $gust_changed"
else
    fail "the copy changed more than src/pd/aero.c and README.md: $gust_changed"
fi
gust_hostile_after=$(cd "$NEW" && sh tests/robust/object-table.sh hostile | grep -c '^gust~ ')
if [ "$gust_hostile_before" -eq 0 ] && [ "$gust_hostile_after" -eq 1 ]; then
    pass "the hostile-input table gains [gust~] from its own file ($gust_hostile_before -> $gust_hostile_after configurations)"
else
    fail "the hostile-input table has $gust_hostile_before -> $gust_hostile_after [gust~] configurations, want 0 -> 1"
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

# --- the lists that read [gust~]'s own files pick it up: in the copy, on
# [gust~] alone. Its unit test, built by the rule for every
# tests/unit/test_*.c: the law and the multi-instance case.
if (cd "$NEW" && nice -n 10 make -s build/tests/test_gust >>"$NEW/build.log" 2>&1); then
    (cd "$NEW" && build/tests/test_gust) >"$NEW/test_gust.txt" 2>&1
    gust_mi=$(grep -F "[gust~] model: two instances interleaved" "$NEW/test_gust.txt")
    if tail -1 "$NEW/test_gust.txt" | grep -q "^[1-9][0-9]* passed, 0 failed$" &&
        [ -n "$gust_mi" ]; then
        pass "tests/unit/test_gust.c built and passed ($(tail -1 "$NEW/test_gust.txt")):$(echo "$gust_mi" | sed 's/^ *ok *//')"
    else
        fail "tests/unit/test_gust.c:"; cat "$NEW/test_gust.txt"
    fi
else
    fail "tests/unit/test_gust.c does not build"; tail -20 "$NEW/build.log"
fi
# the hostile-input test of tests/objects/90-hostile.sh, run in the copy (in
# a subshell, its verdicts added here) for [gust~] only
rm -f "$NEW/hostile-counts"
(
    cd "$NEW" || exit 1
    ROOT=$NEW OUT=$NEW/out passed=0 failed=0 ONLY=90-hostile HOSTILE_ONLY='gust~'
    mkdir -p "$OUT"
    . tests/objects/90-hostile.sh
    echo "$passed $failed" >"$NEW/hostile-counts"
)
if [ -s "$NEW/hostile-counts" ]; then
    read -r gust_p gust_f <"$NEW/hostile-counts"
    passed=$((passed + gust_p))
    failed=$((failed + gust_f))
    [ "$gust_p" -gt 0 ] || fail "the hostile-input test passed nothing for [gust~]"
else
    fail "the hostile-input test did not run [gust~] in the copy"
fi
# a long run of one minute (make check-long's runner, tests/robust/long.sh,
# which plays Debian's pd: the single-precision binary)
if [ "$ext" = pd_linux ]; then
    if (cd "$NEW" && LONG_ONLY=gust LONG_SECONDS=60 LONG_COPIES=4 sh tests/robust/long.sh) \
        >"$NEW/long.txt" 2>&1; then
        pass "make check-long's runner picks up [gust~]: $(grep 'gust-model:' "$NEW/long.txt" | sed 's/^ *//')"
    else
        fail "the long run of [gust~]:"; cat "$NEW/long.txt"
    fi
fi
# its fuzz harness, found by its file name and built as
# tests/objects/95-fuzz-replay.sh builds it (without the sanitizers here, on
# the copy's core library), replaying a few bytes
gust_targets=$(cd "$NEW" && . fuzz/targets.sh && fuzz_targets | tr '\n' ' ')
case " $gust_targets" in
*" gust_args "*)
    printf 'gust\001\002\003\377\200\000' >"$NEW/fuzz-input"
    if (cd "$NEW" && ${CC:-cc} -std=gnu99 -O1 -DFUZZ_REPLAY -Wall -Wextra -fopenmp \
        -Isrc/core/common -Isrc/core/solve -Isrc/core/play fuzz/fuzz_gust_args.c \
        build/libaero_core.a -o build/fuzz_gust_args \
        -lsndfile -lfftw3f_threads -lfftw3f -lfftw3 -lpng -lm) >"$NEW/fuzz-build.log" 2>&1 &&
        ! grep -q 'warning:' "$NEW/fuzz-build.log" &&
        "$NEW/build/fuzz_gust_args" "$NEW/fuzz-input" >"$NEW/fuzz.txt" 2>&1; then
        pass "the fuzz targets include gust_args, found by its file; its harness builds warning-free and replays ($(tail -1 "$NEW/fuzz.txt"))"
    else
        fail "the fuzz harness of [gust~]:"; cat "$NEW/fuzz-build.log" "$NEW/fuzz.txt" 2>/dev/null | head -20
    fi
    ;;
*) fail "the fuzz targets of the copy lack gust_args: $gust_targets" ;;
esac
