#!/bin/sh
# make bench (called by bench/run.sh): loading huge trees (issue 49). A
# 200,000-branch chain (each branch the parent of the next, 12 MB) and
# 1,000,000 leaves at one spot: the seconds `aerotex tree --check` takes to
# read each, and the seconds until [treebranch~] / [leafwave~] have them
# ready in Pd (batch mode: the object is created, its worker loads, the
# clock swaps the new core in; wall time of that Pd run minus an empty
# one). Pd's own thread is not blocked meanwhile
# (tests/objects/62-stalls.sh asserts that). Not a test: figures go to
# BENCHMARKS.md.
ROOT=$(pwd)
DIR=build/bench
mkdir -p "$DIR"
PD=${PD:-$(command -v pd || command -v puredata)}
awk 'BEGIN { for (i = 0; i < 200000; i++)
    printf "branch %d %d 0 0 %.4f 0.001 0 %.4f 0.05 0.05\n", i, i - 1,
        i * 0.0005, (i + 1) * 0.0005 }' >"$DIR/chain.tree"
awk 'BEGIN { print "branch 0 -1 0 0 0 0 0 1 0.1 0.1"
    for (i = 0; i < 1000000; i++) print "leaf 0 0 0 0.5 0.05 0 0.5 0.1 0.05" }' \
    >"$DIR/spot.tree"

now() { date +%s.%N; }
secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", b - a }'; }

# run_pd OBJECT: wall seconds of a Pd creating OBJECT and quitting 0.1 s
# (logical) later
run_pd() {
    {
        echo "#N canvas 0 50 450 300 10;"
        echo "#X obj 10 10 loadbang;"
        echo "#X obj 10 40 delay 100;"
        echo "#X msg 10 70 \\; pd quit;"
        [ -n "$1" ] && echo "#X obj 10 100 $1;"
        echo "#X connect 0 0 1 0;"
        echo "#X connect 1 0 2 0;"
    } >"$DIR/load.pd"
    t0=$(now)
    # shellcheck disable=SC2086
    "$PD" -batch -nogui -noaudio -noprefs -stderr -nostdpath -path "$ROOT" \
        -open "$DIR/load.pd" >>"$DIR/load.log" 2>&1
    secs "$t0" "$(now)"
}

for f in chain spot; do
    t0=$(now)
    build/aerotex tree --check "$DIR/$f.tree" >/dev/null
    echo "aerotex tree --check $f.tree: $(secs "$t0" "$(now)") s"
done
empty=$(run_pd "")
tb=$(run_pd "treebranch~ $ROOT/$DIR/chain.tree")
lw=$(run_pd "leafwave~ $ROOT/$DIR/spot.tree")
echo "[treebranch~] 200,000-branch chain ready: $(secs "$empty" "$tb") s"
echo "[leafwave~] 1,000,000 leaves at one spot ready: $(secs "$empty" "$lw") s"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
