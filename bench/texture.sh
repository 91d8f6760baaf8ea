#!/bin/sh
# aero: texture generation benchmark (called by `make bench`).
# Times `aerotex` on the paper's settings (Dobashi 2003: v0 = 10 m/s,
# d = 1 cm, Re ~ 6600; 45 min FEM on 4 CPUs, 1 h finite differences) and
# the sword set (5 deg directions over its symmetry). Targets: <= 60 s for
# the cylinder on one core, <= 10 min for the sword set (all cores).
set -e
cd "$(dirname "$0")/.."
T=build/aerotex
OUT=build/bench
mkdir -p "$OUT"
[ -x "$T" ] || { echo "bench/texture.sh: build $T first (make tools)" >&2; exit 1; }

stamp() { date +%s.%N; }
elapsed() { echo "$1 $2" | awk '{ printf "%.1f", $2 - $1 }'; }

echo "## Texture generation (aerotex): $(nproc) cores, $(date -u +%Y-%m-%d)"

t0=$(stamp)
OMP_NUM_THREADS=1 $T aeolian --shape circle --diameter 0.01 --speed 10 \
    --grid 24 --threads 1 -q -o "$OUT/cylinder.wav" >"$OUT/cylinder.txt"
t1=$(stamp)
cyl=$(elapsed "$t0" "$t1")
echo "cylinder d = 1 cm, v0 = 10 m/s, 1 core: ${cyl} s (target <= 60 s;" \
     "paper 45 min FEM on 4 CPUs)"
sed 's/^/    /' "$OUT/cylinder.txt"

t0=$(stamp)
$T aeolian --shape polygon textures/sword.poly --diameter 0.04 --speed 10 \
    --symmetry 2 --mirror --directions 10 --grid 32 --settle 20 \
    --duration 0.1 --span3d urans --urans-from 30 -q -o "$OUT/sword.wav" \
    >"$OUT/sword.txt"
t1=$(stamp)
sw=$(elapsed "$t0" "$t1")
echo "sword set, 10 directions (10 deg over 0-90 deg), $(nproc) cores:" \
     "${sw} s (target <= 600 s; paper: hours)"
head -n 1 "$OUT/sword.txt" | sed 's/^/    /'

# --span3d urans (k-omega) against the laminar 2D flow on the same square
# prism, one direction, one core each, one after the other: the cost of
# the turbulence model, as a ratio measured in this run
square() {
    OMP_NUM_THREADS=1 $T aeolian --shape square --diameter 0.01 --speed 10 \
        --grid 24 --duration 0.05 --threads 1 --span3d "$1" -q \
        -o "$OUT/square-$1.wav" >"$OUT/square-$1.txt"
}
t0=$(stamp)
square none
t1=$(stamp)
square urans
t2=$(stamp)
lam=$(elapsed "$t0" "$t1")
ur=$(elapsed "$t1" "$t2")
echo "square prism, 24 cells, 0.05 s, 1 core: laminar ${lam} s," \
     "--span3d urans ${ur} s, ratio $(echo "$lam $ur" | awk '{ printf "%.2f", $2 / $1 }')"
grep "deg:" "$OUT/square-none.txt" "$OUT/square-urans.txt" | sed 's/^/    /'
