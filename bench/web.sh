#!/bin/sh
# aero: `make bench-web`: the cost of each web scene (web/scenes/*.pd) per
# 128-frame block (an AudioWorklet's render quantum; its budget at 48 kHz is
# 2.667 ms) in headless Chromium (the page's wasm Pd on the main thread,
# window.aero.blockCost: 2000 blocks after a second of warm-up) and natively
# in the same run (libpd 0.16.1 + native aero, tests/libpd/render.c: the
# time of an 11 s render minus a 1 s one, so loading is not counted), and
# their ratio. Run after `make web` and the native host of `make check-web`
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
now() { date +%s.%N; }
echo "| scene | Chromium (wasm), ms per 128 frames | native, ms per 128 frames | ratio | share of the 2.667 ms budget (Chromium) |"
echo "|---|---|---|---|---|"
for s in $(ls web/scenes/*.pd | sed 's|web/scenes/||; s|\.pd$||'); do
    t0=$(now); "$R" -data "$ROOT" -path "$ROOT/abstractions" -seconds 1 -settle 0 \
        "web/scenes/$s.pd" "$OUT/bench-$s.wav" 2>/dev/null; t1=$(now)
    "$R" -data "$ROOT" -path "$ROOT/abstractions" -seconds 11 -settle 0 \
        "web/scenes/$s.pd" "$OUT/bench-$s.wav" 2>/dev/null; t2=$(now)
    web=$(sed -n "s/^bench $s //p" "$OUT/bench-web.log")
    awk -v s="$s" -v a="$t0" -v b="$t1" -v c="$t2" -v w="$web" 'BEGIN {
        native = ((c - b) - (b - a)) * 1000 / (10 * 48000 / 128)
        printf "| %s | %.4f | %.4f | %.2f | %.1f %% |\n", s, w, native, w / native, 100 * w / 2.667 }'
done
