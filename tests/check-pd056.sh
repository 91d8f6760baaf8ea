#!/bin/sh
# make check-pd056: the Pd tests of `make check` under today's Pd (0.56-5,
# built here from ../shared/vendor/pure-data-0.56-5.tar.gz) at its default
# rate of 48 kHz: every test that runs Pd (tests/run.sh with PD_ONLY=1: the
# unit tests are the same under any Pd and `make check` runs them), every
# help patch, install and deken, once with single precision and once with a
# double-precision Pd (PD_FLOATSIZE=64) playing the *.linux-amd64-64.so
# externals (side by side; the float-size-independent checks in the single
# pass only). Both Pd builds stay in build/pd056/ (made once).
# Ends with one line per Pd and `N passed, N failed` over both.
# Run from the repository root after `make all lib double`.
ROOT=$(pwd)
ARCHIVE=${PD056_ARCHIVE:-$ROOT/../shared/vendor/pure-data-0.56-5.tar.gz}
PDDIR=$ROOT/build/pd056
RATE=${PD056_RATE:-48000}

if [ ! -f "$ARCHIVE" ]; then
    echo "check-pd056: no $ARCHIVE, nothing to test against" >&2
    exit 1
fi

build_pd() { # NAME MORECFLAGS: $PDDIR/NAME/bin/pd, built once
    [ -x "$PDDIR/$1/bin/pd" ] && return 0
    echo "check-pd056: building Pd 0.56 ($1) in $PDDIR/$1 (log: $PDDIR/$1.log)"
    rm -rf "${PDDIR:?}/$1"
    mkdir -p "$PDDIR/$1"
    tar xzf "$ARCHIVE" -C "$PDDIR/$1" --strip-components=1 &&
        nice -n 10 make -j2 -C "$PDDIR/$1/src" -f makefile.gnu ALSA=false \
            OSS=false MORECFLAGS="$2" bin >"$PDDIR/$1.log" 2>&1
    if [ ! -x "$PDDIR/$1/bin/pd" ]; then
        tail -20 "$PDDIR/$1.log"
        echo "check-pd056: Pd 0.56 ($1) did not build" >&2
        return 1
    fi
}
build_pd single "" || exit 1
build_pd double "-DPD_FLOATSIZE=64" || exit 1

# The two passes run side by side (one Pd each, on a core each); the
# checks whose result cannot depend on Pd's float size (what the binaries
# export, how the GUI draws the help patches) run in the single pass only.
# What both passes share is made before they start: the [body~] fixture
# and the staged linux-amd64 package that `make deken` zips.
[ -f build/tests/sine-sphere.wav ] || build/tests/test_body_texture >/dev/null 2>&1
make -s platform P=linux-amd64 >build/tests/pd056-platform.log 2>&1 ||
    { tail -20 build/tests/pd056-platform.log; exit 1; }

start=$(date +%s)
run_pass() { # NAME FLOATSIZE SKIP
    PD=$PDDIR/$1/bin/pd PD_RATE=$RATE PD_FLOATSIZE=$2 PD_ONLY=1 PD_SKIP=$3 \
        TEST_OUT=build/tests/out-pd056-$1 sh tests/run.sh \
        >"build/tests/pd056-$1.log" 2>&1
}
run_pass single 32 "" &
single_pid=$!
run_pass double 64 "96-exports 97-gui" &
double_pid=$!
wait "$single_pid" "$double_pid"

passed=0 failed=0 summary=""
for v in single:32 double:64; do
    name=${v%%:*} fs=${v#*:}
    pd=$PDDIR/$name/bin/pd
    echo
    echo "######## $("$pd" -version 2>&1 | head -n 1), $fs-bit floats, $RATE Hz"
    cat "build/tests/pd056-$name.log"
    line=$(tail -n 1 "build/tests/pd056-$name.log")
    case "$line" in
        *" passed, "*" failed") ;;
        *) line="0 passed, 1 failed (the run did not finish)" ;;
    esac
    p=${line%% passed*} f=${line#*passed, } f=${f%% failed*}
    passed=$((passed + p)) failed=$((failed + f))
    summary="$summary
Pd 0.56 $fs-bit at $RATE Hz: $line"
done
echo
echo "check-pd056 ($(($(date +%s) - start)) s):$summary"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
