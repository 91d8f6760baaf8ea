#!/bin/sh
# aero: runs the grid-convergence tests (`make check-convergence`), each
# binary once, shows their output as it comes and adds up their closing
# "N passed, N failed" lines; exits 1 if a check failed or a binary did
# not get to its closing line (a crash).
passed=0
failed=0
log=$(mktemp) || exit 1
trap 'rm -f "$log"' EXIT
for t in "$@"; do
    echo "== $t"
    "$t" | tee "$log"
    counts=$(tail -n 1 "$log" |
             sed -n 's/^\([0-9]*\) passed, \([0-9]*\) failed$/\1 \2/p')
    if [ -z "$counts" ]; then
        echo "$t did not finish"
        failed=$((failed + 1))
        continue
    fi
    passed=$((passed + ${counts% *}))
    failed=$((failed + ${counts#* }))
done
echo "check-convergence: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
