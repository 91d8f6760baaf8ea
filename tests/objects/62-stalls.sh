# --- no stalls: loading and rebuilding off Pd's thread (issue 49) ----------
section "[treebranch~] / [leafwave~]: loads and rebuilds do not block Pd's thread"

# Pd's thread is where audio runs: whatever it spends in a message is a
# dropout for the whole Pd. [realtime] is read around each message (and
# around creating an object from a huge file); the longest such block must
# stay under STALL_MS. This bounds a stall, it is not a benchmark (figures
# in BENCHMARKS.md): reading trees/large.tree, or making 128 tables per
# octave, took 75-400 ms in Pd's thread before loading moved to a worker.
STALL_MS=50

# stall_run NAME BODY: a patch that measures with [realtime] the message
# boxes fed by [t b b b] and prints the longest as "NAME-ms: X"
# 1. `tables 128` / `tables 1` / `open small` / `open large` at 200 Hz
#    (one every 5 ms) for 2 s on [leafwave~] and (the opens) [treebranch~]
stall_patch="$OUT/stall-msgs.pd"
{
    echo "#N canvas 0 50 700 500 10;"
    echo "#X obj 10 10 loadbang;"                                   # 0
    echo "#X obj 10 30 t b b;"                                      # 1
    echo "#X msg 200 30 \\; pd dsp 1;"                              # 2
    echo "#X obj 10 60 metro 5;"                                    # 3
    echo "#X obj 10 90 f;"                                          # 4
    echo "#X obj 50 90 + 1;"                                        # 5
    echo "#X obj 10 120 mod 4;"                                     # 6
    echo "#X obj 10 150 t b f b;"                                   # 7
    echo "#X obj 10 180 realtime;"                                  # 8
    echo "#X obj 10 210 max;"                                       # 9
    echo "#X obj 100 180 sel 0 1 2 3;"                              # 10
    echo "#X msg 100 210 tables 128;"                               # 11
    echo "#X msg 200 210 tables 1;"                                 # 12
    echo "#X msg 300 210 open $ROOT/trees/small.tree;"              # 13
    echo "#X msg 400 210 open $ROOT/trees/large.tree;"              # 14
    echo "#X obj 100 250 leafwave~ $ROOT/trees/small.tree;"         # 15
    echo "#X obj 300 250 treebranch~ $ROOT/trees/small.tree;"       # 16
    echo "#X obj 10 300 delay 2000;"                                # 17
    echo "#X obj 10 330 t b b b;"                                   # 18
    echo "#X msg 10 360 stop;"                                      # 19
    echo "#X obj 10 390 f;"                                         # 20
    echo "#X obj 10 420 print msgs-ms;"                             # 21
    echo "#X msg 100 450 \\; pd quit;"                              # 22
    echo "#X obj 400 300 r aero-speed;"                             # 23
    for c in "0 0 1 0" "1 1 2 0" "1 0 3 0" "1 0 17 0" "3 0 4 0" "4 0 5 0" \
        "5 0 4 1" "4 0 6 0" "6 0 7 0" "7 2 8 0" "7 1 10 0" "7 0 8 1" \
        "8 0 9 0" "9 0 9 1" "9 0 20 1" "10 0 11 0" "10 1 12 0" \
        "10 2 13 0" "10 3 14 0" "11 0 15 0" "12 0 15 0" "13 0 15 0" \
        "14 0 15 0" "13 0 16 0" "14 0 16 0" "17 0 18 0" "18 2 19 0" \
        "19 0 3 0" "18 1 20 0" "20 0 21 0" "18 0 22 0"; do
        echo "#X connect $c;"
    done
} >"$stall_patch"
# shellcheck disable=SC2086
timeout 600 "$PD" $PD_FLAGS -path "$ROOT" -open "$stall_patch" \
    >"$OUT/stall-msgs.log" 2>&1
ms=$(sed -n 's/.*msgs-ms: \([0-9.e+-]*\).*/\1/p' "$OUT/stall-msgs.log" | tail -1)
if [ -z "$ms" ]; then
    fail "no figure from the message run"; cat "$OUT/stall-msgs.log"
