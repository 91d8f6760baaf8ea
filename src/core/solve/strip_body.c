/* aero: a slender body of revolution by strip theory (see strip_body.h). */
#include "strip_body.h"
#include "aero_air.h"
#include "aero_util.h"
#include "strouhal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define STATIONS 32     /* local radii measured per region */
#define AZIMUTHS 4      /* radii per station */
#define BISECTIONS 40
/* no shedding below this cross-flow speed over v0 (flow along the axis) */
#define MIN_NORMAL 1e-3

/* the body's radius at height z along azimuth phi (0: the axis is
   outside the body there) */
static double radius_at(const aero_body_shape *b, double z, double phi,
                        double rmax)
{
    double lo = 0.0, hi = rmax, p[3] = {0.0, 0.0, z};
    if (!aero_body_inside(b, p))
        return 0.0;
    for (int n = 0; n < BISECTIONS; n++) {
        double r = 0.5 * (lo + hi);
        p[0] = r * cos(phi);
        p[1] = r * sin(phi);
        if (aero_body_inside(b, p))
            lo = r;
        else
            hi = r;
    }
    return 0.5 * (lo + hi);
}

int aero_strip_layout_measure(const aero_body_shape *b, int regions,
                              aero_strip_layout *out, char *err,
                              size_t errlen)
{
    const double z0 = b->lo[2], dz = (b->hi[2] - b->lo[2]) / regions;
    double rmax = 0.0;
    memset(out, 0, sizeof *out);
    if (b->kind == AERO_BODY_SPHERE) {
        snprintf(err, errlen, "a sphere is not slender: strip theory needs "
                 "a body along its axis (club, capsule, mesh)");
        return -1;
    }
    if (regions < 1 || regions > AERO_STRIP_MAX_REGIONS || !(dz > 0.0)) {
        snprintf(err, errlen, "%d regions: 1..%d along a body of some "
                 "length", regions, AERO_STRIP_MAX_REGIONS);
        return -1;
    }
    for (int a = 0; a < 2; a++)
        rmax = fmax(rmax, fmax(fabs(b->lo[a]), fabs(b->hi[a])));
    rmax *= 1.01;
    out->regions = regions;
    for (int l = 0; l < regions; l++) {
        double rsum = 0.0, zsum = 0.0;
        int inside = 0;
        for (int s = 0; s < STATIONS; s++) {
            double z = z0 + (l + (s + 0.5) / STATIONS) * dz, r = 0.0;
            for (int q = 0; q < AZIMUTHS; q++)
                r += radius_at(b, z, 2.0 * AERO_PI * q / AZIMUTHS, rmax);
            r /= AZIMUTHS;
            if (r > 0.0) {
                inside++;
                rsum += r;
                zsum += r * z; /* the force grows with the diameter */
            }
        }
        if (!inside) {
            snprintf(err, errlen, "region %d (z %g..%g m) holds no part of "
                     "the body's axis: fewer regions", l, z0 + l * dz,
                     z0 + (l + 1) * dz);
            return -1;
        }
        out->diameter[l] = 2.0 * rsum / inside;
        out->z[l] = zsum / rsum;
        out->span[l] = dz * inside / STATIONS;
    }
    return 0;
}

int aero_strip_check_section(const aero_texture *section, char *err,
                             size_t errlen)
{
    char kind[32], shape[32];
    if (!aero_texture_get(section, "kind", kind, sizeof kind) ||
        strcmp(kind, "aeolian") ||
        !aero_texture_get(section, "shape", shape, sizeof shape) ||
        strcmp(shape, "circle") || section->directions != 1 ||
        section->channels != 3 || section->frames < 16) {
        snprintf(err, errlen, "the section must be a circle's aeolian "
                 "texture with one direction ('aerotex aeolian --shape "
                 "circle', e.g. textures/cylinder.wav)");
        return -1;
    }
    if (!(aero_texture_getd(section, "st", 0.0) > 0.0) ||
        !(aero_texture_getd(section, "cl_rms", 0.0) > 0.0) ||
        !(aero_texture_getd(section, "v0", 0.0) > 0.0) ||
        !(aero_texture_getd(section, "diameter", 0.0) > 0.0) ||
        !(section->rate > 0.0)) {
        snprintf(err, errlen, "the section texture lacks st, cl_rms, v0 or "
                 "diameter in its metadata");
        return -1;
    }
    return 0;
}

