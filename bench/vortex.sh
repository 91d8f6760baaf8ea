#!/bin/sh
# make bench: vortex sound (Dobashi et al. 2004).
# 1. the texture set Q(u, t) of 8 speeds (textures/fire.wav's command, to
#    build/bench/fire.wav), wall and CPU time, against the paper's "several
#    minutes" (target <= 2 min);
# 2. [vortex~] cost per source volume in Pd batch mode at 48 kHz: one
#    [vortex~ -texture fire -n N] against an empty patch, the fastest of
#    three runs in CPU time; real-time volumes on one core (target >= 500).
# BENCH_VORTEX_TEXTURE=0 skips part 1.
# Not a test: figures go to BENCHMARKS.md.
ROOT=$(pwd)
DIR=build/bench
mkdir -p "$DIR"
SECONDS_RENDERED=${BENCH_SECONDS:-10}
N=${BENCH_VOLUMES:-1000}
RATE=48000

if [ "${BENCH_VORTEX_TEXTURE:-1}" != 0 ]; then
echo "vortex texture set (8 speeds, 32 x 32 x 48 cells, 0.5 s at 16 kHz)"
/usr/bin/time -f "  wall %e s, CPU %U s (user), %P of the cores" \
    build/aerotex vortex --speeds 1,2,3,4,6,8,12,16 --box 0.1 --grid 32 \
    --duration 0.5 -q -o "$DIR/fire.wav" 2>&1 | sed 's/^/  /' |
    tee "$DIR/vortex-texture.txt"
fi

# patch: N volumes in one [vortex~], a constant speed, 10 s, quit
vortex_patch() { # NAME N FLAGS
    {
        echo "#N canvas 0 50 450 300 10;"
        echo "#X obj 10 10 loadbang;"
        echo "#X msg 10 30 \\; pd dsp 1;"
        echo "#X obj 100 30 delay $((SECONDS_RENDERED * 1000));"
        echo "#X msg 100 50 \\; pd quit;"
        echo "#X obj 10 80 sig~ 6;"
        if [ "$2" -gt 0 ]; then
            echo "#X obj 10 110 vortex~ -texture fire -n $2 $3;"
        else
            echo "#X obj 10 110 *~ 1;"
        fi
        echo "#X obj 10 140 env~ 16384;"
        echo "#X connect 0 0 1 0;"
        echo "#X connect 0 0 2 0;"
        echo "#X connect 2 0 3 0;"
        echo "#X connect 4 0 5 0;"
        echo "#X connect 5 0 6 0;"
    } >"$DIR/$1.pd"
}
# CPU seconds (user + system) of one render: on a shared machine this
# moves much less with the load than wall time
vrun() {
    /usr/bin/time -f "%U %S" -o "$DIR/$1.time" timeout 3600 pd -batch \
        -nogui -noaudio -noprefs -stderr -nostdpath -r $RATE \
        -path "$ROOT" -open "$DIR/$1.pd" >"$DIR/$1.log" 2>&1
    awk '{ printf "%.3f", $1 + $2 }' "$DIR/$1.time"
}
vbest() {
    b=""
    for k in 1 2 3; do
        t=$(vrun "$1")
        b=$(echo "$b $t" | awk '{ m = $1; for (i = 2; i <= NF; i++) if ($i < m) m = $i; print m }')
    done
    echo "$b"
}
vortex_patch vx-empty 0 ""
vortex_patch vx-mono "$N" ""
vortex_patch vx-stereo "$N" "-stereo"
e=$(vbest vx-empty)
m=$(vbest vx-mono)
s=$(vbest vx-stereo)
awk -v n="$N" -v sec="$SECONDS_RENDERED" -v e="$e" -v m="$m" -v s="$s" -v r=$RATE 'BEGIN {
    cm = (m - e) / n; cs = (s - e) / n
    printf "[vortex~] %d source volumes, %d s at %d Hz, Pd batch mode\n", n, sec, r
    printf "  empty patch %8.3f s CPU\n", e
    printf "  mono   %8.3f s  %.2f us per volume per second of sound, %.0f real-time volumes on one core (target >= 500)\n", m, 1e6 * cm / sec, sec / cm
    printf "  stereo %8.3f s  %.2f us per volume per second of sound, %.0f real-time volumes on one core\n", s, 1e6 * cs / sec, sec / cs
}' | tee "$DIR/vortex.txt"
