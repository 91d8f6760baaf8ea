#!/bin/sh
# The cost model of docs/cluster.md, from the figures bench/mpi.sh
# measures (passed in the environment; defaults: the figures in
# BENCHMARKS.md):
#   R         3D flow cell-steps per second on one core
#   STEPS4    the shipped sphere's steps at 4 cells per d (steps grow
#             with the grid)
#   SWORD32   CPU seconds of the shipped sword (10 directions, 32 cells
#             per chord; BENCHMARKS.md: make textures)
# and a cluster's network (assumptions, not measured here):
#   BNODE     bytes per second a node injects (100 Gb/s: 12.5e9)
#   ALPHA     seconds per message (2e-6)
#   CORES     cores per node (64)
#   BMEM      bytes per second of an exchange inside a node, through
#             shared memory (20e9)
# Prints the predictions for the sword (task farm) and the sphere (the 3D
# flow decomposed in slabs, docs/cluster.md) on 64 and 256 cores.
R=${R:-1.85e7} STEPS4=${STEPS4:-579} SWORD32=${SWORD32:-811}
BNODE=${BNODE:-12.5e9} ALPHA=${ALPHA:-2e-6} CORES=${CORES:-64}
BMEM=${BMEM:-20e9}
awk -v r="$R" -v s4="$STEPS4" -v sw="$SWORD32" -v B="$BNODE" -v a="$ALPHA" \
    -v c="$CORES" -v M="$BMEM" 'function ceil(x) { return x == int(x) ? x : int(x) + 1 }
function hms(t) { return t < 3600 ? sprintf("%.0f min", t / 60) : sprintf("%.1f h", t / 3600) }
BEGIN {
    printf "inputs: %.3g cell-steps/s per core, %d steps at 4 cells per d, sword %g CPU s at 32 cells per chord\n", r, s4, sw
    printf "network: %.3g B/s per node, %.3g s per message, %d cores per node\n\n", B, a, c
    # the sword: 2D directions, one core each; 7 of its 10 directions run
    # k-omega at 2.9 x the cost of the 3 laminar ones (BENCHMARKS.md)
    unit = sw / (3 + 7 * 2.9)
    print "sword (task farm; a direction is one core; cost ~ G^3)"
    split("24 32 64 128", G, " ")
    for (gi = 1; gi <= 4; gi++) {
        g = G[gi]; f = (g / 32) ^ 3
        tmax = 2.9 * unit * f; total = sw * f
        for (di = 1; di <= 2; di++) {
            D = di == 1 ? 10 : 19
            tot = D == 10 ? total : total * 19 / 10
            for (pi = 1; pi <= 2; pi++) {
                P = pi == 1 ? 64 : 256
                wall = ceil(D / P) * tmax
                printf "  %2d cells per chord, %2d directions, %3d cores: %s wall (one core: %s), efficiency %.0f %%\n",
                    g, D, P, hms(wall), hms(tot), 100 * tot / (P * wall)
            }
        }
    }
    print ""
    print "sphere (the 3D flow in slabs over P ranks; cost ~ g^4)"
    split("48 64", S, " ")
    for (si = 1; si <= 2; si++) {
        g = S[si]; nx = 6 * g; ny = nx; nz = 12 * g + 1
        cells = nx * ny * nz; steps = s4 * g / 4
        one = cells * steps / r
        printf "  %d cells per d: %d x %d x %d = %.3g cells, %d steps, %.0f GB; one core %s\n",
            g, nx, ny, nz, cells, steps, 82 * cells / 1e9, hms(one)
        for (pi = 1; pi <= 4; pi++) {
            P = pi % 2 ? 64 : 256
            # pi 1, 2: a rank per core; 3, 4: a rank per 16 cores, its
            # threads inside (at the one-core rate: the ideal)
            t = pi <= 2 ? 1 : 16
            Pr = P / t
            # as implemented (src/tools/flow3d_slab.c): each rank steps
            # a window of its nz / Pr planes and H = 10 halo planes each
            # side (computed again, redundantly), and after the
            # projection receives the halo layers of u, v, w (H + 1 of
            # each) from its two neighbours, 4 bytes a value
            H = 10; nl = nz / Pr
            win = nl + 2 * H; if (win > nz) win = nz
            work = cells / (P * r)
            comp = work * win / nl
            halo = 2 * 3 * (H + 1) * 4 * nx * ny
            # the pressure solve: two transposes of the spectrum
            # ((nx/2+1) ny nz complex floats) between planes and z lines
            tr = 2 * 8 * (nx / 2 + 1) * ny * nz / Pr * (Pr - 1) / Pr
            n = P < c ? Pr : c / t                    # ranks per node
            off = P > c ? (P - c) / P : 0             # transposed off-node
            # a node: its two edge slabs send their halos off-node, the
            # rest inside it; the transposes off-node by the fraction off
            comm = (halo * (P > c)) / B + (n * halo - halo * (P > c)) / M \
                + n * tr * off / B + n * tr * (1 - off) / M \
                + (2 * 2 + 2 + 2 * (Pr - 1)) * a
            printf "    %3d cores (%d node%s), %3d ranks x %2d threads: %.2f MB a rank a step (halo %.2f, transposes %.2f), compute %.1f ms (%.1f of it halo planes) + exchange %.1f ms a step: %s wall, efficiency %.0f %%\n",
                P, ceil(P / c), (P > c ? "s" : ""), Pr, t, (halo + tr) / 1e6, halo / 1e6, tr / 1e6, 1e3 * comp, 1e3 * (comp - work), 1e3 * comm,
                hms(steps * (comp + comm)), 100 * work / (comp + comm)
        }
    }
}'
