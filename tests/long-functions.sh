#!/bin/sh
# aero: the functions of src/ longer than LIMIT lines (default 80),
# longest first, each counted from the line that names it to its closing
# brace in column 0 (the project's layout: a definition starts in column
# 0, its body's brace and closing brace stand alone in column 0).
# `make long-functions [LIMIT=n]`; a report, not a check: the last line
# is the count. Usage: long-functions.sh [LIMIT] [FILE...] (default
# every .c file under src/), from the repository root.
LIMIT=${1:-80}
[ $# -gt 0 ] && shift
# the file names have no spaces
# shellcheck disable=SC2046
[ $# -eq 0 ] && set -- $(find src -name '*.c' | sort)
awk -v limit="$LIMIT" '
    FNR == 1 { cand = 0; start = 0 }
    # a line in column 0 with a parenthesis and no semicolon at its end:
    # the first line of a definition, if a brace in column 0 follows
    /^[A-Za-z_][^;]*\(/ && !/;[ \t]*$/ && !start { cand = FNR; head = $0 }
    /^}/ && start {
        n = FNR - start + 1
        if (n > limit) {
            name = head
            sub(/\(.*/, "", name)
            k = split(name, w, /[ \t*]+/)
            printf "%5d %s:%d %s\n", n, FILENAME, start, w[k]
        }
        start = 0
        cand = 0
        next
    }
    /^{/ && cand { start = cand }
    # a declaration ends the candidate
    /;[ \t]*$/ && !start && /^[A-Za-z_}]/ { cand = 0 }
' "$@" | sort -rn | awk -v limit="$LIMIT" '
    { print } END { printf "%d functions over %d lines\n", NR, limit }'
