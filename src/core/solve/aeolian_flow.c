/* aero: a 2D cross-section in a uniform flow, g = dF/dt per unit span
 * (see aeolian_flow.h). */
#include "aeolian_flow.h"
#include "aero_air.h"
#include "texture.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

double aero_aeolian_flow_thinnest(const aero_shape2d *shape)
{
    double thin = 1e300;
    for (int a = 0; a < 180; a++) {
        double w = aero_shape2d_frontal(shape, a * AERO_PI / 180.0);
        if (w < thin) thin = w;
    }
    return thin;
}

int aero_aeolian_flow_domain(const aero_aeolian_flow_params *p,
                             aero_flow2d_params *fp, char *err,
                             size_t errlen)
{
    double ext, thin;
    aero_flow2d_defaults(fp, p->re);
    fp->grid = p->grid;
    fp->cfl = p->cfl;
    if (p->cavity) {
        fp->xmin = -0.3;
        fp->xmax = 3.5;
        fp->ymin = -(p->depth / p->size) - 0.25;
        fp->ymax = 1.5;
        fp->spin = 0.15;
        fp->spin_time = 2.0;
        fp->inlet_theta = p->theta / p->size;
        return 0;
    }
    fp->turbulence = p->turbulence;
    ext = 2.0 * aero_shape2d_radius(p->shape) / p->size;
    if (ext > 1.5) { /* tall polygons: room around them */
        fp->xmin *= ext;
        fp->xmax *= ext;
        fp->ymin *= ext;
        fp->ymax *= ext;
    }
    if (p->stretch > 1.0) {
        /* the rows stay h tall over the body and its near wake, 2 d
           beyond it in every direction, and grow outside: from a 1.5 d to
           a 2.5 d band and from 5 % to 10 % growth, the 24-cell circle's
           St, rms lift and mean drag stay within 0.7 % of the uniform
           grid's (textures/README.md) */
        fp->stretch = p->stretch;
        fp->ycore = aero_shape2d_radius(p->shape) / p->size + 2.0;
    }
    thin = aero_aeolian_flow_thinnest(p->shape);
    if (thin * p->grid / p->size < 1.5) {
        snprintf(err, errlen, "the shape is %.3g cells thin at --grid %g: "
                 "use a finer --grid (at least %.0f)",
                 thin * p->grid / p->size, p->grid,
                 ceil(1.5 * p->size / thin));
        return -1;
    }
    return 0;
}

/* the recorded time after the start-up, d/v0: the loop search range, the
   cross-fade and the low-pass kernel's reach on both sides */
static double record_time(const aero_aeolian_flow_params *p, double rate)
{
    return (1.16 * p->duration + 48.0 / rate) * p->speed / p->size;
}

int aero_aeolian_flow_estimate(const aero_aeolian_flow_params *p, double rate,
                               aero_aeolian_flow_plan *plan, char *err,
                               size_t errlen)
{
    aero_flow2d_params fp;
    aero_flow2d probe;
    if (aero_aeolian_flow_domain(p, &fp, err, errlen) ||
        aero_flow2d_init(&probe, &fp, err, errlen))
        return -1;
    plan->nx = probe.nx;
    plan->ny = probe.ny;
    plan->dt = probe.dt;
    plan->t_end = p->settle + record_time(p, rate);
    /* the steps run at about 1.2 times the first step's size */
    plan->steps = (long)(plan->t_end / (0.85 * probe.dt));
    aero_flow2d_free(&probe);
    return 0;
}

/* the force history after the start-up: times (d/v0), force / (rho v0^2 d) */
typedef struct {
    double *t, *fx, *fy;
    int n, cap;
} history;

/* appends one recorded step, growing the arrays */
static int record(history *r, double t, double fx, double fy)
{
    if (r->n == r->cap) {
        int nc = r->cap ? 2 * r->cap : 4096;
        double *a = realloc(r->t, sizeof(double) * nc);
        if (a) r->t = a;
        a = realloc(r->fx, sizeof(double) * nc);
        if (a) r->fx = a;
        a = realloc(r->fy, sizeof(double) * nc);
        if (a) r->fy = a;
        if (!r->t || !r->fx || !r->fy || !a)
            return -1;
        r->cap = nc;
    }
    r->t[r->n] = t;
    r->fx[r->n] = fx;
    r->fy[r->n] = fy;
    r->n++;
    return 0;
}

/* settles and records the force until t_end: 0 or -1 */
static int run(const aero_aeolian_flow_params *p, aero_flow2d *s,
               double t_end, history *h, aero_aeolian_flow_hook hook,
               long every, void *ctx, char *err, size_t errlen)
{
    for (long step = 0; s->t < t_end; step++) {
        if (aero_flow2d_step(s)) {
            snprintf(err, errlen, "the solver diverged at t = %.4g s (%.0f "
                     "d/v0): try a finer --grid or a smaller --cfl",
                     s->t * p->size / p->speed, s->t);
            return -1;
        }
        if (s->t >= p->settle && record(h, s->t, s->fx, s->fy)) {
            snprintf(err, errlen, "out of memory");
            return -1;
        }
        if (hook && every > 0 && step % every == 0)
            hook(ctx, s, step);
    }
    return 0;
}

/* statistics of the coefficients Cd = 2 Fx, Cl = 2 Fy, and the St of the
   lift's spectral peak */
