#!/bin/sh
# make bench: instructions per source-sample of [aeolian~] (model mode) on
# linux-arm64 and linux-armv7 against linux-amd64, in one run: the core's
# core alone (bench/arm/aeolian-core.c, src/core/play/aeolian*.c, arrivals.c
# and strouhal.c, built with the packages' flags by each architecture's compiler),
# N and 0 sources for 1 s at 48 kHz, the difference over N x 48000.
# Counters: valgrind's callgrind on amd64 (as bench/run.sh); QEMU's user
# emulator for all three (bench/arm/qcount.sh), so amd64 is also counted by
# the same method as the arm builds. Each counter is first checked on a
# loop of exactly 4 instructions per iteration (bench/arm/known-loop.c).
# The sum of squares printed by each build shows they render the same sound.
# Not a test: figures go to BENCHMARKS.md ("[aeolian~] on arm").
#   COUNT_SOURCES=8 (N), COUNT_PD_SOURCES=20 (the objects in Pd; 0: none)
ROOT=$(pwd)
DIR=build/bench/arm
mkdir -p "$DIR"
N=${COUNT_SOURCES:-8}
# the flags of the packages' core (platforms/platform.mk), on each target
CFLAGS="-std=c99 -D_POSIX_C_SOURCE=200809L -O3 -funroll-loops -fomit-frame-pointer \
    -fPIC -fopenmp-simd -Wall -Wextra -Wshadow \
    -Isrc/core/common -Isrc/core/play -Isrc/core/solve"
SRC="bench/arm/aeolian-core.c src/core/play/aeolian.c src/core/play/aeolian_model.c \
    src/core/play/aeolian_texture.c src/core/play/pose_glide.c \
    src/core/play/arrivals.c src/core/common/strouhal.c"

# ARCH COMPILER QEMU...: the command prefix to run that architecture's
# binaries under QEMU
targets="amd64:gcc:qemu-x86_64-static
arm64:aarch64-linux-gnu-gcc:qemu-aarch64-static -L /usr/aarch64-linux-gnu
armv7:arm-linux-gnueabihf-gcc:qemu-arm-static -L /usr/arm-linux-gnueabihf"

# per-source-sample from two counts (N and 0 sources)
per_sample() { awk -v a="$1" -v b="$2" -v n="$N" 'BEGIN {
    if (a == "" || b == "") print "?"; else printf "%.2f", (a - b) / (n * 48000) }'; }
# the known loop: counts of 100000 and 200000 iterations differ by 400000
check_loop() { # LABEL COUNT-COMMAND...
    label=$1
    shift
    c1=$("$@" 100000 2>/dev/null | tail -n 1)
    c2=$("$@" 200000 2>/dev/null | tail -n 1)
    d=$((c2 - c1))
    if [ "$d" -eq 400000 ]; then
        echo "  $label: known loop counted exactly (400000 for 100000 iterations)"
    else
        echo "  $label: known loop counted $d, not 400000: counter not trusted"
        return 1
    fi
}
callgrind() { # PROGRAM ARGS: instructions (callgrind's Ir)
    valgrind --tool=callgrind --callgrind-out-file="$DIR/cg.out" "$@" \
        >"$DIR/cg.stdout" 2>/dev/null &&
        sed -n 's/^summary: //p' "$DIR/cg.out"
}

echo "[aeolian~] model mode, instructions per source-sample by architecture ($N sources, 1 s at 48 kHz)"
echo "$targets" | while IFS=: read -r arch cc qemu; do
    if ! command -v "$cc" >/dev/null || ! command -v "${qemu%% *}" >/dev/null; then
        echo "  $arch: no $cc or ${qemu%% *} (make deps), skipped"
        continue
    fi
    # shellcheck disable=SC2086
    if ! $cc $CFLAGS $SRC -lm -o "$DIR/aeolian-core-$arch" ||
        ! $cc -O2 bench/arm/known-loop.c -o "$DIR/known-loop-$arch"; then
        echo "  $arch: the bench did not build"
        continue
    fi
    # shellcheck disable=SC2086
    if check_loop "$arch, QEMU" sh bench/arm/qcount.sh $qemu "$DIR/known-loop-$arch"; then
        # shellcheck disable=SC2086
        q0=$(sh bench/arm/qcount.sh $qemu "$DIR/aeolian-core-$arch" 0 1 2>/dev/null)
        # shellcheck disable=SC2086
        qn=$(sh bench/arm/qcount.sh $qemu "$DIR/aeolian-core-$arch" "$N" 1 \
            2>"$DIR/out-$arch.txt")
        echo "  $arch (QEMU count): $(per_sample "$qn" "$q0") instructions per source-sample; $(cat "$DIR/out-$arch.txt")"
    fi
    if [ "$arch" = amd64 ] && command -v valgrind >/dev/null &&
        check_loop "amd64, callgrind" callgrind "$DIR/known-loop-$arch"; then
        c0=$(callgrind "$DIR/aeolian-core-$arch" 0 1)
        cn=$(callgrind "$DIR/aeolian-core-$arch" "$N" 1)
        echo "  amd64 (callgrind, native): $(per_sample "$cn" "$c0") instructions per source-sample; $(cat "$DIR/cg.stdout")"
    fi
done | tee "$DIR/count.txt"

