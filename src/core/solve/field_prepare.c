/* aero: field auralization (Shin and Bajaj): acoustic mapping, source
 * strengths, classification, finite volumes and the retarded-time sum. See
 * field_prepare.h for the method and where it departs from the paper. */
#include "field_prepare.h"

#include "aero_air.h"
#include "aero_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void aero_field_params_default(aero_field_params *p)
{
    /* ranges, velocity, thresholds (monopole, dipole, quadrupole), ~0 */
    *p = (aero_field_params){
        .in_lo = 0, .in_hi = 1, .rho_lo = 0, .rho_hi = 1,
        .log_input = AERO_FIELD_LOG_DEFAULT,
        .vscale = AERO_FIELD_VSCALE_DEFAULT,
        .use_velocity = AERO_FIELD_VELOCITY_DEFAULT,
        .threshold = {40, 2e5, 2e5}, .zero = AERO_FIELD_ZERO_DEFAULT};
}

/* each range once, for the setters and for check */
static int span_ok(double lo, double hi)
{
    return aero_is_finite(lo) && aero_is_finite(hi) && hi != lo &&
        fabs(hi - lo) >= AERO_FIELD_SPAN_MIN;
}

static int rho_ok(double rho)
{
    return rho >= AERO_FIELD_RHO_MIN && rho <= AERO_FIELD_RHO_MAX;
}

static int vscale_ok(double k)
{
    return aero_is_finite(k) && fabs(k) <= AERO_FIELD_VSCALE_MAX;
}

static int threshold_ok(double t)
{
    return t > AERO_FIELD_THRESHOLD_MIN && t <= AERO_FIELD_THRESHOLD_MAX;
}

static int zero_ok(double z)
{
    return z >= AERO_FIELD_ZERO_MIN && z <= AERO_FIELD_ZERO_MAX;
}

int aero_field_params_check(const aero_field_params *p, char *err,
                            size_t errlen)
{
    if (!span_ok(p->in_lo, p->in_hi)) {
        aero_say(err, errlen, "input range %g..%g is empty", p->in_lo,
                 p->in_hi);
        return -1;
    }
    if (!rho_ok(p->rho_lo) || !rho_ok(p->rho_hi)) {
        aero_say(err, errlen, "density range %g..%g kg/m^3 must lie in "
                 "%g..%g", p->rho_lo, p->rho_hi, AERO_FIELD_RHO_MIN,
                 AERO_FIELD_RHO_MAX);
        return -1;
    }
    if (!vscale_ok(p->vscale)) {
        aero_say(err, errlen, "velocity scale %g out of range (%g..%g)",
                 p->vscale, -AERO_FIELD_VSCALE_MAX, AERO_FIELD_VSCALE_MAX);
        return -1;
    }
    for (int t = 0; t < 3; t++)
        if (!threshold_ok(p->threshold[t])) {
            aero_say(err, errlen, "%s threshold %g must be > %g",
                     t == 0 ? "monopole" : t == 1 ? "dipole" : "quadrupole",
                     p->threshold[t], AERO_FIELD_THRESHOLD_MIN);
            return -1;
        }
    if (!zero_ok(p->zero)) {
        aero_say(err, errlen, "zero fraction %g out of range (%g..%g)",
                 p->zero, AERO_FIELD_ZERO_MIN, AERO_FIELD_ZERO_MAX);
        return -1;
    }
    return 0;
}

int aero_field_params_set_threshold(aero_field_params *p, const double t[3])
{
    if (!threshold_ok(t[0]) || !threshold_ok(t[1]) || !threshold_ok(t[2]))
        return -1;
    memcpy(p->threshold, t, sizeof p->threshold);
    return 0;
}

int aero_field_params_set_map(aero_field_params *p, double in_lo,
                              double in_hi, double rho_lo, double rho_hi)
{
    if (!span_ok(in_lo, in_hi) || !rho_ok(rho_lo) || !rho_ok(rho_hi))
        return -1;
    p->in_lo = in_lo, p->in_hi = in_hi;
    p->rho_lo = rho_lo, p->rho_hi = rho_hi;
    return 0;
}

