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
"  aerotex info FILE.wav\n"
"      prints a texture's metadata and flow statistics\n"
"\n"
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
    if (!strcmp(argv[1], "info"))
        return aerotex_info(argc - 1, argv + 1);
    if (!strcmp(argv[1], "field-demo"))
        return aerotex_field_demo(argc - 1, argv + 1);
    if (!strcmp(argv[1], "auralize"))
        return aerotex_auralize(argc - 1, argv + 1);
    aerotex_error("unknown command '%s' (try 'aerotex help')", argv[1]);
    return 2;
}
