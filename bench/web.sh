#!/bin/sh
# aero: `make bench-web`: the cost of each web scene (web/scenes/*.pd) per
# 128-frame block (an AudioWorklet's render quantum; its budget at 48 kHz is
# 2.667 ms) in headless Chromium (the page's wasm Pd on the main thread,
# window.aero.blockCost: the fastest of 7 runs of 400 blocks after a second
# of warm-up, wall time) and natively in the same run (libpd 0.16.1 + native
# aero, tests/libpd/render.c: the CPU time of a 31 s render minus a 1 s one,
# so loading is not counted, the fastest of three each), and their ratio.
# The fastest runs: the least disturbed by other work on a loaded machine. Run after `make web` and the native host of `make check-web`
# (build/web-check/render-native). Prints a Markdown table.
ROOT=$(pwd)
OUT=build/web-check
R=$OUT/render-native
[ -x "$R" ] || { echo "bench-web: run make check-web first (no $R)" >&2; exit 1; }
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory build/web \
    >"$OUT/bench-server.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null' EXIT INT TERM
sleep 1
node tests/web/check.mjs "http://127.0.0.1:$port/" "$OUT" 1 bench-only \
    >"$OUT/bench-web.log" 2>&1 || { cat "$OUT/bench-web.log"; exit 1; }
# native: user + system CPU seconds of a render (the fastest of three),
# 1 s and 31 s of sound; their difference is 30 s of processing
cpu() { # SECONDS SCENE
    best=""
    for k in 1 2 3; do
        /usr/bin/time -f "%U %S" -o "$OUT/bench.time" "$R" -data "$ROOT" \
            -path "$ROOT/abstractions" -seconds "$1" -settle 0 \
            "web/scenes/$2.pd" "$OUT/bench-$2.wav" 2>/dev/null
        t=$(tail -n 1 "$OUT/bench.time" | awk '{ print $1 + $2 }')
        best=$(awk -v a="$best" -v b="$t" 'BEGIN { print (a == "" || b < a) ? b : a }')
    done
    echo "$best"
}
echo "| scene | Chromium (wasm), ms per 128 frames | native, ms per 128 frames | ratio | share of the 2.667 ms budget (Chromium) |"
echo "|---|---|---|---|---|"
for s in $(ls web/scenes/*.pd | sed 's|web/scenes/||; s|\.pd$||'); do
    t1=$(cpu 1 "$s")
    t3=$(cpu 31 "$s")
    web=$(sed -n "s/^bench $s //p" "$OUT/bench-web.log")
    awk -v s="$s" -v a="$t1" -v b="$t3" -v w="$web" 'BEGIN {
        native = (b - a) * 1000 / (30 * 48000 / 128)
        printf "| %s | %.4f | %.4f | %.2f | %.1f %% |\n", s, w, native, w / native, 100 * w / 2.667 }'
done