/* the section's x and y at position pos (its samples, wrapped), low-passed
   below fc */
static void section_at(const aero_texture *t, double pos, double fc,
                       double half, double xy[2])
{
    const long n0 = (long)floor(pos - half) + 1, n1 = (long)floor(pos + half);
    double sum = 0.0;
    xy[0] = xy[1] = 0.0;
    for (long n = n0; n <= n1; n++) {
        double h = aero_texture_lowpass_kernel((double)n - pos, fc, half);
        long m = n % t->frames;
        if (m < 0)
            m += t->frames;
        xy[0] += h * t->data[(size_t)m * t->channels];
        xy[1] += h * t->data[(size_t)m * t->channels + 1];
        sum += h;
    }
    if (sum > 0.0) {
        xy[0] /= sum;
        xy[1] /= sum;
    }
}

void aero_strip_render(const aero_texture *section,
                       const aero_strip_layout *layout, double angle,
                       double v0, double rate, uint32_t seed, float *out,
                       int stride, int nout, aero_strip_stats *stats)
{
    const double v0s = aero_texture_getd(section, "v0", 10.0),
                 ds = aero_texture_getd(section, "diameter", 0.01),
                 st_s = aero_texture_getd(section, "st", 0.2),
                 cl_s = aero_texture_getd(section, "cl_rms", 0.3),
                 f_s = st_s * v0s / ds;
    const double un = v0 * fabs(sin(angle * AERO_PI / 180.0));
    double side = 0.0, lateral = 0.0, strongest = -1.0, length = 0.0;
    uint32_t rng = seed * 2654435761u + 12345u;
    memset(stats, 0, sizeof *stats);
    for (int l = 0; l < layout->regions; l++)
        length += layout->span[l];
    for (int l = 0; l < layout->regions; l++) {
        const double d = layout->diameter[l], span = layout->span[l],
                     lc = fmin(AERO_CORRELATION_DIAMETERS * d, length);
        const double re = un * d / AERO_NU, st = aero_strouhal(re),
                     cl = aero_lift_rms(re), f = st * un / d;
        /* section samples per output sample, and the start in its loop */
        const double step = f / f_s * section->rate / rate;
        const double start = 0.5 * (1.0 + aero_uniform(&rng)) * section->frames;
        const double fc = step > 1.0 ? 0.45 / step : 0.5,
                     half = ceil(4.0 / fc);
        const double span_eff = sqrt(span * lc);
        /* the phase wanders (a random walk in cycles, its Lorentzian line
           as wide as model mode's, aero_shedding_line_width): regions of
           one diameter would otherwise play the same tone with frozen
           phases and sum at a random gain instead of adding powers */
        const double wander = sqrt(3.0 * aero_shedding_line_width(re) * f /
                                   (2.0 * AERO_PI * rate)),
                     period = section->rate / f_s;
        double phase = 0.0;
        const double amp = un < MIN_NORMAL * v0 ? 0.0
                           : pow(un / v0s, 3.0) * (st / st_s) * (cl / cl_s) *
                                 span_eff;
        float *o = out + 3 * l;
        side += d * span;
        lateral += pow(cl * 0.5 * un * un * d * span_eff, 2.0);
        if (amp > 0.0 && cl * d * span_eff > strongest) {
            strongest = cl * d * span_eff;
            stats->f_peak = f;
        }
        for (int n = 0; n < nout; n++) {
            double xy[2] = {0.0, 0.0};
            if (amp > 0.0)
                section_at(section, start + step * n + period * phase, fc,
                           half, xy);
            phase += wander * aero_uniform(&rng);
            o[(size_t)n * stride] = (float)(amp * xy[0]);
            o[(size_t)n * stride + 1] = (float)(amp * xy[1]);
            o[(size_t)n * stride + 2] = 0.0f;
        }
    }
    if (side > 0.0 && v0 > 0.0)
        stats->cl_rms = sqrt(lateral) / (0.5 * v0 * v0 * side);
}
