#!/bin/sh
# make check-macos: aero's macOS binaries, checked as far as a Linux machine
# can (no macOS runs here: nothing below runs a Mach-O file).
#
# 1. The structure of every binary of the universal folder build/darwin
#    (make platform P=darwin): each external and the single-binary library
#    in both float sizes (*.d_fat, *.darwin-fat-64.so) and aerotex, read
#    with Debian's LLVM 14 tools (llvm-lipo, llvm-otool, llvm-nm), per
#    architecture slice:
#    - universal, exactly arm64 + x86_64; a Mach-O dylib (Zig's linker
#      makes no MH_BUNDLE; Pd's dlopen() loads either) for an external, an
#      executable for aerotex;
#    - it exports only Pd's entry points (_*_setup);
#    - every undefined symbol is either one m_pd.h (or g_canvas.h, which
#      aero_pd.c includes, or s_stuff.h, fieldsound~.c's) declares, looked up in
#      the flat namespace when Pd loads it (llvm-nm: "dynamically looked
#      up"), or libSystem's; a double external asks for class_new64, a
#      single one for class_new; aerotex takes everything from libSystem;
#    - the only library it loads is /usr/lib/libSystem.B.dylib (nothing of
#      Homebrew, /usr/local or an @rpath);
#    - LC_BUILD_VERSION: platform macos, minos 11.0;
#    - arm64: an ad-hoc code signature whose every page hash is recomputed
#      (tests/macos/codesign.py);
#    with negative controls: a small external built to break the rules
#    (an exported helper, a symbol that is not Pd's, a Homebrew library,
#    macOS 13) fails each
#    check, and a copy of an external with one byte of code changed fails
#    the signature check.
# 2. The compiler's arithmetic: the same zig cc compiles aero for Linux
#    x86_64 (build/zig-linux-amd64, tests/macos/zig-linux.sh): the unit
#    tests of the core run there, and its staged externals play in
#    Debian's Pd through the platform runner (tests/platform/run.sh: every
#    object created, help patches, [aeolian~]'s physics, a texture and a
#    tree, and one render per object equal to the gcc build's within
#    float rounding). FFTW and libsndfile there are Debian's (the core and
#    wrappers are what is compiled by zig).
# Ends with `N passed, N failed`. Run from the repository root after
# `make all lib` and `make platform P=darwin`.
ROOT=$(pwd)
OUT=${TEST_OUT:-build/tests/macos}
STAGE=build/darwin/aero
rm -rf "$OUT"
mkdir -p "$OUT"
. tests/judge.sh
python3 tests/macos/pd-api.py >"$OUT/pd-api.txt"

