#!/bin/sh
# make check-arm: aero's staged arm packages (build/PLATFORM/aero, from
# make platform P=PLATFORM) in Pd 0.56-5 cross-built for that platform
# (platforms/pd.sh), run under QEMU's user-mode emulator, by the shared
# platform runner tests/platform/run.sh (objects, help patches, [aeolian~]'s
# physics, a texture and a tree, one render per object against the native
# render).
#   sh tests/platform/arm.sh [PLATFORM...]   (default: linux-arm64 linux-armv7)
# QEMU is called explicitly (binfmt_misc may be absent), with the cross
# toolchains' sysroots for the arm C library. Ends with one line per
# platform (with its wall time) and `N passed, N failed` over all.
# Run from the repository root after `make all lib` and make platform.
[ $# -gt 0 ] || set -- linux-arm64 linux-armv7
passed=0 failed=0 summary=""
for p in "$@"; do
    case $p in
        linux-arm64) qemu="qemu-aarch64-static -L /usr/aarch64-linux-gnu" ;;
        linux-armv7) qemu="qemu-arm-static -L /usr/arm-linux-gnueabihf" ;;
        *) echo "arm.sh: not an arm platform: $p" >&2; exit 2 ;;
    esac
    start=$(date +%s)
    mkdir -p build/tests
    echo
    echo "######## $p: Pd 0.56-5 under ${qemu%% *}"
    if ! pd=$(sh platforms/pd.sh "$p" single); then
        line="0 passed, 1 failed (no Pd for $p)"
    elif [ ! -d "build/$p/aero" ]; then
        line="0 passed, 1 failed (no build/$p/aero: make platform P=$p)"
    else
        # shellcheck disable=SC2086
        TEST_OUT=build/tests/platform-$p sh tests/platform/run.sh \
            "build/$p/aero" pd_linux $qemu "$pd/bin/pd" |
            tee "build/tests/platform-$p.log"
        line=$(tail -n 1 "build/tests/platform-$p.log")
        case "$line" in
            *" passed, "*" failed") ;;
            *) line="0 passed, 1 failed (the run did not finish)" ;;
        esac
    fi
    p_=${line%% passed*} f_=${line#*passed, } f_=${f_%% failed*}
    passed=$((passed + p_)) failed=$((failed + f_))
    summary="$summary
$p under QEMU ($(($(date +%s) - start)) s): $line"
done
echo
echo "check-arm:$summary"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
