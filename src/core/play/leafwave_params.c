/* aero: [leafwave~]'s parameters: the setters of leafwave.h (those that
 * rebuild call back into the life cycle of leafwave.c). */
#include "leafwave_internal.h"
#include "aero_air.h"
#include "aero_ramp.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int aero_leafwave_set_sample_rate(aero_leafwave *lw, double sr)
{
    if (!(sr >= AERO_LEAFWAVE_SR_MIN && sr <= AERO_LEAFWAVE_SR_MAX))
        return -1;
    if (sr == lw->sample_rate && lw->line)
        return 0;
    if (leafwave_alloc_line(lw, sr))
        return -1;
    double ramp_ms = 1000.0 * lw->ramp_samples / lw->sample_rate;
    lw->sample_rate = sr;
    lw->frame_samples = floor(sr / AERO_LEAFWAVE_FRAME_RATE + 0.5);
    lw->to_next_frame = lw->frame_samples;
    aero_leafwave_set_ramp_ms(lw, ramp_ms);
    leafwave_reset_voices(lw);
    return 0;
}

int aero_leafwave_set_wind(aero_leafwave *lw, double vx, double vy, double vz)
{
    if (!aero_is_finite(vx) || !aero_is_finite(vy) || !aero_is_finite(vz))
        return -1;
    double v[3] = {vx, vy, vz}, s = sqrt(aero_dot3(v, v));
    double lim = AERO_MACH_LIMIT * AERO_C0;
    if (s > lim)
        for (int k = 0; k < 3; k++)
            v[k] *= lim / s;
    for (int k = 0; k < 3; k++) {
        lw->wind[k] = v[k];
        lw->speed_dir[k] = 0.0;
    }
    return s > lim ? -1 : 0;
}

int aero_leafwave_set_speed(aero_leafwave *lw, double speed)
{
    if (!aero_is_finite(speed))
        return -1;
    lw->inlet_speed = speed;
    return fabs(speed) > AERO_MACH_LIMIT * AERO_C0;
}

int aero_leafwave_set_direction(aero_leafwave *lw, double x, double y,
                                double z)
{
    double d[3] = {x, y, z};
    if (!aero_is_finite(x) || !aero_is_finite(y) || !aero_is_finite(z) ||
        !(aero_normalise3(d) > 0.0))
        return -1;
    for (int k = 0; k < 3; k++)
        lw->speed_dir[k] = d[k];
    return 0;
}

int aero_leafwave_set_ears(aero_leafwave *lw, const aero_ears *e)
{
    if (!aero_ears_ok(e, lw->n_ears))
        return -1;
    for (int ear = 0; ear < e->n; ear++) {
        memcpy(lw->ear_target[ear], e->pos[ear], sizeof(lw->ear_target[ear]));
        lw->ramp_left = lw->render_primed ? lw->ramp_samples : 0;
        if (!lw->render_primed)
            for (int k = 0; k < 3; k++)
                lw->ear[ear][k] = lw->ear_target[ear][k];
    }
    return 0;
}

int aero_leafwave_set_gain_db(aero_leafwave *lw, double db)
{
    return aero_set_gain_db(&lw->gain, db);
}

int aero_leafwave_set_ramp_ms(aero_leafwave *lw, double ms)
{
    if (aero_set_ramp_ms(&lw->ramp_samples, ms, lw->sample_rate))
        return -1;
    if (lw->ramp_samples < 1.0)
        lw->ramp_samples = 1.0;
    return 0;
}

int aero_leafwave_set_stiffness(aero_leafwave *lw, double s)
{
    if (aero_set_within(&lw->stiffness, s, AERO_TREE_STIFFNESS_MIN,
                        AERO_TREE_STIFFNESS_MAX))
        return -1;
    if (lw->has_motion)
        aero_tree_motion_set_stiffness(&lw->motion, s);
    return 0;
}

