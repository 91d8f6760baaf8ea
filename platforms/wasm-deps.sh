#!/bin/sh
# aero: FFTW (single precision) and libsndfile (no
# external codecs) compiled for WebAssembly with Debian's emscripten, from
# the archives in ../shared/vendor, into build/deps/wasm/{include,lib}.
# The wasm case of the platform dependency builder (platforms/deps.sh
# PLATFORM, which calls this): each library is built once per machine and
# kept in ${AERO_CACHE:-$HOME/.cache/aero}/deps/wasm/NAME-SHA-SCRIPT, keyed
# by the archive's sha256 and this script's own hash, so a changed archive
# or recipe rebuilds it and an unchanged one is copied.
#
# FFTW is built without its threads: without -pthread, emscripten has no
# threads to offer (FFTW's thread code does not even link: no
# pthread_attr_setscope), and the module runs one Pd in one thread, so the
# planner lock aero asks for (fftwf_make_planner_thread_safe) has nothing
# to serialise; the module defines it as a no-op (web/aero_web.c). A page
# then needs no cross-origin isolation either.
# Usage: platforms/wasm-deps.sh [VENDOR_DIR]
set -eu
vendor=${1:-../shared/vendor}
dest=build/deps/wasm
cache=${AERO_CACHE:-$HOME/.cache/aero}/deps/wasm
# emcc runs its tools under node; Debian's emscripten needs its modules
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}
script_hash=$(sha256sum "$0" | cut -c1-12)
mkdir -p "$dest/include" "$dest/lib" "$cache"

# build NAME ARCHIVE RECIPE: the recipe runs in the unpacked source with
# $prefix set; its include/ and lib/ are cached, then copied to $dest
build() {
    name=$1 archive=$vendor/$2 recipe=$3
    [ -f "$archive" ] || { echo "wasm-deps: $archive is missing" >&2; exit 77; }
    key=$name-$(sha256sum "$archive" | cut -c1-12)-$script_hash
    if [ ! -f "$cache/$key/.done" ]; then
        echo "wasm-deps: building $name for wasm (once: $cache/$key)"
        work=$(mktemp -d "${TMPDIR:-/tmp}/aero-wasm-$name.XXXXXX")
        tar xzf "$archive" -C "$work" --strip-components=1
        rm -rf "$cache/$key"
        prefix=$cache/$key
        if ! (cd "$work" && $recipe) >"$work.log" 2>&1; then
            tail -30 "$work.log"
            echo "wasm-deps: $name failed (log: $work.log)" >&2
            exit 1
        fi
        touch "$prefix/.done"
        rm -rf "$work" "$work.log"
    fi
    cp -R "$cache/$key/include/." "$dest/include/"
    cp -R "$cache/$key/lib/." "$dest/lib/"
}

fftw() {
    # no Fortran, no SIMD codelets for wasm, no threads (below); only the
    # library's folders (its tests and tools would be linked for nothing)
    emconfigure ./configure --host=wasm32-unknown-none \
        --prefix="$prefix" --enable-float --enable-static --disable-shared \
        --disable-threads --disable-fortran --disable-doc CFLAGS=-O2 &&
        sed -i '/^SUBDIRS = /{:a;/\\$/{N;ba};s/.*/SUBDIRS = support kernel simd-support dft rdft reodft api/}' \
            Makefile &&
        emmake make -j2 && emmake make install
}

sndfile() {
    emcmake cmake -S . -B wasm-build -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_INSTALL_PREFIX="$prefix" -DBUILD_SHARED_LIBS=OFF \
        -DENABLE_EXTERNAL_LIBS=OFF -DENABLE_MPEG=OFF -DBUILD_PROGRAMS=OFF \
        -DBUILD_EXAMPLES=OFF -DBUILD_TESTING=OFF -DENABLE_CPACK=OFF \
        -DINSTALL_MANPAGES=OFF -DINSTALL_PKGCONFIG_MODULE=OFF &&
        cmake --build wasm-build -j2 && cmake --install wasm-build
}

build fftw fftw-3.3.10.tar.gz fftw
build sndfile libsndfile-1.2.0.tar.gz sndfile
echo "wasm-deps: $dest/lib: $(ls "$dest/lib" | grep '\.a$' | tr '\n' ' ')"
