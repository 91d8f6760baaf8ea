/* aerotex aeolian: the texture of a stick's cross-section (circle,
 * square, ellipse or a polygon), its options; the run is
 * aerotex_section.c's. */
#include "aerotex_section.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* --shape circle|square|ellipse|polygon FILE */
static int parse_shape(void *job, const char *cmd, int argc, char **argv,
                       int *i)
{
    aeolian_job *j = job;
    if (*i + 1 >= argc) {
        aerotex_error("%s: --shape needs circle, square, ellipse or polygon "
                      "FILE", cmd);
        return -1;
    }
    j->shape_name = argv[++*i];
    if (!strcmp(j->shape_name, "polygon")) {
        if (*i + 1 >= argc) {
            aerotex_error("%s: --shape polygon needs a FILE", cmd);
            return -1;
        }
        j->poly_file = argv[++*i];
    } else if (strcmp(j->shape_name, "circle") &&
               strcmp(j->shape_name, "square") &&
               strcmp(j->shape_name, "ellipse")) {
        aerotex_error("%s: unknown shape '%s' (circle, square, ellipse, "
                      "polygon FILE)", cmd, j->shape_name);
        return -1;
    }
    return 0;
}

static const aerotex_option aeolian_options[] = {
    {"--shape", AEROTEX_CUSTOM, "circle|square|ellipse|polygon FILE", NAN, 0,
     0, 0, "the cross-section (polygon: textures/README.md)",
     "circle", parse_shape},
    {"--diameter", AEROTEX_NUMBER, "m", 0.01, 1e-5, 10.0, AT(d),
     "reference size d: diameter, side, major axis or\nthe polygon's x "
     "extent", NULL, NULL},
    {"--aspect", AEROTEX_NUMBER, "a", 0.5, 0.01, 1.0, AT(aspect),
     "ellipse minor/major axis ratio", NULL, NULL},
    {"--directions", AEROTEX_WHOLE, "N", 1.0, 1.0, 360.0, AT(directions),
     "sampled flow directions", NULL, NULL},
    {"--symmetry", AEROTEX_WHOLE, "K", -1.0, 1.0, 64.0, AT(symmetry),
     "the shape repeats every 360/K deg", "square 4, ellipse 2, polygon 1",
     NULL},
    {"--mirror", AEROTEX_SWITCH, NULL, -1.0, 1, 0, AT(mirror),
     "the shape is mirror-symmetric about its x axis",
     "yes for square and ellipse", NULL},
    {"--no-mirror", AEROTEX_SWITCH, NULL, NAN, 0, 0, AT(mirror),
     "it is not", NULL, NULL},
    {"--span3d", AEROTEX_CHOICE, "none|circle|urans", 1.0, 0, 0, AT(span3d),
     "2D section to 3D body above Re 190: circle: frequencies\nand force "
     "scaled by the 2D circle's error at this Re\nand grid against Roshko's "
     "St and Norberg's C_L';\nurans: the turbulence as an eddy viscosity "
     "(Wilcox's\nk-omega, Kato and Launder's production)\n"
     "(textures/README.md)", NULL, NULL},
    {"--urans-from", AEROTEX_NUMBER, "deg", 0.0, 0.0, 90.0, AT(urans_from),
     "with --span3d urans: directions at a smaller\nincidence to the x "
     "axis run laminar (a thin\nedge-on wake the model would damp)", NULL,
     NULL},
    {"--band-limit", AEROTEX_CHOICE, "grid|off", 0.0, 0, 0, AT(band_limit),
     "with --span3d urans: grid: every channel low-passed\n(cyclic, zero "
     "phase) from v0/(16 h) to v0/(8 h), h the\ncell: the band the grid "
     "resolves; off: not", NULL, NULL},
    {"--stretch", AEROTEX_NUMBER, "r", 1.1, 1.0, 1.2, AT(stretch),
     "rows beyond 2 d of the body grow by r each\n(1: a uniform grid)",
     NULL, NULL},
    FLOW_OPTIONS(16.0, -1.0, "30, 100 below Re 300")};

static void aeolian_init(void *job)
{
    aeolian_job *j = job;
    j->shape_name = "circle";
}

static int run_aeolian(int argc, char **argv)
{
    return aerotex_section_run(&aerotex_aeolian_command, argc, argv);
}

const aerotex_command aerotex_aeolian_command = {
    "aeolian", "--shape <circle|square|ellipse|polygon FILE> -o FILE.wav",
    "sound texture of the aeolian tone of a stick: 2D incompressible flow\n"
    "past its cross-section, g = dF/dt of the force per unit span",
    aeolian_options, sizeof(aeolian_job), aeolian_init, run_aeolian};