int aero_leafwave_set_beta(aero_leafwave *lw, double beta)
{
    if (aero_set_within(&lw->beta, beta, AERO_TREE_BETA_MIN,
                        AERO_TREE_BETA_MAX))
        return -1;
    if (lw->has_motion)
        aero_tree_motion_set_beta(&lw->motion, beta);
    return 0;
}

int aero_leafwave_set_mic(aero_leafwave *lw, double x, double y, double z)
{
    if (!aero_is_finite(x) || !aero_is_finite(y) || !aero_is_finite(z))
        return -1;
    lw->mic[0] = x;
    lw->mic[1] = y;
    lw->mic[2] = z;
    return 0;
}

int aero_leafwave_set_mic_k(aero_leafwave *lw, double k)
{
    return aero_set_within(&lw->mic_k, k, AERO_LEAFWAVE_MIC_K_MIN,
                           AERO_LEAFWAVE_MIC_K_MAX);
}

int aero_leafwave_set_sway(aero_leafwave *lw, double rad)
{
    return aero_set_within(&lw->sway, rad, AERO_LEAFWAVE_SWAY_MIN,
                           AERO_LEAFWAVE_SWAY_MAX);
}

int aero_leafwave_set_coupling(aero_leafwave *lw, double a)
{
    return aero_set_within(&lw->coupling, a, -AERO_LEAFWAVE_COUPLING_MAX,
                           AERO_LEAFWAVE_COUPLING_MAX);
}

int aero_leafwave_set_flutter(aero_leafwave *lw, double hz)
{
    return aero_set_within(&lw->flutter_hz, hz, AERO_LEAFWAVE_FLUTTER_MIN,
                           AERO_LEAFWAVE_FLUTTER_MAX);
}

int aero_leafwave_set_hit(aero_leafwave *lw, double pa)
{
    return aero_set_within(&lw->hit_pa, pa, AERO_LEAFWAVE_PA_MIN,
                           AERO_LEAFWAVE_PA_MAX);
}

int aero_leafwave_set_rub(aero_leafwave *lw, double pa)
{
    return aero_set_within(&lw->rub_pa, pa, AERO_LEAFWAVE_PA_MIN,
                           AERO_LEAFWAVE_PA_MAX);
}

int aero_leafwave_set_reach(aero_leafwave *lw, double factor)
{
    if (aero_set_within(&lw->reach, factor, AERO_LEAFWAVE_REACH_MIN,
                        AERO_LEAFWAVE_REACH_MAX))
        return -1;
    return leafwave_restart(lw, NULL, 0);
}

int aero_leafwave_set_tables(aero_leafwave *lw, double fm, int per_octave,
                             int octaves)
{
    if (!aero_leafwave_tables_valid(fm, per_octave, octaves))
        return -1;
    double old_fm = lw->fm;
    int old_n = lw->tables_per_octave, old_o = lw->octaves;
    lw->fm = fm;
    lw->tables_per_octave = per_octave;
    lw->octaves = octaves;
    if (leafwave_make_tables(lw)) {
        lw->fm = old_fm;
        lw->tables_per_octave = old_n;
        lw->octaves = old_o;
        return -1;
    }
    for (int i = 0; i < lw->nleaves; i++)
        lw->leaves[i].table = aero_leafwave_table_for(
            lw, lw->tree.leaves[i].length, lw->tree.leaves[i].width);
    leafwave_reset_voices(lw);
    return 0;
}

int aero_leafwave_set_voices(aero_leafwave *lw, int n)
{
    if (n < AERO_LEAFWAVE_VOICES_MIN || n > AERO_LEAFWAVE_VOICES_MAX)
        return -1;
    if (leafwave_replace_arrays((void **)&lw->voices,
                                sizeof(aero_leaf_voice) * n,
                                (void **)&lw->free_voices, sizeof(int) * n))
        return -1;
    lw->nvoices = n;
    leafwave_reset_voices(lw);
    return 0;
}

int aero_leafwave_set_seed(aero_leafwave *lw, uint32_t seed)
{
    lw->seed = seed;
    lw->rng = seed ? seed : 1;
    if (leafwave_make_tables(lw))
        return -1;
    return leafwave_restart(lw, NULL, 0);
}

