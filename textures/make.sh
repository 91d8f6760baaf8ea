#!/bin/sh
# aero: remakes the shipped sound textures (`make textures`).
# Each command here is also listed in textures/README.md; run from anywhere.
set -e
cd "$(dirname "$0")/.."
T=build/aerotex
if [ ! -x "$T" ]; then
    echo "textures/make.sh: $T is missing: run 'make tools' first" >&2
    exit 1
fi
# idle OpenMP threads sleep instead of spinning (textures/README.md)
OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
export OMP_WAIT_POLICY
# Two lanes of one thread each, run side by side: each direction's flow is
# one thread's work, so the long textures gain nothing from a second thread
# that a second lane does not, and a lane has no idle thread while another
# texture's last direction finishes (the timings: textures/README.md). A
# texture is the same, bit for bit, at any number of threads. LANES=1 runs
# everything in turn with all threads.
LANES=${LANES:-2}
LOGS=build/textures
mkdir -p "$LOGS"

# circular cylinder, d = 1 cm at 10 m/s (Re ~ 6800), one direction, 24
# cells per diameter, corrected to a 3D cylinder (--span3d circle, default)
cylinder() {
    $T aeolian --shape circle --diameter 0.01 --speed 10 --grid 24 \
        -o textures/cylinder.wav
}
# square prism, side 1 cm at 10 m/s, 8 directions over 0-45 deg, 24 cells
# per side; from 2D to 3D by the k-omega turbulence model (--span3d urans:
# the circle-calibrated correction moves the square's St the wrong way,
# textures/README.md), band limited at what the grid resolves
square() {
    $T aeolian --shape square --diameter 0.01 --speed 10 --directions 8 \
        --grid 24 --span3d urans --duration 0.1 -o textures/square.wav
}
# sword blade (lenticular 40 mm x 5 mm) at 10 m/s, every 10 deg over 0-90
# deg, 4 cells across the blade; stalled (30-90 deg) by the k-omega
# turbulence model, which sheds steadily where the laminar flow bursts
# (clicks), and nearly edge-on (0-20 deg) laminar, where the model would
# damp the thin wake's shedding away; band limited at what the grid
# resolves (the grid's bursts); 0.1 s (textures/README.md)
sword() {
    $T aeolian --shape polygon textures/sword.poly --diameter 0.04 \
        --speed 10 --symmetry 2 --mirror --directions 10 --grid 32 \
        --settle 20 --duration 0.1 --span3d urans --urans-from 30 \
        -o textures/sword.wav
}
# cavity 2 cm long, 1 cm deep in a wall, flow at 10 m/s
cavity() {
    $T cavity --length 0.02 --depth 0.01 --speed 10 --grid 48 \
        -o textures/cavity.wav
}
# fire / jet vortex sound (Dobashi et al. 2004): a 10 cm box of turbulent
# air, 8 average speeds 1..16 m/s, Howe's vortex sound at 1 m, one channel
# each
fire() {
    $T vortex --speeds 1,2,3,4,6,8,12,16 --box 0.1 --grid 32 --duration 0.5 \
        --rate 32000 --extend 14000 \
        -o textures/fire.wav
}
# 3D object textures (Dobashi et al. 2003, 3D case): the paper's sphere
# (radius 5 cm) from a 3D flow at 16.8 cells per diameter, its time axis
# calibrated to the subcritical sphere's St 0.2 (--calibrate sphere, the
# default for a sphere; textures/README.md)
sphere() {
    $T object --shape sphere --radius 0.05 --speed 10 --grid 16.8 \
        --duration 0.6 --limiter off -o textures/sphere.wav
}
# and a club (handle 12.5 mm, tip 30 mm, 0.8 m) with 10 regions and 5 flow
# directions from its axis (0, 45, 90, 135, 180 deg) by strip theory over
# the cylinder texture's section (made first)
club() {
    $T object --shape club --handle 0.0125 --tip 0.03 --length 0.8 \
        --sources 10 --directions 5 --speed 10 --duration 1 --method strip \
        --section textures/cylinder.wav -o textures/club.wav
}

# LANE NAME TEXTURE...: the textures in turn with one thread, into the
# lane's log
lane() {
    name=$1
    shift
    (
        OMP_NUM_THREADS=1
        export OMP_NUM_THREADS
        set -x
        for t in "$@"; do
            $t || exit 1
        done
    ) >"$LOGS/$name.log" 2>&1
}

if [ "$LANES" = 1 ]; then
    set -x
    cylinder
    square
    sword
    cavity
    fire
    sphere
    club
    exit 0
fi
# the lanes balanced by their CPU times at one thread (textures/README.md):
# 1139 s and 1173 s measured
echo "textures/make.sh: two lanes, one thread each (about 19 min on an idle" \
    "2-core machine); progress in $LOGS/a.log and $LOGS/b.log"
lane a square cylinder cavity fire &
a=$!
lane b sword sphere &
b=$!
status=0
wait $a || status=1
wait $b || status=1
cat "$LOGS/a.log" "$LOGS/b.log"
if [ $status -ne 0 ]; then
    echo "textures/make.sh: a lane failed (its log above)" >&2
    exit 1
fi
set -x
club
