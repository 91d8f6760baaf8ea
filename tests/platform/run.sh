#!/bin/sh
# aero: the platform test runner. Runs aero's staged package in a Pd of
# another platform (Windows Pd under wine, arm Pd under qemu) and checks a
# representative subset of `make check`:
#   - every object (each external and abstraction) is created from the
#     package alone (its folder is Pd's only search path), and the single
#     binary loads with -lib aero;
#   - every help patch and abstraction in the package opens with no error;
#   - the physics of [aeolian~]: its peak at St(Re) U / d and the level
#     step with speed (U^3 C_L'(Re) St(Re), ~ +18 dB per doubling);
#   - a texture ([aeolian~ -texture cylinder]) and a tree ([treebranch~
#     small]) played from the package;
#   - one render per object compared with the native Linux render of the
#     same patch made in this run (Debian's Pd and the externals of
#     `make all` in the repository), and a negative control showing that
#     the comparison fails on a render 0.01 dB louder.
# WAVs written by the platform's Pd are measured by the native
# build/aero-analyze. Ends with `N passed, N failed`.
#
#   sh tests/platform/run.sh [-quick] PACKAGE EXT LAUNCHER [ARG...]
#
# PACKAGE   the staged folder (build/PLATFORM/aero, from make platform)
# EXT       the externals' extension there, e.g. windows-amd64-32.dll,
#           windows-amd64-64.dll, pd_linux
# LAUNCHER  the command that runs that Pd, e.g.
#           /usr/lib/wine/wine64 build/pd-windows-amd64-single/bin/pd.com -mmio
#           qemu-aarch64-static -L / build/pd-linux-arm64-single/bin/pd
# -quick    only the objects' creation and one render compared (the
#           double-precision Pd)
# Run from the repository root after `make all lib` (native externals and
# build/aero-analyze, build/aerotex; `make double` too for a double-precision
# platform Pd). NATIVE_PD renders the references: by default Debian's pd;
# for a double-precision platform Pd a native double-precision Pd (Pd 0.56
# with -DPD_FLOATSIZE=64: platforms/pd.sh linux-amd64 double), which
# plays the repository's *.linux-amd64-64.so; TEST_OUT (default build/tests/platform-EXT
# without its suffix) holds patches, logs and WAVs.
#
# Two renders of one patch on two platforms agree only within float
# rounding: the externals are the same C compiled by another compiler
# against another C library, whose libm (sinf, expf, powf...) may round
# differently in the last place, and FFTW's codelets may add in another
# order; in a resonant synthesis a last-place difference does not stay in
# the last place. How far it carries was measured with the one rounding
# difference at hand: the same [aeolian~ -d 0.01] patch (1 s, 10 m/s) in
# Pd 0.56 with 64-bit floats (its [line~] and the wrappers' conversions
# round differently from 32-bit Pd) differs from the 32-bit render by
# 2.8e-5 of the peak (233 float steps of it) in 43996 of 44100 samples. So
# a render counts as the same when no sample differs by more than 1e-4 of
# the peak (SAME_TOL; 3.6 times that); a 0.01 dB gain error (1.2e-3) fails
# it (the negative control). Measured on Debian 12 (mingw-w64 10, wine
# 8.0, make check-windows): 7 of the 9 Windows renders in 32-bit Pd and the
# one in 64-bit Pd are bit-identical to the native ones; [treebranch~] and
# [leafwave~], the two that synthesise through FFTW's inverse transforms
# (the vendored static FFTW there, Debian's here), differ in most samples
# by at most 2 float steps of the peak (2.4e-7 and 2.2e-7 of it).
ROOT=$(pwd)
quick=
if [ "${1:-}" = -quick ]; then
    quick=1
    shift
