# aero: libsndfile 1.2.0 for platforms/deps.sh (sourced by it: CC, CFLAGS,
# AR, JOBS and P are set), without external codecs (FLAC, Vorbis, Opus,
# MPEG: their files compile to stubs). Not its CMake (minutes of checks
# for a cross host, and it wants a C++ compiler the library does not use):
# a config.h written here, and the library's sources compiled, the list of
# its CMakeLists.txt (add_library (sndfile ...)).

sndfile_config() { # config.h on stdout
    cat <<'EOF2'
/* written by aero's platforms/deps/sndfile.sh, not by libsndfile's CMake */
#define PACKAGE "libsndfile"
#define PACKAGE_NAME "libsndfile"
#define PACKAGE_TARNAME "libsndfile"
#define PACKAGE_VERSION "1.2.0"
#define PACKAGE_STRING "libsndfile 1.2.0"
#define PACKAGE_BUGREPORT "sndfile@mega-nerd.com"
#define PACKAGE_URL "http://libsndfile.github.io/libsndfile/"
#define VERSION "1.2.0"
#if __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "aero's libsndfile config.h knows little-endian targets only"
#endif
#define CPU_IS_LITTLE_ENDIAN 1
#define CPU_IS_BIG_ENDIAN 0
#define WORDS_BIGENDIAN 0
/* the portable float-to-int conversions (no CPU-specific clipping) */
#define CPU_CLIPS_POSITIVE 0
#define CPU_CLIPS_NEGATIVE 0
#define COMPILER_IS_GCC 1
#define ENABLE_EXPERIMENTAL_CODE 0
#define HAVE_EXTERNAL_XIPH_LIBS 0
#define HAVE_MPEG 0
#define HAVE_SQLITE3 0
#define HAVE_ALSA_ASOUNDLIB_H 0
#define HAVE_SNDIO_H 0
#define OSX_DARWIN_VERSION 0
#define OS_IS_OPENBSD 0
#define WIN32_TARGET_DLL 0
#define HAVE_CALLOC 1
#define HAVE_MALLOC 1
#define HAVE_REALLOC 1
#define HAVE_FREE 1
#define HAVE_CEIL 1
#define HAVE_FLOOR 1
#define HAVE_FMOD 1
#define HAVE_LRINT 1
#define HAVE_LRINTF 1
#define HAVE_LROUND 1
#define HAVE_LIBM 1
#define HAVE_STDBOOL_H 1
#define HAVE_STDINT_H 1
#define HAVE_INTTYPES_H 1
#define HAVE_STDLIB_H 1
#define HAVE_STRING_H 1
#define HAVE_SYS_STAT_H 1
#define HAVE_SYS_TYPES_H 1
#define HAVE_SYS_TIME_H 1
#define HAVE_UNISTD_H 1
#define HAVE_LOCALE_H 1
#define HAVE_SETLOCALE 1
#define HAVE_SNPRINTF 1
#define HAVE_VSNPRINTF 1
#define HAVE_GETTIMEOFDAY 1
#define HAVE_FSTAT 1
#define HAVE_LSEEK 1
#define HAVE_OPEN 1
#define HAVE_READ 1
#define HAVE_WRITE 1
#define HAVE_GMTIME 1
#define HAVE_LOCALTIME 1
#define HAVE_SSIZE_T 1
#define SIZEOF_INT64_T 8
#define SIZEOF_INT __SIZEOF_INT__
#define SIZEOF_LONG __SIZEOF_LONG__
#define SIZEOF_LONG_LONG __SIZEOF_LONG_LONG__
#define SIZEOF_SHORT __SIZEOF_SHORT__
#define SIZEOF_FLOAT __SIZEOF_FLOAT__
#define SIZEOF_DOUBLE __SIZEOF_DOUBLE__
#define SIZEOF_SIZE_T __SIZEOF_SIZE_T__
#define SIZEOF_SSIZE_T __SIZEOF_SIZE_T__
#define SIZEOF_VOIDP __SIZEOF_POINTER__
#define SIZEOF_WCHAR_T __SIZEOF_WCHAR_T__
#if defined(__x86_64__)
#define HAVE_IMMINTRIN_H 1 /* sfconfig.h then uses SSE2's conversions */
#endif
#ifdef _WIN32
/* file_io.c's Windows half: 64-bit positions through the Windows API */
#define USE_WINDOWS_API 1
#define OS_IS_WIN32 1
#define HAVE_IO_H 1
#define HAVE_DIRECT_H 1
#define HAVE_DECL_S_IRGRP 0
#define SIZEOF_OFF_T 4
#else
#define USE_WINDOWS_API 0
#define OS_IS_WIN32 0
/* 64-bit file positions on 32-bit Linux (armv7) too */
#define _FILE_OFFSET_BITS 64
#define SIZEOF_OFF_T 8
#define HAVE_DECL_S_IRGRP 1
#ifndef __APPLE__ /* macOS has neither (its own is machine/endian.h) */
#define HAVE_BYTESWAP_H 1
#define HAVE_ENDIAN_H 1
#endif
#define HAVE_FSYNC 1
#define HAVE_FTRUNCATE 1
#define HAVE_GETPAGESIZE 1
#define HAVE_MMAP 1
#define HAVE_PIPE 1
#define HAVE_WAITPID 1
#define HAVE_SYS_WAIT_H 1
#define HAVE_GMTIME_R 1
#define HAVE_LOCALTIME_R 1
#define HAVE_DLFCN_H 1
#endif
EOF2
}

sndfile_build() { # PREFIX SRC
    obj="$2/obj"
    mkdir -p "$obj"
    sndfile_config >"$obj/config.h"
    # add_library (sndfile ...) of its CMakeLists.txt: the .c files listed
    # there, src/windows.c only for Windows
    sed -n '/^add_library (sndfile$/,/^\t)/p' "$2/CMakeLists.txt" |
        sed -n 's/^[[:space:]]*\(src\/[A-Za-z0-9_\/]*\.c\)$/\1/p' >"$obj/sources"
    case $P in windows-*) echo src/windows.c >>"$obj/sources" ;; esac
    [ "$(wc -l <"$obj/sources")" -gt 80 ] ||
        { echo "sndfile: the source list of CMakeLists.txt was not found" >&2; exit 1; }
    compile "$2" "$obj" -std=gnu99 -I"$obj" -Isrc -Iinclude <"$obj/sources"
    rm -f "$1/lib/libsndfile.a"
    (cd "$obj" && $AR rcs "$1/lib/libsndfile.a" ./*.o)
    cp "$2/include/sndfile.h" "$1/include/"
    echo "$(wc -l <"$obj/sources") files compiled for libsndfile.a"
}
