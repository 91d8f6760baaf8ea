#!/bin/sh
# aero: the unit tests of src/core, one binary per tests/unit/test_*.c
# (build/tests/test_*, built by `make all`), each a list of named cases
# (tests/unit/unit.h). Sourced by tests/run.sh, which adds the binaries'
# `N passed, N failed` to its own; run alone (make check-unit) it ends with
# that line itself. Run from the repository root.
#   ONLY=pattern   only the binaries whose path contains it (ONLY=cavity)
#   CASE="a b"     only these cases of each binary that has them
#                  (build/tests/test_x --list names a binary's cases;
#                  build/tests/test_x a b runs them directly)
if [ -z "${passed:-}" ]; then # alone: the counters and output of a runner
    OUT=${TEST_OUT:-build/tests/out}
    mkdir -p "$OUT"
    . tests/judge.sh
    unit_alone=1
fi

section "unit tests (src/core)"
unit_ran=0
for t in build/tests/test_*; do
    [ -x "$t" ] || continue
    case "$t" in *"${ONLY:-}"*) ;; *) continue ;; esac
    name=$(basename "$t")
    cases=
    if [ -n "${CASE:-}" ]; then # the asked cases this binary has
        for c in $("$t" --list); do
            case " $CASE " in *" $c "*) cases="$cases $c" ;; esac
        done
        [ -n "$cases" ] || continue
    fi
    unit_ran=$((unit_ran + 1))
    echo "-- $t$cases"
    # shellcheck disable=SC2086
    "$t" $cases >"$OUT/$name.txt" 2>&1
    status=$?
    sed 's/^/  /' "$OUT/$name.txt" | grep -v "^  *[0-9]* passed, [0-9]* failed$"
    summary=$(grep -E "^[0-9]+ passed, [0-9]+ failed$" "$OUT/$name.txt" | tail -n 1)
    if [ -z "$summary" ]; then
        fail "$t ended without a summary (exit $status)"
        continue
    fi
    p=${summary%% passed*}
    f=${summary#*passed, }
    f=${f%% failed*}
    passed=$((passed + p))
    failed=$((failed + f))
    [ "$status" -ne 0 ] && [ "$f" -eq 0 ] && fail "$t exited $status"
done

# a CASE no binary has is a typo, not a pass
[ -n "${CASE:-}" ] && [ "$unit_ran" -eq 0 ] &&
    fail "no unit test${ONLY:+ matching ONLY=$ONLY} has a case named $CASE (build/tests/test_x --list)"

if [ -n "${unit_alone:-}" ]; then
    echo
    echo "$passed passed, $failed failed"
    [ "$failed" -eq 0 ]
fi
