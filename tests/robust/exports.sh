#!/bin/sh
# aero: an external (or the single-binary library) exports only Pd's entry
# points, the *_setup functions. Pd loads externals with RTLD_GLOBAL, so
# any other exported name could bind to another library's code (two aero
# versions, or a library with the same names). Reads each binary's dynamic
# symbol table (ELF: nm -D), export table (PE/Windows DLL: objdump -p) or
# external symbols (Mach-O, macOS: llvm-nm).
# Usage: exports.sh BINARY...; prints each binary's exports other than
# *_setup and exits 1 if there are any (2: no such file, no setup).
set -u
OBJDUMP=${OBJDUMP:-objdump}
bad=0
for f in "$@"; do
    [ -f "$f" ] || { echo "exports: no binary $f (build first)" >&2; exit 2; }
    case $f in
    *.d_* | *.darwin-*.so)
        # Mach-O (both slices of a universal binary): the external symbols
        # it defines
        names=$(llvm-nm-14 -g --defined-only -j "$f" | grep -v -e ':$' -e '^$' | sort -u) ;;
    *.dll)
        # the export table: lines "[Ordinal/Name Pointer] Table" then
        # "\t[   0] name"
        names=$($OBJDUMP -p "$f" | sed -n 's/^[[:space:]]*\[ *[0-9]*\] \([^ ]*\)$/\1/p') ;;
    *)
        names=$(nm -D --defined-only "$f" | awk 'NF == 3 { print $3 }') ;;
    esac
    echo "$names" | grep -q '_setup$' ||
        { echo "exports: $f exports no *_setup" >&2; exit 2; }
    extra=$(echo "$names" | grep -v -e '_setup$' -e '^$')
    if [ -n "$extra" ]; then
        bad=1
        echo "$f exports $(echo "$extra" | wc -l) names besides *_setup:" \
            "$(echo "$extra" | head -5 | tr '\n' ' ')..."
    fi
done
exit $bad
