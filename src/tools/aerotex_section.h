/* aerotex aeolian and cavity (aerotex_aeolian.c, aerotex_cavity.c) share
 * one job and one run: the flow past a 2D cross-section, one channel
 * triple per sampled flow direction, the directions simulated in
 * parallel (aerotex_section.c). */
#ifndef AEROTEX_SECTION_H
#define AEROTEX_SECTION_H

#include "aerotex.h"
#include "aeolian_flow.h"

#include <stddef.h>

typedef struct {
    aerotex_job job;
    int cavity;
    const char *shape_name, *poly_file;
    double d, aspect, v0, re, nu, grid, settle, cfl, stretch;
    double length, depth;
    double theta;         /* cavity: the inflow boundary layer's momentum
                             thickness, m (0: none) */
    double thin;          /* the section's thinnest frontal width, m */
    int directions, symmetry, mirror; /* symmetry, mirror: -1 by shape */
    int span3d;           /* SPAN3D_NONE, _CIRCLE (the circle-calibrated
                             2D-to-3D correction) or _URANS (k-omega) */
    aero_span3d correction; /* what the texture carries (span3d.h) */
    double urans_from;    /* --span3d urans: directions at a smaller
                             incidence to the x axis, deg, run laminar */
    int band_limit;       /* --span3d urans: BAND_LIMIT_GRID (every channel
                             band limited at what the grid resolves,
                             band_limit.h) or BAND_LIMIT_OFF */
    double band_pass, band_stop; /* its roll-off, Hz (0: none applied) */
    int blade;            /* a thin polygon: the texture says its section */
    double blade_chord, blade_te, blade_psi; /* m, m, deg */
} aeolian_job;

enum { SPAN3D_NONE, SPAN3D_CIRCLE, SPAN3D_URANS };
enum { BAND_LIMIT_GRID, BAND_LIMIT_OFF };

#define AT(field) offsetof(aeolian_job, field)
/* the options aeolian and cavity share */
#define FLOW_OPTIONS(grid_def, settle_def, settle_shown)                \
    {"--speed", AEROTEX_NUMBER, "m/s", 10.0, 1e-3, 1e4, AT(v0),         \
     "base speed v0", NULL, NULL},                                      \
    {"--re", AEROTEX_NUMBER, "Re", 0.0, 1.0, 1e6, AT(re),               \
     "Reynolds number v0 d / nu", "air", NULL},                         \
    {"--duration", AEROTEX_NUMBER, "s", 0.2, 1e-3, 10.0,                \
     AT(job.duration), "texture length", NULL, NULL},                   \
    {"--rate", AEROTEX_NUMBER, "Hz", 16000.0, 1000.0, 192000.0,         \
     AT(job.rate), "texture sample rate", NULL, NULL},                  \
    {"--grid", AEROTEX_NUMBER, "cells", grid_def, 4.0, 200.0, AT(grid), \
     "cells per reference size d", NULL, NULL},                         \
    {"--settle", AEROTEX_NUMBER, "d/v0", settle_def, 0.0, 1e4,          \
     AT(settle), "start-up discarded, in units of d/v0", settle_shown,  \
     NULL},                                                             \
    {"--cfl", AEROTEX_NUMBER, "c", 0.5, 0.05, 0.8, AT(cfl),             \
     "solver step factor", NULL, NULL},                                 \
    AEROTEX_JOB_OPTIONS("directions",                                   \
                        "vorticity snapshots DIR/dirKK_NNNN.png")

/* parses the command line into a job of cmd (aeolian or cavity), runs
   it: the exit status */
int aerotex_section_run(const aerotex_command *cmd, int argc, char **argv);

#endif