int aero_field_params_set_zero(aero_field_params *p, double zero)
{
    return aero_set_within(&p->zero, zero, AERO_FIELD_ZERO_MIN,
                           AERO_FIELD_ZERO_MAX);
}

int aero_field_params_set_vscale(aero_field_params *p, double vscale)
{
    return aero_set_within(&p->vscale, vscale, -AERO_FIELD_VSCALE_MAX,
                           AERO_FIELD_VSCALE_MAX);
}

int aero_field_params_set_log(aero_field_params *p, int on)
{
    if (on != 0 && on != 1)
        return -1;
    p->log_input = on;
    return 0;
}

int aero_field_params_set_velocity(aero_field_params *p, int on)
{
    if (on != 0 && on != 1)
        return -1;
    p->use_velocity = on;
    return 0;
}

void aero_field_sources_free(aero_field_sources *s)
{
    AERO_FREE_ALL(s->pos, s->vertex, s->g, s->type, s->first, s->last);
    memset(s, 0, sizeof *s);
}

/* --- preprocessing ------------------------------------------------------- */

void aero_field_pre_free(aero_field_pre *p)
{
    for (int k = 0; k < AERO_FIELD_RING; k++)
        AERO_FREE_ALL(p->rho[k], p->dv[k], p->q[k], p->quad[k]);
    for (int a = 0; a < 3; a++)
        AERO_FREE_ALL(p->vel[a], p->strength[a]);
    for (int a = 0; a < 6; a++)
        free(p->tens[a]);
    AERO_FREE_ALL(p->cls, p->work, p->entries);
    memset(p, 0, sizeof *p);
}

int aero_field_pre_init(aero_field_pre *p, const aero_volume_info *info,
                        const aero_field_params *par, char *err,
                        size_t errlen)
{
    int ok = 1;
    memset(p, 0, sizeof *p);
    if (aero_field_params_check(par, err, errlen))
        return -1;
    if (info->nx < 2 || info->ny < 2 || info->nz < 2 || info->frames < 1 ||
        !(info->rate > 0) || (info->fields != 1 && info->fields != 4)) {
        aero_say(err, errlen,
                 "unusable volume (dims, frames, rate or fields)");
        return -1;
    }
    p->info = *info;
    p->par = *par;
    p->n = aero_volume_count(info);
    p->flow = par->use_velocity && info->fields == 4;
    for (int k = 0; k < AERO_FIELD_RING; k++) {
        ok &= !!(p->rho[k] = malloc(p->n * sizeof(float)));
        ok &= !!(p->dv[k] = malloc(p->n * sizeof(float)));
        ok &= !!(p->q[k] = malloc(p->n * sizeof(float)));
        ok &= !!(p->quad[k] = malloc(p->n * sizeof(float)));
    }
    for (int a = 0; a < 3; a++) {
        ok &= !!(p->vel[a] = malloc(p->n * sizeof(float)));
        ok &= !!(p->strength[a] = malloc(p->n * sizeof(float)));
    }
    for (int a = 0; a < 6; a++)
        ok &= !!(p->tens[a] = malloc(p->n * sizeof(float)));
    ok &= !!(p->cls = malloc(p->n));
    ok &= !!(p->work = malloc(2 * p->n * sizeof(double)));
    if (!ok) {
        aero_field_pre_free(p);
        aero_say(err, errlen, "out of memory for a %dx%dx%d volume", info->nx,
                 info->ny, info->nz);
        return -1;
    }
    return 0;
}

/* ring slot of frame j (clamped to the frames that exist) */
static int slot(const aero_field_pre *p, int j)
{
    if (j < 0)
        j = 0;
    if (j > p->info.frames - 1)
        j = p->info.frames - 1;
    return j % AERO_FIELD_RING;
}

/* d/dt at frame j as sum w[k] f[idx[k]] (times the rate): central inside,
 * second-order one-sided at the first and last frames (a clamped or
 * first-order end would turn the start of a translation into a false
 * monopole); returns the number of terms */
