#!/bin/sh
# make demo: renders every scene in demo/*.pd with real Pd in batch mode
# into $DEMO_DIR (default build/demo/): a WAV per scene, its spectrogram
# (PNG, sox) and index.html, which lists the scenes with an audio player
# and the picture. Scenes use the abstractions and the shipped textures,
# so this works from a fresh clone after `make deps` and `make`.
set -e
ROOT=$(pwd)
DIR=${DEMO_DIR:-build/demo}
mkdir -p "$DIR"
total=$(ls demo/*.pd | wc -l)
k=0
{
    echo '<!DOCTYPE html>'
    echo '<html><head><meta charset="utf-8"><title>aero demo scenes</title>'
    echo '<style>body{font-family:sans-serif;max-width:1000px;margin:auto}'
    echo 'section{margin:2em 0}img{width:100%}</style></head><body>'
    echo '<h1>aero: the sound of moving air</h1>'
    echo '<p>Each scene was rendered by Pure Data in batch mode with'
    echo '<code>make demo</code>; its patch is in demo/.</p>'
} >"$DIR/index.html"
for scene in demo/*.pd; do
    name=$(basename "$scene" .pd)
    k=$((k + 1))
    printf 'demo: [%d/%d] %s ... ' "$k" "$total" "$name"
    cp "$scene" "$DIR/"
    rm -f "$DIR/$name.wav"
    (cd "$DIR" && timeout 600 "${PD:-pd}" -batch -nogui -noaudio -noprefs \
        -stderr -nostdpath -r "${PD_RATE:-44100}" -path "$ROOT" -path "$ROOT/abstractions" \
        -path "$ROOT/demo/lib" -open "$name.pd" >"$name.log" 2>&1)
    if [ ! -s "$DIR/$name.wav" ]; then
        echo "did not render, see $DIR/$name.log" >&2
        exit 1
    fi
    sox -V1 "$DIR/$name.wav" -n spectrogram -x 1200 -y 513 -z 90 \
        -t "aero: $name" -o "$DIR/$name.png"
    echo "$(soxi -d "$DIR/$name.wav" 2>/dev/null) -> $DIR/$name.wav, $name.png"
    # the scene's description: its comment box
    about=$(sed -n 's/^#X text [0-9]* [0-9]* \(.*\), f [0-9]*;$/\1/p' "$scene" |
        head -n 1 | sed 's/ \\,/,/g; s/\\;/;/g; s/&/\&amp;/g; s/</\&lt;/g')
    {
        echo "<section><h2>$name</h2><p>$about</p>"
        echo "<audio controls preload=\"none\" src=\"$name.wav\"></audio>"
        echo "<img src=\"$name.png\" alt=\"spectrogram of $name\"></section>"
    } >>"$DIR/index.html"
done
echo '</body></html>' >>"$DIR/index.html"
echo "demo: open $DIR/index.html in a browser"
