/* aero: [cavity~]'s texture mode: a cavity texture from `aerotex cavity`
 * read at the flow's rate and radiated as a compact dipole to each ear
 * (see cavity.h; the object and its settings: cavity.c). */
#include "cavity_internal.h"

#include "aero_air.h"
#include "aero_util.h"

#include <math.h>

/* ear e's projection of the texture's force, folded with the radiation
   law: (x . g) W / (4 pi c0 r^2) as cx g_x + cy g_y */
static void ear_projection(aero_cavity *m, int e, double law, float *cx,
                           float *cy)
{
    const double *ear = m->ctl + AERO_CAV_EAR + 3 * e;
    double l = m->ctl[AERO_CAV_LENGTH], w = m->ctl[AERO_CAV_WIDTH];
    double r = aero_cavity_ear_distance(m, e, sqrt(l * w));
    double radiation = w / (4.0 * AERO_PI * AERO_C0 * r * r) *
                       m->ctl[AERO_CAV_GAIN];
    /* closer than sqrt(L W), heard as there along the listener's own
       direction; exactly at the cavity along +y, out of the opening (the
       wall's normal, where a listener of a cavity in a wall stands) */
    const double out_of_wall[3] = {0.0, 1.0, 0.0};
    double x[3] = {ear[0], ear[1], ear[2]};
    aero_near_field(x, sqrt(l * w), out_of_wall, &m->near);
    radiation *= law;
    *cx = (float)(x[0] * radiation), *cy = (float)(x[1] * radiation);
}

/* Texture mode: the texture coordinate advances by (v/v0)(L0/L) (Dobashi et
 * al. 2003 eq. 3: the shear-layer modes sit at St_L = f L / v, so the pitch
 * follows the cavity's length as an aeolian texture's follows d0/d), amplitude
 * (v/v0)^n (g = dF/dt per unit width: F ~ v^2 L, f ~ v/L), Curle dipole
 * p = (x . g) W / (4 pi c0 r^2) at each ear. */
void aero_cavity_texture_process(aero_cavity *m, const float *u,
                                 float *const *out, int n, double u_end)
{
    const aero_texture *t = m->texture;
    double l = m->ctl[AERO_CAV_LENGTH];
    double inv_v0 = 1.0 / m->texture_v0;
    /* the speed law folded into the projection: (v/v0)^2 per sample, or
       (v/v0)^n once per chunk, gliding over it */
    double p1 = 1.0, p0 = 1.0;
    int square = m->exponent == 2.0;
    if (!square) {
        p1 = pow(u_end * inv_v0, m->exponent);
        if (!m->primed)
            m->speed_power = p1;
        p0 = m->speed_power;
        m->speed_power = p1;
    }
    float cx[AERO_CAVITY_MAX_EARS], cy[AERO_CAVITY_MAX_EARS];
    for (int e = 0; e < m->n_ears; e++)
        ear_projection(m, e, square ? inv_v0 * inv_v0 : 1.0, cx + e, cy + e);
    const double step = t->rate / m->sample_rate * inv_v0 *
                        (m->texture_length > 0.0 ? m->texture_length / l : 1.0);
    const float *data = t->data;
    const long frames = t->frames, channels = t->channels;
    double pos = m->texture_pos;
    for (int i = 0; i < n; i++) {
        long k = (long)pos;
        long k1 = k + 1 < frames ? k + 1 : 0;
        float frac = (float)(pos - k);
        const float *a = data + k * channels, *b = data + k1 * channels;
        float gx = a[0] + (b[0] - a[0]) * frac;
        float gy = a[1] + (b[1] - a[1]) * frac;
        float law = square ? u[i] * u[i]
                           : (float)(p0 + (p1 - p0) * (i + 1) / n);
        for (int e = 0; e < m->n_ears; e++)
            out[e][i] = (cx[e] * gx + cy[e] * gy) * law;
        pos += u[i] * step;
        if (pos >= frames)
            pos -= frames * floor(pos / frames);
    }
    m->texture_pos = pos;
}