static int time_stencil(int frames, int j, int *idx, double *w)
{
    if (frames == 1)
        return 0;
    if (frames == 2) {
        idx[0] = 0, idx[1] = 1, w[0] = -1, w[1] = 1;
        return 2;
    }
    if (j == 0) {
        idx[0] = 0, idx[1] = 1, idx[2] = 2;
        w[0] = -1.5, w[1] = 2, w[2] = -0.5;
        return 3;
    }
    if (j == frames - 1) {
        idx[0] = j, idx[1] = j - 1, idx[2] = j - 2;
        w[0] = 1.5, w[1] = -2, w[2] = 0.5;
        return 3;
    }
    idx[0] = j - 1, idx[1] = j + 1, w[0] = -0.5, w[1] = 0.5;
    return 2;
}

/* the last frame the stencil of frame j reaches */
static int stencil_end(int frames, int j)
{
    int idx[3], end = j;
    double w[3];
    int terms = time_stencil(frames, j, idx, w);
    for (int k = 0; k < terms; k++)
        if (idx[k] > end)
            end = idx[k];
    return end;
}

/* out = d/dt of the ring array `ring` at frame j */
static void time_derivative(const aero_field_pre *p, float *const *ring,
                            int j, double *out)
{
    int idx[3];
    double w[3];
    int terms = time_stencil(p->info.frames, j, idx, w);
    const double rate = p->info.rate;
    for (size_t i = 0; i < p->n; i++)
        out[i] = 0;
    for (int k = 0; k < terms; k++) {
        const float *f = ring[slot(p, idx[k])];
        const double c = w[k] * rate;
        for (size_t i = 0; i < p->n; i++)
            out[i] += c * f[i];
    }
}

/* half the inverse spacings: central differences over two cells */
static void half_inverse_spacing(const aero_volume_info *v, double *ih)
{
    for (int a = 0; a < 3; a++)
        ih[a] = 0.5 / v->spacing[a];
}

/* 1. acoustic mapping (Shin and Bajaj, sec. 3.2.2): the raw value to a
 * density (NaN: rho_lo; negative: 0) */
static void map_density(const aero_field_pre *p, const float *raw,
                        float *rho)
{
    const double lo = p->par.in_lo, span = p->par.in_hi - p->par.in_lo;
    const double rlo = p->par.rho_lo, rspan = p->par.rho_hi - p->par.rho_lo;
    for (size_t i = 0; i < p->n; i++) {
        double s = raw[i];
        if (p->par.log_input)
            s = pow(10.0, s > 300 ? 300 : s);
        double r = rlo + rspan * (s - lo) / span;
        if (!aero_is_finite(r) || r < 0)
            r = aero_is_finite(r) && r < 0 ? 0 : rlo;
        rho[i] = (float)r;
    }
}

/* 2. particle velocity: the flow's own (not finite or over 1e4: 0), or
 * vscale * grad(rho) */
static void particle_velocity(aero_field_pre *p, const float *raw,
                              const float *rho)
{
    const aero_volume_info *v = &p->info;
    const int nx = v->nx, ny = v->ny, nz = v->nz;
    const size_t sx = 1, sy = (size_t)nx, sz = (size_t)nx * ny;
    double ih[3];
    float **vel = p->vel;
    half_inverse_spacing(v, ih);
    for (int z = 0; z < nz; z++)
        for (int y = 0; y < ny; y++)
            for (int x = 0; x < nx; x++) {
                size_t i = x + sy * y + sz * z;
                if (p->flow) {
                    for (int a = 0; a < 3; a++) {
                        double u = raw[i + (size_t)(a + 1) * p->n];
                        vel[a][i] = aero_is_finite(u) && fabs(u) < 1e4
                                        ? (float)u : 0.0f;
                    }
                    continue;
                }
                size_t xm = x > 0 ? i - sx : i, xp = x < nx - 1 ? i + sx : i;
                size_t ym = y > 0 ? i - sy : i, yp = y < ny - 1 ? i + sy : i;
                size_t zm = z > 0 ? i - sz : i, zp = z < nz - 1 ? i + sz : i;
                double k = p->par.vscale;
                vel[0][i] = (float)(k * (rho[xp] - rho[xm]) * ih[0]);
                vel[1][i] = (float)(k * (rho[yp] - rho[ym]) * ih[1]);
                vel[2][i] = (float)(k * (rho[zp] - rho[zm]) * ih[2]);
            }
}

