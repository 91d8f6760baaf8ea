#!/bin/sh
# make demo: renders the demo scenes with real Pd in batch mode into
# build/demo/ (WAV) with a spectrogram of each (PNG, sox).
set -e
ROOT=$(pwd)
DIR=build/demo
mkdir -p "$DIR"
for scene in demo/*.pd; do
    name=$(basename "$scene" .pd)
    cp "$scene" "$DIR/"
    (cd "$DIR" && timeout 600 pd -batch -nogui -noaudio -noprefs -stderr \
        -nostdpath -path "$ROOT" -open "$name.pd" >"$name.log" 2>&1)
    if [ ! -s "$DIR/$name.wav" ]; then
        echo "demo: $name did not render, see $DIR/$name.log" >&2
        exit 1
    fi
    sox -V1 "$DIR/$name.wav" -n spectrogram -x 1200 -y 513 -z 90 \
        -t "aero: $name" -o "$DIR/$name.png"
    echo "demo: $DIR/$name.wav ($(soxi -d "$DIR/$name.wav" 2>/dev/null)) and $DIR/$name.png"
done
