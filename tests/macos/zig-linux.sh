#!/bin/sh
# aero compiled by the macOS builds' compiler, zig cc (platforms/zig.sh), for
# Linux x86_64, so that its code can run here (tests/macos/check.sh):
#   build/zig-linux-amd64/aero/   the staged folder of make platform
#                                 P=linux-amd64 (platforms/platform.mk, the
#                                 same flags as the macOS externals), its
#                                 externals compiled and linked by zig cc
#   build/zig-linux-amd64/tests/  the unit tests of tests/unit, on the same
#                                 zig-compiled core
# for x86_64-linux-gnu with glibc 2.34 (the newest Zig 0.11 builds; Debian 12 has 2.36), linked to Debian's
# shared FFTW and libsndfile: the code under test is aero's, compiled by zig.
# No OpenMP (as on macOS: zig has no OpenMP runtime there), so the core's
# `omp parallel` loops run in one thread, as in the macOS aerotex.
set -eu
ZIG=$(sh platforms/zig.sh)
ZIG_GLOBAL_CACHE_DIR=${ZIG_GLOBAL_CACHE_DIR:-${AERO_CACHE:-$HOME/.cache/aero}/zig-cache}
export ZIG_GLOBAL_CACHE_DIR
B=build/zig-linux-amd64
CC="$ZIG cc -target x86_64-linux-gnu.2.34"
SYSLIBS="-L/usr/lib/x86_64-linux-gnu -lsndfile -lfftw3f_threads -lfftw3f -lfftw3 -lm -lpthread"
mkdir -p "$B/deps/include" "$B/tests"
ln -sf /usr/include/fftw3.h /usr/include/sndfile.h "$B/deps/include/"
make --no-print-directory -s -f platforms/platform.mk P=linux-amd64 B="$B" \
    DEPS="$B/deps" CC="$CC" AR="$ZIG ar" CHECK_BINARIES=no \
    LIBS="$B/libaero_core.a $SYSLIBS"
# the unit tests of the players (what the externals run) and the spectral
# helpers, about 15 s in all on the gcc build: the flow solvers' tests run
# for minutes each (ZIG_UNITS overrides the list; the tests' own binaries
# are the gcc build's, build/tests/)
ZIG_UNITS=${ZIG_UNITS:-test_aeolian_model test_band_limit test_bandwidth_extension
    test_body test_cavity test_combustion_noise test_leafwave
    test_texture test_tree test_tree_motion test_treebranch test_vortex
    test_vortex_sound}
# built as the Makefile builds them, with platform.mk's flags
CFLAGS="-std=c99 -D_POSIX_C_SOURCE=200809L -O3 -funroll-loops -fomit-frame-pointer
    -fPIC -Wall -Wextra -Wshadow -Isrc/core/common -Isrc/core/solve -Isrc/core/play
    -I$B/deps/include -fopenmp-simd"
for t in $ZIG_UNITS; do
    bin=$B/tests/$t
    if [ ! -x "$bin" ] || [ -n "$(find tests/unit src/core -newer "$bin" -name '*.[ch]' | head -1)" ]; then
        # shellcheck disable=SC2086
        $CC $CFLAGS "tests/unit/$t.c" -o "$bin" "$B/libaero_core.a" $SYSLIBS
    fi
done
echo "zig-linux.sh: $B built"
