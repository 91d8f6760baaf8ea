#!/bin/sh
# aero: writes tests/unit/bpm_figures.h, the curves of Brooks, Pope and
# Marcolini (1989) that test_airfoil_noise.c checks against, from the
# report's figures as digitized by the AcousticAnalogies.jl project
# (OpenMDAO, test/bpm_data/, Apache-2.0; the copy in
# ../shared/reference/bpm beside the clone). The numbers go into a header
# so that the test needs no file at run time (it runs under valgrind,
# wine and qemu from wherever). Run from the repository root:
#   sh tests/unit/bpm_figures.sh [dir]
set -e
dir=${1:-../shared/reference/bpm}
out=tests/unit/bpm_figures.h
{
    echo "/* aero: one-third-octave spectra (kHz, dB re 20 uPa) of Brooks, Pope"
    echo " * and Marcolini (1989), NASA RP-1218, as digitized by AcousticAnalogies.jl"
    echo " * (OpenMDAO, test/bpm_data/, Apache-2.0, copyright NASA 2023); figure 6"
    echo " * is the boundary layer over the chord (Rc in millions, thickness/chord)."
    echo " * Written by tests/unit/bpm_figures.sh from those CSV files, unchanged. */"
    for f in "$dir"/19890016302-figure*.csv; do
        base=$(basename "$f" .csv)
        case "$base" in
        *figure06-* | *figure1[12]-* | *figure2[68]-* | *figure3[89]-* | *figure4[58]-* | \
            *figure5[49]-* | *figure6[0569]-* | *figure9[189]-*) ;;
        *) continue ;;
        esac
        name=$(echo "${base#19890016302-}" | tr -c 'A-Za-z0-9\n' '_')
        echo "static const float ${name}[][2] = {"
        awk -F, 'NF == 2 { printf "    {%#.6gf, %#.6gf},\n", $1 + 0, $2 + 0 }' "$f"
        echo "};"
    done
} >"$out"
echo "wrote $out"
