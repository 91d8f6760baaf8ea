#!/bin/sh
# aero: the unit tests too slow for valgrind memcheck, one name (test_x) a
# line. A test declares itself slow with a line of its source
# tests/unit/test_x.c that starts with `/* aero-test: slow` (the reason may
# follow; CONTRIBUTING.md). valgrind.sh leaves these out; check-asan runs
# every unit test, these included, under ASan+UBSan+LSan. Run from the
# repository root.
grep -l '^/\* aero-test: slow' tests/unit/test_*.c 2>/dev/null |
    sed 's|^.*/||; s|\.c$||'
