#!/bin/sh
# Makes docs/img/sword-top.png: make demo's sword scene (demo/sword.pd)
# before and after the airfoil self-noise band (issue 48), their
# spectrograms, and the one-third-octave levels of its fastest swing
# beside the model's (Brooks et al. 1989) for the blade at mid-swing.
#   sh docs/img/sword-top.sh BEFORE_TREE
# BEFORE_TREE: a checkout of the commit before the band, built with
# `make all lib` (e.g. git worktree add /tmp/before 026359f). Run from the
# repository root after `make all lib`; needs Pd, sox and ImageMagick.
set -e
before_tree=${1:?usage: sh docs/img/sword-top.sh BEFORE_TREE}
tmp=build/sword-top
mkdir -p "$tmp"
render() { # TREE DIR: demo/sword.pd rendered with TREE's objects into DIR
    mkdir -p "$2"
    cp demo/sword.pd "$2/"
    rm -f "$2/sword.wav"
    root=$(cd "$1" && pwd)
    (cd "$2" && timeout 600 "${PD:-pd}" -batch -nogui -noaudio -noprefs \
        -stderr -nostdpath -r 44100 -path "$root" -path "$root/abstractions" \
        -path "$root/demo/lib" -open sword.pd >sword.log 2>&1)
    [ -s "$2/sword.wav" ]
}
render "$before_tree" "$tmp/before"
render . "$tmp/after"
# the fastest swing: triggered 2.4 s after load, recorded from 0.1 s, 180
# ms long; its middle 60 ms (the tip at 87-100 % of its 22.8 m/s)
bands() { # WAV: each band's level, the mean power of both ears
    for fc in 200 250 315 400 500 630 800 1000 1250 1600 2000 2500 3150 \
        4000 5000 6300 8000 10000 12500 16000 20000; do
        lo=$(awk -v f="$fc" 'BEGIN { print f / 1.122462 }')
        hi=$(awk -v f="$fc" 'BEGIN { print f * 1.122462 }')
        for ch in 0 1; do
            build/aero-analyze band "$1" "$lo" "$hi" --ch $ch --skip 2.36 \
                --dur 0.06 | sed 's/.*: \([-0-9.]*\) dB.*/\1/'
        done | awk -v f="$fc" '{ p += 10^($1 / 10) } END {
            printf "%s %.2f\n", f, 10 * log(p / 2) / log(10) }'
    done
}
bands "$tmp/before/sword.wav" >"$tmp/before.txt"
bands "$tmp/after/sword.wav" >"$tmp/after.txt"
# the model at the ears for the blade at mid-swing (aero.swing~: 7 sources
# 0.2-1.0 m from the hand, omega = 150 deg x pi / (2 x 0.18 s), alpha 0,
# the blade in the plane z = 1.3, ears (+-0.09, 0, 1.6); the noise is the
# lift's dipole, vertical: power (0.3 / R^2)^2 at R), with the demo's
# make-up gain of 8
for i in 0 1 2 3 4 5 6; do
    r=$(awk -v i=$i 'BEGIN { print 0.2 + 0.8 * (i + 0.5) / 7 }')
    v=$(awk -v r="$r" 'BEGIN { print 150 * 3.14159265 / 180 * 3.14159265 / 0.36 * r }')
    build/aerotex airfoil --speed "$v" --alpha 0 --span 0.1142857 \
        --distance 1 --from 200 --to 20000 | grep -v '^#' |
        awk -v r="$r" '{ R2 = 0.0081 + (0.3 + r)^2 + 0.09
                         print $1, 10^($NF / 10) * (0.3 / R2)^2 }'
done | awk '{ p[$1] += $2 } END { for (k in p)
    printf "%.1f %.2f\n", k, 10 * log(p[k]) / log(10) + 20 * log(8) / log(10) }' |
    sort -n >"$tmp/model.txt"
for d in before after; do
    sox -V1 "$tmp/$d/sword.wav" -n spectrogram -x 1200 -y 513 -z 90 \
        -t "aero: make demo's sword, $d the model's band" -o "$tmp/$d.png"
done
pts() { # FILE: its levels joined by lines (ImageMagick closes a path)
    awk 'function X(f) { return 70 + (log(f) / log(10) - log(200) / log(10)) / 2 * 1080 }
         function Y(d) { if (d < -20) d = -20; return 380 - (d + 20) / 90 * 330 }
         { x = X($1); y = Y($2)
           if (NR > 1) printf "line %.1f,%.1f %.1f,%.1f ", px, py, x, y
           px = x; py = y }' "$1"
}
grid=
for f in 200 500 1000 2000 5000 10000 20000; do
    x=$(awk -v f=$f 'BEGIN { print 70 + (log(f) / log(10) - log(200) / log(10)) / 2 * 1080 }')
    grid="$grid line $x,50 $x,380"
done
for d in -20 0 20 40 60; do
    y=$(awk -v d=$d 'BEGIN { print 380 - (d + 20) / 90 * 330 }')
    grid="$grid line 70,$y 1150,$y"
done
font=$(fc-match -f '%{file}' 'DejaVu Sans')
convert -size 1200x430 xc:white -font "$font" -stroke '#dddddd' -draw "$grid" \
    -fill none -strokewidth 3 \
    -stroke '#888888' -draw "$(pts "$tmp/before.txt")" \
    -stroke '#d62728' -draw "$(pts "$tmp/after.txt")" \
    -stroke '#1f77b4' -strokewidth 2 \
    -draw "stroke-dasharray 8 5 $(pts "$tmp/model.txt")" \
    -stroke none -fill black -pointsize 14 \
    -annotate +70+30 "The fastest swing (edge first, 150 deg in 180 ms, tip 22.8 m/s): one-third-octave levels of its middle 60 ms, both ears (dB SPL, make-up gain 8)" \
    -annotate +55+400 "200 Hz" -annotate +410+400 "1 kHz" -annotate +735+400 "5 kHz" \
    -annotate +900+400 "10 kHz" -annotate +1100+400 "20 kHz" \
    -annotate +25+385 "-20" -annotate +40+312 "0" -annotate +32+238 "20" \
    -annotate +32+165 "40" -annotate +32+92 "60" \
    -fill '#888888' -annotate +700+70 "before: the texture alone (its band limit 1.1-2.3 kHz at the tip)" \
    -fill '#d62728' -annotate +700+90 "after: the texture and the model's band above it" \
    -fill '#1f77b4' -annotate +700+110 "Brooks et al. 1989 for the blade at mid-swing (its fastest)" \
    "$tmp/chart.png"
montage "$tmp/before.png" "$tmp/after.png" "$tmp/chart.png" -tile 1x3 \
    -geometry +0+4 docs/img/sword-top.png
echo "wrote docs/img/sword-top.png"