# --- in Pd: the same sources as objects in a patch ---------------------------
# N + 1 [aeolian~ -d 0.01] and one, each fed the same gusting speed as
# bench/run.sh (a 10 ms metro -> [expr] -> [line~]) and summed by
# [throw~], 1 s at 48 kHz in batch mode: on amd64 Debian's Pd with the
# externals of make all (callgrind), on arm Pd 0.56-5 (platforms/pd.sh)
# with the staged package (make platform P=...) under QEMU. Skipped where
# either is missing.
pd_patch() { # FILE N
    {
        echo "#N canvas 0 50 450 300 10;"
        echo "#X obj 10 10 loadbang;"
        echo "#X msg 10 30 \\; pd dsp 1;"
        echo "#X obj 100 30 delay 1000;"
        echo "#X msg 100 50 \\; pd quit;"
        echo "#X obj 200 10 metro 10;"
        echo "#X obj 200 30 expr 12 + 4*sin(\\\$f1*0.013) + 3*sin(\\\$f1*0.031);"
        echo "#X obj 200 50 f;"
        echo "#X obj 230 50 + 1;"
        echo "#X msg 200 70 \\\$1 10;"
        echo "#X obj 200 90 line~;"
        echo "#X obj 10 200 catch~ sum;"
        echo "#X obj 10 220 env~ 16384;"
        i=0
        while [ $i -lt "$2" ]; do
            echo "#X obj 10 120 aeolian~ -d 0.01;"
            echo "#X obj 10 150 throw~ sum;"
            i=$((i + 1))
        done
        for c in "0 0 1 0" "0 0 2 0" "2 0 3 0" "0 0 4 0" "4 0 6 0" "6 0 7 0" \
            "7 0 6 1" "6 0 5 0" "5 0 8 0" "8 0 9 0" "10 0 11 0"; do
            echo "#X connect $c;"
        done
        i=0
        while [ $i -lt "$2" ]; do
            echo "#X connect 9 0 $((12 + 2 * i)) 0;"
            echo "#X connect $((12 + 2 * i)) 0 $((13 + 2 * i)) 0;"
            i=$((i + 1))
        done
    } >"$1"
}
PD_N=${COUNT_PD_SOURCES:-20}
[ "$PD_N" -gt 0 ] || exit 0
# the baseline has one object, so that loading the external and setting up
# its class (a few million instructions, once) cancel out
pd_patch "$DIR/pd-empty.pd" 1
pd_patch "$DIR/pd-aeolian.pd" $((PD_N + 1))
PDFLAGS="-batch -nogui -noaudio -noprefs -stderr -nostdpath -r 48000"
echo "[aeolian~] in Pd, instructions per source-sample ($((PD_N + 1)) objects minus 1, 1 s at 48 kHz)" |
    tee -a "$DIR/count.txt"
{
    native_pd=$(command -v pd || command -v puredata)
    if [ -n "$native_pd" ] && [ -f "aeolian~.pd_linux" ] && command -v valgrind >/dev/null; then
        # shellcheck disable=SC2086
        c0=$(callgrind "$native_pd" $PDFLAGS -path "$ROOT" -open "$DIR/pd-empty.pd")
        # shellcheck disable=SC2086
        cn=$(callgrind "$native_pd" $PDFLAGS -path "$ROOT" -open "$DIR/pd-aeolian.pd")
        N=$PD_N
        echo "  amd64 ($("$native_pd" -version 2>&1 | sed -n 's/^Pd-\([0-9.]*\).*/Pd \1/p'), callgrind): $(per_sample "$cn" "$c0")"
    else
        echo "  amd64: no native Pd, aeolian~.pd_linux or valgrind, skipped"
    fi
    for p in linux-arm64 linux-armv7; do
        case $p in
            linux-arm64) qemu="qemu-aarch64-static -L /usr/aarch64-linux-gnu" ;;
            linux-armv7) qemu="qemu-arm-static -L /usr/arm-linux-gnueabihf" ;;
        esac
        pkg=build/$p/aero
        if [ ! -f "$pkg/aeolian~.pd_linux" ] || ! command -v "${qemu%% *}" >/dev/null ||
            ! pd=$(sh platforms/pd.sh "$p" single 2>/dev/null); then
            echo "  $p: no $pkg/aeolian~.pd_linux (make platform P=$p) or no Pd, skipped"
            continue
        fi
        # shellcheck disable=SC2086
        q0=$(sh bench/arm/qcount.sh $qemu "$pd/bin/pd" $PDFLAGS -path "$pkg" \
            -open "$DIR/pd-empty.pd" 2>/dev/null)
        # shellcheck disable=SC2086
        qn=$(sh bench/arm/qcount.sh $qemu "$pd/bin/pd" $PDFLAGS -path "$pkg" \
            -open "$DIR/pd-aeolian.pd" 2>"$DIR/pd-$p.log")
        N=$PD_N
        if grep -q "couldn't create" "$DIR/pd-$p.log"; then
            echo "  $p: [aeolian~] not created (see $DIR/pd-$p.log)"
        else
            echo "  $p (Pd 0.56-5 under QEMU, QEMU count): $(per_sample "$qn" "$q0")"
        fi
    done
} | tee -a "$DIR/count.txt"
