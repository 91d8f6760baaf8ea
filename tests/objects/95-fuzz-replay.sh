# --- fuzz regressions: every fuzz harness fuzz/fuzz_NAME.c (fuzz/targets.sh),
# built without libFuzzer (-DFUZZ_REPLAY), replays its shipped seeds and
# every input a fuzz run ever broke it with (fuzz/regress/NAME/*). Each
# input must load or be refused with a message, never break an invariant
# of the harness (finite output, consistent sizes) or crash.
section "fuzz regressions: seeds and saved crashes replayed (fuzz/fuzz_*.c)"
# The harnesses and the core are compiled here with ASan and UBSan
# (float-to-int overflow included), so that undefined behaviour a fuzz run once
# found stays caught, as do overflows and leaks.
replay_flags=${FUZZ_REPLAY_FLAGS:--fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all}
replay_dir=build/fuzz-replay
rm -rf "$replay_dir/core" # no object of a source that is gone
mkdir -p "$replay_dir/core"
replay_ok=1
for c in src/core/*/*.c; do
    # shellcheck disable=SC2086
    ${CC:-cc} -std=gnu99 -O1 -g -fopenmp -Isrc/core/common -Isrc/core/solve -Isrc/core/play $replay_flags -c "$c" \
        -o "$replay_dir/core/$(basename "$c" .c).o" 2>>"$OUT/fuzz-core.build" ||
        replay_ok=0
done
. fuzz/targets.sh
fuzz_targets | while read -r name; do
    extra=$(fuzz_key "$name" sources)
    seeds=$(fuzz_seeds "$name")
    bin=$replay_dir/$name
    # shellcheck disable=SC2086
    if [ "$replay_ok" -ne 1 ] || ! ${CC:-cc} -std=gnu99 -O1 -g -DFUZZ_REPLAY \
        -Wall -Wextra -fopenmp $replay_flags -Isrc/core/common -Isrc/core/solve -Isrc/core/play "fuzz/fuzz_$name.c" \
        $extra "$replay_dir"/core/*.o -o "$bin" \
        -lsndfile -lfftw3f_threads -lfftw3f -lfftw3 -lpng -lm >"$OUT/fuzz-$name.build" 2>&1; then
        echo "  FAIL  fuzz harness $name does not build"
        cat "$OUT/fuzz-core.build" "$OUT/fuzz-$name.build" 2>/dev/null | head -20
        echo "0 passed, 1 failed" >"$OUT/fuzz-$name.txt"
        continue
    fi
    # shellcheck disable=SC2086
    files=$(ls $seeds fuzz/regress/"$name"/* 2>/dev/null)
    [ -n "$files" ] || continue # a program-like input: fuzzed, nothing saved yet
    # shellcheck disable=SC2086
    "$bin" $files >"$OUT/fuzz-$name.txt" 2>&1 ||
        grep -q "passed, [0-9]* failed$" "$OUT/fuzz-$name.txt" ||
        echo "0 passed, 1 failed (crashed)" >>"$OUT/fuzz-$name.txt"
done
for f in "$OUT"/fuzz-*.txt; do
    [ -f "$f" ] || continue
    summary=$(grep -E "^[0-9]+ passed, [0-9]+ failed" "$f" | tail -n 1)
    p=${summary%% passed*}
    f_=${summary#*passed, }
    f_=${f_%% failed*}
    if [ "${f_:-1}" -eq 0 ]; then
        pass "fuzz $(basename "$f" .txt | sed 's/^fuzz-//'): $p inputs replayed"
    else
        fail "fuzz $(basename "$f" .txt | sed 's/^fuzz-//'): $summary"
        grep FAIL "$f" | head -5
    fi
done
