#!/bin/sh
# make bench: cost per source of [aeolian~] (model mode) against the
# paper-001 vanilla cylinder (bench/vanilla-cylinder.pd) in the same Pd,
# batch mode, 48 kHz, plus how many [aeolian~] one core renders in real
# time, and the cost of [cavity~] beside it. Wall time of each Pd run
# minus an empty run with the same driver.
# Not a test: figures go to BENCHMARKS.md.
ROOT=$(pwd)
DIR=build/bench
mkdir -p "$DIR"
SECONDS_RENDERED=${BENCH_SECONDS:-10}
N=${BENCH_SOURCES:-500}
RATE=48000

# gen_patch NAME N OBJECT: N copies of OBJECT fed by one gusting speed (a
# metro every 10 ms -> the control inlet, and [line~] for signal inlets),
# summed into one [throw~]
gen_patch() {
    {
        echo "#N canvas 0 50 800 600 10;"
        echo "#X obj 10 10 loadbang;"                               # 0
        echo "#X msg 10 30 \\; pd dsp 1;"                           # 1
        echo "#X obj 100 30 delay $((SECONDS_RENDERED * 1000));"    # 2
        echo "#X msg 100 50 \\; pd quit;"                           # 3
        echo "#X obj 200 10 metro 10;"                              # 4
        echo "#X obj 200 30 expr 12 + 4*sin(\\\$f1*0.013) + 3*sin(\\\$f1*0.031);" # 5
        echo "#X obj 200 50 f;"                                     # 6
        echo "#X obj 230 50 + 1;"                                   # 7
        echo "#X msg 200 70 \\\$1 10;"                             # 8
        echo "#X obj 200 90 line~;"                                 # 9
        echo "#X obj 10 500 catch~ sum;"                            # 10
        echo "#X obj 10 520 env~ 16384;"                            # 11
        i=0
        while [ $i -lt "$2" ]; do
            echo "#X obj $((10 + (i % 20) * 30)) $((150 + (i / 20) % 300)) $3;"
            echo "#X obj 10 480 throw~ sum;"
            i=$((i + 1))
        done
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
        echo "#X connect 10 0 11 0;"
        i=0
        while [ $i -lt "$2" ]; do
            obj=$((12 + 2 * i))
            case "$3" in
                vanilla-cylinder*) echo "#X connect 5 0 $obj 0;" ;;
                *) echo "#X connect 9 0 $obj 0;" ;;
            esac
            echo "#X connect $obj 0 $((obj + 1)) 0;"
            i=$((i + 1))
        done
    } >"$DIR/$1.pd"
}

# run NAME: wall seconds of one batch-mode render
run() {
    start=$(date +%s.%N)
    timeout 3600 pd -batch -nogui -noaudio -noprefs -stderr -nostdpath -r $RATE \
        -path "$ROOT" -path "$ROOT/bench" -open "$DIR/$1.pd" >"$DIR/$1.log" 2>&1
    end=$(date +%s.%N)
    echo "$start $end" | awk '{ printf "%.3f", $2 - $1 }'
}

gen_patch empty 0 "aeolian~"
gen_patch vanilla "$N" "vanilla-cylinder 0.01"
gen_patch aeolian "$N" "aeolian~ -d 0.01"
gen_patch cavity "$N" "cavity~ -L 0.02 -D 0.01 -W 0.05"
# texture mode: N point sources as N/10 sticks of 10 sources each
gen_patch texture "$((N / 10))" "aeolian~ -texture cylinder -n 10 -l 0.3"

best() { # the fastest of three runs (least disturbed by the machine)
    b=""
    for k in 1 2 3; do
        t=$(run "$1")
        b=$(echo "$b $t" | awk '{ m = $1; for (i = 2; i <= NF; i++) if ($i < m) m = $i; print m }')
    done
    echo "$b"
}
t_empty=$(best empty)
t_vanilla=$(best vanilla)
t_aeolian=$(best aeolian)
t_cavity=$(best cavity)
t_texture=$(best texture)