# --- the checks of one slice: each prints what is wrong, nothing if right ---
# filetype BIN ARCH: the Mach-O file type (DYLIB, BUNDLE, EXECUTE)
filetype() {
    llvm-otool-14 -hv -arch "$2" "$1" 2>/dev/null |
        awk '/MH_MAGIC/ { for (i = 1; i <= NF; i++)
            if ($i ~ /^(DYLIB|BUNDLE|EXECUTE|OBJECT)$/) print $i }'
}
# the external symbols a slice defines other than *_setup (or "none" when
# it defines no setup at all)
bad_exports() { # BIN ARCH
    names=$(llvm-nm-14 -g --defined-only -j -arch "$2" "$1" 2>/dev/null |
        grep -v -e ':$' -e '^$')
    echo "$names" | grep -q '^_.*_setup$' || { echo "no-setup"; return; }
    echo "$names" | grep -v '^_.*_setup$' | head -3 | tr '\n' ' '
}
# the undefined symbols that are neither libSystem's nor Pd's API looked up
# at load time; PD=no: nothing may be looked up (aerotex)
bad_imports() { # BIN ARCH PD(yes|no)
    llvm-nm-14 -m -arch "$2" "$1" 2>/dev/null | awk -v pd="$3" -v api="$OUT/pd-api.txt" '
        BEGIN { while ((getline n < api) > 0) ok[n] = 1 }
        /\(undefined\)/ {
            for (i = 1; i <= NF; i++) if ($i == "external") name = $(i + 1)
            if ($0 ~ /\(from libSystem\)$/) next
            if (pd == "yes" && $0 ~ /\(dynamically looked up\)$/ && (name in ok)) next
            print name }' | head -5 | tr '\n' ' '
}
# the libraries a slice loads besides libSystem (LC_LOAD_DYLIB and kin,
# LC_RPATH)
bad_dylibs() { # BIN ARCH
    llvm-otool-14 -l -arch "$2" "$1" 2>/dev/null | awk '
        /^ *cmd / { cmd = $2 }
        cmd ~ /^LC_(LOAD_DYLIB|LOAD_WEAK_DYLIB|REEXPORT_DYLIB|LAZY_LOAD_DYLIB|LOAD_UPWARD_DYLIB)$/ && $1 == "name" {
            if ($2 != "/usr/lib/libSystem.B.dylib") print $2 }
        cmd == "LC_RPATH" && $1 == "path" { print "rpath:" $2 }' | tr '\n' ' '
}
# LC_BUILD_VERSION other than macOS, minos 11.0
bad_minos() { # BIN ARCH
    v=$(llvm-otool-14 -l -arch "$2" "$1" 2>/dev/null | awk '
        /^ *cmd / { cmd = $2 }
        cmd == "LC_BUILD_VERSION" && $1 == "platform" { p = $2 }
        cmd == "LC_BUILD_VERSION" && $1 == "minos" { m = $2 }
        END { print p " " m }')
    [ "$v" = "macos 11.0" ] || echo "build-version:${v:-none}"
}
# every check of one slice; KIND external32, external64 or tool
check_slice() { # BIN ARCH KIND
    w=""
    t=$(filetype "$1" "$2")
    case "$3:$t" in external*:BUNDLE | tool:EXECUTE) ;;
        *) w="$w type:${t:-none}" ;; esac
    e=$(bad_exports "$1" "$2")
    [ "$3" = tool ] && e=""
    [ -z "$e" ] || w="$w exports:$e"
    i=$(bad_imports "$1" "$2" "$([ "$3" = tool ] && echo no || echo yes)")
    [ -z "$i" ] || w="$w imports:$i"
    undef=$(llvm-nm-14 -u -j -arch "$2" "$1" 2>/dev/null)
    case "$3" in
        external64) echo "$undef" | grep -q -x _class_new64 || w="$w no-class_new64" ;;
        external32) echo "$undef" | grep -q -x _class_new && ! echo "$undef" |
            grep -q -x _class_new64 || w="$w not-32-bit-floats" ;;
    esac
    d=$(bad_dylibs "$1" "$2")
    [ -z "$d" ] || w="$w loads:$d"
    m=$(bad_minos "$1" "$2")
    [ -z "$m" ] || w="$w $m"
    if [ "$2" = arm64 ]; then
        s=$(python3 tests/macos/codesign.py "$1" arm64) || w="$w signature:$s"
    fi
    echo "$w"
}