elif awk -v m="$ms" -v b="$STALL_MS" 'BEGIN { exit !(m < b) }'; then
    pass "tables 128 / tables 1 / open small / open large at 200 Hz: the longest message took $ms ms in Pd's thread (< $STALL_MS)"
else
    fail "tables / open at 200 Hz: a message took $ms ms in Pd's thread (>= $STALL_MS)"
fi
if grep -qi "error\|fail" "$OUT/stall-msgs.log"; then
    fail "errors in the message run"; cat "$OUT/stall-msgs.log"
else
    pass "the message run is clean"
fi

# 2. creating [treebranch~] on a 200,000-branch chain (12 MB) and
#    [leafwave~] on 100,000 leaves at one spot, while DSP runs: the creation
#    returns at once and the tree plays once ready
awk 'BEGIN { for (i = 0; i < 200000; i++)
    printf "branch %d %d 0 0 %.4f 0.001 0 %.4f 0.05 0.05\n", i, i - 1,
        i * 0.0005, (i + 1) * 0.0005 }' >"$OUT/chain.tree"
awk 'BEGIN { print "branch 0 -1 0 0 0 0 0 1 0.1 0.1"
    for (i = 0; i < 100000; i++) print "leaf 0 0 0 0.5 0.05 0 0.5 0.1 0.05" }' \
    >"$OUT/spot.tree"
stall_patch="$OUT/stall-create.pd"
{
    echo "#N canvas 0 50 700 500 10;"
    echo "#X obj 10 10 loadbang;"                                   # 0
    echo "#X obj 10 30 t b b b;"                                    # 1
    echo "#X msg 200 30 \\; pd dsp 1;"                              # 2
    echo "#X obj 10 60 t b b b;"                                    # 3
    echo "#X obj 10 90 realtime;"                                   # 4
    echo "#X msg 100 90 \\; pd-stall-create.pd obj 10 400 treebranch~ $ROOT/$OUT/chain.tree \\; pd-stall-create.pd obj 10 430 leafwave~ $ROOT/$OUT/spot.tree;" # 5
    echo "#X obj 10 120 print create-ms;"                           # 6
    echo "#X obj 10 150 delay 100;"                                 # 7
    echo "#X msg 10 180 \\; pd quit;"                               # 8
    for c in "0 0 1 0" "1 2 2 0" "1 1 3 0" "1 0 7 0" "3 2 4 0" "3 1 5 0" \
        "3 0 4 1" "4 0 6 0" "7 0 8 0"; do
        echo "#X connect $c;"
    done
} >"$stall_patch"
# shellcheck disable=SC2086
timeout 600 "$PD" $PD_FLAGS -path "$ROOT" -open "$stall_patch" \
    >"$OUT/stall-create.log" 2>&1
ms=$(sed -n 's/.*create-ms: \([0-9.e+-]*\).*/\1/p' "$OUT/stall-create.log" | tail -1)
if [ -z "$ms" ]; then
    fail "no figure from the creation run"; cat "$OUT/stall-create.log"
elif awk -v m="$ms" -v b="$STALL_MS" 'BEGIN { exit !(m < b) }'; then
    pass "creating [treebranch~] on a 200,000-branch chain and [leafwave~] on 100,000 leaves at one spot took $ms ms in Pd's thread (< $STALL_MS)"
else
    fail "creating the huge trees took $ms ms in Pd's thread (>= $STALL_MS)"
fi
if grep -qi "error\|fail" "$OUT/stall-create.log"; then
    fail "errors in the creation run"; cat "$OUT/stall-create.log"
else
    pass "the creation run is clean"
fi

