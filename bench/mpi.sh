#!/bin/sh
# make bench: aerotex over MPI ranks (build/aerotex-mpi; docs/cluster.md),
# the measured inputs of the cost model in docs/cluster.md:
# 1. the 3D flow's cost: cell-steps per second on one core (the sphere of
#    textures/make.sh at a coarse grid, short, --threads 1, CPU time), and
#    the steps of the shipped sphere's duration at 4 cells per d (steps
#    scale with the grid);
# 2. the task farm's strong scaling at N = 1 and 2 ranks (one thread
#    each): the sword of textures/make.sh at BENCH_SWORD_GRID cells per
#    chord (default 16), wall and CPU time, and the ranks' textures
#    compared with cmp (equal);
# 3. FFTW's MPI transposes of a sphere's spectrum (bench/mpi-transpose.c),
#    the pressure solve's exchange in slabs, at 1 and 2 ranks;
# 4. bench/mpi-model.sh's predictions from these figures.
# Skipped without build/aerotex-mpi and mpirun. Not a test: figures go to
# BENCHMARKS.md.
DIR=build/bench/mpi
mkdir -p "$DIR"
ROOT=$(pwd)
if [ ! -x build/aerotex-mpi ] || ! command -v mpirun >/dev/null 2>&1; then
    echo "bench/mpi.sh: no build/aerotex-mpi or mpirun (Open MPI: make deps)"
    exit 0
fi
G=${BENCH_SWORD_GRID:-16}
echo "aerotex-mpi (load $(cut -d' ' -f1-3 /proc/loadavg))"

# 1. cell-steps per second per core of the 3D flow
for g in 8 12; do
    /usr/bin/time -f "%U %e" -o "$DIR/sphere$g.time" build/aerotex object \
        --shape sphere --radius 0.05 --speed 10 --grid $g --duration 0.05 \
        --settle 0.5 --limiter off --threads 1 -q -o "$DIR/sphere$g.wav" \
        >"$DIR/sphere$g.txt" 2>/dev/null
    sed -n 's/.*grid \([0-9]*\) x \([0-9]*\) x \([0-9]*\), \([0-9]*\) steps.*/\1 \2 \3 \4/p' \
        "$DIR/sphere$g.txt" | {
        read -r nx ny nz steps
        read -r cpu _ <"$DIR/sphere$g.time"
        awk -v g=$g -v nx="$nx" -v ny="$ny" -v nz="$nz" -v s="$steps" -v c="$cpu" 'BEGIN {
            printf "  3D flow, sphere at %d cells per d: %d x %d x %d cells, %d steps, %.2f s CPU: %.3g cell-steps/s on one core\n",
                g, nx, ny, nz, s, c, nx * ny * nz * s / c }'
    }
done | tee "$DIR/r.txt"
build/aerotex object --shape sphere --radius 0.05 --speed 10 --grid 4 \
    --duration 0.6 --limiter off --threads 1 -q -o "$DIR/sphere4.wav" |
    sed -n 's/.*grid \([0-9]* x [0-9]* x [0-9]*\), \([0-9]*\) steps of \([0-9.]*\) ms.*/  the shipped sphere (--duration 0.6) at 4 cells per d: \1 cells, \2 steps of \3 ms/p' |
    tee -a "$DIR/r.txt"

# 2. the task farm: the sword section, N = 1 and 2 ranks, wall time and
#    each rank's CPU time (on a shared machine the wall time is an upper
#    bound; the largest rank's CPU time is what the farm's balance allows)
SWORD="aeolian --shape polygon $ROOT/textures/sword.poly --diameter 0.04 --speed 10 --symmetry 2 --mirror --directions 10 --grid $G --settle 20 --duration 0.1 --span3d urans --urans-from 30 --threads 1 -q -o sword.wav"
for n in 1 2; do
    mkdir -p "$DIR/np$n"
    rm -f "$DIR/np$n"/cpu.*
    # shellcheck disable=SC2086,SC2016
    (cd "$DIR/np$n" && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
        /usr/bin/time -f "%e" -o time mpirun --oversubscribe -np $n \
        sh -c '/usr/bin/time -f "%U %S" -o cpu.$OMPI_COMM_WORLD_RANK "$0" "$@"' \
        "$ROOT/build/aerotex-mpi" $SWORD >out.txt 2>&1)
    cpus=$(cat "$DIR/np$n"/cpu.* | awk '{ printf "%s%.1f", (NR > 1 ? " + " : ""), $1 + $2 }')
    echo "  sword, $G cells per chord, 10 directions, $n rank(s) x 1 thread: $(cat "$DIR/np$n/time") s wall, ranks' CPU $cpus s"
