#!/bin/sh
# aero: `make check-long`: each long run of the objects' configurations
# (the `long` lines of tests/robust/objects/CLASS.txt) renders LONG_SECONDS
# (default 3600) of audio in one batch-mode Pd run, with varying input.
# The patch prints every minute of audio: the CPU time that minute took
# ([cputime], independent of other jobs' wall time) and the count of
# non-finite output samples so far; the script samples Pd's VmRSS every
# 0.2 s. Pass, per line:
#   - every minute rendered, no NaN/Inf on the outlet;
#   - no slow-down (denormals would show here): CPU per minute in the
#     last 5 minutes within 10 % of minutes 2-6 (minute 1 includes
#     loading; see tests/robust/long-judge.awk for why the fastest
#     minute of each five is compared);
#   - memory flat: VmRSS at the end at most 1 MB above its value after
#     the first tenth of the minutes (a leak of one byte per 64-sample
#     block would add 2.5 MB an hour); sampled every 0.2 s, by minutes of
#     audio; a run too short or fast to be sampled after its first tenth
#     says so and is not judged on memory.
# Results: build/long/NAME.log (minutes), build/long/NAME.rss, and a
# summary in build/long/summary.txt. LONG_ONLY=name runs the runs whose name contains it.
set -u
SECONDS_TOTAL=${LONG_SECONDS:-3600}
D=build/long
mkdir -p "$D"
: >"$D/summary.txt"
passed=0
failed=0
minutes=$((SECONDS_TOTAL / 60))
COPIES=${LONG_COPIES:-16}
sh tests/robust/object-table.sh long >"$D/table.txt"
while IFS='|' read -r name box msg every; do
    name=$(echo $name) box=$(echo $box) msg=$(echo $msg) every=$(echo ${every:--})
    case "$name" in *"${LONG_ONLY:-}"*) ;; *) continue ;; esac
    init="\\; pd dsp 1"
    [ "$msg" != "-" ] && init="$init \\; long-obj $msg"
    patch=$D/$name.pd
    cat >"$patch" <<PATCH
