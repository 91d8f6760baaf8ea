/* aero: field auralization, the real-time half (see fieldsound.h):
 * Catmull-Rom strengths between frames, summed at the listener at the
 * retarded time. */
#include "fieldsound.h"

#include "aero_air.h"
#include "aero_util.h"
#include "aero_ramp.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* --- rendering ------------------------------------------------------------ */

int aero_fieldsound_init(aero_fieldsound *r, double sample_rate, int n_ears,
                         uint32_t seed)
{
    (void)seed; /* nothing random: the sources are the flow's own */
    memset(r, 0, sizeof *r);
    int sr_ok = sample_rate > 0 && sample_rate < 1e7 && n_ears == 1;
    r->sample_rate = sr_ok ? sample_rate : AERO_SAMPLE_RATE_FALLBACK;
    r->speed = r->speed_target = 0;
    r->ramp_ms = AERO_RAMP_MS_DEFAULT;
    r->gain = pow(10.0, AERO_GAIN_DB_DEFAULT / 20.0);
    r->phase = -2;
    return sr_ok ? 0 : -1;
}

void aero_fieldsound_free(aero_fieldsound *r)
{
    free(r->dist);
    r->dist = NULL;
    r->src = NULL;
}

int aero_fieldsound_set_sources(aero_fieldsound *r,
                                const aero_field_sources *s)
{
    free(r->dist);
    r->dist = NULL;
    r->src = NULL;
    r->playing = 0;
    r->envelope = 0;
    r->dist_valid = 0;
    if (!s)
        return 0;
    r->dist = malloc(sizeof(float) * (s->count ? s->count : 1));
    if (!r->dist)
        return -1;
    r->src = s;
    if (!(r->speed_target > 0))
        r->speed = r->speed_target = s->rate;
    return 0;
}

int aero_fieldsound_set_sample_rate(aero_fieldsound *r, double sr)
{
    if (!(sr > 0 && sr < 1e7))
        return -1;
    r->sample_rate = sr;
    return 0;
}

int aero_fieldsound_set_speed(aero_fieldsound *r, double fps)
{
    if (!(fps >= AERO_FIELD_SPEED_MIN && fps <= AERO_FIELD_SPEED_MAX))
        return -1;
    r->speed_target = fps;
    if (!r->playing)
        r->speed = fps;
    return 0;
}

int aero_fieldsound_set_ears(aero_fieldsound *r, const aero_ears *e)
{
    if (!aero_ears_ok(e, 1))
        return -1;
    memcpy(r->target, e->pos[0], sizeof r->target);
    r->ramp_left = r->ramp_ms * 0.001 * r->sample_rate;
    if (r->ramp_left < 1)
        r->ramp_left = 1;
    return 0;
}

int aero_fieldsound_place_ears(aero_fieldsound *r, const aero_ears *e)
{
    if (!aero_ears_ok(e, 1))
        return -1;
    memcpy(r->target, e->pos[0], sizeof r->target);
    memcpy(r->listener, e->pos[0], sizeof r->listener);
    r->ramp_left = 0;
    r->dist_valid = 0;
    return 0;
}

int aero_fieldsound_set_ramp_ms(aero_fieldsound *r, double ms)
{
    if (!(ms >= AERO_RAMP_MS_MIN && ms <= AERO_RAMP_MS_MAX))
        return -1;
    r->ramp_ms = ms;
    return 0;
}

int aero_fieldsound_set_gain_db(aero_fieldsound *r, double db)
{
    if (!(db >= AERO_GAIN_DB_MIN && db <= AERO_GAIN_DB_MAX))
        return -1;
    r->gain = pow(10.0, db / 20.0);
    return 0;
}

void aero_fieldsound_play(aero_fieldsound *r)
{
    if (!r->src)
        return;
    /* frame time -2 at the start: the first cubic piece that reaches
     * frame 0 (Catmull-Rom looks two frames ahead) begins at u = -2, so
     * nothing is heard before D/c0 (the interpolation's latency is two
     * frames) */
    r->phase = -2;
    r->speed = r->speed_target;
    r->playing = 1;
    r->envelope = 1;
}

void aero_fieldsound_stop(aero_fieldsound *r)
{
    r->playing = 0;
}

double aero_fieldsound_length(const aero_field_sources *s, double speed,
                              double distance)
{
    if (!s || !(speed > 0))
        return 0;
    return (s->frames + 3) / speed + (s->max_reach + distance) / AERO_C0;
}

/* Catmull-Rom coefficients of the piece [m, m+1) of source row g (zero
 * outside the frames), each value scaled by its type's factor */
