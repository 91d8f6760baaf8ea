#!/bin/sh
# Builds embed.js + embed.wasm from glue.c, aero and libpd (docs/web.md):
#   AERO=/path/to/aero sh build.sh          (OPT=-O1: a quicker build, a
#                                            slower module; default -O3)
# after `make web` in AERO, which builds what this links: libpd 0.16.1 for
# wasm (LIBPD=$AERO/build/libpd/wasm), aero's core for wasm and FFTW and
# libsndfile for wasm (build/deps/wasm).
set -eu
AERO=${AERO:?set AERO to the folder of aero where make web has run}
LIBPD=${LIBPD:-$AERO/build/libpd/wasm}
NODE_PATH=${NODE_PATH:-/usr/share/nodejs} emcc ${OPT:--O3} -DHAVE_LIBPD \
    -I"$LIBPD/libpd_wrapper" -I"$LIBPD/pure-data/src" \
    -I"$AERO/src/pd" -I"$AERO/src/core/common" -I"$AERO/src/core/solve" \
    -I"$AERO/src/core/play" -I"$AERO/build/deps/wasm/include" \
    glue.c "$AERO"/src/pd/*.c \
    "$AERO/build/wasm/libaero_core.a" "$LIBPD/libs/libpd.a" \
    "$AERO/build/deps/wasm/lib/libsndfile.a" "$AERO/build/deps/wasm/lib/libfftw3f.a" \
    -sMODULARIZE=1 -sEXPORT_ES6=1 -sEXPORT_NAME=createEmbed \
    -sENVIRONMENT=web -sALLOW_MEMORY_GROWTH=1 -sFORCE_FILESYSTEM=1 \
    -sEXPORTED_RUNTIME_METHODS=FS,cwrap \
    -sEXPORTED_FUNCTIONS=_embed_init,_embed_open,_embed_process,_libpd_start_message,_libpd_add_float,_libpd_add_symbol,_libpd_finish_message,_malloc,_free \
    -o embed.js
echo "built embed.js, embed.wasm: serve this folder (python3 -m http.server --bind 127.0.0.1) and open it"
