#!/bin/sh
# aero: the core unit tests (build/tests/test_*, the normal -O3
# build) under valgrind memcheck: no invalid read/write, no use of
# uninitialised values, no definite or indirect leak. "Possibly lost" and
# "still reachable" blocks are libgomp's thread pool and are not errors.
# VALGRIND_SKIP (default: the three flow-solver tests, which run a minute
# or more natively and would run hours under valgrind; check-asan runs them
# under ASan+LSan instead) lists test names to leave out.
set -u
SKIP=${VALGRIND_SKIP-test_flow2d test_cavity_flow test_body_flow}
D=build/valgrind
mkdir -p "$D"
passed=0
failed=0
skipped=""
for t in build/tests/test_*; do
    [ -x "$t" ] || continue
    name=$(basename "$t")
    case " $SKIP " in *" $name "*) skipped="$skipped $name"; continue ;; esac
    OMP_NUM_THREADS=1 nice valgrind --tool=memcheck --leak-check=full \
        --errors-for-leak-kinds=definite,indirect \
        --show-leak-kinds=definite,indirect --track-origins=yes \
        --error-exitcode=9 --log-file="$D/$name.log" "$t" >"$D/$name.out" 2>&1
    status=$?
    summary=$(grep "ERROR SUMMARY" "$D/$name.log" | sed 's/^==[0-9]*== //')
    leaks=$(grep -E "definitely lost|indirectly lost" "$D/$name.log" | sed 's/^==[0-9]*== *//' | tr '\n' ' ')
    if [ "$status" -eq 0 ]; then
        passed=$((passed + 1))
        echo "  ok    valgrind $name: ${summary:-no errors} ${leaks:-(no leaks)}"
    else
        failed=$((failed + 1))
        echo "  FAIL  valgrind $name (exit $status): $summary"
        grep -E -A12 "Invalid|uninitialised|definitely lost in" "$D/$name.log" | head -30
    fi
done
[ -n "$skipped" ] && echo "  (skipped under valgrind, run by check-asan:$skipped)"
echo "valgrind: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
