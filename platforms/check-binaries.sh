#!/bin/sh
# aero: what every binary of a staged platform folder must be, checked
# after `make platform` builds it:
#   sh platforms/check-binaries.sh PLATFORM BINARY...
# - it exports only Pd's entry points (*_setup: tests/robust/exports.sh)
# - it needs nothing but the system's C library and Pd: on Linux its
#   DT_NEEDED entries are libc, libm, libpthread, libdl or the loader; on
#   Windows its DLL imports are Windows' own (KERNEL32, msvcrt) and pd.dll;
#   on macOS the only library it links is /usr/lib/libSystem.B.dylib (Pd's
#   functions are looked up at load time; make check-macos checks more)
# Exits 1 naming each binary that is not.
set -u
P=$1
shift
case $P in
windows-*) OBJDUMP=x86_64-w64-mingw32-objdump ;;
*) OBJDUMP=objdump ;;
esac
export OBJDUMP
bad=0
sh "$(dirname "$0")/../tests/robust/exports.sh" "$@" || bad=1
for f in "$@"; do
    case $P in
    darwin*)
        # llvm-otool -L: the binary's own install name first (a dylib's
        # LC_ID_DYLIB), then the libraries it loads
        deps=$(llvm-otool-14 -L -arch all "$f" | grep '^[[:space:]]' |
            awk '{ print $1 }' | grep -v -x -e "$(basename "$f")" | sort -u)
        extra=$(echo "$deps" | grep -v -x -e /usr/lib/libSystem.B.dylib) ;;
    windows-*)
        deps=$($OBJDUMP -p "$f" | sed -n 's/^[[:space:]]*DLL Name: //p')
        extra=$(echo "$deps" | grep -v -i -x -e KERNEL32.dll -e msvcrt.dll -e pd.dll) ;;
    *)
        deps=$(readelf -d "$f" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
        extra=$(echo "$deps" | grep -v -e '^libc\.so' -e '^libm\.so' \
            -e '^libpthread\.so' -e '^libdl\.so' -e '^ld-linux') ;;
    esac
    if [ -n "$extra" ]; then
        bad=1
        echo "$f needs $(echo "$extra" | tr '\n' ' ')"
    fi
done
[ $bad -eq 0 ] && echo "$# binaries: only *_setup exported, only system libraries needed"
exit $bad
