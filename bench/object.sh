#!/bin/sh
# make bench: 3D object textures (Dobashi et al. 2003, the 3D case).
# 1. the sphere and club textures (textures/sphere.wav and club.wav's
#    commands, to build/bench/), wall and CPU time, against the paper's
#    "10 hours (3D simulations)" on a 1.3 GHz Pentium III (target <= 15 min
#    each on this machine);
# 2. [body~] cost per body in Pd batch mode at 48 kHz: N whirled spheres
#    (one region each) and N clubs (10 regions) against an empty patch,
#    the fastest of three runs in CPU time.
# BENCH_OBJECT_TEXTURE=0 skips part 1.
# Not a test: figures go to BENCHMARKS.md.
ROOT=$(pwd)
DIR=build/bench
mkdir -p "$DIR"
SECONDS_RENDERED=${BENCH_SECONDS:-10}
N=${BENCH_BODIES:-200}
RATE=48000

texture_cmd() { # the command textures/make.sh records for FILE (its
    # continued lines joined)
    sed -e ':a' -e '/\\$/N; s/\\\n *//; ta' textures/make.sh |
        sed -n "s|^\$T object \(.*\) -o textures/$1.wav.*|\1|p"
}
if [ "${BENCH_OBJECT_TEXTURE:-1}" != 0 ]; then
    for t in sphere club; do
        args=$(texture_cmd $t)
        echo "$t texture: aerotex object $args"
        # shellcheck disable=SC2086
        /usr/bin/time -f "  wall %e s, CPU %U s (user), %P of the cores" \
            build/aerotex object $args -q -o "$DIR/$t.wav" 2>&1 |
            sed 's/^/  /' | tee "$DIR/object-$t.txt"
    done
fi

# N bodies, each posed every 10 ms on its own circle, 10 s, quit
body_patch() { # NAME N TEXTURE
    {
        echo "#N canvas 0 50 450 300 10;"
        echo "#X obj 10 10 loadbang;"                                  # 0
        echo "#X msg 10 30 \\; pd dsp 1;"                              # 1
        echo "#X obj 100 30 delay $((SECONDS_RENDERED * 1000));"       # 2
        echo "#X msg 100 50 \\; pd quit;"                              # 3
        echo "#X obj 200 10 metro 10;"                                 # 4
        echo "#X obj 200 30 f;"                                        # 5
        echo "#X obj 240 30 + 0.01;"                                   # 6
        echo "#X obj 200 50 expr 1.2*cos(\\\$f1*9.42) \\; 3 + 1.2*sin(\\\$f1*9.42);" # 7
        echo "#X msg 200 70 pose \\\$1 \\\$2 1.6 30 \\\$1 0;"               # 8
        echo "#X obj 10 400 env~ 16384;"                               # 9
        i=0
        while [ $i -lt "$2" ]; do
            echo "#X obj $((10 + (i % 20) * 20)) $((120 + (i / 20) % 200)) body~ -texture $3 -seed $((i + 1));"
            i=$((i + 1))
        done
        echo "#X connect 0 0 1 0;"
        echo "#X connect 0 0 2 0;"
        echo "#X connect 2 0 3 0;"
        echo "#X connect 0 0 4 0;"
        echo "#X connect 4 0 5 0;"
        echo "#X connect 5 0 6 0;"
        echo "#X connect 6 0 5 1;"
        echo "#X connect 5 0 7 0;"
        echo "#X connect 7 0 8 0;"
        echo "#X connect 7 1 8 1;"
        i=0
        while [ $i -lt "$2" ]; do
            echo "#X connect 8 0 $((10 + i)) 0;"
            echo "#X connect $((10 + i)) 0 9 0;"
            i=$((i + 1))
        done
    } >"$DIR/$1.pd"
}
. bench/pd-cpu.sh # brun, bbest
body_patch bd-empty 0 sphere
body_patch bd-sphere "$N" sphere
body_patch bd-club "$N" club
e=$(bbest bd-empty)
s=$(bbest bd-sphere)
c=$(bbest bd-club)
awk -v n="$N" -v sec="$SECONDS_RENDERED" -v e="$e" -v s="$s" -v c="$c" -v r=$RATE 'BEGIN {
    cs = (s - e) / n; cc = (c - e) / n
    printf "[body~] %d moving bodies, %d s at %d Hz, Pd batch mode, mono\n", n, sec, r
    printf "  empty patch %8.3f s CPU\n", e
    printf "  sphere (1 region)  %8.3f s  %.2f us per body per second of sound, %.0f real-time bodies on one core\n", s, 1e6 * cs / sec, sec / cs
    printf "  club (10 regions)  %8.3f s  %.2f us per body per second of sound, %.0f real-time bodies on one core\n", c, 1e6 * cc / sec, sec / cc
}' | tee "$DIR/object.txt"