/* 3. T_ij = rho v_i v_j (xx yy zz xy xz yz); momentum rho v_i kept in
 * vel afterwards */
static void stress_tensor(aero_field_pre *p, const float *rho)
{
    float **vel = p->vel, **tens = p->tens;
    for (size_t i = 0; i < p->n; i++) {
        double r = rho[i], a = vel[0][i], b = vel[1][i], c = vel[2][i];
        tens[0][i] = (float)(r * a * a);
        tens[1][i] = (float)(r * b * b);
        tens[2][i] = (float)(r * c * c);
        tens[3][i] = (float)(r * a * b);
        tens[4][i] = (float)(r * a * c);
        tens[5][i] = (float)(r * b * c);
        vel[0][i] = (float)(r * a);
        vel[1][i] = (float)(r * b);
        vel[2][i] = (float)(r * c);
    }
}

/* 4. div(rho v) (eq. 13 before d/dt) and d2 T_ij / dx_i dx_j (eq. 14):
 * diagonal terms by the 3-point second difference, the mixed ones by
 * the 4-point cross difference, counted twice (T is symmetric) */
static void divergence_and_lighthill(aero_field_pre *p, float *dv,
                                     float *quad)
{
    const aero_volume_info *v = &p->info;
    const int nx = v->nx, ny = v->ny, nz = v->nz;
    const size_t sx = 1, sy = (size_t)nx, sz = (size_t)nx * ny;
    float *const *vel = p->vel, *const *tens = p->tens;
    double ih[3];
    const double h2[3] = {1 / (v->spacing[0] * v->spacing[0]),
                          1 / (v->spacing[1] * v->spacing[1]),
                          1 / (v->spacing[2] * v->spacing[2])};
    half_inverse_spacing(v, ih);
    for (int z = 0; z < nz; z++)
        for (int y = 0; y < ny; y++)
            for (int x = 0; x < nx; x++) {
                size_t i = x + sy * y + sz * z;
                size_t dxm = x > 0 ? sx : 0, dxp = x < nx - 1 ? sx : 0;
                size_t dym = y > 0 ? sy : 0, dyp = y < ny - 1 ? sy : 0;
                size_t dzm = z > 0 ? sz : 0, dzp = z < nz - 1 ? sz : 0;
                double d = (vel[0][i + dxp] - vel[0][i - dxm]) * ih[0] +
                           (vel[1][i + dyp] - vel[1][i - dym]) * ih[1] +
                           (vel[2][i + dzp] - vel[2][i - dzm]) * ih[2];
                dv[i] = (float)d;
                double qq =
                    (tens[0][i + dxp] - 2 * tens[0][i] + tens[0][i - dxm]) *
                        (dxm && dxp ? h2[0] : 0) +
                    (tens[1][i + dyp] - 2 * tens[1][i] + tens[1][i - dym]) *
                        (dym && dyp ? h2[1] : 0) +
                    (tens[2][i + dzp] - 2 * tens[2][i] + tens[2][i - dzm]) *
                        (dzm && dzp ? h2[2] : 0);
                qq += 2 * (tens[3][i + dxp + dyp] - tens[3][i + dxp - dym] -
                           tens[3][i - dxm + dyp] + tens[3][i - dxm - dym]) *
                      ih[0] * ih[1];
                qq += 2 * (tens[4][i + dxp + dzp] - tens[4][i + dxp - dzm] -
                           tens[4][i - dxm + dzp] + tens[4][i - dxm - dzm]) *
                      ih[0] * ih[2];
                qq += 2 * (tens[5][i + dyp + dzp] - tens[5][i + dyp - dzm] -
                           tens[5][i - dym + dzp] + tens[5][i - dym - dzm]) *
                      ih[1] * ih[2];
                quad[i] = (float)qq;
            }
}

