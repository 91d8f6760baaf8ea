/* aero: the flow of textures/square.wav for the tests (textures/make.sh):
 * a 1 cm square prism in a 10 m/s wind (Re 6768), the texture's domain
 * (rows growing by 10 % beyond the body's band) and start-up (30 d/v0),
 * flow onto a face. Shared by tests/unit/test_urans.c and
 * tests/convergence/test_square_urans.c. */
#ifndef AERO_SQUARE_FLOW_H
#define AERO_SQUARE_FLOW_H

#include "aeolian_flow.h"
#include "shape2d.h"

#include <string.h>

/* 0, or -1 with err set; st holds the run's statistics */
static inline int square_flow(double grid, double duration, double rate,
                              int turbulence, aero_aeolian_flow_stats *st,
                              char *err, size_t errlen)
{
    aero_shape2d square;
    aero_aeolian_flow_params p;
    int r;
    memset(&p, 0, sizeof p);
    aero_shape2d_square(&square, 0.01);
    p.shape = &square;
    p.size = 0.01;
    p.speed = 10.0;
    p.re = 6768.0;
    p.grid = grid;
    p.cfl = 0.5;
    p.stretch = 1.1;
    p.settle = 30.0;
    p.duration = duration;
    p.angle = 0.0;
    p.turbulence = turbulence;
    r = aero_aeolian_flow_simulate(&p, rate, NULL, 0, 0, st, NULL, 1, NULL,
                                   err, errlen) != 0 ? -1 : 0;
    aero_shape2d_free(&square);
    return r;
}

#endif
