#!/bin/sh
# make check-pd056: the Pd tests of `make check` under today's Pd (0.56-5,
# built here from ../shared/vendor/pure-data-0.56-5.tar.gz) at its default
# rate of 48 kHz: every test that runs Pd (tests/run.sh with PD_ONLY=1: the
# unit tests are the same under any Pd and `make check` runs them), every
# help patch, install and deken, once with single precision and once with a
# double-precision Pd (PD_FLOATSIZE=64) playing the *.linux-amd64-64.so
# externals. Both Pd builds stay in build/pd056/ (made once).
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

start=$(date +%s)
passed=0 failed=0 summary=""
for v in single:32 double:64; do
    name=${v%%:*} fs=${v#*:}
    pd=$PDDIR/$name/bin/pd
    echo
    echo "######## $("$pd" -version 2>&1 | head -n 1), $fs-bit floats, $RATE Hz"
    PD=$pd PD_RATE=$RATE PD_FLOATSIZE=$fs PD_ONLY=1 \
        TEST_OUT=build/tests/out-pd056-$name sh tests/run.sh |
        tee "build/tests/pd056-$name.log"
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
