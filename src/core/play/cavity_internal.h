/* aero: what the files of [cavity~]'s core share (cavity.c, the object;
 * cavity_model.c and cavity_texture.c, its two modes). Not for hosts:
 * they use cavity.h. */
#ifndef AERO_CAVITY_INTERNAL_H
#define AERO_CAVITY_INTERNAL_H

#include "cavity.h"

/* samples per chunk: the laws and the phase's steps are updated per chunk */
#define AERO_CAVITY_CHUNK 64

/* the distance of ear e from the opening, at least r_min (the near-field
   policy, aero_near_field: a closer ear is recorded in m->near) */
double aero_cavity_ear_distance(aero_cavity *m, int e, double r_min);

/* one chunk (n <= AERO_CAVITY_CHUNK) of each mode into out[0..n_ears-1]:
   u the sanitised speeds, u_mean their mean, u_end the last */
void aero_cavity_model_process(aero_cavity *m, const float *u,
                               float *const *out, int n, double u_mean,
                               double u_end);
void aero_cavity_texture_process(aero_cavity *m, const float *u,
                                 float *const *out, int n, double u_end);

#endif
