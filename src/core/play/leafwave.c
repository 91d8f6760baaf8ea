/* aero: leaves in the wind (see leafwave.h; Matsuyama et al. 2005, sections
 * "Generation of Leaf Sound" and "Sound Rendering"; the equations and
 * figures cited below are theirs). */
#include "leafwave_internal.h"
#include "aero_air.h"
#include "aero_util.h"

#include "aero_fftw.h"
#include "aero_ramp.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The parts: leafwave_leaves.c (leaves on the tree, their contacts),
 * leafwave_pairs.c (neighbour pairs by a spatial hash), leafwave_tables.c
 * (wave tables and voices), leafwave_params.c (setters); this file holds
 * the life cycle and process. Their constants: leafwave_internal.h. */

/* ---- life cycle ---------------------------------------------------------- */

static void clear_line(aero_leafwave *lw)
{
    if (lw->line)
        memset(lw->line, 0, sizeof(float) * lw->line_len);
    lw->line_pos = 0;
}

int leafwave_alloc_line(aero_leafwave *lw, double sr)
{
    int len = (int)(AERO_LEAFWAVE_MAX_DISTANCE / AERO_C0 * sr) + 2 * DRY_CHUNK +
              8192;
    float *line = calloc((size_t)len, sizeof(float));
    if (!line)
        return -1;
    free(lw->line);
    lw->line = line;
    lw->line_len = len;
    lw->line_pos = 0;
    lw->render_primed = 0;
    return 0;
}

int aero_leafwave_init(aero_leafwave *lw, double sample_rate, int n_ears,
                       uint32_t seed)
{
    static const double listener[3] = AERO_LEAFWAVE_LISTENER_DEFAULT;
    memset(lw, 0, sizeof(*lw));
    if (!(sample_rate >= AERO_LEAFWAVE_SR_MIN &&
          sample_rate <= AERO_LEAFWAVE_SR_MAX))
        sample_rate = AERO_SAMPLE_RATE_FALLBACK;
    lw->sample_rate = sample_rate;
    lw->n_ears = n_ears == 2 ? 2 : 1;
    lw->seed = seed;
    lw->rng = seed ? seed : 1;
    lw->stiffness = AERO_TREE_STIFFNESS_DEFAULT;
    lw->beta = AERO_TREE_BETA_DEFAULT;
    lw->sway = AERO_LEAFWAVE_SWAY_DEFAULT;
    lw->coupling = AERO_LEAFWAVE_COUPLING_DEFAULT;
    lw->flutter_hz = AERO_LEAFWAVE_FLUTTER_DEFAULT;
    lw->reach = AERO_LEAFWAVE_REACH_DEFAULT;
    lw->hit_pa = AERO_LEAFWAVE_HIT_DEFAULT;
    lw->rub_pa = AERO_LEAFWAVE_RUB_DEFAULT;
    lw->gain = pow(10.0, AERO_GAIN_DB_DEFAULT / 20.0);
    lw->mic_k = AERO_LEAFWAVE_MIC_K_DEFAULT;
    lw->fm = AERO_LEAFWAVE_FM_DEFAULT;
    lw->tables_per_octave = AERO_LEAFWAVE_PER_OCTAVE_DEFAULT;
    lw->octaves = AERO_LEAFWAVE_OCTAVES_DEFAULT;
    lw->nvoices = AERO_LEAFWAVE_VOICES_DEFAULT;
    lw->frame_samples = floor(sample_rate / AERO_LEAFWAVE_FRAME_RATE + 0.5);
    lw->to_next_frame = lw->frame_samples;
    for (int e = 0; e < lw->n_ears; e++) {
        double x = lw->n_ears == 2
            ? (e ? AERO_EAR_HALF_SPACING : -AERO_EAR_HALF_SPACING) : 0.0;
        lw->ear[e][0] = lw->ear_target[e][0] = listener[0] + x;
        lw->ear[e][1] = lw->ear_target[e][1] = listener[1];
        lw->ear[e][2] = lw->ear_target[e][2] = listener[2];
    }
    lw->ramp_samples = AERO_RAMP_MS_DEFAULT / 1000.0 * sample_rate;
    lw->voices = malloc(sizeof(aero_leaf_voice) * lw->nvoices);
    lw->free_voices = malloc(sizeof(int) * lw->nvoices);
    if (!lw->voices || !lw->free_voices ||
        leafwave_alloc_line(lw, sample_rate) || leafwave_make_fft(lw) ||
        leafwave_make_tables(lw)) {
        aero_leafwave_free(lw);
        return -1;
    }
    leafwave_reset_voices(lw);
    return 0;
}

