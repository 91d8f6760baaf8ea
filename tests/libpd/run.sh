#!/bin/sh
# aero: `make check-libpd`: aero embedded in libpd 0.16.1, the
# way a game, an app or a plugin (Unity, Godot, plugdata) uses it. Builds
# libpd from ../shared/vendor into build/libpd/ (single- and
# multi-instance, once: tests/libpd/build-libpd.sh), links aero statically
# into host programs (one aero_setup()), renders patches and judges the
# sound with build/aero-analyze as tests/run.sh does in Pd; fuzzes every
# object's method table through Pd's parsing layer (fuzz_tables.c); then
# several instances in several threads under helgrind. Ends with `N passed, N
# failed`; skips (exit 0) when the libpd archives are absent.
# Run from the repository root after `make all`. LIBPD_VENDOR overrides
# ../shared/vendor.
ROOT=$(pwd)
OUT=build/libpd/out
ANALYZE=build/aero-analyze
VENDOR=${LIBPD_VENDOR:-../shared/vendor}
RATE=48000
started=$(date +%s)

. tests/judge.sh # pass, fail, judge, log_clean, section
# the same samples (libsndfile's PEAK chunk holds a time stamp: files
# written at different seconds differ in their headers)
same_sound() {
    [ -s "$1" ] && [ -s "$2" ] &&
        [ "$(sox "$1" -t f32 - 2>/dev/null | md5sum)" = \
          "$(sox "$2" -t f32 - 2>/dev/null | md5sum)" ]
}

# --- libpd, both variants ----------------------------------------------------
section "libpd 0.16.1 (Pd 0.56-5) from $VENDOR into build/libpd/"
for variant in single multi; do
    sh tests/libpd/build-libpd.sh "$variant" "$VENDOR"
    status=$?
    if [ "$status" -eq 77 ]; then
        echo "check-libpd: skipped (no libpd archive in $VENDOR)"
        exit 0
    fi
    [ "$status" -eq 0 ] || { echo "check-libpd: libpd $variant did not build"; exit 1; }
done
pass "libpd built: build/libpd/single (make STATIC=true), build/libpd/multi (make STATIC=true MULTI=true)"
rm -rf "$OUT"
mkdir -p "$OUT"

. tests/laws.sh # tone_hz: the published St(Re) laws
# Curle: p_rms = rho U^3 St C_L' L_c / (4 c0 r), C_L'(Re) from Norberg's
# (2003) fits for 1600 < Re < 2.25e5 (as tests/objects/10-aeolian.sh),
# L_c = 3 d: a 3 d long cylinder heard at r across the flow
curle_db() {
    awk -v u="$1" -v d="$2" -v r="$3" 'BEGIN { re = 1.225 * u * d / 1.81e-5
        st = 0.198 * (1 - 19.7 / re)
        x = log(re / 1600) / log(10)
        cl = re < 5400 ? 0.045 + 3 * x^4.6 : 0.52 - 0.06 * x^-2.6
        p = 1.225 * u^3 * st * cl * 3 * d / (4 * 343 * r)
        printf "%.3f", 20 * log(p / 20e-6) / log(10) }'
}
st_cyl=$(build/aerotex info textures/cylinder.wav | sed -n 's/^st=//p')
st_tone() { awk -v st="$st_cyl" -v v="$1" -v d="$2" 'BEGIN { printf "%.6g\n", st * v / d }'; }

CC=${CC:-cc}
HOST_SRC="src/pd/*.c"
# host_build VARIANT OUT SOURCE [EXTRA...]: a test host linked statically
host_build() {
    _v=$1 _out=$2 _src=$3
    shift 3
    _l=build/libpd/$_v
    _d=""
    [ "$_v" = multi ] && _d="-DPDINSTANCE -DPDTHREADS"
    # shellcheck disable=SC2086
    $CC -std=c99 -D_POSIX_C_SOURCE=200809L -O2 -g -Wall -Wextra -Werror $_d \
        -I$_l/libpd_wrapper -I$_l/pure-data/src -Isrc/pd -Isrc/core/common -Isrc/core/solve -Isrc/core/play \
        "$_src" $HOST_SRC "$@" $_l/libs/libpd.a build/libaero_core.a \
        -lsndfile -lfftw3f_threads -lfftw3f -lm -lpthread -ldl -o "$_out" \
        >"$_out.build.log" 2>&1 || { cat "$_out.build.log"; return 1; }
}

