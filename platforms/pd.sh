#!/bin/sh
# aero: Pd 0.56-5 for another platform, the test client of the platform
# checks (make check-windows, make check-arm), built from
# ../shared/vendor/pure-data-0.56-5.tar.gz.
#
#   sh platforms/pd.sh PLATFORM [single|double]
#
# PLATFORM is Pd's name: windows-amd64, linux-arm64, linux-armv7,
# linux-amd64 (each a case below). double builds Pd with
# -DPD_FLOATSIZE=64, which loads only externals named *.PLATFORM-64.*
# (Pd >= 0.54).
#
# The build is cached outside the clone, in
# ${AERO_CACHE:-$HOME/.cache/aero}/pd/PLATFORM-PRECISION-KEY, KEY made of the
# archive's sha256 and this script's, so a changed archive or script builds
# anew and every clone on the machine shares one build. The result is linked
# from build/pd-PLATFORM-PRECISION/ (stable paths, other scripts use them):
#   windows-amd64:
#     bin/pd.com  bin/pd.exe  bin/pd.dll  bin/libwinpthread-1.dll
#                 (pd.dll needs it beside it)
#     bin/pd.dll.a  pd.dll's import library (what externals link)
#     src/m_pd.h   Pd's headers
#     extra/ doc/  Pd's own abstractions (extra/*.pd) and documentation,
#                  where Pd looks for them (the folder above bin/)
#   linux-arm64, linux-armv7, linux-amd64 (Debian's aarch64-linux-gnu-,
#   arm-linux-gnueabihf- and x86_64-linux-gnu- compilers, makefile.gnu
#   without ALSA or OSS: Pd's dummy audio API, for batch mode with -noaudio):
#     bin/pd       on arm run under qemu-user, e.g.
#                  qemu-aarch64-static -L /usr/aarch64-linux-gnu bin/pd ...
#                  qemu-arm-static -L /usr/arm-linux-gnueabihf bin/pd ...
#     src/m_pd.h   Pd's headers
#     extra/       Pd's own abstractions
# Prints the path of build/pd-PLATFORM-PRECISION. PD_ARCHIVE overrides the
# archive.
set -e
PLATFORM=${1:?usage: sh platforms/pd.sh PLATFORM [single|double]}
PRECISION=${2:-single}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
ARCHIVE=${PD_ARCHIVE:-$(sh "$ROOT/platforms/vendor.sh" pure-data-0.56-5.tar.gz)}
CACHE=${AERO_CACHE:-$HOME/.cache/aero}

case $PRECISION in
    single) FLOATSIZE= ;;
    double) FLOATSIZE=-DPD_FLOATSIZE=64 ;;
    *) echo "pd.sh: precision is single or double, not $PRECISION" >&2; exit 2 ;;
esac
if [ ! -f "$ARCHIVE" ]; then
    echo "pd.sh: no $ARCHIVE" >&2
    exit 1
fi

# Pd's own optimisation flags (its makefiles' defaults) plus the float size
OPT="-O3 -funroll-loops -fomit-frame-pointer $FLOATSIZE"

# --- one function per platform: build in $SRC (the unpacked archive), put
# the result into $DEST -----------------------------------------------------
build_windows_amd64() {
    t=x86_64-w64-mingw32
    # makefile.mingw without ASIO (its SDK is not free to ship): no ASIO
    # sources, no -DPA_USE_ASIO; the rest of its ARCH_CFLAGS as they are.
    # With no C++ left, gcc links (Debian's g++-mingw-w64 is not needed).
    set -- -f makefile.mingw CC=$t-gcc CXX=$t-gcc WINDRES=$t-windres \
        "STRIP=$t-strip --strip-unneeded -R .note -R .comment" ASIOSRC= \
        "ARCH_CFLAGS=-DPD -DPD_INTERNAL -DWINVER=0x0502 -DPA_USE_WASAPI -DUSEAPI_MMIO -DUSEAPI_PORTAUDIO -mms-bitfields -DWISH='\"wish86.exe\"'" \
        "MORECFLAGS=$OPT"
    # pd.a (the import library) is a side product of linking pd.dll, which
    # pd.com and pd.exe link: pd.dll first, then the programs
    nice -n 10 make -C "$SRC/src" -j2 "$@" ../bin/pd.dll
    nice -n 10 make -C "$SRC/src" -j2 "$@" ../bin/pd.com ../bin/pd.exe
    mkdir -p "$DEST/bin" "$DEST/src"
    cp "$SRC/bin/pd.com" "$SRC/bin/pd.exe" "$SRC/bin/pd.dll" "$DEST/bin/"
    cp "$SRC/src/pd.a" "$DEST/bin/pd.dll.a"
    cp /usr/$t/lib/libwinpthread-1.dll "$DEST/bin/"
    cp "$SRC"/src/*.h "$DEST/src/"
    # what Pd's own install puts there: extra's abstractions, the doc tree
    mkdir -p "$DEST/extra"
    cp "$SRC"/extra/*.pd "$DEST/extra/"
    cp -R "$SRC/doc" "$DEST/"
}

# Linux on arm: makefile.gnu with the cross compiler (~40 s of CPU each)
build_linux_cross() { # TRIPLET
    nice -n 10 make -C "$SRC/src" -j2 -f makefile.gnu CC="$1-gcc" \
        ALSA=false OSS=false "MORECFLAGS=$FLOATSIZE" ../bin/pd
    mkdir -p "$DEST/bin" "$DEST/src" "$DEST/extra"
    cp "$SRC/bin/pd" "$DEST/bin/"
    cp "$SRC"/src/*.h "$DEST/src/"
    cp "$SRC"/extra/*.pd "$DEST/extra/"
}
build_linux_arm64() { build_linux_cross aarch64-linux-gnu; }
build_linux_armv7() { build_linux_cross arm-linux-gnueabihf; }
# the native one: the reference a double-precision platform Pd's renders
# are compared with (make check-windows)
build_linux_amd64() { build_linux_cross x86_64-linux-gnu; }

case $PLATFORM in
    windows-amd64) build=build_windows_amd64 ;;
    linux-arm64) build=build_linux_arm64 ;;
    linux-armv7) build=build_linux_armv7 ;;
    linux-amd64) build=build_linux_amd64 ;;
    *) echo "pd.sh: no build for platform $PLATFORM" >&2; exit 2 ;;
esac

key=$( (sha256sum <"$ARCHIVE"; sha256sum <"$0") | sha256sum | cut -c1-16)
entry=$CACHE/pd/$PLATFORM-$PRECISION-$key
link=$ROOT/build/pd-$PLATFORM-$PRECISION

if [ ! -f "$entry/.complete" ]; then
    mkdir -p "$CACHE/pd"
    work=$(mktemp -d "$CACHE/pd/.build-$PLATFORM-$PRECISION.XXXXXX")
    log=$work.log
    echo "pd.sh: building Pd 0.56 for $PLATFORM ($PRECISION) in $work (log: $log)" >&2
    SRC=$work/src DEST=$work/pd
    mkdir -p "$SRC"
    if ! { tar xzf "$ARCHIVE" -C "$SRC" --strip-components=1 &&
        $build; } >"$log" 2>&1; then
        tail -30 "$log" >&2
        echo "pd.sh: Pd for $PLATFORM ($PRECISION) did not build (log: $log)" >&2
        exit 1
    fi
    touch "$DEST/.complete"
    # another build of the same key may have finished meanwhile: keep one
    mv -T "$DEST" "$entry" 2>/dev/null || true
    rm -rf "$work" "$log"
fi
mkdir -p "$ROOT/build"
ln -sfn "$entry" "$link"
echo "$link"
