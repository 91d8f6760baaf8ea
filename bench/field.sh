#!/bin/sh
# aero: field auralization benchmark (Shin and Bajaj; called by `make bench`).
# The paper's table (SGI Onyx2): preprocessing 6200 s per frame per source
# type at 64^3, 236 us per audio sample. Targets: <= 0.1 s per frame,
# <= 2 us per sample. Measured with `aerotex auralize` on the synthetic
# burst: preprocessing per frame (all three types at once; computing only,
# and with reading the frame files), and rendering per sample while the
# burst is heard, the chunk polynomials against the per-sample sum of the
# same sources (the paper's algorithm) in the same run. Best of 3 runs, in
# processor time (the machine is shared: wall time would count others).
set -e
cd "$(dirname "$0")/.."
T=build/aerotex
OUT=build/bench
mkdir -p "$OUT"
[ -x "$T" ] || { echo "bench/field.sh: build $T first (make tools)" >&2; exit 1; }

echo "## Field auralization (aerotex auralize): $(date -u +%Y-%m-%d)"
printf '0 2 0.3 0.2\n' >"$OUT/field-path.txt"

# best VALUE of the line matching PATTERN (field N) over 3 runs of ARGS
best_of3() { # PATTERN FIELD ARGS...
    pat=$1 field=$2
    shift 2
    b=""
    for k in 1 2 3; do
        v=$("$T" "$@" | grep "$pat" | awk -v f="$field" '{ print $f }')
        b=$(echo "$b $v" | awk '{ m = $1; for (i = 2; i <= NF; i++) if ($i < m) m = $i; print m }')
    done
    echo "$b"
}

echo "preprocessing per frame, all three source types, computing only (ms):"
for n in 10 20 30 40 50 64; do
    ms=$(best_of3 "^preprocessing" 9 auralize --demo "$n" --path "$OUT/field-path.txt" \
        -q -o "$OUT/field.wav" | tr -d '(')
    echo "  ${n}^3: $ms ms"
done

"$T" field-demo --size 64 -q -o "$OUT/field64" >/dev/null
with_io=$(best_of3 "^preprocessing" 5 auralize "$OUT/field64" --path "$OUT/field-path.txt" \
    -q -o "$OUT/field.wav")
echo "64^3 from disk (48 frames of 1 MB), reading included: $with_io ms per frame" \
     "(target <= 100 ms; paper 6200 s per type)"
"$T" auralize "$OUT/field64" --path "$OUT/field-path.txt" -q -o "$OUT/field.wav" |
    sed 's/^/    /'

echo "rendering per sample while the burst is heard (us), 64^3, listener 2 m:"
for speed in 1000 250; do
    poly=$(best_of3 "^rendering" 11 auralize "$OUT/field64" --path "$OUT/field-path.txt" \
        --speed "$speed" -q -o "$OUT/field.wav")
    direct=$(best_of3 "^rendering" 11 auralize "$OUT/field64" --path "$OUT/field-path.txt" \
        --speed "$speed" --direct -q -o "$OUT/field-direct.wav")
    echo "  speed $speed frames/s: chunk polynomials $poly us, per-sample sum" \
         "$direct us (ratio $(echo "$poly $direct" | awk '{ printf "%.2f", $1 / $2 }');" \
         "target <= 2 us; paper 236 us)"
done