#N canvas 0 50 700 500 10;
#X obj 10 10 loadbang;
#X msg 10 30 $init;
#X obj 10 60 metro 1000;
#X obj 10 80 f;
#X obj 50 80 + 1;
#X obj 10 100 mod 60;
#X obj 10 120 moses 50;
#X obj 10 140 random 300;
#X obj 10 160 / 10;
#X msg 100 140 0;
#X msg 10 180 \\\$1 500;
#X obj 10 200 line~;
#X obj 10 230 $box;
#X obj 10 260 expr~ if(abs(\\\$v1) < 1e30 \\, 0 \\, 1);
#X obj 10 280 rpole~ 1;
#X obj 10 300 snapshot~;
#X obj 200 60 metro 60000;
#X obj 200 80 t b b b;
#X obj 300 120 cputime;
#X obj 200 140 f;
#X obj 240 140 + 1;
#X obj 200 330 pack f f f;
#X obj 200 350 print long;
#X obj 200 30 r long-obj;
#X obj 400 60 delay $((SECONDS_TOTAL * 1000 + 10));
#X msg 400 80 \; pd quit;
#X obj 10 130 t b;
#X connect 0 0 1 0;
#X connect 0 0 2 0;
#X connect 2 0 3 0;
#X connect 3 0 4 0;
#X connect 4 0 3 1;
#X connect 3 0 5 0;
#X connect 5 0 6 0;
#X connect 6 0 26 0;
#X connect 26 0 7 0;
#X connect 6 1 9 0;
#X connect 7 0 8 0;
#X connect 8 0 10 0;
#X connect 9 0 10 0;
#X connect 10 0 11 0;
#X connect 12 0 13 0;
#X connect 13 0 14 0;
#X connect 14 0 15 0;
#X connect 0 0 16 0;
#X connect 16 0 17 0;
#X connect 17 2 18 1;
#X connect 17 1 15 0;
#X connect 17 0 19 0;
#X connect 19 0 20 0;
#X connect 20 0 19 1;
#X connect 18 0 21 1;
#X connect 15 0 21 2;
#X connect 19 0 21 0;
#X connect 21 0 22 0;
#X connect 23 0 12 0;
#X connect 0 0 24 0;
#X connect 24 0 25 0;
#X connect 0 0 18 0;
#X connect 17 0 18 0;
PATCH
    # the input: the speed signal into the left inlet, or (4th field) a
    # message made of each new speed target, $1 ($1 escaped for the file)
    if [ "$every" = "-" ]; then
        echo "#X connect 11 0 12 0;" >>"$patch"
        feed="11 0"
    else
        echo "#X msg 100 180 $(printf '%s' "$every" | sed -e 's/\$1/\\$1/g' -e 's/,/ \\, /g');" >>"$patch"
        echo "#X connect 8 0 27 0;" >>"$patch"
        echo "#X connect 9 0 27 0;" >>"$patch"
        echo "#X connect 27 0 12 0;" >>"$patch"
        feed="27 0"
    fi
    first=27
    [ "$every" != "-" ] && first=28
    # more copies of the object (indices $first...), same input, outlets summed
    # into the check: the object's cost, not Pd's, dominates the timing
    c=1
    while [ "$c" -lt "$COPIES" ]; do
        echo "#X obj $((10 + c * 40)) 230 $box;" >>"$patch"
        echo "#X connect $feed $((first - 1 + c)) 0;" >>"$patch"
        echo "#X connect $((first - 1 + c)) 0 13 0;" >>"$patch"
        echo "#X connect 23 0 $((first - 1 + c)) 0;" >>"$patch"
        c=$((c + 1))
    done
    echo "== long run: $name ([$box], $minutes minutes of audio)"
    # shellcheck disable=SC2086
    nice pd -batch -nogui -noaudio -noprefs -stderr -nostdpath -nrt \
        -path "$(pwd)" -open "$patch" </dev/null >"$D/$name.log" 2>&1 &
    pid=$!
    : >"$D/$name.rss"
    # each sample: the minutes of audio printed so far and VmRSS (kB), so
    # that the baseline is taken by audio time, not wall time (a cheap
    # object renders its hour in seconds)
    while kill -0 "$pid" 2>/dev/null; do
        rss=$(sed -n 's/^VmRSS:[[:space:]]*\([0-9]*\) kB/\1/p' "/proc/$pid/status" 2>/dev/null)
        # a process being torn down reports VmRSS 0: not a sample
        [ "${rss:-0}" -gt 0 ] && echo "$(grep -c '^long:' "$D/$name.log") $rss" >>"$D/$name.rss"
        sleep 0.2
    done
    wait "$pid"
    status=$?
    # "long: MINUTE CPU_MS BAD" (minute 1 is the first full minute)
    verdict=$(awk -v want="$minutes" -v rssfile="$D/$name.rss" \
        -f tests/robust/long-judge.awk "$D/$name.log")
    ok=$?
    [ "$status" -ne 0 ] && { verdict="FAIL Pd exited $status; $verdict"; ok=1; }
    # an object never created would pass the rest (the counters run on)
    grep -q -e "couldn't create" -e "can't load" "$D/$name.log" &&
        { verdict="FAIL [$box] not created; $verdict"; ok=1; }
    echo "  $name: $verdict" | tee -a "$D/summary.txt"
    if [ "$ok" -eq 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); grep -v "^long:" "$D/$name.log" | head -10; fi
done <"$D/table.txt"
hours=$(awk -v s="$SECONDS_TOTAL" -v n="$passed" -v f="$failed" 'BEGIN { printf "%.2f", s * (n + f) / 3600 }')
echo "long runs: $hours hours of audio rendered; $passed passed, $failed failed"
[ "$failed" -eq 0 ]
