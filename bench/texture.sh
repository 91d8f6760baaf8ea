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
    --symmetry 2 --mirror --directions 19 --grid 20 --settle 20 \
    --span3d none -q -o "$OUT/sword.wav" >"$OUT/sword.txt"
t1=$(stamp)
sw=$(elapsed "$t0" "$t1")
echo "sword set, 19 directions (5 deg over 0-90 deg), $(nproc) cores:" \
     "${sw} s (target <= 600 s; paper: hours)"
head -n 1 "$OUT/sword.txt" | sed 's/^/    /'