/* Spatial stage of one frame: mapped density, velocity, momentum
 * divergence div(rho v) and the Lighthill term d2(rho v_i v_j)/dx_i dx_j,
 * central differences (one-sided halves at the faces). */
static void spatial(aero_field_pre *p, const float *raw, int j)
{
    float *rho = p->rho[slot(p, j)];
    map_density(p, raw, rho);
    particle_velocity(p, raw, rho);
    stress_tensor(p, rho);
    divergence_and_lighthill(p, p->dv[slot(p, j)], p->quad[slot(p, j)]);
}

/* q_j: the mass source, d rho/dt (+ div(rho v) with a flow: continuity) */
static void mass_source(aero_field_pre *p, int j)
{
    const float *dv = p->dv[slot(p, j)];
    float *q = p->q[slot(p, j)];
    double *d = p->work;
    time_derivative(p, p->rho, j, d);
    for (size_t i = 0; i < p->n; i++)
        q[i] = (float)(d[i] + (p->flow ? dv[i] : 0));
}

static int add_entry(aero_field_pre *p, unsigned int vertex, float g,
                     unsigned char type)
{
    if (p->count == p->cap) {
        size_t cap = p->cap ? 2 * p->cap : 4096;
        aero_field_entry *e = realloc(p->entries, cap * sizeof *e);
        if (!e)
            return -1;
        p->entries = e;
        p->cap = cap;
    }
    p->entries[p->count].vertex = vertex;
    p->entries[p->count].g = g;
    p->entries[p->count].type = type;
    p->count++;
    return 0;
}

/* Frame j: strengths, classification, source volumes, entries. The frame
 * index of each entry is implicit: frames are emitted in order and
 * separated by an entry of type NONE. */
static int emit(aero_field_pre *p, int j)
{
    const aero_volume_info *v = &p->info;
    const int nx = v->nx, ny = v->ny, nz = v->nz;
    const size_t sy = (size_t)nx, sz = (size_t)nx * ny;
    const double zero = p->par.zero;
    const double *th = p->par.threshold;
    const float *q = p->q[slot(p, j)];
    const float *quad = p->quad[slot(p, j)];
    double *dq = p->work, *ddv = p->work + p->n;
    time_derivative(p, p->q, j, dq);
    time_derivative(p, p->dv, j, ddv);
    float *sm = p->strength[0], *sd = p->strength[1], *sq = p->strength[2];
    unsigned char *cls = p->cls;
    for (size_t i = 0; i < p->n; i++) {
        double m = fabs(q[i]), d = fabs(ddv[i]);
        double w = fabs(quad[i]);
        sm[i] = (float)m, sd[i] = (float)d, sq[i] = (float)w;
        cls[i] = m > th[0] ? AERO_FIELD_MONOPOLE
                 : m <= zero * th[0] && d > th[1] ? AERO_FIELD_DIPOLE
                 : m <= zero * th[0] && d <= zero * th[1] && w > th[2]
                     ? AERO_FIELD_QUADRUPOLE
                     : AERO_FIELD_NONE;
    }
    for (int z = 0; z < nz; z++)
        for (int y = 0; y < ny; y++)
            for (int x = 0; x < nx; x++) {
                size_t i = x + sy * y + sz * z;
                int t = cls[i];
                if (!t)
                    continue;
                const float *s = p->strength[t - 1];
                const double thr = th[t - 1], si = s[i];
                /* the six edges: cut distance to the threshold surface */
                const int has[6] = {x > 0, x < nx - 1, y > 0, y < ny - 1,
                                    z > 0, z < nz - 1};
                const long step[6] = {-1, 1, -(long)sy, (long)sy, -(long)sz,
                                      (long)sz};
                double sum = 0;
                int edges = 0;
                for (int e = 0; e < 6; e++) {
                    if (!has[e])
                        continue;
                    size_t nb = (size_t)((long)i + step[e]);
                    double h = v->spacing[e / 2], cut = 0.5 * h;
                    if (cls[nb] != t && s[nb] < thr)
                        cut = h * (si - thr) / (si - s[nb]);
                    sum += cut;
                    edges++;
                }
                double radius = sum / edges;
                double dvol = 4.0 / 3.0 * AERO_PI * radius * radius * radius;
                double f = t == AERO_FIELD_MONOPOLE ? dq[i]
                           : t == AERO_FIELD_DIPOLE ? ddv[i]
                                                    : quad[i];
                if (!aero_is_finite(f * dvol))
                    continue;
                if (add_entry(p, (unsigned int)i, (float)(f * dvol),
                              (unsigned char)t))
                    return -1;
                p->points[t]++;
            }
    p->emitted++;
    return add_entry(p, 0, 0, AERO_FIELD_NONE);
}