static void statistics(const history *h, aero_flowstats *st, double *st_peak)
{
    double *cd = malloc(sizeof(double) * (h->n + 1));
    double *cl = malloc(sizeof(double) * (h->n + 1));
    if (cd && cl) {
        for (int m = 0; m < h->n; m++) {
            cd[m] = 2.0 * h->fx[m];
            cl[m] = 2.0 * h->fy[m];
        }
        aero_flow2d_stats(h->t, cd, cl, h->n, st);
        /* no periodic lift (flow2d.h's St 0: no shedding, or too short
           a record): no spectral St either, rather than a peak of noise */
        *st_peak = st->st > 0.0 ? aero_spectral_st(h->t, cl, h->n, 0.02, 3.0)
                                : 0.0;
    }
    free(cd);
    free(cl);
}

/* g = dF/dt in N/(m s) at the texture rate: 0 or -1 */
static int resample(const aero_aeolian_flow_params *p, const history *h,
                    const aero_span3d *c, double rate, float *out, int stride,
                    int nout, char *err, size_t errlen)
{
    /* s per d/v0, and the force in N/m, as a 3D body's (span3d.h) */
    const double tunit = p->size / p->speed / c->frequency_scale;
    const double scale = AERO_RHO * p->speed * p->speed * p->size *
                         c->force_scale;
    const double t0 = 20.0 / rate;                           /* kernel reach */
    double *ts = malloc(sizeof(double) * (h->n + 1)), start;
    if (!ts) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    for (int m = 0; m < h->n; m++)
        ts[m] = h->t[m] * tunit;
    start = ts[0] + t0;
    if (h->n < 2 || ts[h->n - 1] < start + nout / rate + 18.0 / rate) {
        snprintf(err, errlen, "internal: recording too short (2D-to-3D "
                 "frequency scale %g)", c->frequency_scale);
        free(ts);
        return -1;
    }
    aero_texture_resample_derivative(ts, h->fx, h->n, rate, start, scale,
                                     out, stride, nout);
    aero_texture_resample_derivative(ts, h->fy, h->n, rate, start, scale,
                                     out + 1, stride, nout);
    free(ts);
    return 0;
}

/* the 2D-to-3D correction this run's output carries: 0 or -1 */
static int correction(const aero_aeolian_flow_params *p,
                      aero_aeolian_flow_stats *st, char *err, size_t errlen)
{
    aero_span3d_none(&st->span3d, p->re);
    if (!p->span3d_self) {
        if (p->span3d)
            st->span3d = *p->span3d;
        return 0;
    }
    if (aero_span3d_calibrate(&st->span3d, p->re, st->st_peak,
                              st->flow.cl_rms)) {
        snprintf(err, errlen, "the calibration circle at Re %.4g did not "
                 "shed (St %g, Cl rms %g): no 2D-to-3D correction; use "
                 "--span3d none to make the texture anyway", p->re,
                 st->st_peak, st->flow.cl_rms);
        return -1;
    }
    return 0;
}

/* the run's callbacks, passed through to run() */
typedef struct {
    aero_aeolian_flow_hook hook;
    long every;
    void *ctx;
} progress;

/* the force recorded past the body in s: settled and recorded, its
   statistics and the 2D-to-3D correction, then g resampled into out (if
   not NULL): 0 or -1 */
static int record_and_resample(const aero_aeolian_flow_params *p,
                               aero_flow2d *s, history *h, double rate,
                               float *out, int stride, int nout,
                               aero_aeolian_flow_stats *st,
                               const progress *pr, char *err, size_t errlen)
{
    const double t_record = record_time(p, rate);
    st->dt = s->dt;
    if (run(p, s, p->settle + t_record, h, pr->hook, pr->every, pr->ctx,
            err, errlen))
        return -1;
    statistics(h, &st->flow, &st->st_peak);
    if (correction(p, st, err, errlen))
        return -1;
    if (!out)
        return 0;
    /* a 2D flow that sheds slower than the real body (frequency scale >
       1, e.g. the circle on a fine grid) is squeezed in time: record on
       until it fills the texture */
    if (st->span3d.frequency_scale > 1.0 &&
        run(p, s, p->settle + t_record * st->span3d.frequency_scale, h,
            pr->hook, pr->every, pr->ctx, err, errlen))
        return -1;
    return resample(p, h, &st->span3d, rate, out, stride, nout, err, errlen);
}

int aero_aeolian_flow_simulate(const aero_aeolian_flow_params *p,
                               double rate, float *out, int stride, int nout,
                               aero_aeolian_flow_stats *st,
                               aero_aeolian_flow_hook hook, long every,
                               void *ctx, char *err, size_t errlen)
{
    const progress pr = {hook, every, ctx};
    aero_flow2d_params fp;
    aero_flow2d s;
    history h = {NULL, NULL, NULL, 0, 0};
    int status = -1;
    memset(st, 0, sizeof *st);
    if (aero_aeolian_flow_domain(p, &fp, err, errlen) ||
        aero_flow2d_init(&s, &fp, err, errlen))
        return -1;
    if (aero_flow2d_set_body(&s, p->shape, p->angle * AERO_PI / 180.0, err,
                             errlen) == 0)
        status = record_and_resample(p, &s, &h, rate, out, stride, nout, st,
                                     &pr, err, errlen);
    free(h.t);
    free(h.fx);
    free(h.fy);
    aero_flow2d_free(&s);
    return status;
}
