/* aerotex: sound textures of moving air from a 2D flow solver.
 * Paper 000 (Dobashi et al. 2003): the sound source function g = dF/dt of
 * an object is precomputed by fluid simulation and stored as a texture;
 * real-time objects only read it. See textures/README.md. */
#include "aerotex.h"
#include "texture.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void aerotex_error(const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "aerotex: ");
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\n");
}

static void usage(FILE *f)
{
    fprintf(f,
"usage: aerotex <command> [options]\n"
"\n"
"  aerotex aeolian --shape <circle|square|ellipse|polygon FILE> -o FILE.wav\n"
"      sound texture of the aeolian tone of a stick: 2D incompressible flow\n"
"      past its cross-section, g = dF/dt of the force per unit span\n"
"      --diameter <m>       reference size d: diameter, side, major axis or\n"
"                           the polygon's x extent (default 0.01)\n"
"      --aspect <a>         ellipse minor/major axis ratio (default 0.5)\n"
"      --speed <m/s>        base speed v0 (default 10)\n"
"      --re <Re>            Reynolds number v0 d / nu (default: air)\n"
"      --directions <N>     sampled flow directions (default 1)\n"
"      --symmetry <K>       the shape repeats every 360/K deg (default:\n"
"                           square 4, ellipse 2, polygon 1)\n"
"      --mirror, --no-mirror  the shape is mirror-symmetric about its x\n"
"                           axis (default: yes for square and ellipse)\n"
"      --duration <s>       texture length (default 0.2)\n"
"      --rate <Hz>          texture sample rate (default 16000)\n"
"      --grid <cells>       cells per reference size d (default 16)\n"
"      --settle <d/v0>      start-up discarded, in units of d/v0\n"
"                           (default 30, 100 below Re 300)\n"
"      --threads <n>        directions run in parallel (default: all cores)\n"
"      --png DIR            vorticity snapshots DIR/dirKK_NNNN.png\n"
"      -q                   no progress bar\n"
"\n"
"  aerotex cavity --length <m> --depth <m> --speed <m/s> -o FILE.wav\n"
"      sound texture of a cavity tone: 2D flow over a rectangular cavity in\n"
"      a wall, g = dF/dt of the force on its walls. Also --re, --duration,\n"
"      --rate, --grid (cells per length, default 48; coarser grids damp\n"
"      the shear layer and give no tone), --settle (default 80 L/v0), --png,\n"
"      -q\n"
"\n"
"  aerotex vortex --speeds <u1,...,uN> -o FILE.wav\n"
"      vortex-sound texture Q(u, t) of a turbulent box of air (fire, jets;\n"
"      paper 004): 3D incompressible flow with a randomly perturbed inflow\n"
"      at the bottom, periodic sides, open top; Howe's vortex sound at 1 m,\n"
"      one channel per speed (p = Q / r)\n"
"      --speeds <list>      increasing average speeds, m/s (default\n"
"                           1,2,3,4,6,8,12,16)\n"
"      --box <m>            box width, the source volume's size (default 0.1)\n"
"      --grid <n>           cells across the box, even (default 32)\n"
"      --height <n>         cells along the flow (default 1.5 grid)\n"
"      --duration <s>       texture length (default 0.5)\n"
"      --rate <Hz>          texture sample rate (default 16000)\n"
"      --extend <Hz>        spectral bandwidth extension (Chadwick & James\n"
"                           2011) from the resolved band up to this (1.1 x\n"
"                           it below rate / 2; default 0: off)\n"
"      --turbulence <i>     rms inflow perturbation / u (default 0.3)\n"
"      --confinement <eps>  vorticity confinement eps h / box (default 9.6)\n"
"      --cfl <c>            step = c h / u (default 0.5)\n"
"      --settle <n>         start-up discarded, flow-through times (default 3)\n"
"      --receivers <n>      virtual receivers on a ring (default 8)\n"
"      --elevation <deg>    of the ring (default 0)\n"
"      --source <window|cells>  Howe integral with a smooth window (default)\n"
"                           or the paper's integral cells (eq. 3-4)\n"
"      --seed <n>           turbulence seed (default 1)\n"
"      --threads <n>        speeds run in parallel (default: all cores)\n"
"      --png DIR            |vorticity| slices DIR/uKK_STEP.png\n"
"      -q                   no progress bar\n"
"\n"
"  aerotex object --shape <sphere|capsule|club> | --mesh FILE -o FILE.wav\n"
"      3D object texture (paper 000, 3D case): 3D incompressible flow past\n"
"      a body (immersed boundary), the force on each of n regions, g_l =\n"
"      dF_l/dt per sampled direction; played by [body~]\n"
"      --radius <m>         sphere (0.05) or capsule (0.02) radius\n"
"      --length <m>         capsule (0.3) or club (0.8) length\n"
"      --handle <m>, --tip <m>  club radii (0.0125, 0.03)\n"
"      --mesh FILE          a closed triangle mesh (v/f lines, OBJ subset;\n"
"                           see textures/README.md), axis z\n"
"      --sources <n>        regions: slices along the axis, sectors around\n"
"                           the flow for a sphere (default 1; club 10)\n"
"      --directions <N>     flow angles from the axis over 0..180 deg\n"
"                           (0..90 with --mirror, capsule default); 1 for a\n"
"                           sphere (default 1 sphere, 5 otherwise)\n"
"      --mirror, --no-mirror  the body is symmetric under z -> -z\n"
"      --speed <m/s>        base speed v0 (default 10)\n"
"      --grid <cells>       cells per reference size d (default 10)\n"
"      --duration <s>       texture length (default 0.5)\n"
"      --rate <Hz>          texture rate (default 4000: the 3D steps resolve\n"
"                           ~1 kHz)\n"
"      --settle <d/v0>      start-up discarded (default 25)\n"
"      --cfl <c>            step = c h / v0 (default 0.7)\n"
"      --threads <n>, --seed <n>, --png DIR, -q\n"
"\n"
"  aerotex info FILE.wav\n"
"      prints a texture's metadata and flow statistics\n"
"\n"
"  aerotex tree -o FILE.tree [--depth N] [--leaves N] [--seed N]\n"
"      a tree for [treebranch~] and [leafwave~]: a vertical trunk forking\n"
"      2-4 ways for N levels (depth 6: ~1160 branches), leaves spread over\n"
"      the outermost branches. Also --height <m> (trunk, default 2),\n"
"      --diameter <m> (trunk, default 0.2), --leaf-length <m> (0.08),\n"
"      --leaf-width <m> (0.05); defaults depth 4, 2000 leaves, seed 1\n"
"  aerotex tree --check FILE.tree\n"
"      reads a tree, reports bad lines with their numbers, prints its size\n"
"  aerotex field-demo -o DIR\n"
"      writes a synthetic volume (an expanding burst with turbulence) in the\n"
"      field volume format (src/core/field_volume.h): --size N (64),\n"
"      --frames N (48), --spacing m (0.02), --rate fps (1000),\n"
"      --shell-speed m/s (15), --velocity (also vx vy vz), --seed n, -q\n"
"\n"
"  aerotex auralize DIR --path FILE -o OUT.wav\n"
"      field auralization (paper 002): the sound of volume DIR heard along\n"
"      a listener path (lines 't x y z', seconds and metres, linear in\n"
"      between). --rate Hz (48000), --speed fps (the data's rate),\n"
"      --threshold M D Q (40 2e5 2e5), --zero f (1), --map IN_LO IN_HI\n"
"      RHO_LO RHO_HI (0 1 0 1), --log, --vscale k (1), --no-velocity,\n"
"      --gain dB, --duration s, --direct (per-sample reference sum),\n"
"      --demo [N] (the synthetic burst in memory instead of DIR), -q\n"
"\n"
"  aerotex help\n"
"      this text\n");
}