# --- 1. the universal folder ---------------------------------------------
section "the macOS binaries ($STAGE): Mach-O, exports, imports, libraries, minos, signature"
classes=$(for c in src/pd/*~.c; do basename "$c" .c; done)
if [ ! -d "$STAGE" ]; then
    fail "no $STAGE (make platform P=darwin)"
fi
bins=""
for c in $classes aero; do
    bins="$bins $STAGE/$c.d_fat:external32 $STAGE/$c.darwin-fat-64.so:external64"
done
bins="$bins build/darwin/aerotex:tool"
nbin=0
for entry in $bins; do
    b=${entry%:*} kind=${entry##*:}
    [ -d "$STAGE" ] || break
    if [ ! -f "$b" ]; then
        fail "no $b"; continue
    fi
    nbin=$((nbin + 1))
    archs=$(llvm-lipo-14 -archs "$b" 2>/dev/null | tr ' ' '\n' | grep . | LC_ALL=C sort | tr '\n' ' ')
    wrong=""
    [ "$archs" = "arm64 x86_64 " ] || wrong=" archs:$archs"
    for a in arm64 x86_64; do
        w=$(check_slice "$b" $a $kind)
        [ -z "$w" ] || wrong="$wrong [$a]$w"
    done
    if [ -z "$wrong" ]; then
        case $kind in
            tool) what="executable, every import from libSystem" ;;
            external32) what="single-precision external (class_new), Pd's API looked up flat" ;;
            external64) what="double-precision external (class_new64), Pd's API looked up flat" ;;
        esac
        pass "$(basename "$b"): universal arm64 + x86_64 $what, only libSystem loaded, minos 11.0, arm64 signed"
    else
        fail "$(basename "$b"):$wrong"
    fi
done
[ -d "$STAGE" ] && echo "  ($nbin binaries read slice by slice; m_pd.h, g_canvas.h and s_stuff.h declare $(wc -l <"$OUT/pd-api.txt") names)"

# --- negative controls ---------------------------------------------------
section "negative controls: the checks fail on binaries that break them"
ZIG=$(sh platforms/zig.sh)
export ZIG_GLOBAL_CACHE_DIR=${ZIG_GLOBAL_CACHE_DIR:-${AERO_CACHE:-$HOME/.cache/aero}/zig-cache}
cat >"$OUT/control.c" <<'EOF'
/* a small external that breaks the rules: helper() is exported, it calls
   a function Pd does not declare and one of a Homebrew library, and it is
   built for macOS 13 */
#include "m_pd.h"
void not_pd_api(void);
void foo(void);
static t_class *control_class;
static void *control_new(void) { return pd_new(control_class); }
int helper(int x) { not_pd_api(); foo(); return x + 1; }
__attribute__((visibility("default"))) void control_setup(void)
{
    control_class = class_new(gensym("control"), (t_newmethod)control_new,
        0, sizeof(t_object), 0, 0);
    post("control %d", helper(1));
}
EOF
# the Homebrew library: its interface only (a text stub, as Apple's SDKs
# ship libraries), enough to link against
cat >"$OUT/libfoo.tbd" <<'EOF'
--- !tapi-tbd
tbd-version: 4
targets: [ arm64-macos ]
install-name: '/opt/homebrew/lib/libfoo.dylib'
exports:
  - targets: [ arm64-macos ]
    symbols: [ _foo ]
...
EOF
# compiled and linked as platform.mk does, without the exports list
if $ZIG cc -target aarch64-macos.13.0 -O2 -I/usr/include/pd -c "$OUT/control.c" \
        -o "$OUT/control.o" >"$OUT/control.log" 2>&1 &&
    ld64.lld-14 -arch arm64 -platform_version macos 13.0 13.0 -bundle \
        -undefined dynamic_lookup -o "$OUT/control.d_arm64" "$OUT/control.o" \
        "$OUT/libfoo.tbd" "$(dirname "$ZIG")/lib/libc/darwin/libSystem.13.tbd" \
        >>"$OUT/control.log" 2>&1; then
    c=$OUT/control.d_arm64
    e=$(bad_exports "$c" arm64)
    case "$e" in *_helper*) pass "negative control: an exported helper is found ($e)" ;;
        *) fail "negative control: the exported _helper is not found (${e:-nothing})" ;; esac
    i=$(bad_imports "$c" arm64 yes)
    case "$i" in *_not_pd_api*) pass "negative control: a symbol m_pd.h does not declare is found ($i)" ;;
        *) fail "negative control: _not_pd_api is not found among the imports (${i:-nothing})" ;; esac
    d=$(bad_dylibs "$c" arm64)
    case "$d" in */opt/homebrew/lib/libfoo.dylib*) pass "negative control: a Homebrew library is found ($d)" ;;
        *) fail "negative control: the Homebrew library is not found (${d:-nothing})" ;; esac
    m=$(bad_minos "$c" arm64)
    case "$m" in *13.0*) pass "negative control: a macOS 13 minimum is found ($m)" ;;
        *) fail "negative control: minos 13 is not found (${m:-nothing})" ;; esac
    i=$(bad_imports "$c" arm64 no)
    case "$i" in *_pd_new*) pass "negative control: as a tool, its Pd imports are found ($i)" ;;
        *) fail "negative control: a tool's Pd imports are not found (${i:-nothing})" ;; esac
