/* aero: field auralization of time-varying volume data, the offline half
 * (the sources of sound in each frame; fieldsound.h plays them), after
 * Shin and Bajaj (Auralization I: vortex sound synthesis), made fast.
 *
 * 1. Acoustic mapping (Shin and Bajaj, sec. 3.2.2): the field value s
 *    (10^s if the data are logarithms) is mapped linearly from
 *    [in_lo, in_hi] onto an air density [rho_lo, rho_hi] (kg/m^3). The
 *    particle velocity is the volume's own velocity fields if it has them
 *    (a flow), else the paper's mapping v = vscale * grad(rho).
 * 2. Per vertex and frame, by plain central differences (no search, so
 *    O(vertices) per frame: milliseconds, not the paper's 6200 s at 64^3):
 *      monopole strength   |q|,  q = d rho/dt + div(rho v) with a flow
 *                          (the mass not carried in by the flow, i.e. the
 *                          continuity residual: a mass source), q = d rho/dt
 *                          with the gradient mapping (the paper's choice)
 *      dipole strength     |div d(rho v)/dt|            (eq. 13)
 *      quadrupole strength |d2(rho v_i v_j)/dx_i dx_j|  (eq. 14)
 * 3. Exclusive classification: a vertex is a monopole if its monopole
 *    strength passes its threshold; a dipole if the dipole strength passes
 *    while the monopole strength is ~0; a quadrupole if the quadrupole
 *    strength passes while both are ~0. "~0" is below `zero` times the
 *    threshold (zero = 1: the first type that passes wins).
 * 4. Finite source volumes (3.2.4.1): a sphere around each source point
 *    whose radius is the mean of its cut distances along the (up to) six
 *    edges: to where the strength crosses the threshold (linear), or half
 *    the edge when the neighbour is a source of the same type or is not cut.
 * 5. Pressure (eqs. 15-17): p = 1/(4 pi) SUM_k F_k(t - D_k/c0) dV_k / D_k
 *    over the source points whose radiation has reached the listener, the
 *    strengths F (times dV, zero where a vertex is not a source) cubically
 *    interpolated between frames (Catmull-Rom). Eq. 15 as printed uses
 *    d rho/dt, which is a mass rate (kg/m^3/s), not a wave-equation source:
 *    the monopole term here is dq/dt (kg/m^3/s^2, Lighthill's d q/dt), so
 *    that all three terms are in pascals. Dipole: d/dt div(rho v) (eq. 16),
 *    quadrupole: d2(rho v_i v_j)/dx_i dx_j (eq. 17), signed.
 *
 * Time: the data run at `rate` frames/s; playback at `speed` frames/s
 * compresses time by speed/rate, so a term with n time derivatives scales
 * by (speed/rate)^n (with a flow all three scale as ^2, since the velocity
 * is compressed too; with the gradient mapping 2, 1, 0). Thresholds are in
 * the data's own time (SI per second of data), independent of speed.
 *
 * Rendering: instead of evaluating every source at every sample (the
 * paper's 236 us per sample), each source adds, once per chunk of 64
 * samples, the polynomial (in sample index) of its interpolated strength
 * times its linearly varying 1/D to a chunk accumulator; the output is one
 * polynomial evaluation per sample. The per-sample sum is kept as the
 * reference (`direct`), for tests and the benchmark.
 *
 * Life cycle: aero_field_pre_* turns frames into aero_field_sources
 * (owning arrays), aero_fieldsound_* plays them. No globals. */
#ifndef AERO_FIELD_PREPARE_H
#define AERO_FIELD_PREPARE_H

#include "field_volume.h"

#include <stddef.h>

enum {
    AERO_FIELD_NONE,
    AERO_FIELD_MONOPOLE,
    AERO_FIELD_DIPOLE,
    AERO_FIELD_QUADRUPOLE
};

typedef struct aero_field_params {
    double in_lo, in_hi;    /* input range (after 10^ if log_input) */
    double rho_lo, rho_hi;  /* mapped air density range, kg/m^3 */
    int log_input;          /* the field holds log10 of the value */
    double vscale;          /* gradient mapping, m/s per kg/m^4 */
    int use_velocity;       /* use the volume's velocity fields if any */
    double threshold[3];    /* monopole kg/m^3/s, dipole and quadrupole
                               kg/m^3/s^2 (index type - 1) */
    double zero;            /* "~0" = below zero * threshold, 0..1 */
} aero_field_params;

/* ranges of the settings (the setters below and aero_field_params_check
   hold them) */