/* compute every q and emit every frame whose stencils are complete */
static int advance(aero_field_pre *p)
{
    const int frames = p->info.frames;
    while (p->q_done < frames && stencil_end(frames, p->q_done) < p->pushed)
        mass_source(p, p->q_done++);
    while (p->emitted < frames &&
           stencil_end(frames, p->emitted) < p->q_done)
        if (emit(p, p->emitted))
            return -1;
    return 0;
}

int aero_field_pre_push(aero_field_pre *p, const float *raw, char *err,
                        size_t errlen)
{
    int j = p->pushed;
    if (j >= p->info.frames) {
        aero_say(err, errlen, "more frames pushed than the volume has");
        return -1;
    }
    spatial(p, raw, j);
    p->pushed++;
    if (advance(p)) {
        aero_say(err, errlen, "out of memory for the source list");
        return -1;
    }
    return 0;
}

/* id[i]: the index of vertex i among the active ones (a source in at
   least one frame) in order, or -1; their count */
static int number_active(const aero_field_pre *p, int *id)
{
    int count = 0;
    for (size_t i = 0; i < p->n; i++)
        id[i] = -1;
    for (size_t e = 0; e < p->count; e++)
        if (p->entries[e].type && id[p->entries[e].vertex] < 0)
            id[p->entries[e].vertex] = count++;
    return count;
}

/* the list's header: sizes, the nearest a listener may come (half the
   finest spacing), the time derivatives per kind of source */
static void describe_sources(const aero_field_pre *p, int count,
                             aero_field_sources *out)
{
    const aero_volume_info *v = &p->info;
    double hmin = v->spacing[0];
    out->count = count;
    out->frames = v->frames;
    out->rate = v->rate;
    for (int a = 1; a < 3; a++)
        if (v->spacing[a] < hmin)
            hmin = v->spacing[a];
    out->min_distance = 0.5 * hmin;
    /* with a flow all terms carry two time derivatives (see the header) */
    out->exponent[AERO_FIELD_NONE] = 0;
    out->exponent[AERO_FIELD_MONOPOLE] = 2;
    out->exponent[AERO_FIELD_DIPOLE] = p->flow ? 2 : 1;
    out->exponent[AERO_FIELD_QUADRUPOLE] = p->flow ? 2 : 0;
    memcpy(out->points, p->points, sizeof out->points);
}

/* the arrays of count sources over their frames: 0, or -1 */
static int alloc_sources(aero_field_sources *out, int count, int frames)
{
    const size_t one = (size_t)(count ? count : 1);
    size_t cells = one * frames;
    out->pos = malloc(3 * sizeof(float) * one);
    out->vertex = malloc(sizeof(int) * one);
    out->g = calloc(cells, sizeof(float));
    out->type = calloc(cells, 1);
    out->first = malloc(sizeof(int) * one);
    out->last = malloc(sizeof(int) * one);
    return out->pos && out->vertex && out->g && out->type && out->first &&
                   out->last
               ? 0
               : -1;
}

/* each active vertex's position, its distance from the origin (the
   farthest: max_reach), no frame yet */