done
t1=$(cat "$DIR/np1/time") t2=$(cat "$DIR/np2/time")
c1=$(awk '{ print $1 + $2 }' "$DIR/np1/cpu.0")
c2=$(cat "$DIR/np2"/cpu.* | awk '{ c = $1 + $2; if (c > m) m = c } END { print m }')
awk -v a="$t1" -v b="$t2" -v c1="$c1" -v c2="$c2" 'BEGIN {
    printf "  wall: speed-up %.2f, efficiency %.0f %%; CPU (one rank / the largest of two): speed-up %.2f, efficiency %.0f %%\n",
        a / b, 50 * a / b, c1 / c2, 50 * c1 / c2 }'
cmp "$DIR/np1/sword.wav" "$DIR/np2/sword.wav" && echo "  the two textures are equal (cmp)"
echo "  load after: $(cut -d' ' -f1-3 /proc/loadavg)"

# 3. the pressure solve's exchange in slabs: FFTW's MPI transposes of the
#    sphere's spectrum at 24 cells per d (144 x 144 x 289), 2 ranks
if mpicc -std=c99 -O2 bench/mpi-transpose.c -o "$DIR/mpi-transpose" \
    -lfftw3f_mpi -lfftw3f -lm 2>"$DIR/transpose.log"; then
    for n in 1 2; do
        OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
            mpirun --oversubscribe -np $n "$DIR/mpi-transpose" 144 144 289 20
    done
else
    echo "  (no FFTW MPI library: libfftw3-mpi-dev)"
fi

# 3b. one 3D flow in slabs (object --slabs): the sphere at 12 cells per d,
#    one process, then 1 and 2 ranks of one thread; the samples compared
#    (the metadata holds the command line), the halo and transpose bytes
#    of a step from build/tests/flow3d-slab on the same grid
sargs="object --shape sphere --grid 12 --duration 0.1 --settle 0.5 --limiter off --threads 1 -q -o s.wav"
mkdir -p "$DIR/slab1" "$DIR/slab2" "$DIR/slab0"
# shellcheck disable=SC2086
(cd "$DIR/slab0" && /usr/bin/time -f "%e %U" -o time "$ROOT/build/aerotex" $sargs) >/dev/null 2>&1
for n in 1 2; do
    # shellcheck disable=SC2086
    (cd "$DIR/slab$n" && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
        /usr/bin/time -f "%e %U" -o time mpirun --oversubscribe -np $n \
        "$ROOT/build/aerotex-mpi" $sargs --slabs) >/dev/null 2>&1
done
echo "  the sphere's flow at 12 cells per d (72 x 72 x 145): one process $(cut -d' ' -f1 "$DIR/slab0/time") s wall; --slabs 1 rank $(cut -d' ' -f1 "$DIR/slab1/time") s, 2 ranks $(cut -d' ' -f1 "$DIR/slab2/time") s wall"
cmp -s "$DIR/slab1/s.wav" "$DIR/slab2/s.wav" && echo "  1 and 2 ranks' textures are equal (cmp)"
if [ -x build/tests/flow3d-slab ]; then
    for n in 2 4; do
        OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
            mpirun --oversubscribe -np $n build/tests/flow3d-slab 72 72 145 1e-12 \
            halo 2 10 2>/dev/null | sed 's/^/  /'
    done
fi

# 4. the cost model's predictions from the figures above (docs/cluster.md)
R=$(sed -n 's/.*12 cells per d.*: \([0-9.e+]*\) cell-steps.*/\1/p' "$DIR/r.txt")
STEPS4=$(sed -n 's/.*4 cells per d: .* cells, \([0-9]*\) steps.*/\1/p' "$DIR/r.txt")
echo
R=${R:-1.85e7} STEPS4=${STEPS4:-579} sh bench/mpi-model.sh | sed 's/^/  /'
