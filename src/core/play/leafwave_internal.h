/* aero: what the parts of [leafwave~]'s core (leafwave.c and
 * leafwave_*.c) share: its constants and the functions one part calls in
 * another. Internal: only those files include it. */
#ifndef AERO_LEAFWAVE_INTERNAL_H
#define AERO_LEAFWAVE_INTERNAL_H

#include "leafwave.h"

#include <stddef.h>

#define WIND_REF 8.0          /* m/s: leaves reach ~tanh(1) of their sway */
#define FLUTTER_WIND 5.0      /* m/s: flutter rate doubles by this speed */
#define FLUTTER_DAMPING 0.3   /* zeta of a leaf's resonance */
#define SWAY_Y 0.7            /* longitudinal / lateral amplitude */
#define SWAY_R 0.5            /* free torsion / lateral amplitude */
#define DROOP 0.5             /* blade droop: tan of its angle below the stalk */
#define CONTACT_DEPTH 0.3     /* contact ellipsoid depth / blade half width */
#define RUB_SPEED_REF 0.5     /* m/s of sliding that plays a table at 1x */
#define RATE_MIN 0.25
#define RATE_MAX 2.0          /* tables hold content up to 0.45 fs / RATE_MAX */
#define HIT_ATTACK_S 0.001
#define HIT_DECAY_S 0.015
#define RELEASE_S 0.06        /* key off: slow decay (fig. 13) */
#define SILENT_PA 1e-7        /* a voice below this at 1 m is done */
#define DRY_CHUNK 256
#define STEAL_LOOK 8          /* voices looked at when all are busy */
#define BAND_OCTAVES_FACTOR 8.0 /* tables roll off above 8 f_i */
#define MIN_DISTANCE 0.1      /* m: 1/r is held below this */

static inline double clampd(double v, double lo, double hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* leafwave_tables.c */
int leafwave_replace_arrays(void **a, size_t a_bytes, void **b,
                            size_t b_bytes);
int leafwave_make_fft(aero_leafwave *lw);
void leafwave_free_fft(aero_leafwave *lw);
int leafwave_make_tables(aero_leafwave *lw);
void leafwave_reset_voices(aero_leafwave *lw);
void leafwave_key_on(aero_leafwave *lw, aero_leaf_pair *pr, int p, double frac,
                     double peak);
void leafwave_rub(aero_leafwave *lw, aero_leaf_pair *pr, int p, double vt);
void leafwave_key_off(aero_leafwave *lw, aero_leaf_pair *pr);
void leafwave_free_silent_voices(aero_leafwave *lw);
void leafwave_render_voices(aero_leafwave *lw, float *dry, int n);

/* leafwave_pairs.c */
int leafwave_build_pairs(aero_leafwave *lw);

/* leafwave_leaves.c */
void leafwave_free_leaves(aero_leafwave *lw);
void leafwave_build_leaves(aero_leafwave *lw);
void leafwave_leaf_frame(aero_leafwave *lw, double sway);

/* leafwave.c */
int leafwave_alloc_line(aero_leafwave *lw, double sr);
int leafwave_restart(aero_leafwave *lw, char *err, size_t errlen);

#endif