int aerotex_info(int argc, char **argv)
{
    aero_texture t;
    char err[512];
    const char *p;
    if (argc != 2) {
        aerotex_error("info takes one texture file");
        return 2;
    }
    if (aero_texture_load(argv[1], &t, err, sizeof err)) {
        aerotex_error("%s", err);
        return 1;
    }
    printf("file: %s\n", argv[1]);
    printf("frames=%d\nchannels=%d\nseconds=%.6g\n", t.frames, t.channels,
           t.frames / t.rate);
    /* every metadata line as it is stored */
    p = t.meta;
    while (p && *p) {
        const char *e = strchr(p, '\n');
        int n = e ? (int)(e - p) : (int)strlen(p);
        printf("%.*s\n", n, p);
        p = e ? e + 1 : NULL;
    }
    aero_texture_free(&t);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if (!strcmp(argv[1], "help") || !strcmp(argv[1], "--help") ||
        !strcmp(argv[1], "-h")) {
        usage(stdout);
        return 0;
    }
    if (!strcmp(argv[1], "aeolian"))
        return aerotex_aeolian(argc - 1, argv + 1, 0);
    if (!strcmp(argv[1], "cavity"))
        return aerotex_aeolian(argc - 1, argv + 1, 1);
    if (!strcmp(argv[1], "object"))
        return aerotex_object(argc - 1, argv + 1);
    if (!strcmp(argv[1], "vortex"))
        return aerotex_vortex(argc - 1, argv + 1);
    if (!strcmp(argv[1], "info"))
        return aerotex_info(argc - 1, argv + 1);
    if (!strcmp(argv[1], "tree"))
        return aerotex_tree(argc - 1, argv + 1);
    if (!strcmp(argv[1], "field-demo"))
        return aerotex_field_demo(argc - 1, argv + 1);
    if (!strcmp(argv[1], "auralize"))
        return aerotex_auralize(argc - 1, argv + 1);
    aerotex_error("unknown command '%s' (try 'aerotex help')", argv[1]);
    return 2;
}
