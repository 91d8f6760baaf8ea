#!/bin/sh
# make bench (called by bench/run.sh): real-time cost of [leafwave~] on the
# paper's large tree (Matsuyama et al. 2005, Table 1: 1160 branches, 16380
# leaves, 645.5 s of computation per second of leaf sound on a 2.53 GHz
# Pentium 4). One Pd in batch mode at 48 kHz renders BENCH_SECONDS (10) of
# a tree in gusting wind (8 +- 4 m/s from a 10 ms metro into [line~]);
# the cost is the wall time minus an empty patch with the same driver, the
# fastest of three runs. Pd runs on one core. Also both objects of the
# tree together ([treebranch~] beside [leafwave~]), the target. Not a test: figures go to
# BENCHMARKS.md.
ROOT=$(pwd)
DIR=build/bench
mkdir -p "$DIR"
SECONDS_RENDERED=${BENCH_SECONDS:-10}
RATE=48000
TREE=trees/large.tree
if [ ! -f "$TREE" ]; then
    TREE=$DIR/large.tree
    build/aerotex tree -o "$TREE" --depth 6 --leaves 16380 --seed 1 >/dev/null ||
        exit 1
fi

# leaf_patch NAME "OBJECT" SECONDS: OBJECT fed by a gusting speed, its
# output summed into [env~] so it is computed
leaf_patch() {
    {
        echo "#N canvas 0 50 800 600 10;"
        echo "#X obj 10 10 loadbang;"                               # 0
        echo "#X msg 10 30 \\; pd dsp 1;"                           # 1
        echo "#X obj 100 30 delay $(($3 * 1000));"                  # 2
        echo "#X msg 100 50 \\; pd quit;"                           # 3
        echo "#X obj 200 10 metro 10;"                              # 4
        echo "#X obj 200 30 expr 8 + 3*sin(\\\$f1*0.013) + 1.5*sin(\\\$f1*0.071);" # 5
        echo "#X obj 200 50 f;"                                     # 6
        echo "#X obj 230 50 + 1;"                                   # 7
        echo "#X msg 200 70 \\\$1 10;"                              # 8
        echo "#X obj 200 90 line~;"                                 # 9
        echo "#X obj 200 150 $2;"                                   # 10
        echo "#X obj 200 200 env~ 16384;"                           # 11
        for c in "0 0 1 0" "0 0 2 0" "2 0 3 0" "0 0 4 0" "4 0 6 0" \
            "6 0 7 0" "7 0 6 1" "6 0 5 0" "5 0 8 0" "8 0 9 0" "9 0 10 0" \
            "10 0 11 0"; do
            echo "#X connect $c;"
        done
        if [ -n "$4" ]; then # a second object beside the first
            echo "#X obj 400 150 $4;"                               # 12
            echo "#X obj 400 200 env~ 16384;"                       # 13
            echo "#X connect 9 0 12 0;"
            echo "#X connect 12 0 13 0;"
        fi
    } >"$DIR/$1.pd"
}

run() { # wall seconds of one batch-mode render
    start=$(date +%s.%N)
    timeout 3600 pd -batch -nogui -noaudio -noprefs -stderr -nostdpath -r $RATE \
        -path "$ROOT" -open "$DIR/$1.pd" >"$DIR/$1.log" 2>&1
    end=$(date +%s.%N)
    echo "$start $end" | awk '{ printf "%.3f", $2 - $1 }'
}
best() { # the fastest of three runs (least disturbed by the machine)
    b=""
    for k in 1 2 3; do
        t=$(run "$1")
        b=$(echo "$b $t" | awk '{ m = $1; for (i = 2; i <= NF; i++) if ($i < m) m = $i; print m }')
    done
    echo "$b"
}

leaf_patch leaf-empty "+~ 0" "$SECONDS_RENDERED"
leaf_patch leaf-load "leafwave~ $TREE" 0
leaf_patch leaf-empty0 "+~ 0" 0
leaf_patch leaf-256 "leafwave~ $TREE" "$SECONDS_RENDERED"
leaf_patch leaf-1024 "leafwave~ $TREE -voices 1024" "$SECONDS_RENDERED"
# the whole tree: [treebranch~] and [leafwave~] in one Pd (one core)
leaf_patch tree-both "leafwave~ $TREE -seed 1" "$SECONDS_RENDERED" \
    "treebranch~ $TREE -seed 1"
te=$(best leaf-empty)
t0=$(best leaf-empty0)
tl=$(best leaf-load)
t256=$(best leaf-256)
t1024=$(best leaf-1024)
tboth=$(best tree-both)
size=$(build/aerotex tree --check "$TREE" 2>/dev/null | tr '\n' ' ')
awk -v s="$SECONDS_RENDERED" -v e="$te" -v e0="$t0" -v l="$tl" \
    -v a="$t256" -v b="$t1024" -v c="$tboth" -v r=$RATE -v size="$size" -v tree="$TREE" 'BEGIN {
    printf "[leafwave~] on the paper'"'"'s large tree (%s: %s), %d s at %d Hz, Pd batch mode, one core\n", tree, size, s, r
    printf "  load (tree file, leaf frames, neighbour lists, 48 wave tables): %.3f s\n", l - e0
    fa = (a - e) / s; fb = (b - e) / s
    printf "  256 voices (default): %.3f s per second of sound, real-time factor %.2f (paper: 645.5 s, %.0fx faster)\n", fa, fa, 645.524 / fa
    printf "  1024 voices:          %.3f s per second of sound, real-time factor %.2f (paper: 645.5 s, %.0fx faster)\n", fb, fb, 645.524 / fb
    fc = (c - e) / s
    printf "  [treebranch~] + [leafwave~] in one Pd: %.3f s per second of sound, real-time factor %.2f (paper: 578.2 + 645.5 s)\n", fc, fc
}' | tee "$DIR/leafwave.txt"

# Instruction counts (callgrind) of 1 s of sound, minus the empty patch:
# unlike wall time they do not move with the machine's load (the tree's
# load is included: it happens once)
if command -v valgrind >/dev/null 2>&1; then
    count_ir() {
        valgrind --tool=callgrind --callgrind-out-file="$DIR/$1.callgrind" \
            pd -batch -nogui -noaudio -noprefs -stderr -nostdpath -r $RATE \
            -path "$ROOT" -open "$DIR/$1.pd" >/dev/null 2>&1
        sed -n 's/^summary: //p' "$DIR/$1.callgrind"
    }
    leaf_patch leaf-ir-empty "+~ 0" 1
    leaf_patch leaf-ir "leafwave~ $TREE" 1
    ie=$(count_ir leaf-ir-empty)
    il=$(count_ir leaf-ir)
    awk -v e="$ie" -v l="$il" 'BEGIN {
        printf "  instructions (callgrind) for 1 s of sound, loading included: %.3g\n", l - e }' |
        tee -a "$DIR/leafwave.txt"
fi