for variant in single multi; do
    V=build/libpd/$variant
    section "libpd $variant-instance: aero linked statically, one aero_setup()"
    if host_build "$variant" "$OUT/render-$variant" tests/libpd/render.c; then
        pass "test host builds against $V/libs/libpd.a, warning-free"
    else
        fail "test host against $V"; continue
    fi
    R=$OUT/render-$variant

    # 1. the Strouhal tone and Curle's level (tests/objects/10-aeolian.sh)
    f=$(tone_hz 10 0.01)
    "$R" -seconds 4 tests/libpd/tone.pd "$OUT/tone-$variant.wav" 2>"$OUT/tone-$variant.log"
    judge $ANALYZE peak "$OUT/tone-$variant.wav" --expect "$f" --tol 0.02 \
        --fmin "$(awk -v f="$f" 'BEGIN{print f/2}')" \
        --fmax "$(awk -v f="$f" 'BEGIN{print f*1.5}')" \
        --smooth "$(awk -v f="$f" 'BEGIN{print f*0.04}')"
    judge $ANALYZE level "$OUT/tone-$variant.wav" --expect "$(curle_db 10 0.01 2)" --tol 1
    judge $ANALYZE finite "$OUT/tone-$variant.wav"
    log_clean "$OUT/tone-$variant.log" "tone.pd: no error from Pd or aero"

    # 2. a texture found without a help directory: the host's data path
    #    (aero_set_data_path), $AERO_DATA, next to the patch; the stick's
    #    tone at St v / d of the texture (tests/objects/15-aeolian-texture.sh)
    "$R" -data "$ROOT" -seconds 1 tests/libpd/texture.pd "$OUT/tx-$variant.wav" \
        2>"$OUT/tx-$variant.log"
    log_clean "$OUT/tx-$variant.log" "texture found through aero_set_data_path($ROOT)"
    judge $ANALYZE peak "$OUT/tx-$variant.wav" --expect "$(st_tone 10 0.005)" \
        --tol 0.01 --fmin 300 --fmax 800
    AERO_DATA=$ROOT "$R" -seconds 1 tests/libpd/texture.pd "$OUT/tx-env-$variant.wav" \
        2>"$OUT/tx-env-$variant.log"
    if same_sound "$OUT/tx-$variant.wav" "$OUT/tx-env-$variant.wav"; then
        pass "texture found through AERO_DATA=$ROOT: the same sound"
    else
        fail "AERO_DATA: not the sound of the data path"; head -5 "$OUT/tx-env-$variant.log"
    fi
    mkdir -p "$OUT/beside-$variant"
    cp tests/libpd/texture.pd textures/cylinder.wav "$OUT/beside-$variant/"
    "$R" -seconds 1 "$OUT/beside-$variant/texture.pd" "$OUT/tx-beside-$variant.wav" \
        2>"$OUT/tx-beside-$variant.log"
    if same_sound "$OUT/tx-$variant.wav" "$OUT/tx-beside-$variant.wav"; then
        pass "texture found next to the patch: the same sound"
    else
        fail "texture next to the patch"; head -5 "$OUT/tx-beside-$variant.log"
    fi
    # on Pd's search path (libpd_add_to_search_path) and in a folder the
    # patch declares ([declare -path])
    "$R" -path "$ROOT/$OUT/beside-$variant" -seconds 1 tests/libpd/texture.pd \
        "$OUT/tx-path-$variant.wav" 2>"$OUT/tx-path-$variant.log"
    if same_sound "$OUT/tx-$variant.wav" "$OUT/tx-path-$variant.wav"; then
        pass "texture found on Pd's search path: the same sound"
    else
        fail "texture on Pd's search path"; head -5 "$OUT/tx-path-$variant.log"
    fi
    mkdir -p "$OUT/declare-$variant"
    sed "1a\\