awk -v n="$N" -v s="$SECONDS_RENDERED" -v e="$t_empty" -v v="$t_vanilla" \
    -v a="$t_aeolian" -v c="$t_cavity" -v t="$t_texture" -v r="$RATE" 'BEGIN {
    cv = (v - e) / n; ca = (a - e) / n
    printf "[aeolian~] model mode vs the paper-001 vanilla cylinder, %d sources, %d s at %d Hz, Pd batch mode\n", n, s, r
    printf "  empty patch           %8.3f s\n", e
    printf "  %d x vanilla cylinder %8.3f s   %.2f us per source per second of sound\n", n, v, 1e6 * cv / s
    printf "  %d x [aeolian~]       %8.3f s   %.2f us per source per second of sound\n", n, a, 1e6 * ca / s
    printf "  cost ratio aeolian~/vanilla: %.3f (target <= 0.333)\n", ca / cv
    printf "  real-time [aeolian~] sources on one core at %d Hz: %.0f (target >= 1000)\n", r, s / ca
    cc = (c - e) / n
    printf "  %d x [cavity~] (model) %8.3f s   %.2f us per source per second of sound, %.0f real-time sources\n", n, c, 1e6 * cc / s, s / cc
    ct = (t - e) / (10 * int(n / 10))
    printf "  %d x [aeolian~ -texture cylinder -n 10] (%d point sources) %8.3f s   %.2f us per point source per second of sound, %.0f real-time point sources (target >= 1000); %.2f x the model mode per source\n", int(n / 10), 10 * int(n / 10), t, 1e6 * ct / s, s / ct, ct / ca
}' | tee "$DIR/aeolian.txt"

# benchmarks of other parts, each in its own script
# Instruction counts (valgrind's callgrind) of a 1 s render of 50 sources:
# unlike wall time they do not move with the machine's load.
if command -v valgrind >/dev/null 2>&1; then
    count_ir() {
        sed -e "s/delay $((SECONDS_RENDERED * 1000))/delay 1000/" "$DIR/$1.pd" \
            >"$DIR/$1-ir.pd"
        valgrind --tool=callgrind --callgrind-out-file="$DIR/$1.callgrind" \
            pd -batch -nogui -noaudio -noprefs -stderr -nostdpath -r $RATE \
            -path "$ROOT" -path "$ROOT/bench" -open "$DIR/$1-ir.pd" \
            >/dev/null 2>&1
        sed -n 's/^summary: //p' "$DIR/$1.callgrind"
    }
    N_SAVED=$N
    N=50
    gen_patch empty-ir 0 "aeolian~"
    gen_patch vanilla-ir $N "vanilla-cylinder 0.01"
    gen_patch aeolian-ir $N "aeolian~ -d 0.01"
    e=$(count_ir empty-ir); v=$(count_ir vanilla-ir); a=$(count_ir aeolian-ir)
    awk -v e="$e" -v v="$v" -v a="$a" -v n=$N -v r=$RATE 'BEGIN {
        printf "  instructions per source per sample (callgrind, %d sources, 1 s): vanilla %.1f, [aeolian~] %.1f, ratio %.3f\n",
            n, (v - e) / n / r, (a - e) / n / r, (a - e) / (v - e) }' |
        tee -a "$DIR/aeolian.txt"
    N=$N_SAVED
fi

# instructions per source-sample on arm64 and armv7 against amd64 (QEMU's
# count and callgrind), for the Raspberry Pi estimate in BENCHMARKS.md
sh bench/arm/count.sh

[ -n "$BENCH_ONLY_AEOLIAN" ] && exit 0
# the peer: [aeolian~] and [cavity~] against SDT's [windkarman~] and
# [windcavity~], and both texture modes per source, in one run
sh bench/peer.sh
for b in bench/texture.sh bench/field.sh; do
    [ -f "$b" ] && sh "$b"
done
# [treebranch~] on the shipped trees against Matsuyama et al. 2005's Table I
sh bench/treebranch.sh
# [leafwave~] on the paper's large tree, and both tree objects together
sh bench/leafwave.sh
# loading huge trees: the 200,000-branch chain, 1,000,000 leaves at one spot
sh bench/load.sh
# vortex sound: texture set and [vortex~] per volume
[ -f bench/vortex.sh ] && sh bench/vortex.sh
# 3D object textures: sphere and club, and [body~] per body
[ -f bench/object.sh ] && sh bench/object.sh
echo
[ -f bench/rotor.sh ] && sh bench/rotor.sh
echo
# aerotex over MPI ranks: the cost model's inputs (docs/cluster.md)
[ -f bench/mpi.sh ] && sh bench/mpi.sh
exit 0
