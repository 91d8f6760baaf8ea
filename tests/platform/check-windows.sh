#!/bin/sh
# make check-windows: aero's Windows package (build/windows-amd64/aero, made
# by `make platform P=windows-amd64`) in Pd 0.56-5 for Windows
# (platforms/pd.sh, cross-built with mingw-w64) under wine64, by
# tests/platform/run.sh: the whole representative subset in the
# single-precision Pd (*.windows-amd64-32.dll), against Debian's Pd; every
# object's creation and one render in the double-precision Pd
# (*.windows-amd64-64.dll), against Pd 0.56 with 64-bit floats built here
# (platforms/pd.sh linux-amd64 double) playing the *.linux-amd64-64.so of
# `make double`.
#
# Wine runs with a new, empty prefix in build/wine (its own Windows folders
# and registry, nothing installed): so the package loads with nothing but
# Pd's own files, as on a Windows machine that has only Pd. No display is
# used (CI has none), wine's debug output is off, its ALSA driver is not
# loaded (the machine has no sound card: wine would print ALSA's errors),
# and Pd uses its MME audio API (-mmio): the default, PortAudio, fails to
# initialise without a driver and says "error ... opening audio" even with
# -noaudio. The wineserver is shut down at the end.
# Before the runs, every DLL's imports are checked: only Pd (pd.dll) and
# the system's own libraries, so nothing else needs to be installed.
# Ends with `N passed, N failed`. Run from the repository root after
# `make all lib double` and `make platform P=windows-amd64`.
ROOT=$(pwd)
PKG=${WINDOWS_PKG:-build/windows-amd64/aero}
WINE=${WINE:-/usr/lib/wine/wine64}
WINESERVER=${WINESERVER:-/usr/lib/wine/wineserver}
OBJDUMP=${OBJDUMP:-x86_64-w64-mingw32-objdump}
export WINESERVER
start=$(date +%s)

if [ ! -d "$PKG" ]; then
    echo "check-windows: no $PKG (make platform P=windows-amd64)" >&2
    exit 1
fi
for p in "windows-amd64 single" "windows-amd64 double" "linux-amd64 double"; do
    # shellcheck disable=SC2086
    sh platforms/pd.sh $p >/dev/null || exit 1
done
pd_built=$(date +%s)

export WINEPREFIX="$ROOT/build/wine"
export WINEDEBUG=-all
# no Mono or Gecko installer prompts, no ALSA driver
export WINEDLLOVERRIDES="mscoree,mshtml=;winealsa.drv=d"
unset DISPLAY WAYLAND_DISPLAY
rm -rf "$WINEPREFIX"
mkdir -p "$WINEPREFIX"
stop_wine() { "$WINESERVER" -k 2>/dev/null; "$WINESERVER" -w 2>/dev/null; }
trap stop_wine EXIT
trap 'exit 1' INT TERM
echo "check-windows: $("$WINE" --version) with a new prefix in $WINEPREFIX (log: build/wine.log)"
"$WINE" wineboot --init >build/wine.log 2>&1
# one wineserver for all the Pd runs (it would otherwise start anew for
# each), shut down by stop_wine
"$WINESERVER" -p
prefix_made=$(date +%s)

passed=0 failed=0
echo "== the DLLs import only pd.dll and Windows' own libraries"
# the system DLLs of a bare Windows (msvcrt: mingw-w64's C runtime)
system='^(pd\.dll|kernel32\.dll|msvcrt\.dll|user32\.dll|advapi32\.dll|ws2_32\.dll|api-ms-win-.*\.dll)$'
for dll in "$PKG"/*.dll; do
    imports=$("$OBJDUMP" -p "$dll" | sed -n 's/^[[:space:]]*DLL Name: //p' | tr -d '\r')
    other=$(echo "$imports" | tr 'A-Z' 'a-z' | grep -v -E "$system")
    if [ -z "$imports" ]; then
        failed=$((failed + 1)); echo "  FAIL  $(basename "$dll"): no imports read"
    elif [ -n "$other" ]; then
        failed=$((failed + 1)); echo "  FAIL  $(basename "$dll") needs $(echo $other)"
    else
        passed=$((passed + 1)); echo "  ok    $(basename "$dll") imports $(echo $imports)"
    fi
done

summary=""
run() { # NAME LABEL NATIVE_PD ARGS...: one run of tests/platform/run.sh
    _name=$1 _label=$2 _native=$3
    shift 3
    echo
    echo "######## Pd 0.56-5 for Windows ($_label) under wine"
    NATIVE_PD=$_native sh tests/platform/run.sh "$@" |
        tee "build/tests/windows-$_name.log"
    line=$(tail -n 1 "build/tests/windows-$_name.log")
    case "$line" in
        *" passed, "*" failed") ;;
        *) line="0 passed, 1 failed (the run did not finish)" ;;
    esac
    p=${line%% passed*} f=${line#*passed, } f=${f%% failed*}
    passed=$((passed + p)) failed=$((failed + f))
    summary="$summary
$_label: $line"
}
mkdir -p build/tests
run single "32-bit floats" "$(command -v pd || command -v puredata)" \
    "$PKG" windows-amd64-32.dll \
    "$WINE" "$ROOT/build/pd-windows-amd64-single/bin/pd.com" -mmio
run double "64-bit floats" "$ROOT/build/pd-linux-amd64-double/bin/pd" \
    -quick "$PKG" windows-amd64-64.dll \
    "$WINE" "$ROOT/build/pd-windows-amd64-double/bin/pd.com" -mmio
stop_wine
end=$(date +%s)
echo
echo "check-windows ($((end - start)) s: Pd $((pd_built - start)) s, wine prefix $((prefix_made - pd_built)) s, tests $((end - prefix_made)) s):$summary"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