#X declare -path ../beside-$variant;" tests/libpd/texture.pd >"$OUT/declare-$variant/texture.pd"
    "$R" -seconds 1 "$OUT/declare-$variant/texture.pd" "$OUT/tx-declare-$variant.wav" \
        2>"$OUT/tx-declare-$variant.log"
    if same_sound "$OUT/tx-$variant.wav" "$OUT/tx-declare-$variant.wav"; then
        pass "texture found through [declare -path]: the same sound"
    else
        fail "texture through [declare -path]"; head -5 "$OUT/tx-declare-$variant.log"
    fi
    # nowhere: the error names every place it looked
    env -u AERO_DATA "$R" -seconds 1 tests/libpd/texture.pd "$OUT/tx-none-$variant.wav" \
        2>"$OUT/tx-none-$variant.log"
    missing=""
    for place in "can't find texture 'cylinder'" "next to the patch (tests/libpd)" \
        "Pd's search path" "AERO_DATA" "aero_set_data_path()" "aero's own textures/"; do
        grep -q -F "$place" "$OUT/tx-none-$variant.log" || missing="$missing '$place'"
    done
    if [ -z "$missing" ]; then
        pass "texture nowhere: $(grep -o "can't find.*" "$OUT/tx-none-$variant.log" | head -1)"
    else
        fail "texture nowhere: the error lacks$missing"; cat "$OUT/tx-none-$variant.log"
    fi

    # 3. every object, textures and trees from the data path
    "$R" -data "$ROOT" -seconds 1 tests/libpd/every-object.pd \
        "$OUT/every-$variant.wav" 2>"$OUT/every-$variant.log"
    log_clean "$OUT/every-$variant.log" "every-object.pd: every object created, every file found"
    judge $ANALYZE finite "$OUT/every-$variant.wav" --ch 0
    judge $ANALYZE finite "$OUT/every-$variant.wav" --ch 1
    judge $ANALYZE level "$OUT/every-$variant.wav" --ch 0 --min 20
    judge $ANALYZE level "$OUT/every-$variant.wav" --ch 1 --min 20

    # 4. the example, built and run exactly as docs/libpd.md says, static then
    #    shared (an rpath; -fPIC wrappers)
    for link in static shared; do
        host=$OUT/libpd-host-$variant-$link
        if ! make -s --no-print-directory libpd-example LIBPD_DIR="$V" \
            LIBPD_LINK=$link LIBPD_HOST="$host" >"$host.make.log" 2>&1; then
            fail "make libpd-example LIBPD_DIR=$V LIBPD_LINK=$link"; cat "$host.make.log"
            continue
        fi
        run=$(sed -n 's/^run: //p' "$host.make.log")
        kind=$(sed -n 's/^libpd: //p' "$host.make.log")
        wav=${run##* }
        rm -f "$wav"
        # shellcheck disable=SC2086
        if $run >"$host.log" 2>&1 && [ -s "$wav" ]; then
            cp "$wav" "$OUT/sword-$variant-$link.wav"
            pass "make libpd-example LIBPD_DIR=$V LIBPD_LINK=$link ($kind); '$run' runs"
        else
            fail "'$run' ($kind)"; cat "$host.log"; continue
        fi
        log_clean "$host.log" "the sword texture found (examples/libpd-sword.pd declares no path)"
    done
    if same_sound "$OUT/sword-$variant-static.wav" "$OUT/sword-$variant-shared.wav"; then
        pass "static and shared example hosts: the same sound"
    else
        fail "static and shared example hosts differ"
    fi
    # docs/libpd.md's pitfall: against a shared single-instance libpd, wrappers
    # built without -fPIC get a copy relocation of Pd's s_signal (libpd,
    # linked -Bsymbolic, keeps its own) and crash in their DSP routine; the
    # example's shared build (-fPIC) has no such relocation
    if [ "$variant" = single ]; then
        nopic=$OUT/render-single-shared-nopic
        $CC -std=c99 -D_POSIX_C_SOURCE=200809L -O2 -I$V/libpd_wrapper \
            -I$V/pure-data/src -Isrc/pd -Isrc/core/common -Isrc/core/solve -Isrc/core/play tests/libpd/render.c $HOST_SRC \
            -L$V/libs -lpd -Wl,-rpath,"$ROOT/$V/libs" build/libaero_core.a \
            -lsndfile -lfftw3f_threads -lfftw3f -lm -lpthread -ldl -o "$nopic" 2>/dev/null
        "$nopic" tests/libpd/tone.pd "$OUT/nopic.wav" >/dev/null 2>&1
        status=$?
        if readelf -r "$nopic" | grep -q "_COPY.* s_signal" &&
            [ "$status" -ne 0 ] &&
            ! readelf -r "$OUT/libpd-host-single-shared" | grep -q "COPY.* s_signal"; then
            pass "the pitfall: without -fPIC, a copy relocation of s_signal and exit $status; with -fPIC none"
        else
            fail "the copy-relocation pitfall of docs/libpd.md did not show (exit $status)"
        fi
    fi
    # The swing (examples/libpd-host.c): 20 -> 160 degrees in 300 ms,
    # the blade from r = 0.2 to 1 m, edge first; peak angular speed
    # 140 deg pi / (2 0.3 s). The sword texture's tone St v / d (edge
    # first) spans the blade, root to tip, at that speed; Doppler at
    # most c0 / (c0 - v_tip). After the swing the blade rests in still
    # air: silence.
    S=$OUT/sword-$variant-static.wav
    st=$(build/aerotex info textures/sword.wav | sed -n 's/^st=//p')
    d=$(build/aerotex info textures/sword.wav | sed -n 's/^diameter=//p')
    band=$(awk -v st="$st" -v d="$d" 'BEGIN { w = 140 * 3.14159265 / 180 * 3.14159265 / 0.6
        printf "--min %.4g --max %.4g", st * w * 0.2 / d, st * w / d * 343 / (343 - w) }')
    # shellcheck disable=SC2086
    judge $ANALYZE peak "$S" --skip 0.05 --dur 0.3 --fmin 20 --fmax 5000 --smooth 20 $band
    judge $ANALYZE level "$S" --skip 0.05 --dur 0.3 --min 40
    judge $ANALYZE level "$S" --skip 1 --dur 1 --max -100
    judge $ANALYZE finite "$S" --ch 0
    judge $ANALYZE finite "$S" --ch 1
done

section "single- and multi-instance libpd: the same sound"
for w in tone tx every sword; do
    a=$OUT/$w-single.wav b=$OUT/$w-multi.wav
    [ "$w" = sword ] && a=$OUT/sword-single-static.wav b=$OUT/sword-multi-static.wav
    if same_sound "$a" "$b"; then
        pass "$w: bit-identical samples"
    else
        fail "$w: single- and multi-instance renders differ"
    fi
done

# --- every object's table, fuzzed through Pd's parsing layer ------------------
# tests/libpd/fuzz_tables.c, built once per wrapper with the wrapper included
# (its aero_pd_spec table, class and setup) and ASan/UBSan: hostile creation
# flags and messages made from the table, sent as a patch would send them,
# the corpus tests/libpd/fuzz-corpus.txt first, then FUZZ_TABLE_CASES
# (default 100) random cases from seed 1; every sample must be finite.
# The negative control puts a NaN into the output: it must fail.
section "every object's method table fuzzed through Pd (single-instance libpd)"
V=build/libpd/single
fuzz_build() { # NAME: build/libpd/out/fuzz-NAME from src/pd/NAME~.c
    # shellcheck disable=SC2086
    $CC -std=c99 -D_POSIX_C_SOURCE=200809L -O1 -g -Wall -Wextra -Werror \
        -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all \
        -DAERO_FUZZ_WRAPPER="\"$1~.c\"" -DAERO_FUZZ_NAME="$1" \
        -I$V/libpd_wrapper -I$V/pure-data/src -Isrc/pd -Isrc/core/common \
        -Isrc/core/solve -Isrc/core/play tests/libpd/fuzz_tables.c src/pd/aero_pd.c \
        $V/libs/libpd.a build/libaero_core.a -lsndfile -lfftw3f_threads -lfftw3f \
        -lm -lpthread -ldl -fopenmp -o "$OUT/fuzz-$1" >"$OUT/fuzz-$1.build.log" 2>&1
}
for w in src/pd/*~.c; do
    name=$(basename "$w" .c)
    name=${name%\~}
    if ! fuzz_build "$name"; then
        fail "fuzz harness for [$name~] does not build"; head -20 "$OUT/fuzz-$name.build.log"
        continue
    fi
    if "$OUT/fuzz-$name" -cases "${FUZZ_TABLE_CASES:-100}" -data "$ROOT" \
        tests/libpd/fuzz-corpus.txt >"$OUT/fuzz-$name.log" 2>&1; then
        pass "$(tail -n 1 "$OUT/fuzz-$name.log")"
    else
        fail "[$name~] under the table fuzzer; the case that broke it (add it to tests/libpd/fuzz-corpus.txt):"
        grep -v "^ " "$OUT/fuzz-$name.log" | tail -n 6 | cut -c1-400
    fi
done
if "$OUT/fuzz-cavity" -cases 5 -control 1 -data "$ROOT" >"$OUT/fuzz-control.log" 2>&1; then
    fail "negative control: a NaN in the output went unnoticed"
elif grep -q "^FAIL cavity~: output sample nan" "$OUT/fuzz-control.log"; then
    pass "negative control: $(grep "^FAIL" "$OUT/fuzz-control.log")"
else
    fail "negative control ended otherwise:"; tail -n 5 "$OUT/fuzz-control.log"
fi

# --- several instances in several threads ------------------------------------
# Four instances, each in its own thread, open every-object.pd, render 50
# blocks and close it, twice, all at once, under helgrind with
# --fair-sched=yes (without it valgrind runs threads one after the other
# and hides every race). Races inside Pd itself are suppressed by name
# (tests/libpd/pd-races.supp); aero must add none. The negative control
# builds the cores that plan FFTs while Pd runs ([treebranch~]'s and
# [leafwave~]'s) with -DAERO_FFTW_UNSERIALISED (FFTW's planner left
# unserialised; one serialised planner call anywhere would serialise the
# whole process): helgrind must report races in FFTW.
section "four libpd instances in four threads (helgrind --fair-sched=yes)"
T=$OUT/threads
if host_build multi "$T" tests/libpd/threads.c; then
    # first without valgrind: the sound of every instance
    if line=$("$T" -data "$ROOT" 4 3 200 tests/libpd/every-object.pd 2>"$T.log"); then
        pass "${line#ok }"
    else
        fail "${line#FAIL }"; tail -20 "$T.log"
    fi
    log_clean "$T.log" "threads: every object created, every file found, in every instance"
else
    fail "threads host"
fi
unserialised=
# every file of the two FFT players (leafwave's core is split by role; its
# tables reach the planner from leafwave_tables.c)
for src in src/core/play/treebranch.c src/core/play/leafwave*.c; do
    core=$(basename "$src" .c)
    $CC -std=c99 -D_POSIX_C_SOURCE=200809L -O3 -fPIC -Isrc/core/common -Isrc/core/solve -Isrc/core/play -DAERO_FFTW_UNSERIALISED \
        -c "$src" -o "$OUT/$core-unserialised.o"
    unserialised="$unserialised $OUT/$core-unserialised.o"
done
# shellcheck disable=SC2086
host_build multi "$T-unserialised" tests/libpd/threads.c $unserialised ||
    fail "threads host, negative control"
if ! command -v valgrind >/dev/null; then
    fail "valgrind is missing (make deps)"
else
    for build in "" -unserialised; do
        timeout 900 valgrind --tool=helgrind --fair-sched=yes \
            --suppressions=tests/libpd/pd-races.supp \
            "$T$build" -data "$ROOT" 4 2 50 tests/libpd/every-object.pd \
            >"$T$build.helgrind" 2>&1
        races=$(grep -c "Possible data race" "$T$build.helgrind")
        summary=$(grep "ERROR SUMMARY" "$T$build.helgrind" | tail -1 | sed 's/^==[0-9]*== //')
        places=$(grep -A3 "Possible data race" "$T$build.helgrind" |
            sed -n 's/.*  at 0x[0-9A-F]*: \([^ ]*\).*/\1/p' | sort -u | tr '\n' ' ')
        if [ -z "$build" ]; then
            if [ "$races" -eq 0 ] && grep -q "^ok " "$T$build.helgrind"; then
                pass "helgrind: no race outside Pd's own ($summary)"
            else
                fail "helgrind: $races races ($summary) in: $places"
                grep -A12 "Possible data race" "$T$build.helgrind" | head -60
            fi
        else
            if grep -q "fftwf_" "$T$build.helgrind" && [ "$races" -gt 0 ]; then
                pass "negative control: the unserialised FFTW planner shows $races races ($summary) in: $places"
            else
                fail "negative control: helgrind saw no race in an unserialised FFTW planner ($summary)"
            fi
        fi
    done
fi

echo
echo "check-libpd: $(($(date +%s) - started)) s"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