static void piece(const float *g, const unsigned char *type, int frames,
                  int m, const double *scale, double c[4])
{
    double p[4];
    for (int k = 0; k < 4; k++) {
        int f = m - 1 + k;
        p[k] = f >= 0 && f < frames ? g[f] * scale[type[f]] : 0.0;
    }
    c[0] = p[1];
    c[1] = 0.5 * (p[2] - p[0]);
    c[2] = p[0] - 2.5 * p[1] + 2 * p[2] - 0.5 * p[3];
    c[3] = 0.5 * (p[3] - p[0]) + 1.5 * (p[1] - p[2]);
}

/* the listener over a chunk of c samples: l0 where it is, l1 where it
 * goes (a linear ramp toward the target, at most Mach 0.3) */
static void move_listener(aero_fieldsound *r, int c, double l0[3],
                          double l1[3])
{
    memcpy(l0, r->listener, sizeof(double) * 3);
    memcpy(l1, l0, sizeof(double) * 3);
    aero_glide_values(l1, r->target, 3,
                      aero_glide_fraction(&r->ramp_left, c));
    double d[3], len = 0;
    double lim = AERO_MACH_LIMIT * AERO_C0 * c / r->sample_rate;
    for (int a = 0; a < 3; a++)
        d[a] = l1[a] - l0[a], len += d[a] * d[a];
    len = sqrt(len);
    if (len > lim) {
        /* faster than Mach 0.3: go on toward the target next chunk */
        for (int a = 0; a < 3; a++)
            l1[a] = l0[a] + d[a] * lim / len;
        r->clamped = 1;
        if (r->ramp_left < c)
            r->ramp_left = c;
    }
    memcpy(r->listener, l1, sizeof(double) * 3);
}

/* what every source of one chunk shares */
typedef struct {
    int c;                 /* samples */
    double l0[3], l1[3];   /* the listener at the chunk's ends */
    double ph0, ph1;       /* playhead, data frames */
    double s0, s1;         /* playback speed, frames per second */
    double scale[4];       /* per source type */
} chunk;

/* adds the Catmull-Rom piece cf, read at x = al + b i, times 1/D =
 * w0 + wd i, over samples is..ie-1 into acc */
static void add_piece(aero_fieldsound *r, const double cf[4],
                      double al, double b, double w0, double wd, int is,
                      int ie)
{
    double *acc = r->acc;
    if (r->direct) {
        /* the reference: every sample evaluated on its own */
        for (int i = is; i < ie; i++) {
            double x = al + b * i;
            double v = ((cf[3] * x + cf[2]) * x + cf[1]) * x + cf[0];
            acc[5 * i] += v * (w0 + wd * i);
        }
        return;
    }
    /* the piece as a cubic in the sample index i (x = al + b i), times
     * 1/D = w0 + wd i: a quartic, added from is to ie */
    double g0 = ((cf[3] * al + cf[2]) * al + cf[1]) * al + cf[0];
    double g1 = ((3 * cf[3] * al + 2 * cf[2]) * al + cf[1]) * b;
    double g2 = (3 * cf[3] * al + cf[2]) * b * b;
    double g3 = cf[3] * b * b * b;
    double f[5] = {g0 * w0, g1 * w0 + g0 * wd, g2 * w0 + g1 * wd,
                   g3 * w0 + g2 * wd, g3 * wd};
    double *a_s = acc + 5 * is, *a_e = acc + 5 * ie;
    for (int j = 0; j < 5; j++) {
        a_s[j] += f[j];
        a_e[j] -= f[j];
    }
}

/* source k over the chunk, at the retarded time; 1 while some of it is
 * still to be heard */