# 3. deleted while loading: in a subpatch, [leafwave~] on the leaves at one
#    spot, [treebranch~] on the chain, and both on small trees asked a new
#    seed and new tables at once (jobs that share the live tree), all
#    deleted 5 ms later, ten times over: the objects go at once (the worker
#    drops what it made when it is done), nothing crashes, nothing in the
#    log but the run's own lines
stall_patch="$OUT/stall-delete.pd"
{
    echo "#N canvas 0 50 700 500 10;"
    echo "#X obj 10 10 loadbang;"                                   # 0
    echo "#X msg 200 10 \\; pd dsp 1;"                              # 1
    echo "#X obj 10 40 metro 5;"                                    # 2
    echo "#X obj 10 70 f;"                                          # 3
    echo "#X obj 50 70 + 1;"                                        # 4
    echo "#X obj 10 100 moses 20;"                                  # 5
    echo "#X obj 10 130 mod 2;"                                     # 6
    echo "#X obj 10 160 sel 0 1;"                                   # 7
    echo "#X msg 10 190 \\; pd-sub obj 10 10 leafwave~ $ROOT/$OUT/spot.tree \\; pd-sub obj 10 40 treebranch~ $ROOT/$OUT/chain.tree \\; pd-sub obj 10 70 leafwave~ $ROOT/trees/small.tree \\; pd-sub obj 10 100 treebranch~ $ROOT/trees/small.tree \\; pd-sub obj 10 130 r stall-seed \\; pd-sub obj 100 130 r stall-tables \\; pd-sub connect 4 0 0 0 \\; pd-sub connect 4 0 1 0 \\; pd-sub connect 4 0 2 0 \\; pd-sub connect 4 0 3 0 \\; pd-sub connect 5 0 0 0 \\; pd-sub connect 5 0 2 0 \\; stall-seed seed 7 \\; stall-tables tables 24;" # 8
    echo "#X msg 100 220 \\; pd-sub clear;"                         # 9
    echo "#X obj 100 100 t b b;"                                    # 10
    echo "#X msg 100 130 stop;"                                     # 11
    echo "#X obj 200 130 print stall-delete;"                       # 12
    echo "#X msg 200 160 done \\; pd quit;"                         # 13
    echo "#N canvas 0 0 300 200 sub 0;"
    echo "#X restore 300 300 pd sub;"                               # 14
    for c in "0 0 1 0" "0 0 2 0" "2 0 3 0" "3 0 4 0" "4 0 3 1" "3 0 5 0" \
        "5 0 6 0" "6 0 7 0" "7 0 8 0" "7 1 9 0" "5 1 10 0" "10 1 11 0" \
        "11 0 2 0" "10 0 13 0" "13 0 12 0"; do
        echo "#X connect $c;"
    done
} >"$stall_patch"
# shellcheck disable=SC2086
timeout 600 "$PD" $PD_FLAGS -path "$ROOT" -open "$stall_patch" \
    >"$OUT/stall-delete.log" 2>&1
rc=$?
if [ $rc -eq 0 ] && grep -q "stall-delete: done" "$OUT/stall-delete.log"; then
    pass "[treebranch~] and [leafwave~] deleted while loading, ten times: Pd carries on and quits cleanly"
else
    fail "deleting while loading: Pd exit $rc"; tail -20 "$OUT/stall-delete.log"
fi
if grep -v "stall-delete: done" "$OUT/stall-delete.log" | grep -q .; then
    fail "unexpected lines in the deletion run"; head -20 "$OUT/stall-delete.log"
else
    pass "the deletion run is clean"
fi

# 4. the swap does not click: a tree in steady wind, another tree opened
#    at 1 s (medium -> large for [treebranch~]; for [leafwave~], whose
#    leaves sound alike on any tree, the same tree with other tables):
#    the old sound fades out under the new one over 10 ms, so no 2 ms
#    window's sharpest jump stands out from its neighbours' by more than
#    4x (the measure of 60-leafwave.sh's collisions). A guard, not a fix:
#    the objects that rebuilt in place did not click either (1.6 and 1.9);
#    a new [treebranch~] core starts silent for the sound's 15 ms flight,
#    so swapping it in without the fade cuts to silence: ratio 8.3.
pd_render stall-swap-tb "treebranch~ trees/medium.tree -listener 0 -5 1.7" 1 2000 \
    "; aero-speed 12" 0 "1000 ; aero-obj open trees/large.tree"
judge $ANALYZE clicks "$OUT/stall-swap-tb.wav" --max 4
pd_render stall-swap-lw "leafwave~ tests/data/leafwave-small.tree -seed 1" 1 2000 \
    "; aero-speed 8" 0 "1000 ; aero-obj tables 24"
judge $ANALYZE clicks "$OUT/stall-swap-lw.wav" --max 4