static void place_sources(const aero_field_pre *p, const int *id,
                          aero_field_sources *out)
{
    const aero_volume_info *v = &p->info;
    for (size_t i = 0; i < p->n; i++) {
        int s = id[i];
        if (s < 0)
            continue;
        int x = (int)(i % v->nx), y = (int)(i / v->nx % v->ny);
        int z = (int)(i / ((size_t)v->nx * v->ny));
        double pos[3] = {v->origin[0] + x * v->spacing[0],
                         v->origin[1] + y * v->spacing[1],
                         v->origin[2] + z * v->spacing[2]};
        double reach = sqrt(pos[0] * pos[0] + pos[1] * pos[1] +
                            pos[2] * pos[2]);
        for (int a = 0; a < 3; a++)
            out->pos[3 * s + a] = (float)pos[a];
        if (reach > out->max_reach)
            out->max_reach = reach;
        out->vertex[s] = (int)i;
        out->first[s] = v->frames;
        out->last[s] = -1;
    }
}

/* the entries, frame by frame (an entry of type NONE ends a frame), into
   each source's strength and type per frame, and its first and last
   frame */
static void fill_sources(const aero_field_pre *p, const int *id,
                         aero_field_sources *out)
{
    const int frames = p->info.frames;
    int frame = 0;
    for (size_t e = 0; e < p->count; e++) {
        const aero_field_entry *en = &p->entries[e];
        if (!en->type) {
            frame++;
            continue;
        }
        int s = id[en->vertex];
        out->g[(size_t)s * frames + frame] = en->g;
        out->type[(size_t)s * frames + frame] = en->type;
        if (frame < out->first[s])
            out->first[s] = frame;
        if (frame > out->last[s])
            out->last[s] = frame;
    }
}

int aero_field_pre_finish(aero_field_pre *p, aero_field_sources *out,
                          char *err, size_t errlen)
{
    const int frames = p->info.frames;
    int *id = NULL, count;
    memset(out, 0, sizeof *out);
    if (p->pushed != frames) {
        aero_say(err, errlen, "only %d of %d frames were read", p->pushed,
                 frames);
        return -1;
    }
    if (advance(p) || p->emitted != frames) {
        aero_say(err, errlen, "out of memory for the source list");
        return -1;
    }
    id = malloc(p->n * sizeof(int));
    if (!id)
        goto oom;
    count = number_active(p, id);
    describe_sources(p, count, out);
    if (alloc_sources(out, count, frames))
        goto oom;
    place_sources(p, id, out);
    fill_sources(p, id, out);
    free(id);
    free(p->entries);
    p->entries = NULL;
    p->count = p->cap = 0;
    return 0;
oom:
    free(id);
    aero_field_sources_free(out);
    aero_say(err, errlen, "out of memory for the sources");
    return -1;
}

int aero_field_prepare(const aero_volume_info *info,
                       const aero_field_demo *demo,
                       const aero_field_params *par, aero_field_sources *out,
                       aero_field_progress_fn progress, void *ctx, char *err,
                       size_t errlen)
{
    aero_field_pre pre;
    float *raw;
    int rc = -1;
    memset(out, 0, sizeof *out);
    /* the first frame file before any allocation: a hostile header
       (1024^3 vertices, no data) must not cost tens of GB first */
    if (!demo && aero_volume_check_frame(info, 0, err, errlen))
        return -1;
    if (aero_field_pre_init(&pre, info, par, err, errlen))
        return -1;
    raw = malloc(aero_volume_count(info) * info->fields * sizeof(float));
    if (!raw) {
        aero_say(err, errlen, "out of memory");
        aero_field_pre_free(&pre);
        return -1;
    }
    for (int k = 0; k < info->frames; k++) {
        if (demo)
            aero_field_demo_frame(demo, k, raw);
        else if (aero_volume_read_frame(info, k, raw, err, errlen))
            goto done;
        if (aero_field_pre_push(&pre, raw, err, errlen))
            goto done;
        if (progress && progress(ctx, k + 1, info->frames)) {
            aero_say(err, errlen, "cancelled");
            goto done;
        }
    }
    rc = aero_field_pre_finish(&pre, out, err, errlen);
done:
    free(raw);
    aero_field_pre_free(&pre);
    return rc;
}

