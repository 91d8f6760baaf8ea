# aero: the verdicts of a test runner (sourced by tests/run.sh and
# tests/platform/run.sh): pass/fail counters, a command judged by its exit
# status, a negative control, a Pd log without errors, a value against a
# published window. The runner prints "$passed passed, $failed failed".
passed=0
failed=0
pass() { passed=$((passed + 1)); echo "  ok    $*"; }
fail() { failed=$((failed + 1)); echo "  FAIL  $*"; }
# judge a command by its exit status; its own output says what it measured
judge() {
    if line=$("$@" 2>&1); then
        passed=$((passed + 1)); echo "  $line"
    else
        failed=$((failed + 1)); echo "  $line"
        case "$line" in FAIL*) ;; *) echo "  FAIL  ($*)" ;; esac
    fi
}
# the same, for a check that is meant to fail (a negative control)
judge_fails() { # exit 1 is a measured failure; 2 (unreadable file) is not
    line=$("$@" 2>&1)
    status=$?
    if [ "$status" -eq 1 ]; then
        pass "negative control fails as it must: $line"
    else
        fail "negative control (exit $status): $line"
    fi
}
log_clean() { # LOG: no creation failure, no error in Pd's log (Pd reports
    # a bad connection or a message nothing takes without the word error)
    if grep -q -i -e "couldn't create" -e "error" -e "connection failed" \
        -e "no method for" -e "inlet: expected" -e "bad arguments" "$1"; then
        fail "$2"; sed 's/^/        /' "$1" | head -20
    else
        pass "$2"
    fi
}
section() { echo; echo "== $*"; }
in_range() { # NAME VALUE LO HI SOURCE: a measured value against a published
    # window (an empty VALUE fails)
    if awk -v x="$2" -v lo="$3" -v hi="$4" 'BEGIN { exit !(x != "" && x >= lo && x <= hi) }'; then
        pass "$1 = $2 in $3..$4 ($5)"
    else
        fail "$1 = ${2:-?} not in $3..$4 ($5)"
    fi
}
reports_at_least() { # LOG OBJECT N: each bad flag/message named the object
    count=$(grep -c -F "$2" "$1")
    if [ "$count" -ge "$3" ]; then
        pass "$2 reports each bad flag and message ($count reports)"
    else
        fail "$2: only $count reports of bad input (want >= $3)"; cat "$1"
    fi
}
