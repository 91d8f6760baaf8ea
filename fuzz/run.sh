#!/bin/sh
# aero: `make fuzz`: builds each harness fuzz/fuzz_NAME.c (fuzz/targets.sh
# says how a harness states its extra sources and seeds) with libFuzzer
# (clang -fsanitize=fuzzer,address,undefined) and runs it FUZZ_SECONDS
# (default 300) from its seeds plus the corpus of earlier runs
# (build-fuzz/corpus/NAME). A crash, hang (> 10 s per input), leak, memory
# blow-up (> 2 GB) or sanitizer report fails; the input is kept in
# build-fuzz/artifacts/NAME/: copy it to fuzz/regress/NAME/ so that
# `make check` replays it forever. FUZZ_ONLY=name runs one harness.
# Summary: build-fuzz/summary.txt (executions per harness).
set -u
SECONDS_EACH=${FUZZ_SECONDS:-300}
B=build-fuzz
mkdir -p "$B"
CC=${FUZZ_CC:-clang}
FLAGS="-g -O1 -std=gnu99 -fsanitize=fuzzer,address,undefined \
 -fno-sanitize-recover=all -fopenmp -Wall -Wextra -Wno-unknown-pragmas \
 -Isrc/core/common -Isrc/core/solve -Isrc/core/play"
LIBS="-lsndfile -lfftw3f_threads -lfftw3f -lfftw3 -lpng -lm"
status=0
: >"$B/summary.txt"
. fuzz/targets.sh
fuzz_targets | while read -r name; do
    case "$name" in *"${FUZZ_ONLY:-}"*) ;; *) continue ;; esac
    extra=$(fuzz_key "$name" sources)
    seeds=$(fuzz_seeds "$name")
    bin=$B/fuzz_$name
    echo "== fuzz $name: build"
    # shellcheck disable=SC2086
    $CC $FLAGS "fuzz/fuzz_$name.c" src/core/*/*.c $extra -o "$bin" $LIBS \
        >"$B/$name.build.log" 2>&1 || { cat "$B/$name.build.log"; exit 1; }
    corpus=$B/corpus/$name
    art=$B/artifacts/$name
    mkdir -p "$corpus" "$art"
    seeddirs=""
    if [ -n "$seeds" ]; then
        mkdir -p "$B/seeds/$name"
        # shellcheck disable=SC2086
        cp $seeds "$B/seeds/$name/"
        seeddirs="$B/seeds/$name"
    fi
    [ -d "fuzz/regress/$name" ] && seeddirs="$seeddirs fuzz/regress/$name"
    # inputs as long as the longest seed (at least 4 kB, at most 1 MB)
    maxlen=$(for d in $seeddirs; do
        ls -l "$d"; done | awk '$5 > m { m = $5 } END { m = m < 4096 ? 4096 : m;
        print (m > 1048576 ? 1048576 : m) }')
    echo "== fuzz $name: ${SECONDS_EACH} s"
    # shellcheck disable=SC2086
    ASAN_OPTIONS=detect_leaks=1 nice "$bin" -max_total_time="$SECONDS_EACH" \
        -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024 \
        -max_len=$maxlen -print_final_stats=1 -artifact_prefix="$art/" \
        "$corpus" $seeddirs >"$B/$name.log" 2>&1
    rc=$?
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$B/$name.log" | tail -1)
    crashes=$(ls "$art" | wc -l)
    echo "$name executions=${runs:-?} seconds=$SECONDS_EACH exit=$rc artifacts=$crashes corpus=$(ls "$corpus" | wc -l)" \
        | tee -a "$B/summary.txt"
    if [ "$rc" -ne 0 ] || [ "$crashes" -ne 0 ]; then
        grep -E -A20 "ERROR|runtime error|fuzz: " "$B/$name.log" | head -40
        echo "FAIL  fuzz $name: see $B/$name.log, inputs in $art"
        echo fail >"$B/failed"
    fi
done
if [ -f "$B/failed" ]; then rm -f "$B/failed"; exit 1; fi
echo "fuzz: no crash, hang or sanitizer report ($(awk '{print $2}' "$B/summary.txt" | tr '\n' ' '))"