static int add_source(aero_fieldsound *r, const chunk *ch, int k)
{
    const aero_field_sources *s = r->src;
    const double inv_c0 = 1.0 / AERO_C0;
    const int c = ch->c, frames = s->frames;
    const double dmin = s->min_distance;
    const float *pos = s->pos + 3 * k;
    const double *l0 = ch->l0, *l1 = ch->l1;
    int remaining = 0;
    double e1[3] = {l1[0] - pos[0], l1[1] - pos[1], l1[2] - pos[2]};
    double d1 = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]), d0;
    if (r->dist_valid)
        d0 = r->dist[k];
    else {
        double e0[3] = {l0[0] - pos[0], l0[1] - pos[1], l0[2] - pos[2]};
        d0 = sqrt(e0[0] * e0[0] + e0[1] * e0[1] + e0[2] * e0[2]);
    }
    r->dist[k] = (float)d1;
    if (d1 < dmin) /* the near-field policy (aero_near_field) */
        aero_near_seen(&r->near, dmin);
    /* retarded frame time at both ends of the chunk: the radiation
     * leaving the source at frame u arrives D/c0 later */
    double u0 = ch->ph0 - ch->s0 * d0 * inv_c0;
    double u1 = ch->ph1 - ch->s1 * d1 * inv_c0;
    if (u0 < s->last[k] + 2)
        remaining = 1;
    if (u1 < s->first[k] - 2 || u0 >= s->last[k] + 2)
        return remaining; /* not reached yet, or heard out */
    double b = (u1 - u0) / c;
    if (!(b > 1e-12))
        b = 1e-12;
    double w0 = 1 / (d0 > dmin ? d0 : dmin);
    double w1 = 1 / (d1 > dmin ? d1 : dmin);
    double wd = (w1 - w0) / c;
    const float *g = s->g + (size_t)k * frames;
    const unsigned char *ty = s->type + (size_t)k * frames;
    int m_lo = (int)floor(u0), m_hi = (int)floor(u1);
    if (m_lo < s->first[k] - 2)
        m_lo = s->first[k] - 2;
    if (m_hi > s->last[k] + 1)
        m_hi = s->last[k] + 1;
    for (int m = m_lo; m <= m_hi; m++) {
        int is = m <= u0 ? 0 : (int)ceil((m - u0) / b);
        int ie = m + 1 > u1 ? c : (int)ceil((m + 1 - u0) / b);
        if (is < 0) is = 0;
        if (ie > c) ie = c;
        if (ie <= is)
            continue;
        double cf[4];
        piece(g, ty, frames, m, ch->scale, cf);
        if (cf[0] == 0 && cf[1] == 0 && cf[2] == 0 && cf[3] == 0)
            continue;
        add_piece(r, cf, u0 - m, b, w0, wd, is, ie);
    }
    return remaining;
}

/* the accumulated chunk into out, faded from env0 to env1 */
static void sum_chunk(const aero_fieldsound *r, float *out, int c,
                      double env0, double env1)
{
    const double *acc = r->acc;
    if (r->direct) {
        for (int i = 0; i < c; i++) {
            double e = env0 + (env1 - env0) * i / c;
            out[i] = (float)(acc[5 * i] * e);
        }
    } else {
        double p[5] = {0, 0, 0, 0, 0};
        for (int i = 0; i < c; i++) {
            for (int j = 0; j < 5; j++)
                p[j] += acc[5 * i + j];
            double x = i;
            double v = (((p[4] * x + p[3]) * x + p[2]) * x + p[1]) * x + p[0];
            double e = env0 + (env1 - env0) * i / c;
            out[i] = (float)(v * e);
        }
    }
    for (int i = 0; i < c; i++)
        if (!aero_is_finite(out[i]))
            out[i] = 0;
}

/* one chunk of c <= AERO_FIELD_CHUNK samples */
static int render_chunk(aero_fieldsound *r, float *out, int c)
{
    const aero_field_sources *s = r->src;
    const double sr = r->sample_rate;
    double env0 = r->envelope, env1;
    chunk ch;
    int remaining = 0;
    ch.c = c;
    ch.s0 = r->speed;
    ch.ph0 = r->phase;
    move_listener(r, c, ch.l0, ch.l1);

    /* playhead and speed: the speed glides to its target in ~10 ms */
    {
        double glide = c / (0.01 * sr);
        ch.s1 = ch.s0 + (r->speed_target - ch.s0) * (glide > 1 ? 1 : glide);
    }
    ch.ph1 = ch.ph0 + 0.5 * (ch.s0 + ch.s1) * c / sr;
    env1 = r->playing ? 1.0 : 0.0;
    if (!s || (env0 <= 0 && env1 <= 0)) {
        memset(out, 0, sizeof(float) * c);
        r->speed = ch.s1;
        r->envelope = env1;
        r->dist_valid = 0;
        return 0;
    }
    {
        double sm = 0.5 * (ch.s0 + ch.s1) / s->rate;
        for (int t = 0; t < 4; t++)
            ch.scale[t] = t ? r->gain / (4 * AERO_PI) *
                                  pow(sm, s->exponent[t])
                            : 0;
    }
    memset(r->acc, 0, sizeof(double) * 5 * (c + 1));
    for (int k = 0; k < s->count; k++)
        remaining |= add_source(r, &ch, k);
    r->dist_valid = 1;
    sum_chunk(r, out, c, env0, env1);
    r->phase = ch.ph1;
    r->speed = ch.s1;
    r->envelope = env1;
    if (r->playing && !remaining)
        r->playing = 0; /* every source has been heard */
    return r->playing;
}

int aero_fieldsound_process(aero_fieldsound *r, float *out, int n)
{
    int playing = 0;
    while (n > 0) {
        int c = n < AERO_FIELD_CHUNK ? n : AERO_FIELD_CHUNK;
        playing = render_chunk(r, out, c);
        out += c;
        n -= c;
    }
    return playing;
}
