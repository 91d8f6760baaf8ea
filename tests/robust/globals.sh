#!/bin/sh
# aero: no writable globals in src/, so that two Pd instances
# (libpd with PDINSTANCE, or two patches) never share mutable state
# through aero. Reads the symbol tables of the compiled objects of src/core
# and src/pd (objdump -t) and fails on any data object in a writable
# section (.data, .bss, COMMON, thread-local), file-static or not.
# Read-only tables are fine (.rodata, and .data.rel.ro: pointer tables
# that the loader relocates, then write-protects).
# Allowed, each for its reason:
#   *_class in src/pd   Pd's class pointer, written once by the setup
#                       function when the library loads; Pd shares classes
#                       between instances by design (m_pd.h), objects
#                       never write it.
#   aero_data_dir in src/pd/aero_pd.o  the data folder a libpd host sets
#                       once with aero_set_data_path() (aero.h), before
#                       opening patches; the one process setting of aero.
# (FFTW's planner is serialised by FFTW's own lock:
# src/core/common/aero_fftw.h.) Usage: globals.sh [OBJECT...] (default:
# build/core/*/*.o src/pd/*.o); exit 1 when a writable global appears. Run by
# `make check-globals` and by `make check` (tests/objects/96-globals.sh, with a negative control).
set -u
[ $# -eq 0 ] && set -- build/core/*/*.o src/pd/*.o
found=0
for obj in "$@"; do
    [ -f "$obj" ] || { echo "globals: no object $obj (build first)" >&2; exit 2; }
    bad=$(objdump -t "$obj" | awk -v obj="$obj" '
        # columns: address flags... section size name; the section is the
        # field before the size (the last but one)
        / O / {
            sec = $(NF - 2); name = $NF
            writable = (sec == ".data" || sec ~ /^\.data\./ || sec ~ /^\.bss/ ||
                        sec == "*COM*" || sec ~ /^\.tdata/ || sec ~ /^\.tbss/) &&
                       sec !~ /^\.data\.rel\.ro/
            if (!writable) next
            if (obj ~ /src\/pd\// && name ~ /_class$/) next
            if (obj ~ /src\/pd\/aero_pd\.o$/ && name == "aero_data_dir") next
            print obj ": " name " in " sec
        }')
    if [ -n "$bad" ]; then
        echo "$bad"
        found=1
    fi
done
[ "$found" -eq 0 ] && echo "globals: no writable global in $# object files"
exit $found