void aero_leafwave_clear_tree(aero_leafwave *lw)
{
    if (lw->has_motion)
        aero_tree_motion_free(&lw->motion);
    lw->has_motion = 0;
    if (lw->has_tree)
        aero_tree_free(&lw->tree);
    lw->has_tree = 0;
    leafwave_free_leaves(lw);
    leafwave_reset_voices(lw);
    clear_line(lw);
}

void aero_leafwave_free(aero_leafwave *lw)
{
    aero_leafwave_clear_tree(lw);
    free(lw->voices);
    free(lw->free_voices);
    free(lw->tables);
    leafwave_free_fft(lw);
    free(lw->crossings);
    free(lw->crossing_start);
    lw->crossings = lw->crossing_start = NULL;
    free(lw->branch_rot);
    lw->branch_rot = NULL;
    free(lw->line);
    lw->voices = NULL;
    lw->free_voices = NULL;
    lw->tables = NULL;
    lw->line = NULL;
    lw->nvoices = 0;
}

/* (re)starts the leaves and the branch motion of the current tree */
int leafwave_restart(aero_leafwave *lw, char *err, size_t errlen)
{
    if (lw->has_motion)
        aero_tree_motion_free(&lw->motion);
    lw->has_motion = 0;
    leafwave_free_leaves(lw);
    lw->frames = 0;
    lw->keyons_total = 0;
    lw->to_next_frame = lw->frame_samples;
    clear_line(lw);
    leafwave_reset_voices(lw);
    if (!lw->has_tree)
        return 0;
    free(lw->branch_rot);
    lw->branch_rot = malloc(sizeof(double) * 9 * lw->tree.nbranches);
    if (lw->branch_rot &&
        aero_tree_motion_init(&lw->motion, &lw->tree, lw->seed) == 0) {
        lw->has_motion = 1;
        aero_tree_motion_set_stiffness(&lw->motion, lw->stiffness);
        aero_tree_motion_set_beta(&lw->motion, lw->beta);
    }
    /* distances are measured to the trunk, as [treebranch~] does (the
       midpoint of the first root branch): both objects' sounds arrive
       together */
    for (int k = 0; k < 3; k++)
        lw->source[k] = 0.5 * (lw->tree.branches[0].a[k] +
                               lw->tree.branches[0].b[k]);
    lw->nleaves = lw->tree.nleaves;
    if (lw->nleaves > 0) {
        lw->leaves = calloc((size_t)lw->nleaves, sizeof(aero_leaf_state));
        if (!lw->leaves) {
            lw->nleaves = 0;
            if (err)
                snprintf(err, errlen, "out of memory for %d leaves",
                         lw->tree.nleaves);
            return -1;
        }
        leafwave_build_leaves(lw);
        if (leafwave_build_pairs(lw)) {
            leafwave_free_leaves(lw);
            if (err)
                snprintf(err, errlen, "out of memory for the neighbour lists");
            return -1;
        }
    }
    leafwave_reset_voices(lw);
    return 0;
}

int aero_leafwave_set_tree(aero_leafwave *lw, aero_tree *t, char *err,
                           size_t errlen)
{
    aero_leafwave_clear_tree(lw);
    if (!t)
        return 0;
    if (!lw->tables) { /* an init that ran out of memory */
        aero_tree_free(t);
        if (err)
            snprintf(err, errlen, "out of memory");
        return -1;
    }
    lw->tree = *t;
    memset(t, 0, sizeof(*t));
    lw->has_tree = 1;
    for (int i = 0; i < lw->tree.nleaves; i++) {
        int b = lw->tree.leaves[i].branch;
        if (b < 0 || b >= lw->tree.nbranches) {
            if (err)
                snprintf(err, errlen, "leaf %d names no branch", i);
            aero_leafwave_clear_tree(lw);
            return -1;
        }
    }
    if (leafwave_restart(lw, err, errlen)) {
        aero_leafwave_clear_tree(lw);
        return -1;
    }
    return 0;
}

