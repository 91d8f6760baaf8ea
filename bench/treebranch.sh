#!/bin/sh
# make bench (called by bench/run.sh): cost of [treebranch~] on the shipped
# trees, against Matsuyama et al. 2005's Table I (branch sound: 63.8 s for the
# (123 branches, 4860 leaves) tree and 578.2 s for the (1160, 16380) tree
# per 30 frames = 1 s of sound, Pentium 4 2.53 GHz). One Pd process (one
# core), batch mode, 48 kHz, a gusting wind (metro every 10 ms -> [line~]);
# wall time minus an empty patch with the same driver, fastest of three.
# Not a test: figures go to BENCHMARKS.md.
ROOT=$(pwd)
DIR=build/bench
mkdir -p "$DIR"
SECONDS_RENDERED=${BENCH_SECONDS:-20}
RATE=48000

gen_tree_patch() { # NAME OBJECT|"" (empty: the driver alone)
    {
        echo "#N canvas 0 50 800 600 10;"
        echo "#X obj 10 10 loadbang;"                               # 0
        echo "#X msg 10 30 \\; pd dsp 1;"                           # 1
        echo "#X obj 100 30 delay $((SECONDS_RENDERED * 1000));"    # 2
        echo "#X msg 100 50 \\; pd quit;"                           # 3
        echo "#X obj 200 10 metro 10;"                              # 4
        echo "#X obj 200 30 expr 8 + 3*sin(\\\$f1*0.013) + 2*sin(\\\$f1*0.031);" # 5
        echo "#X obj 200 50 f;"                                     # 6
        echo "#X obj 230 50 + 1;"                                   # 7
        echo "#X msg 200 70 \\\$1 10;"                             # 8
        echo "#X obj 200 90 line~;"                                 # 9
        echo "#X obj 10 500 env~ 16384;"                            # 10
        [ -n "$2" ] && echo "#X obj 10 150 $2;"                     # 11
        echo "#X connect 0 0 1 0;"
        echo "#X connect 0 0 2 0;"
        echo "#X connect 2 0 3 0;"
        echo "#X connect 0 0 4 0;"
        echo "#X connect 4 0 6 0;"
        echo "#X connect 6 0 7 0;"
        echo "#X connect 7 0 6 1;"
        echo "#X connect 6 0 5 0;"
        echo "#X connect 5 0 8 0;"
        echo "#X connect 8 0 9 0;"
        if [ -n "$2" ]; then
            echo "#X connect 9 0 11 0;"
            echo "#X connect 11 0 10 0;"
        else
            echo "#X connect 9 0 10 0;"
        fi
    } >"$DIR/$1.pd"
}

run() {
    start=$(date +%s.%N)
    timeout 3600 pd -batch -nogui -noaudio -noprefs -stderr -nostdpath -r $RATE \
        -path "$ROOT" -open "$DIR/$1.pd" >"$DIR/$1.log" 2>&1
    end=$(date +%s.%N)
    echo "$start $end" | awk '{ printf "%.3f", $2 - $1 }'
}
best() {
    b=""
    for k in 1 2 3; do
        t=$(run "$1")
        b=$(echo "$b $t" | awk '{ m = $1; for (i = 2; i <= NF; i++) if ($i < m) m = $i; print m }')
    done
    echo "$b"
}

gen_tree_patch tree-empty ""
gen_tree_patch tree-medium "treebranch~ medium -listener 0 -12 1.7"
gen_tree_patch tree-large "treebranch~ large -listener 0 -15 1.7"
gen_tree_patch tree-large-stereo "treebranch~ large -stereo -ears -0.09 -15 1.7 0.09 -15 1.7"
e=$(best tree-empty)
m=$(best tree-medium)
l=$(best tree-large)
s=$(best tree-large-stereo)
awk -v e="$e" -v m="$m" -v l="$l" -v s="$s" -v sec="$SECONDS_RENDERED" -v r=$RATE 'BEGIN {
    printf "[treebranch~] %d s of a gusting wind (5..13 m/s) at %d Hz, one Pd process, batch mode\n", sec, r
    printf "  empty patch (driver only)           %7.3f s\n", e
    cm = (m - e) / sec; cl = (l - e) / sec; cs = (s - e) / sec
    printf "  medium tree (126 branches)          %7.3f s  %.4f s per s of sound, real-time factor %.0f (paper: 63.8 s per s)\n", m, cm, 1 / cm
    printf "  large tree (1155 branches)          %7.3f s  %.4f s per s of sound, real-time factor %.0f (paper: 578.2 s per s, %.0fx faster)\n", l, cl, 1 / cl, 578.2 / cl
    printf "  large tree, -stereo                 %7.3f s  %.4f s per s of sound, real-time factor %.0f\n", s, cs, 1 / cs
}' | tee "$DIR/treebranch.txt"