void aero_leafwave_count_states(const aero_leafwave *lw, int counts[5])
{
    for (int s = 0; s < 5; s++)
        counts[s] = 0;
    for (int p = 0; p < lw->npairs; p++)
        counts[lw->pairs[p].state]++;
}

/* ---- loading in a worker, swapping in the host's thread ------------------ */

int aero_leafwave_tables_valid(double fm, int per_octave, int octaves)
{
    return aero_is_finite(fm) && fm >= AERO_LEAFWAVE_FM_MIN &&
        fm <= AERO_LEAFWAVE_FM_MAX &&
        per_octave >= AERO_LEAFWAVE_PER_OCTAVE_MIN &&
        per_octave <= AERO_LEAFWAVE_PER_OCTAVE_MAX &&
        octaves >= AERO_LEAFWAVE_OCTAVES_MIN &&
        octaves <= AERO_LEAFWAVE_OCTAVES_MAX &&
        per_octave * octaves <= AERO_LEAFWAVE_TABLES_MAX;
}

int aero_leafwave_reach_valid(double factor)
{
    double r = 0.0;
    return aero_set_within(&r, factor, AERO_LEAFWAVE_REACH_MIN,
                           AERO_LEAFWAVE_REACH_MAX) == 0;
}

void aero_leafwave_copy_settings(aero_leafwave *dst, const aero_leafwave *src)
{
    memcpy(dst->wind, src->wind, sizeof(dst->wind));
    dst->inlet_speed = src->inlet_speed;
    memcpy(dst->speed_dir, src->speed_dir, sizeof(dst->speed_dir));
    aero_leafwave_set_stiffness(dst, src->stiffness);
    aero_leafwave_set_beta(dst, src->beta);
    dst->sway = src->sway;
    dst->coupling = src->coupling;
    dst->flutter_hz = src->flutter_hz;
    dst->hit_pa = src->hit_pa;
    dst->rub_pa = src->rub_pa;
    dst->gain = src->gain;
    memcpy(dst->mic, src->mic, sizeof(dst->mic));
    dst->mic_k = src->mic_k;
    if (dst->nvoices != src->nvoices)
        aero_leafwave_set_voices(dst, src->nvoices);
    aero_leafwave_set_ramp_ms(dst, 1000.0 * src->ramp_samples /
                                       src->sample_rate);
    if (dst->n_ears == src->n_ears) {
        memcpy(dst->ear_target, src->ear_target, sizeof(dst->ear_target));
        memcpy(dst->ear, src->ear, sizeof(dst->ear));
        dst->ramp_left = src->ramp_left;
    }
}

int aero_leafwave_build(aero_leafwave *lw, const aero_leafwave *src,
                        const aero_leafwave_rebuild *want, aero_tree *t,
                        char *err, size_t errlen)
{
    if (aero_leafwave_init(lw, src->sample_rate, src->n_ears, want->seed)) {
        if (t)
            aero_tree_free(t);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    if ((want->fm != lw->fm || want->per_octave != lw->tables_per_octave ||
         want->octaves != lw->octaves) &&
        aero_leafwave_set_tables(lw, want->fm, want->per_octave,
                                 want->octaves)) {
        if (t)
            aero_tree_free(t);
        aero_leafwave_free(lw);
        snprintf(err, errlen, "out of memory for the tables");
        return -1;
    }
    lw->reach = want->reach; /* no tree yet: nothing to rebuild */
    aero_leafwave_copy_settings(lw, src);
    if (t && aero_leafwave_set_tree(lw, t, err, errlen)) {
        aero_leafwave_free(lw);
        return -1;
    }
    return 0;
}

void aero_leafwave_move(aero_leafwave *dst, aero_leafwave *src)
{
    *dst = *src;
    dst->motion.tree = &dst->tree; /* the motion points into its owner */
    memset(src, 0, sizeof(*src));
}