/* ---- process -------------------------------------------------------------- */

/* cardioid of the microphone (eq. 16, C = 0): mu between its axis and the
   direction from the ear to the trunk; no axis: facing the tree */
static double mic_factor(const aero_leafwave *lw, const double ear[3])
{
    double to[3], axis[3] = {lw->mic[0], lw->mic[1], lw->mic[2]};
    for (int k = 0; k < 3; k++)
        to[k] = lw->source[k] - ear[k];
    if (aero_normalise3(axis) <= 0.0 || aero_normalise3(to) <= 0.0 ||
        lw->mic_k == 0.0)
        return 1.0;
    double c = 0.5 * (1.0 + aero_dot3(axis, to));
    return c <= 0.0 ? 0.0 : pow(c, lw->mic_k);
}

/* the wind now: the `wind` vector plus the inlet speed (the mean of the
   block, read before any output) along the set direction, else the
   wind's (+x without one),
   clamped at Mach 0.3; returns 1 when clamped */
static int wind_now(const aero_leafwave *lw, const float *speed, int n,
                    double w[3], double *u)
{
    double u_in = lw->inlet_speed;
    int clamped = 0;
    if (speed && n > 0) {
        double sum = 0.0;
        for (int s = 0; s < n; s++)
            sum += aero_speed_in(speed[s], &clamped);
        u_in = sum / n;
    }
    double dir[3] = {lw->wind[0], lw->wind[1], lw->wind[2]};
    if (aero_dot3(lw->speed_dir, lw->speed_dir) > 0.0) {
        for (int k = 0; k < 3; k++)
            dir[k] = lw->speed_dir[k];
    } else if (aero_normalise3(dir) <= 0.0) {
        dir[0] = 1.0;
        dir[1] = dir[2] = 0.0;
    }
    for (int k = 0; k < 3; k++)
        w[k] = lw->wind[k] + u_in * dir[k];
    double lim = AERO_MACH_LIMIT * AERO_C0;
    *u = sqrt(aero_dot3(w, w));
    if (!(*u > lim))
        return clamped;
    for (int k = 0; k < 3; k++)
        w[k] *= lim / *u;
    *u = lim;
    return 1;
}

/* AR(2) resonator x[n] = c1 x[n-1] + c2 x[n-2] + g w[n] at frequency f,
   damping zeta, frame rate fr; g makes x unit-rms for w uniform on [-1,1)
   (variance 1/3): gamma0 = (1 - c2) s2 / ((1 + c2)((1 - c2)^2 - c1^2)) */
static void resonator(double f, double fr, double coef[3])
{
    double w = 2.0 * AERO_PI * f / fr;
    if (w > 2.5)
        w = 2.5; /* below the frame Nyquist */
    double r = exp(-FLUTTER_DAMPING * w);
    double c1 = 2.0 * r * cos(w * sqrt(1.0 - FLUTTER_DAMPING * FLUTTER_DAMPING));
    double c2 = -r * r;
    double var = (1.0 - c2) / ((1.0 + c2) * ((1.0 - c2) * (1.0 - c2) - c1 * c1))
        / 3.0;
    coef[0] = c1;
    coef[1] = c2;
    coef[2] = 1.0 / sqrt(var);
}

/* leaf amplitudes follow the drag load U^2 (saturating), their flutter
   rate rises with the wind: the resonators of the flutter classes for
   wind speed u; returns the sway amplitude */
static double flutter_for_wind(aero_leafwave *lw, double u)
{
    double x = (u / WIND_REF) * (u / WIND_REF) / lw->stiffness;
    double f0 = lw->flutter_hz * sqrt(lw->stiffness) * (1.0 + u / FLUTTER_WIND);
    for (int c = 0; c < AERO_LEAFWAVE_FLUTTER_CLASSES; c++)
        resonator(f0 * 0.7 * pow(2.0, (double)c / (AERO_LEAFWAVE_FLUTTER_CLASSES - 1)),
                  lw->sample_rate / lw->frame_samples, lw->flutter_coef[c]);
    return lw->sway * tanh(x);
}

