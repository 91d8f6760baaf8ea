#!/bin/sh
# aero: the static libraries the packaged externals link, for one platform:
#   sh platforms/deps.sh PLATFORM      (linux-amd64 windows-amd64 linux-arm64
#                                       linux-armv7 darwin-arm64 darwin-amd64;
#                                       wasm with emcc)
# builds, from the archives in ../shared/vendor (AERO_VENDOR overrides):
#   libfftw3f.a   FFTW 3.3.10, single precision, its threads API inside
#                 (fftwf_make_planner_thread_safe): pthreads, or win32
#                 threads on Windows, none for wasm (platforms/deps/fftw.sh)
#   libfftw3.a    the same in double precision (aerotex's bandwidth
#                 extension), where aerotex is built (Windows, macOS); the
#                 externals of both float sizes link libfftw3f.a only
#   libsndfile.a  libsndfile 1.2.0 without external codecs: WAV, AIFF and
#                 the other formats it reads itself (platforms/deps/sndfile.sh)
# all position-independent with their symbols hidden (nothing of them is
# exported from an external that links them), and their headers.
#
# Neither library's own build system is used: a configure or CMake run
# for a cross host takes minutes of checks whose answers are known here.
# Each script writes the library's config.h from the compiler's predefined
# macros and the platform, and compiles the library's sources only (no
# tests, tools or programs), JOBS (default 2) at a time.
#
# Each library is built once per machine into the cache
# ${AERO_CACHE:-$HOME/.cache/aero}/deps/LIB-PLATFORM-KEY, KEY made of the
# archive's sha256 and a hash of this script and the library's: change
# either and it is rebuilt; a missing one is built. Concurrent runs (several
# clones) wait on a lock. build/deps/PLATFORM/{include,lib} link to the
# cached files.
set -eu

P=${1:?usage: sh platforms/deps.sh PLATFORM}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
HERE="$ROOT/platforms"
VENDOR=${AERO_VENDOR:-$ROOT/../shared/vendor}
CACHE=${AERO_CACHE:-$HOME/.cache/aero}/deps
JOBS=${JOBS:-2}

DOUBLE=no
case $P in
linux-amd64) CC=gcc AR=ar ;;
linux-arm64) CC=aarch64-linux-gnu-gcc AR=aarch64-linux-gnu-ar ;;
linux-armv7) CC=arm-linux-gnueabihf-gcc AR=arm-linux-gnueabihf-ar ;;
windows-amd64) CC=x86_64-w64-mingw32-gcc AR=x86_64-w64-mingw32-ar DOUBLE=yes ;;
# macOS 11 and later: Zig's clang and its own Mach-O tools (platforms/zig.sh)
darwin-arm64|darwin-amd64)
    ZIG=$(sh "$ROOT/platforms/zig.sh")
    ZIG_GLOBAL_CACHE_DIR=${ZIG_GLOBAL_CACHE_DIR:-${AERO_CACHE:-$HOME/.cache/aero}/zig-cache}
    export ZIG_GLOBAL_CACHE_DIR
    arch=aarch64
    [ "$P" = darwin-amd64 ] && arch=x86_64
    CC="$ZIG cc -target $arch-macos.11.0" AR="$ZIG ar --format=darwin" DOUBLE=yes ;;
wasm) CC=emcc AR=emar ;;
*) echo "deps.sh: unknown platform '$P'" >&2; exit 2 ;;
esac
command -v "${CC%% *}" >/dev/null || { echo "deps.sh: $CC not found (make deps)" >&2; exit 1; }
# Position-independent (linked into shared objects; -fPIC means nothing to
# PE) and hidden. armhf: Debian's defaults (ARMv7-A, VFPv3-D16, Thumb-2),
# which every Pi from the 2 on runs.
CFLAGS="-O2 -fvisibility=hidden"
case $P in windows-*|wasm) ;; *) CFLAGS="$CFLAGS -fPIC" ;; esac

# compile SRC OBJDIR FLAGS... < list of .c files relative to SRC: one
# object per file in OBJDIR (named by its path), JOBS at a time; fails if
# any fails. (Paths without spaces.)
compile() {
    DEPS_SRC=$1 DEPS_OBJ=$2
    shift 2
    DEPS_CC="$CC $CFLAGS $*"
    export DEPS_OBJ DEPS_CC
    (cd "$DEPS_SRC" && xargs -P "$JOBS" -I{} sh -c \
        'exec $DEPS_CC -c "$1" -o "$DEPS_OBJ/$(echo "$1" | tr / _ | sed "s/c\$/o/")"' \
        - {})
}

. "$HERE/deps/fftw.sh"
. "$HERE/deps/sndfile.sh"

mkdir -p "$CACHE"

# build LIB ARCHIVE: runs LIB_build PREFIX SRC in a temporary folder unless
# the cache holds it; prints the cached prefix
build() {
    [ -f "$2" ] || { echo "deps.sh: $2 not found" >&2; exit 1; }
    key="$(sha256sum "$2" | cut -c1-12)-$(cat "$HERE/deps.sh" "$HERE/deps/$1.sh" |
        sha256sum | cut -c1-12)"
    prefix="$CACHE/$1-$P-$key"
    if [ ! -f "$prefix/.done" ]; then
        (
            flock 9
            if [ ! -f "$prefix/.done" ]; then
                tmp="$CACHE/.tmp-$1-$P-$$"
                rm -rf "$tmp" "$prefix"
                mkdir -p "$tmp/src" "$tmp/prefix/include" "$tmp/prefix/lib"
                start=$(date +%s)
                tar -xzf "$2" -C "$tmp/src" --strip-components=1
                # in the background so that set -e holds inside it
                "$1_build" "$tmp/prefix" "$tmp/src" >"$tmp/build.log" 2>&1 &
                wait $! ||
                    { tail -30 "$tmp/build.log" >&2
                      echo "deps.sh: $1 for $P failed (log: $tmp/build.log)" >&2
                      exit 1; }
                echo "deps.sh: $1 for $P built in $(( $(date +%s) - start )) s" \
                    >"$tmp/prefix/.done"
                mv "$tmp/prefix" "$prefix"
                rm -rf "$tmp"
                cat "$prefix/.done" >&2
            fi
        ) 9>"$CACHE/.lock-$1-$P"
    fi
    echo "$prefix"
}

fftw=$(build fftw "$VENDOR/fftw-3.3.10.tar.gz")
sndfile=$(build sndfile "$VENDOR/libsndfile-1.2.0.tar.gz")

# build/deps/PLATFORM: links to the cached files
out="$ROOT/build/deps/$P"
rm -rf "$out"
mkdir -p "$out/include" "$out/lib"
for d in "$fftw" "$sndfile"; do
    for f in "$d"/include/* "$d"/lib/*; do
        ln -s "$f" "$out/${f#"$d"/}"
    done
done
