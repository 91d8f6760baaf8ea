#!/bin/sh
# Negative control of check-asan: an instrumented external with a heap
# overflow and one with a leak, loaded into Pd the way the suite loads
# aero's, must each leave a sanitizer report. Arg: the reports folder.
# Reports land under control-* and are not counted as findings.
set -u
reports=$1
dir=build/tests/out/asan-control
mkdir -p "$dir"
gcc -g -fPIC -shared -fsanitize=address,undefined -DPD -I/usr/include/pd \
    tests/robust/asan-control.c -o "$dir/asan_control.pd_linux" || exit 1
status=0
for case in "overflow 0" "leak 1"; do
    set -- $case
    printf '#N canvas 0 50 300 200 10;\n#X obj 10 10 asan_control %s;\n' "$2" \
        >"$dir/$1.pd"
    ASAN_OPTIONS="log_path=$reports/control-$1:detect_leaks=1" \
        timeout 60 pd -batch -nogui -noaudio -noprefs -stderr -nostdpath \
        -path "$dir" -open "$dir/$1.pd" -send "pd quit" >"$dir/$1.log" 2>&1
    what=$([ "$1" = overflow ] && echo heap-buffer-overflow || echo "detected memory leaks")
    if cat "$reports"/control-"$1".* 2>/dev/null | grep -q "$what"; then
        echo "  ok    negative control: a $1 in an external is reported ($what)"
    else
        echo "  FAIL  negative control: the $1 in asan_control was not reported"
        status=1
    fi
done
exit $status