fi
if [ $# -lt 3 ] || [ ! -d "$1" ]; then
    echo "usage: sh tests/platform/run.sh [-quick] PACKAGE EXT LAUNCHER [ARG...]" >&2
    exit 2
fi
PKG=$(cd "$1" && pwd)
EXT=$2
shift 2
LABEL=${EXT%.*}
OUT=${TEST_OUT:-build/tests/platform-$LABEL} # relative to ROOT
ANALYZE=build/aero-analyze
NATIVE_PD=${NATIVE_PD:-$(command -v pd || command -v puredata)}
# the largest difference from the native render, relative to its peak, that
# counts as float rounding (see above)
SAME_TOL=${SAME_TOL:-1e-4}
export ROOT OUT
# the data must come from the package: no AERO_DATA from the environment
unset AERO_DATA
. tests/pdtest.sh
. tests/judge.sh
. tests/laws.sh
rm -rf "$OUT"
mkdir -p "$OUT"

# the launcher as one program, so pdtest.sh's helpers run it as "$PD"
quote() { printf "'%s' " "$(printf '%s' "$1" | sed "s/'/'\\\\''/g")"; }
{
    echo '#!/bin/sh'
    printf 'exec '
    for a in "$@"; do quote "$a"; done
    echo '"$@"'
} >"$OUT/pd"
chmod +x "$OUT/pd"
PLATFORM_PD=$ROOT/$OUT/pd

on_platform() { PD=$PLATFORM_PD PD_SEARCH=$PKG; }
on_native() { PD=$NATIVE_PD PD_SEARCH=$ROOT; }

# log_clean for a platform's Pd: without wine's own report of its request
# socket closing under a Pd that is quitting ("wine client error:NNN:
# sendmsg: Socket operation on non-socket", printed after Pd's last line;
# seen once in a CI run of check-windows, not in three reruns): wine's
# message, not Pd's or aero's, and each object's creation is checked line
# by line besides
platform_log_clean() { # LOG LABEL
    grep -v -E '^wine client error:[0-9a-f]+: sendmsg: Socket operation on non-socket$' \
        "$1" >"$1.clean"
    log_clean "$1.clean" "$2"
}

classes=$(for c in src/pd/*~.c; do basename "$c" .c; done)
abstractions=$(for a in abstractions/*.pd; do basename "$a" .pd; done)

echo "platform: $* (externals *.$EXT in $PKG)"
echo "native:   $NATIVE_PD with the externals in $ROOT"

# --- every object from the package alone ------------------------------------
section "every object created from the package alone"
for c in $classes aero; do
    if [ -f "$PKG/$c.$EXT" ]; then
        pass "the package has $c.$EXT"
    else
        fail "no $c.$EXT in $PKG"
    fi
done
{
    echo '#N canvas 0 50 450 300 12;'
    y=10
    for c in $classes $abstractions; do echo "#X obj 10 $y $c;"; y=$((y + 30)); done
} >"$OUT/create-all.pd"
on_platform
# -verbose: Pd says which file each class came from
# shellcheck disable=SC2086
timeout 120 "$PD" $PD_FLAGS -verbose -path "$PKG" -open "$ROOT/$OUT/create-all.pd" \
    -send "pd quit" >"$OUT/create-all.log" 2>&1
# (the lines of the search itself name every file tried: not errors)
grep -v -E "tried .* and (succeeded|failed)" "$OUT/create-all.log" \
    >"$OUT/create-all.errors"
platform_log_clean "$OUT/create-all.errors" "creates $(echo $classes $abstractions)"
for c in $classes; do
    if grep -F "$c.$EXT" "$OUT/create-all.log" | grep -q "succeeded"; then
        pass "[$c] loaded from $c.$EXT"
    else
        fail "[$c] not loaded from $c.$EXT"
    fi
done
for a in $abstractions; do
    if grep -F "$a.pd" "$OUT/create-all.log" | grep -q "succeeded"; then
        pass "[$a] opened from the package's $a.pd"
    else
        fail "[$a] not opened from the package's $a.pd"
    fi
done
# negative control: without the package in the search path nothing
# creates them (neither Pd's own files nor the wine prefix or system)
# shellcheck disable=SC2086
timeout 120 "$PD" $PD_FLAGS -open "$ROOT/$OUT/create-all.pd" \
    -send "pd quit" >"$OUT/create-none.log" 2>&1
n=$(grep -c "couldn't create" "$OUT/create-none.log")
want=$(echo $classes $abstractions | wc -w)
if [ "$n" -eq "$want" ]; then
    pass "negative control: without -path to the package none of the $want objects is created"
else
    fail "negative control: without the package $n of $want objects fail to create"
    sed 's/^/        /' "$OUT/create-none.log" | head -20
fi
# the single binary, loaded with -lib aero, creates every class
{
    echo '#N canvas 0 50 450 300 12;'
    y=10
    for c in $classes; do echo "#X obj 10 $y $c;"; y=$((y + 30)); done
} >"$OUT/uses-lib.pd"
mkdir -p "$OUT/lib"
# shellcheck disable=SC2086
(cd "$OUT/lib" && timeout 120 "$PD" $PD_FLAGS -path "$PKG" -lib aero \
    -open "$ROOT/$OUT/uses-lib.pd" -send "pd quit" >lib.log 2>&1)
if grep -q "aero: aerodynamic sound library loaded" "$OUT/lib/lib.log"; then
    platform_log_clean "$OUT/lib/lib.log" "single binary: -lib aero loads aero.$EXT and creates $(echo $classes)"
else
    fail "the single binary aero.$EXT did not load"; sed 's/^/        /' "$OUT/lib/lib.log" | head -20
fi

# --- one render per object against the native render ----------------------
# compare NAME CHAIN NCH DUR INIT [MSGINLET EVENTS...]: pd_render on the
# platform (unless a physics check already made NAME) and natively
compare() {
    _cmp=$1
    shift
    on_platform
    [ -f "$OUT/$_cmp.wav" ] || pd_render "$_cmp" "$@"
    on_native
    pd_render "native-$_cmp" "$@"
    judge $ANALYZE same "$OUT/native-$_cmp.wav" "$OUT/$_cmp.wav" --max "$SAME_TOL"
}

# negative_control NAME MS: the comparison fails on the native render of
# NAME's patch ([aeolian~ -d 0.01] at 10 m/s for MS ms) 0.01 dB louder
# (1.2e-3 relative)
negative_control() {
    on_native
    pd_render "native-$1-gain" "aeolian~ -d 0.01 -gain 0.01" 1 "$2" "; aero-speed 10"
    judge_fails $ANALYZE same "$OUT/native-$1-gain.wav" "$OUT/$1.wav" \
        --max "$SAME_TOL"
}

if [ -n "$quick" ]; then
    section "one render against the native render"
    compare ae-u10 "aeolian~ -d 0.01" 1 1000 "; aero-speed 10"
    negative_control ae-u10 1000
    echo
    echo "$passed passed, $failed failed"
    [ "$failed" -eq 0 ]
    exit
fi

# --- help patches and abstractions -------------------------------------------
section "the package's help patches and abstractions open without errors"
on_platform
npatches=0
for p in "$PKG"/*.pd; do
    [ -f "$p" ] || continue
    npatches=$((npatches + 1))
    pd_open_log "$p" "$OUT/open-$(basename "$p").log"
    platform_log_clean "$OUT/open-$(basename "$p").log" "opens cleanly: $(basename "$p")"
done
want=$(ls help/*.pd abstractions/*.pd | wc -l)
if [ "$npatches" -eq "$want" ]; then
    pass "the package has all $want help patches and abstractions"
else
    fail "the package has $npatches help patches and abstractions, the repository $want"
fi

# --- [aeolian~]'s physics on the platform ----------------------------------
section "[aeolian~] on the platform: Strouhal/Reynolds model"
on_platform
# the peak at St(Re) U / d (tests/laws.sh), a turbulent and a laminar wake
for case in "10 0.01" "20 0.005" "2 0.0005"; do
    set -- $case
    f=$(tone_hz "$1" "$2")
    pd_render "peak-u$1-d$2" "aeolian~ -d $2" 1 4000 "; aero-speed $1"
    judge $ANALYZE peak "$OUT/peak-u$1-d$2.wav" --expect "$f" --tol 0.02 \
        --fmin "$(awk -v f="$f" 'BEGIN{print f/2}')" \
        --fmax "$(awk -v f="$f" 'BEGIN{print f*1.5}')" \
        --smooth "$(awk -v f="$f" 'BEGIN{print f*0.04}')"
done
# the level with speed: U^3 C_L'(Re) St(Re), twice
for u in 5 10 20; do
    pd_render "lvl-u$u" "aeolian~ -d 0.01" 1 3000 "; aero-speed $u"
done
for pair in "5 10" "10 20"; do
    set -- $pair
    judge $ANALYZE leveldiff "$OUT/lvl-u$1.wav" "$OUT/lvl-u$2.wav" \
        --expect "$(level_step_db "$1" "$2" 0.01)" --tol 1.5
done

# --- a texture and a tree from the package -------------------------------
section "a texture and a tree played from the package"
on_platform
# the cylinder texture's own St (build/aerotex info of the package's copy):
# a stick of d = 1 cm in 14 m/s peaks at St U / d
st_cyl=$(build/aerotex info "$PKG/textures/cylinder.wav" | sed -n 's/^st=//p')
pd_render tx-inlet "aeolian~ -texture cylinder" 1 1000 "; aero-speed 14"
platform_log_clean "$OUT/tx-inlet.log" "[aeolian~ -texture cylinder] loads textures/cylinder.wav"
judge $ANALYZE peak "$OUT/tx-inlet.wav" \
    --expect "$(awk -v st="$st_cyl" 'BEGIN { print st * 14 / 0.01 }')" \
    --tol 0.01 --fmin 200 --fmax 600
pd_render tb-small "treebranch~ small -listener 0 -12 1.7" 1 1500 "; aero-speed 8"
platform_log_clean "$OUT/tb-small.log" "[treebranch~ small] loads trees/small.tree"
judge $ANALYZE finite "$OUT/tb-small.wav"
judge $ANALYZE level "$OUT/tb-small.wav" --min 30

# --- every object against the native render --------------------------------
section "one render per object against the native render (within $SAME_TOL of the peak)"
compare peak-u10-d0.01 "aeolian~ -d 0.01" 1 4000 "; aero-speed 10"
compare tx-inlet "aeolian~ -texture cylinder" 1 1000 "; aero-speed 14"
compare cavity "cavity~ -L 0.02 -D 0.01 -W 0.05" 1 1000 "; aero-speed 10"
compare vortex "vortex~ -texture fire -seed 5" 1 1000 "; aero-speed 8"
compare body "body~ -texture sphere -seed 1" 1 1000 \
    "; aero-speed 10; aero-obj listener 0 3 0"
compare rotor "rotor~ -listener 0 1 0" 1 1000 "; aero-speed 3000"
compare tb-small "treebranch~ small -listener 0 -12 1.7" 1 1500 "; aero-speed 8"
compare leafwave "leafwave~ small -seed 1" 1 1000 "; aero-speed 8"
compare fieldsound "snapshot~|fieldsound~ -demo 24 -sync -listener 4 0 0" 1 400 \
    "" 0 "0 ; aero-obj play"
compare stereo "aeolian~ -d 0.01 -l 0.2 -stereo" 2 1000 \
    "; aero-speed 10; aero-obj ears 0 1 0 0 2 0"
negative_control peak-u10-d0.01 4000

echo
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
