# aero: FFTW 3.3.10 for platforms/deps.sh (sourced by it: CC, CFLAGS, AR,
# JOBS and DOUBLE are set). Not FFTW's own configure (4 minutes for a cross
# host) and make (its tests and tools too): a config.h written here from
# the compiler's predefined macros, and only the library's folders
# compiled. On x86_64 its SSE2 codelets too (every x86_64 CPU has SSE2,
# FFTW needs no detection there): the scalar ones alone are 2-3 times
# slower for the c2r transforms aero runs per block. None on arm: FFTW
# 3.3.10 detects NEON with an ARMv7 instruction under a SIGILL handler
# (wrong on arm64, and a signal handler in a library Pd loads) and
# Debian's armhf baseline has no NEON.

fftw_config() { # PRECISION(single|double): config.h on stdout
    cat <<EOF
/* written by aero's platforms/deps/fftw.sh, not by FFTW's configure */
#define PACKAGE "fftw"
#define VERSION "3.3.10"
#define PACKAGE_VERSION VERSION
#define PACKAGE_STRING "fftw 3.3.10"
#define FFTW_CC "$CC $CFLAGS"
$( [ "$1" = single ] && echo "#define FFTW_SINGLE 1" && echo "#define BENCHFFT_SINGLE 1")
#define DISABLE_FORTRAN 1
#define FFTW_ENABLE_ALLOCA 1
#define HAVE_ALLOCA 1
$( [ "$P" = wasm ] || echo "#define HAVE_THREADS 1")
#define STDC_HEADERS 1
#define HAVE_STDDEF_H 1
#define HAVE_STDINT_H 1
#define HAVE_INTTYPES_H 1
#define HAVE_STDLIB_H 1
#define HAVE_STRING_H 1
#define HAVE_LIMITS_H 1
#define HAVE_SYS_TYPES_H 1
#define HAVE_SYS_TIME_H 1
#define HAVE_UNISTD_H 1
#define HAVE_GETTIMEOFDAY 1
#define HAVE_UINTPTR_T 1
#define HAVE_ABORT 1
#define HAVE_MEMSET 1
#define HAVE_MEMMOVE 1
#define HAVE_SQRT 1
#define HAVE_SNPRINTF 1
#define HAVE_LIBM 1
#define HAVE_DECL_SINL 1
#define HAVE_DECL_COSL 1
#define SIZEOF_INT __SIZEOF_INT__
#define SIZEOF_UNSIGNED_INT __SIZEOF_INT__
#define SIZEOF_LONG __SIZEOF_LONG__
#define SIZEOF_UNSIGNED_LONG __SIZEOF_LONG__
#define SIZEOF_LONG_LONG __SIZEOF_LONG_LONG__
#define SIZEOF_UNSIGNED_LONG_LONG __SIZEOF_LONG_LONG__
#define SIZEOF_VOID_P __SIZEOF_POINTER__
#define SIZEOF_SIZE_T __SIZEOF_SIZE_T__
#define SIZEOF_PTRDIFF_T __SIZEOF_PTRDIFF_T__
#define SIZEOF_FLOAT __SIZEOF_FLOAT__
#define SIZEOF_DOUBLE __SIZEOF_DOUBLE__
#define SIZEOF_FFTW_R2R_KIND 4
/* threads/threads.c: POSIX threads, else its win32 branch */
#ifndef _WIN32
#define USING_POSIX_THREADS 1
#define HAVE_ALLOCA_H 1
#define HAVE_POSIX_MEMALIGN 1
#else
/* SIMD wants 16-byte aligned buffers; Windows' C library has no
   posix_memalign: FFTW's own aligned malloc */
#define WITH_OUR_MALLOC 1
#endif
$( [ "$FFTW_SIMD" = sse2 ] && echo "#define HAVE_SSE2 1")
EOF
}

case $P in
linux-amd64|windows-amd64|darwin-amd64) FFTW_SIMD=sse2 ;;
*) FFTW_SIMD=none ;;
esac

FFTW_DIRS="kernel api dft dft/scalar dft/scalar/codelets rdft rdft/scalar
    rdft/scalar/r2cf rdft/scalar/r2cb rdft/scalar/r2r reodft threads"
# wasm: no threads. Without -pthread emscripten has none to offer (FFTW's
# threads.c does not link there: no pthread_attr_setscope), and the web
# module runs one Pd in one thread, so the planner lock aero asks for
# (fftwf_make_planner_thread_safe) has nothing to serialise: web/aero_web.c
# defines it as a no-op
[ "$P" = wasm ] && FFTW_DIRS=$(echo $FFTW_DIRS | sed 's/ threads$//')
# the SIMD codelets (stubs that include dft/simd/common/*.c) and the
# detection in simd-support/ (each file guarded by its HAVE_ macro)
[ "$FFTW_SIMD" = none ] ||
    FFTW_DIRS="$FFTW_DIRS dft/simd/$FFTW_SIMD rdft/simd/$FFTW_SIMD simd-support"

# one precision into PREFIX from the unpacked SRC: libfftw3f.a or libfftw3.a
fftw_one() { # PREFIX SRC PRECISION LIBNAME
    obj="$2/obj-$3"
    mkdir -p "$obj"
    fftw_config "$3" >"$obj/config.h"
    # the library's folders only; threads without its OpenMP variant, the
    # Fortran API left out (DISABLE_FORTRAN)
    (cd "$2" && for d in $FFTW_DIRS; do ls "$d"/*.c; done) |
        grep -v -e '^threads/openmp\.c$' -e 'f77' >"$obj/sources"
    compile "$2" "$obj" -I"$obj" -I. -Ikernel <"$obj/sources"
    rm -f "$1/lib/$4"
    (cd "$obj" && $AR rcs "$1/lib/$4" ./*.o)
    echo "$(wc -l <"$obj/sources") files compiled for $4"
}

fftw_build() { # PREFIX SRC
    fftw_one "$1" "$2" single libfftw3f.a
    if [ "$DOUBLE" = yes ]; then
        fftw_one "$1" "$2" double libfftw3.a
    fi
    cp "$2/api/fftw3.h" "$1/include/"
}

