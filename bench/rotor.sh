#!/bin/sh
# make bench: [rotor~]'s cost as a drone (issue 52: four rotors of two
# blades within 1 % of one core at 48 kHz). N drones, each four
# [rotor~]s at 5400-6600 rpm gliding (a [line~] each, a new target every
# 100 ms: the thrust commands of a hovering, yawing drone), heard 5 m
# away, rendered for BENCH_SECONDS of DSP in Pd batch mode at 48 kHz (as
# fast as it goes: 10 s of sound take about 1 s per 10 drones). Measured:
# the CPU time (user + system) of that Pd, less that of the same patch with
# each [line~] wired straight to the sum and no [rotor~] (Pd's start, its
# scheduler, the [expr]s and [line~]s that drive the rotors: 0.00-0.01 s,
# under /usr/bin/time's 10 ms resolution), so the figure is the rotors'
# own cost from their creation on; the fastest of three runs of each.
# Not a test: figures go to BENCHMARKS.md.
ROOT=$(pwd)
DIR=build/bench
mkdir -p "$DIR"
SECONDS_RENDERED=${BENCH_SECONDS:-10}
N=${BENCH_DRONES:-25}
RATE=48000

rotor_patch() { # NAME DRONES [FLAGS]: FLAGS "none", no [rotor~]s
    {
        echo "#N canvas 0 50 450 300 10;"
        echo "#X obj 10 10 loadbang;"                                  # 0
        echo "#X msg 10 30 \\; pd dsp 1;"                              # 1
        echo "#X obj 100 30 delay $((SECONDS_RENDERED * 1000));"       # 2
        echo "#X msg 100 50 \\; pd quit;"                              # 3
        echo "#X obj 200 10 metro 100;"                                # 4
        echo "#X obj 200 30 f;"                                        # 5
        echo "#X obj 240 30 + 1;"                                      # 6
        echo "#X obj 10 400 env~ 16384;"                               # 7
        i=0
        while [ $i -lt $(($2 * 4)) ]; do
            # rotor i: its rpm target, a line~ to it, the rotor placed at
            # its arm of the drone
            echo "#X obj 200 60 expr 6000 + 600*sin(\\\$f1*0.7 + $i);"
            echo "#X msg 200 80 \\\$1 100;"
            echo "#X obj 200 100 line~;"
            [ "${3:-}" = none ] ||
                echo "#X obj 200 120 rotor~ -listener $(( i % 4 - 2 ))e-1 5 0 ${3:-};"
            i=$((i + 1))
        done
        echo "#X connect 0 0 1 0;"
        echo "#X connect 0 0 2 0;"
        echo "#X connect 2 0 3 0;"
        echo "#X connect 0 0 4 0;"
        echo "#X connect 4 0 5 0;"
        echo "#X connect 5 0 6 0;"
        echo "#X connect 6 0 5 1;"
        i=0
        k=4 # objects per rotor
        [ "${3:-}" = none ] && k=3
        while [ $i -lt $(($2 * 4)) ]; do
            o=$((8 + k * i))
            echo "#X connect 5 0 $o 0;"
            echo "#X connect $o 0 $((o + 1)) 0;"
            echo "#X connect $((o + 1)) 0 $((o + 2)) 0;"
            if [ $k = 4 ]; then
                echo "#X connect $((o + 2)) 0 $((o + 3)) 0;"
                echo "#X connect $((o + 3)) 0 7 0;"
            else
                echo "#X connect $((o + 2)) 0 7 0;"
            fi
            i=$((i + 1))
        done
    } >"$DIR/$1.pd"
}
. bench/pd-cpu.sh # brun, bbest
rotor_patch rt-empty "$N" none
rotor_patch rt-drones "$N"
rotor_patch rt-tones "$N" "-noise -200"
e=$(bbest rt-empty)
d=$(bbest rt-drones)
t=$(bbest rt-tones)
awk -v n="$N" -v sec="$SECONDS_RENDERED" -v e="$e" -v d="$d" -v t="$t" -v r=$RATE 'BEGIN {
    per = (d - e) / n / sec; pt = (t - e) / n / sec
    printf "[rotor~] %d drones (4 rotors x 2 blades each), %d s at %d Hz, Pd batch mode, mono\n", n, sec, r
    printf "  the drivers alone %8.3f s CPU, drones %8.3f s, tones alone %8.3f s\n", e, d, t
    printf "  one drone: %.1f us per second of sound, %.3f %% of one core\n", 1e6 * per, 100 * per
    printf "  its tones alone (-noise -200): %.1f us, %.3f %% of one core\n", 1e6 * pt, 100 * pt
}' | tee "$DIR/rotor.txt"