#define AERO_FIELD_SPAN_MIN 1e-30     /* the input range's least width */
#define AERO_FIELD_RHO_MIN 0.0        /* mapped density, kg/m^3 */
#define AERO_FIELD_RHO_MAX 1e6
#define AERO_FIELD_VSCALE_MAX 1e6     /* either way, m/s per kg/m^4 */
#define AERO_FIELD_THRESHOLD_MIN 0.0  /* excluded: a threshold is > 0 */
#define AERO_FIELD_THRESHOLD_MAX 1e30
#define AERO_FIELD_ZERO_MIN 0.0
#define AERO_FIELD_ZERO_MAX 1.0
/* defaults of the numbers a patch sets one at a time */
#define AERO_FIELD_VSCALE_DEFAULT 1.0
#define AERO_FIELD_ZERO_DEFAULT 1.0
#define AERO_FIELD_LOG_DEFAULT 0
#define AERO_FIELD_VELOCITY_DEFAULT 1

/* Identity mapping (input 0..1 -> 0..1 kg/m^3), vscale 1, velocity fields
 * used, thresholds 40, 2e5, 2e5 (suited to the demo burst), zero 1. */
void aero_field_params_default(aero_field_params *p);
/* 0 if usable, else -1 and a message (ranges, thresholds > 0, ...) */
int aero_field_params_check(const aero_field_params *p, char *err,
                            size_t errlen);
/* The setters: 0, or -1 with p unchanged when the values are out of the
 * ranges above. map: the input range in_lo..in_hi (not empty, either
 * order) to the density range rho_lo..rho_hi; threshold: monopole, dipole,
 * quadrupole, each in (AERO_FIELD_THRESHOLD_MIN, AERO_FIELD_THRESHOLD_MAX];
 * log and velocity: 0 or 1. */
int aero_field_params_set_threshold(aero_field_params *p, const double t[3]);
int aero_field_params_set_map(aero_field_params *p, double in_lo,
                              double in_hi, double rho_lo, double rho_hi);
int aero_field_params_set_zero(aero_field_params *p, double zero);
int aero_field_params_set_vscale(aero_field_params *p, double vscale);
int aero_field_params_set_log(aero_field_params *p, int on);
int aero_field_params_set_velocity(aero_field_params *p, int on);

typedef struct aero_field_sources {
    int count;             /* active vertices (a source in some frame) */
    int frames;
    double rate;           /* data frames per second */
    double min_distance;   /* 1/D is capped at 1/min_distance */
    int exponent[4];       /* speed exponent per type */
    float *pos;            /* 3 per source, m */
    int *vertex;           /* grid index of each source */
    float *g;              /* count * frames: F dV, data time, 0 = none */
    unsigned char *type;   /* count * frames: AERO_FIELD_* */
    int *first, *last;     /* frames where g != 0 */
    long points[4];        /* source points per type over all frames */
    double max_reach;      /* m: largest distance from the origin to a
                              source (for render lengths) */
} aero_field_sources;

void aero_field_sources_free(aero_field_sources *s);

/* --- preprocessing: frames in, sources out ----------------------------- */
typedef struct aero_field_entry {
    unsigned int vertex;
    float g;
    unsigned char type;
} aero_field_entry;

#define AERO_FIELD_RING 8 /* frames kept for the time differences */

typedef struct aero_field_pre {
    aero_volume_info info;
    aero_field_params par;
    size_t n;
    int pushed, q_done, emitted, flow;
    float *rho[AERO_FIELD_RING], *dv[AERO_FIELD_RING]; /* by frame % RING */
    float *q[AERO_FIELD_RING], *quad[AERO_FIELD_RING];
    double *work;
    float *vel[3], *tens[6], *strength[3];
    unsigned char *cls;
    aero_field_entry *entries;
    size_t count, cap;
    long points[4];
} aero_field_pre;

int aero_field_pre_init(aero_field_pre *p, const aero_volume_info *info,
                        const aero_field_params *par, char *err,
                        size_t errlen);
/* the next raw frame (info.fields * count floats); -1: out of memory */
int aero_field_pre_push(aero_field_pre *p, const float *raw, char *err,
                        size_t errlen);
/* after the last frame: the sources (the preprocessor may then be freed) */
int aero_field_pre_finish(aero_field_pre *p, aero_field_sources *out,
                          char *err, size_t errlen);
void aero_field_pre_free(aero_field_pre *p);

/* Read (or, with demo != NULL, synthesise) every frame and preprocess it.
 * progress(ctx, done, total) after each frame; non-zero from it cancels
 * (returns -1, err "cancelled"). */
typedef int (*aero_field_progress_fn)(void *ctx, int done, int total);
int aero_field_prepare(const aero_volume_info *info,
                       const aero_field_demo *demo,
                       const aero_field_params *par, aero_field_sources *out,
                       aero_field_progress_fn progress, void *ctx, char *err,
                       size_t errlen);

#endif
