#!/bin/sh
# aero: the core unit tests (build/tests/test_*, the normal -O3
# build) under valgrind memcheck: no invalid read/write, no use of
# uninitialised values, no definite or indirect leak. "Possibly lost" and
# "still reachable" blocks are libgomp's thread pool and are not errors.
# Memcheck runs this code some 30-150x slower than natively: a test whose
# source declares it slow (a line `/* aero-test: slow */`, listed by
# tests/robust/slow-tests.sh; CONTRIBUTING.md) is left out here, and
# check-asan runs it under ASan+UBSan+LSan instead. An undeclared test that
# needs more than VALGRIND_CPU_LIMIT seconds of CPU under memcheck (default
# 240; the whole run must stay under 15 minutes) is stopped and fails,
# saying to declare it, so a slow test shows itself instead of hanging.
# A negative control (tests/robust/valgrind-control.c) must be reported:
# a heap overflow and a leak.
#   ONLY=pattern       only the tests whose path contains it (as tests/run.sh);
#                      the negative control always runs
#   VALGRIND_SKIP="test_a test_b"  more tests to leave out, by name
set -u
LIMIT=${VALGRIND_CPU_LIMIT:-240}
SLOW=$(sh tests/robust/slow-tests.sh | tr '\n' ' ')
SKIP=${VALGRIND_SKIP:-}
D=build/valgrind
mkdir -p "$D"
passed=0
failed=0
skipped=""
slow=""
cpu() { # CPU seconds of the shell's finished children so far, in $cpu
    # (`times` in the shell itself: a command substitution would fork)
    times >"$D/times"
    cpu=$(awk 'NR == 2 { s = 0
        for (i = 1; i <= 2; i++) { split($i, a, "m"); s += a[1] * 60 + a[2] }
        printf "%.1f\n", s }' "$D/times")
}
memcheck() { # NAME COMMAND...: exit status in $status, CPU time in $took
    name=$1
    shift
    cpu
    before=$cpu
    # a hard CPU limit: SIGKILL past it, whatever the machine's load
    (ulimit -t "$LIMIT"
        OMP_NUM_THREADS=1 exec nice valgrind --tool=memcheck --leak-check=full \
            --errors-for-leak-kinds=definite,indirect \
            --show-leak-kinds=definite,indirect --track-origins=yes \
            --error-exitcode=9 --log-file="$D/$name.log" "$@") \
        >"$D/$name.out" 2>&1
    status=$?
    cpu
    took=$(awk -v a="$before" -v b="$cpu" 'BEGIN { printf "%.1f s CPU", b - a }')
}
for t in build/tests/test_*; do
    [ -x "$t" ] || continue
    case "$t" in *"${ONLY:-}"*) ;; *) continue ;; esac
    name=$(basename "$t")
    case " $SLOW " in *" $name "*) slow="$slow $name"; continue ;; esac
    case " $SKIP " in *" $name "*) skipped="$skipped $name"; continue ;; esac
    memcheck "$name" "$t"
    summary=$(grep "ERROR SUMMARY" "$D/$name.log" | sed 's/^==[0-9]*== //')
    leaks=$(grep -E "definitely lost|indirectly lost" "$D/$name.log" | sed 's/^==[0-9]*== *//' | tr '\n' ' ')
    if [ "$status" -eq 0 ]; then
        passed=$((passed + 1))
        echo "  ok    valgrind $name ($took): ${summary:-no errors} ${leaks:-(no leaks)}"
    elif [ "$status" -eq 137 ] || [ "$status" -eq 152 ]; then
        failed=$((failed + 1))
        echo "  FAIL  valgrind $name: stopped after $LIMIT s of CPU under memcheck;" \
            "if it is correct but long, declare it with a line" \
            "'/* aero-test: slow */' in tests/unit/$name.c (CONTRIBUTING.md)"
    else
        failed=$((failed + 1))
        echo "  FAIL  valgrind $name (exit $status, $took): $summary"
        grep -E -A12 "Invalid|uninitialised|definitely lost in" "$D/$name.log" | head -30
    fi
done
[ -n "$slow" ] && echo "  (declared slow, left to check-asan's ASan+UBSan run:$slow)"
[ -n "$skipped" ] && echo "  (left out by VALGRIND_SKIP:$skipped)"
[ -n "${ONLY:-}" ] && [ $((passed + failed)) -eq 0 ] && echo "  (no unit test to run under memcheck matches ONLY=$ONLY)"

# negative control: memcheck with these options must fail on a real defect
if ${CC:-cc} -g -O0 tests/robust/valgrind-control.c -o "$D/valgrind-control"; then
    for defect in overflow leak; do
        memcheck "control-$defect" "$D/valgrind-control" "$defect"
        what=$([ "$defect" = overflow ] && echo "Invalid read" || echo "definitely lost in")
        if [ "$status" -eq 9 ] && grep -q "$what" "$D/control-$defect.log"; then
            passed=$((passed + 1))
            echo "  ok    negative control: memcheck reports the $defect (exit 9: $(grep -m1 "$what" "$D/control-$defect.log" | sed 's/^==[0-9]*== *//'))"
        else
            failed=$((failed + 1))
            echo "  FAIL  negative control: the $defect in valgrind-control was not reported (exit $status)"
        fi
    done
else
    failed=$((failed + 1))
    echo "  FAIL  negative control: tests/robust/valgrind-control.c does not compile"
fi
echo "valgrind: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