else
    fail "negative control: the control external did not build"; tail -5 "$OUT/control.log"
fi
b=$STAGE/aeolian~.d_fat
if [ -f "$b" ]; then
    # one byte of the arm64 slice's code changed (the slice's offset from
    # the universal header, its text 16 KiB in)
    off=$(llvm-otool-14 -f "$b" 2>/dev/null | awk '$1 == "cputype" { c = $2 }
        c == 16777228 && $1 == "offset" { print $2; exit }')
    cp "$b" "$OUT/flipped.d_fat"
    pos=$((off + 16384 + 100))
    byte=$(od -A n -t u1 -j "$pos" -N 1 "$b" | tr -d ' ')
    printf "$(printf '\\%03o' $(( (byte + 1) % 256 )))" |
        dd of="$OUT/flipped.d_fat" bs=1 seek="$pos" conv=notrunc 2>/dev/null
    if s=$(python3 tests/macos/codesign.py "$OUT/flipped.d_fat" arm64); then
        fail "negative control: a changed byte at $pos passes the signature check ($s)"
    else
        pass "negative control: a changed byte fails the signature check ($s)"
    fi
fi

# --- 2. the compiler's arithmetic on Linux ------------------------------------
section "zig cc's code on Linux x86_64: the unit tests and the externals in Pd"
if sh tests/macos/zig-linux.sh >"$OUT/zig-linux.log" 2>&1; then
    pass "zig cc built aero for x86_64-linux-gnu (build/zig-linux-amd64)"
    # the externals under test are clang's (zig's), the reference ones gcc's
    if readelf -p .comment build/zig-linux-amd64/aero/aeolian~.pd_linux 2>/dev/null |
        grep -q clang && ! readelf -p .comment aeolian~.pd_linux 2>/dev/null | grep -q clang; then
        pass "the externals played are zig's clang's (.comment), the references gcc's"
    else
        fail "build/zig-linux-amd64's externals are not clang's, or the native ones are"
    fi
    # the unit tests (ZIG_UNITS, tests/macos/zig-linux.sh), each binary's
    # own `N passed, N failed` added to these
    for t in build/zig-linux-amd64/tests/test_*; do
        [ -x "$t" ] || continue
        "$t" >"$OUT/$(basename "$t").txt" 2>&1
        status=$?
        line=$(grep -E "^[0-9]+ passed, [0-9]+ failed$" "$OUT/$(basename "$t").txt" | tail -n 1)
        grep -E '^ *FAIL' "$OUT/$(basename "$t").txt" | sed 's/^/  /'
        if [ -z "$line" ]; then
            fail "zig: $t ended without a summary (exit $status)"; continue
        fi
        p=${line%% passed*} f=${line#*passed, } f=${f%% failed*}
        passed=$((passed + p)) failed=$((failed + f))
        [ "$status" -eq 0 ] || [ "$f" -gt 0 ] || fail "zig: $t exited $status"
        echo "  zig: $t: $line"
    done
    # the platform runner: its own counters, added to these
    TEST_OUT=$OUT/platform sh tests/platform/run.sh build/zig-linux-amd64/aero pd_linux \
        "$(command -v pd || command -v puredata)" >"$OUT/platform.log" 2>&1
    sed 's/^/  /' "$OUT/platform.log" | grep -E '^  *(ok|FAIL)|^  *==' | grep -v '^  *ok ' || true
    line=$(tail -n 1 "$OUT/platform.log")
    case "$line" in
        *" passed, "*" failed")
            p=${line%% passed*} f=${line#*passed, } f=${f%% failed*}
            passed=$((passed + p)) failed=$((failed + f))
            echo "  the platform runner with zig's externals: $line" ;;
        *) fail "the platform runner did not finish ($OUT/platform.log)" ;;
    esac
else
    fail "zig cc could not build aero for Linux"; tail -20 "$OUT/zig-linux.log"
fi

echo
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
