#!/bin/sh
# aero: a new object joins with its own files and one word in AERO_OBJECTS
# (src/pd/aero.c); every list of objects is read from those. This check
# makes a forgotten file an error instead of a silently untested object:
# for each word W of AERO_OBJECTS, [W~] must have
#   - its wrapper src/pd/W~.c;
#   - its robustness configurations tests/robust/objects/W~.txt with at
#     least one `hostile` and one `long` line (tests/robust/objects/README.md);
#   - a multi-instance case, unit_multi_instance("W~", ...) in one of
#     tests/unit/test_*.c (tests/unit/multi_instance.h);
#   - a fuzz harness of its messages, a fuzz/fuzz_*.c with the line
#     `/* aero-fuzz: object W~ */` (fuzz/targets.sh);
#   - its line in README.md's object list: [W~] and its help patch.
# And the reverse: a wrapper, robustness file, multi-instance case or fuzz
# harness for an object that AERO_OBJECTS does not name is an error too (a
# renamed or removed object's leftovers). Prints `ok`/`FAIL` lines, one per
# object and one per stray file, and exits 1 on a failure.
# Usage, from the root of a tree: sh tests/robust/registered.sh
words=$(sed -n '/^#define AERO_OBJECTS/,/[^\\]$/p' src/pd/aero.c |
    grep -o 'X([A-Za-z0-9_]*)' | sed 's/^X(\(.*\))$/\1/')
if [ -z "$words" ]; then
    echo "FAIL no AERO_OBJECTS in src/pd/aero.c"
    exit 1
fi
status=0
# the classes each list names
mi=$(grep -h -o 'unit_multi_instance("[^"]*"' tests/unit/test_*.c 2>/dev/null |
    sed 's/.*("\(.*\)"$/\1/' | sort -u)
fz=$(grep -h '^/\* aero-fuzz: object ' fuzz/fuzz_*.c 2>/dev/null |
    sed 's|^/\* aero-fuzz: object \([^ ]*\) \*/$|\1|' | sort -u)
has() { printf '%s\n' "$2" | grep -q -x -F -e "$1"; }
n=0
for w in $words; do
    c="$w~"
    n=$((n + 1))
    missing=""
    [ -f "src/pd/$c.c" ] || missing="$missing, its wrapper src/pd/$c.c"
    f="tests/robust/objects/$c.txt"
    nh=0 nl=0
    if [ -f "$f" ]; then
        nh=$(grep -c '^hostile[[:space:]]*|' "$f")
        nl=$(grep -c '^long[[:space:]]*|' "$f")
        [ "$nh" -gt 0 ] || missing="$missing, a hostile line in $f"
        [ "$nl" -gt 0 ] || missing="$missing, a long line in $f"
    else
        missing="$missing, its robustness file $f"
    fi
    has "$c" "$mi" ||
        missing="$missing, a unit_multi_instance(\"$c\", ...) case in tests/unit/test_*.c"
    has "$c" "$fz" ||
        missing="$missing, a fuzz harness with /* aero-fuzz: object $c */"
    grep -F -e "[$c]" README.md 2>/dev/null | grep -q -F -e "$c-help.pd" ||
        missing="$missing, a README.md line naming [$c] and $c-help.pd"
    if [ -n "$missing" ]; then
        echo "FAIL [$c] (AERO_OBJECTS) lacks${missing#,}"
        status=1
    else
        echo "ok   [$c]: wrapper, $nh hostile and $nl long configurations, multi-instance case, fuzz harness, README line"
    fi
done
# the reverse: files of objects AERO_OBJECTS does not name
known=$(for w in $words; do echo "$w~"; done)
stray() {
    has "$1" "$known" && return
    echo "FAIL $2 is for [$1], which AERO_OBJECTS (src/pd/aero.c) does not name"
    status=1
}
for f in src/pd/*~.c; do [ -f "$f" ] && stray "$(basename "$f" .c)" "$f"; done
for f in tests/robust/objects/*.txt; do
    [ -f "$f" ] && stray "$(basename "$f" .txt)" "$f"
done
for c in $mi; do stray "$c" "a unit_multi_instance(\"$c\", ...) case"; done
for c in $fz; do stray "$c" "a fuzz harness (aero-fuzz: object $c)"; done
[ "$status" -eq 0 ] && echo "ok   $n objects of AERO_OBJECTS, no file for any other"
exit "$status"
