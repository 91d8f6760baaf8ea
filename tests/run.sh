#!/bin/sh
# aero: everything `make check` runs (and so CI): unit tests of src/core,
# Pd batch-mode renders judged by build/aero-analyze, every help patch and
# abstraction opened in Pd. Ends with one line `N passed, N failed`.
# Run from the repository root after `make all lib` (and `make double`
# for a double-precision Pd).
#   PD=/path/to/pd      the Pd to test with (default: Debian's pd)
#   PD_RATE=48000       its sample rate (default 44100), passed as -r
#   PD_FLOATSIZE=64     that Pd is a double-precision build
#   PD_ONLY=1           only the tests that run Pd: the unit tests, fuzz
#                       replays and compile checks do not depend on which
#                       Pd runs them (make check-pd056 runs them once)
ROOT=$(pwd)
OUT=${TEST_OUT:-build/tests/out} # relative to ROOT
ANALYZE=build/aero-analyze
export ROOT OUT
. tests/pdtest.sh
rm -rf "$OUT"
mkdir -p "$OUT"

. tests/judge.sh

# ONLY=pattern (e.g. ONLY=vortex sh tests/run.sh) runs only the unit tests,
# object test scripts and help patches whose path contains the pattern;
# CASE="name..." only those cases of the unit tests (tests/unit/run.sh).
only() { case "$1" in *"${ONLY:-}"*) return 0 ;; *) return 1 ;; esac; }

# --- unit tests of src/core (tests/unit/run.sh; CASE= picks cases) --------
[ -z "${PD_ONLY:-}" ] && . tests/unit/run.sh

# the fixture the [body~] tests play, written by test_body (which
# PD_ONLY=1, or an ONLY that does not name it, does not run as a test)
if [ ! -f build/tests/sine-sphere.wav ] && [ -x build/tests/test_body ]; then
    build/tests/test_body pd_fixture >"$OUT/test_body.txt" 2>&1
fi

# --- build variants ----------------------------------------------------------
section "build variants"
if [ -n "${PD_ONLY:-}" ]; then
    :
elif make -s pdinstance >"$OUT/pdinstance.log" 2>&1; then
    pass "wrappers compile warning-free with -DPDINSTANCE -DPDTHREADS"
else
    fail "wrappers with -DPDINSTANCE -DPDTHREADS"; cat "$OUT/pdinstance.log"
fi
# the single binary, loaded with -lib, creates every class (Pd picks the
# one of its float size)
mkdir -p "$OUT/single"
cp aero.pd_linux "$OUT/single/"
[ -f aero.linux-amd64-64.so ] && cp aero.linux-amd64-64.so "$OUT/single/"
classes=$(for c in src/pd/*~.c; do basename "$c" .c; done)
{
    echo '#N canvas 0 50 450 300 12;'
    y=10
    for c in $classes; do echo "#X obj 10 $y $c;"; y=$((y + 30)); done
} >"$OUT/single/uses-lib.pd"
# shellcheck disable=SC2086
(cd "$OUT/single" && timeout 60 "$PD" $PD_FLAGS -path . -lib aero \
    -open uses-lib.pd -send "pd quit" >lib.log 2>&1)
if grep -q "aero: aerodynamic sound library loaded" "$OUT/single/lib.log"; then
    log_clean "$OUT/single/lib.log" "single binary: -lib aero loads and creates $(echo $classes)"
else
    fail "single binary aero.pd_linux did not load"; cat "$OUT/single/lib.log"
fi

# --- each object's tests in real Pd: tests/objects/NN-name.sh, in order ----
. tests/laws.sh

# A NaN made inside Pd (inf - inf), to feed objects through a signal inlet
# (1e300: the product overflows in double-precision Pd too)
nan_expr='expr~ \$v1*1e300*1e300 - \$v1*1e300*1e300'
for object_tests in tests/objects/*.sh; do
    # read for any ONLY: 90-hostile.sh runs the named objects' lines
    only "$object_tests" || case "$object_tests" in *90-hostile.sh) ;; *) continue ;; esac
    case "$object_tests" in # no Pd in these
        *fuzz-replay.sh | *globals.sh) [ -n "${PD_ONLY:-}" ] && continue ;;
    esac
    . "$object_tests"
done

# --- every help patch and abstraction opens cleanly --------------------------
section "help patches and abstractions open in Pd without errors"
for p in help/*.pd abstractions/*.pd; do
    [ -f "$p" ] || continue
    only "$p" || continue
    pd_open_log "$ROOT/$p" "$OUT/open-$(basename "$p").log"
    log_clean "$OUT/open-$(basename "$p").log" "opens cleanly: $p"
done

echo
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