/* n samples of the leaves' sound, frame by frame, into the delay line */
static void render_dry(aero_leafwave *lw, double sway, int n)
{
    for (int done = 0; done < n;) {
        int seg = n - done;
        if (seg > DRY_CHUNK)
            seg = DRY_CHUNK;
        if (seg > (int)lw->to_next_frame)
            seg = (int)lw->to_next_frame;
        float dry[DRY_CHUNK];
        leafwave_render_voices(lw, dry, seg);
        for (int s = 0; s < seg; s++) {
            lw->line[lw->line_pos] = dry[s];
            if (++lw->line_pos == lw->line_len)
                lw->line_pos = 0;
        }
        if (lw->has_motion)
            aero_tree_motion_advance(&lw->motion, seg / lw->sample_rate);
        lw->to_next_frame -= seg;
        if (lw->to_next_frame <= 0.0) {
            lw->to_next_frame += lw->frame_samples;
            if (lw->nleaves > 0)
                leafwave_leaf_frame(lw, sway);
        }
        done += seg;
    }
}

/* the ears glide to their targets over the ramp */
static void glide_ears(aero_leafwave *lw, int n)
{
    if (!(lw->ramp_left > 0))
        return;
    aero_glide_values(&lw->ear[0][0], &lw->ear_target[0][0], 3 * lw->n_ears,
                      aero_glide_fraction(&lw->ramp_left, n));
}

/* ear e reads the line with a moving stylus: delay r / c0 interpolated
   over the block (Doppler), 1/r, the cardioid; the block was written from
   start_pos on */
static void read_ear(aero_leafwave *lw, int e, int start_pos, float *out,
                     int n)
{
    double max_delay = lw->line_len - 2.0 * DRY_CHUNK - 4096.0;
    double r = 0.0;
    for (int k = 0; k < 3; k++)
        r += (lw->ear[e][k] - lw->source[k]) * (lw->ear[e][k] - lw->source[k]);
    r = sqrt(r);
    double delay = clampd(r / AERO_C0 * lw->sample_rate, 1.0, max_delay);
    if (r < MIN_DISTANCE) /* the near-field policy (aero_near_field) */
        aero_near_seen(&lw->near, MIN_DISTANCE);
    double amp = lw->gain * mic_factor(lw, lw->ear[e]) /
                 (r > MIN_DISTANCE ? r : MIN_DISTANCE);
    if (!lw->render_primed) {
        lw->delay_prev[e] = delay;
        lw->amp_prev[e] = amp;
    }
    double d0 = lw->delay_prev[e], a0 = lw->amp_prev[e];
    for (int s = 0; s < n; s++) {
        double f = (s + 1.0) / n;
        double dl = d0 + f * (delay - d0);
        double rp = start_pos + s - dl;
        while (rp < 0.0)
            rp += lw->line_len;
        int i0 = (int)rp;
        double fr = rp - i0;
        if (i0 >= lw->line_len)
            i0 -= lw->line_len;
        int i1 = i0 + 1 == lw->line_len ? 0 : i0 + 1;
        double v = lw->line[i0] + fr * (lw->line[i1] - lw->line[i0]);
        double y = v * (a0 + f * (amp - a0));
        out[s] = aero_is_finite(y) ? (float)y : 0.0f;
    }
    lw->delay_prev[e] = delay;
    lw->amp_prev[e] = amp;
}

int aero_leafwave_process(aero_leafwave *lw, const float *speed,
                          float *const *outs, int n)
{
    double w[3], u;
    int clamped = wind_now(lw, speed, n, w, &u);
    if (!lw->tables || !lw->line) {
        /* an init that ran out of memory: silent */
        for (int e = 0; e < lw->n_ears; e++)
            memset(outs[e], 0, sizeof(float) * (size_t)n);
        return clamped;
    }
    if (lw->has_motion)
        aero_tree_motion_set_wind(&lw->motion, w);
    double sway = flutter_for_wind(lw, u);
    int start_pos = lw->line_pos;
    render_dry(lw, sway, n);
    glide_ears(lw, n);
    for (int e = 0; e < lw->n_ears; e++)
        read_ear(lw, e, start_pos, outs[e], n);
    lw->render_primed = 1;
    return clamped;
}
