/* aerotex cavity: the texture of a rectangular cavity in a wall, its
 * options; the run is aerotex_section.c's. */
#include "aerotex_section.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const aerotex_option cavity_options[] = {
    {"--length", AEROTEX_NUMBER, "m", 0.0, 1e-5, 10.0, AT(length),
     "the cavity's length along the flow", "", NULL},
    {"--depth", AEROTEX_NUMBER, "m", 0.0, 1e-5, 10.0, AT(depth),
     "its depth", "", NULL},
    /* the shear layer over the cavity starts as the boundary layer the
       wall brings: its thickness selects the mode (Gharib & Roshko 1987;
       Rowley et al. 2002), textures/README.md */
    {"--theta", AEROTEX_NUMBER, "m", 0.0, 0.0, 1.0, AT(theta),
     "momentum thickness of the laminar boundary layer\nthe wall brings "
     "to the inflow edge, 0.3 length\nupstream of the cavity (at most 0.1 "
     "length)", "0: none, it grows from the inflow edge", NULL},
    /* a cavity's shear layer starts as the wall's boundary layer, a cell
       or two thick: below ~48 cells per length the grid damps it and the
       flow stays steady (no Rossiter tone); its oscillation takes ~50-80
       L/v0 to grow from the seeding to its saturated level */
    FLOW_OPTIONS(48.0, 80.0, NULL)};

static void cavity_init(void *job)
{
    aeolian_job *j = job;
    j->cavity = 1;
    j->stretch = 1.0; /* its wall force sums rows of h: a uniform grid */
    j->directions = 1;
    j->symmetry = 1;
    j->mirror = 0;
}

static int run_cavity(int argc, char **argv)
{
    return aerotex_section_run(&aerotex_cavity_command, argc, argv);
}

const aerotex_command aerotex_cavity_command = {
    "cavity", "--length <m> --depth <m> --speed <m/s> -o FILE.wav",
    "sound texture of a cavity tone: 2D flow over a rectangular cavity in\n"
    "a wall, g = dF/dt of the force on its walls",
    cavity_options, sizeof(aeolian_job), cavity_init, run_cavity};
