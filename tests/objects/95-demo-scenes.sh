# --- make demo: every scene renders, audible, finite, unclipped ------------
section "demo scenes (make demo) render in Pd"

if DEMO_DIR="$OUT/demo" sh tests/demo.sh >"$OUT/demo.log" 2>&1; then
    pass "make demo renders $(ls demo/*.pd | wc -l) scenes and index.html"
else
    fail "make demo"; tail -5 "$OUT/demo.log"
fi
for scene in demo/*.pd; do
    name=$(basename "$scene" .pd)
    # no NaN/Inf, no sample beyond 0 dBFS after the scene's make-up gain
    judge $ANALYZE finite "$OUT/demo/$name.wav" --max 1.0
    # audible: 1.0 = 94 dB on this scale; 40 dB is -54 dBFS rms
    judge $ANALYZE level "$OUT/demo/$name.wav" --min 40
    log_clean "$OUT/demo/$name.log" "scene $name: Pd log without errors"
done
if grep -q "<audio" "$OUT/demo/index.html" && [ -s "$OUT/demo/fence.png" ]; then
    pass "index.html lists the scenes with players and spectrograms"
else
    fail "index.html or the spectrograms are missing"
fi
