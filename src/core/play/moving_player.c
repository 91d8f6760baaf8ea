/* aero: the settings every player of moving bodies shares (see
 * moving_player.h). */
#include "moving_player.h"

#include <math.h>
#include <string.h>

static int alloc_rings(aero_moving_player *p, double sr)
{
    return aero_arrivals_alloc(&p->arrivals, p->n_ears, sr, p->max_delay_s,
                               4 * p->chunk);
}

int aero_moving_player_init(aero_moving_player *p, double sample_rate,
                            int n_ears, uint32_t seed, int chunk,
                            double max_delay_s)
{
    memset(p, 0, sizeof(*p));
    p->n_ears = n_ears < 1 ? 1 : n_ears > 2 ? 2 : n_ears;
    p->sample_rate = sample_rate;
    p->chunk = chunk;
    p->max_delay_s = max_delay_s;
    p->rng = seed ? seed : 1;
    p->exponent = AERO_MOVING_EXPONENT_DEFAULT;
    p->ramp_samples = AERO_RAMP_MS_DEFAULT / 1000.0 * sample_rate;
    aero_ramp_jump(&p->gain, pow(10.0, AERO_GAIN_DB_DEFAULT / 20.0));
    for (int e = 0; e < AERO_EARS_MAX; e++) {
        aero_ramp_jump(&p->ear[3 * e + 0],
                       p->n_ears == 2 ? (e ? AERO_EAR_HALF_SPACING
                                             : -AERO_EAR_HALF_SPACING)
                                    : 0.0);
        aero_ramp_jump(&p->ear[3 * e + 1], 1.0);
        aero_ramp_jump(&p->ear[3 * e + 2], 0.0);
    }
    return alloc_rings(p, sample_rate);
}

void aero_moving_player_free(aero_moving_player *p)
{
    aero_arrivals_free(&p->arrivals);
}

void aero_moving_player_ramp(const aero_moving_player *p, aero_ramp *r,
                             double v)
{
    aero_ramp_to(r, v, p->ramp_samples, p->chunk);
}

int aero_moving_player_set_sample_rate(aero_moving_player *p, double sr)
{
    if (!(sr >= AERO_MOVING_SR_MIN && sr <= AERO_MOVING_SR_MAX))
        return -1;
    if (sr == p->sample_rate && p->arrivals.ring[0])
        return 0;
    double ms = p->ramp_samples / p->sample_rate * 1000.0;
    if (alloc_rings(p, sr))
        return -1;
    p->sample_rate = sr;
    p->ramp_samples = ms * 0.001 * sr;
    return 1;
}

int aero_moving_player_set_exponent(aero_moving_player *p, double e)
{
    if (!(e >= AERO_MOVING_EXPONENT_MIN && e <= AERO_MOVING_EXPONENT_MAX))
        return -1;
    p->exponent = e;
    return 0;
}

/* The ears and the gain go to a new value at once while nothing sounds:
   nothing heard moves, and a listener placed as a stream of poses begins
   is not still flying there (2 m in 20 ms) when the sound starts, a
   Doppler rate that steps at the glide's end (issue 48). */
static void ramp_heard(const aero_moving_player *p, aero_ramp *r, double v)
{
    if (p->sounding)
        aero_moving_player_ramp(p, r, v);
    else
        aero_ramp_jump(r, v);
}

int aero_moving_player_set_gain_db(aero_moving_player *p, double db)
{
    if (!(db >= AERO_GAIN_DB_MIN && db <= AERO_GAIN_DB_MAX))
        return -1;
    ramp_heard(p, &p->gain, pow(10.0, db / 20.0));
    return 0;
}

int aero_moving_player_set_ramp_ms(aero_moving_player *p, double ms)
{
    if (!(ms >= AERO_RAMP_MS_MIN && ms <= AERO_RAMP_MS_MAX))
        return -1;
    p->ramp_samples = ms * 0.001 * p->sample_rate;
    return 0;
}

int aero_moving_player_set_wind(aero_moving_player *p, const double w[3])
{
    if (!aero_finite_within(w, 3, AERO_MOVING_WIND_MAX))
        return -1;
    for (int i = 0; i < 3; i++)
        aero_moving_player_ramp(p, &p->wind[i], w[i]);
    return 0;
}

int aero_moving_player_set_ears(aero_moving_player *p, const aero_ears *e)
{
    if (!aero_ears_ok(e, p->n_ears))
        return -1;
    for (int k = 0; k < e->n; k++)
        for (int i = 0; i < 3; i++)
            ramp_heard(p, &p->ear[3 * k + i], e->pos[k][i]);
    return 0;
}
