/* unit tests of src/core/play/leafwave.c: the leaves of Matsuyama et al. 2005
 * (wave tables f_i = fm 2^(i/N), the per-pair state machine of fig. 12,
 * collisions as onsets, wind dependence, determinism by seed, neighbour lists
 * from the k-d tree against brute force, 1/r and the cardioid microphone). */
#include "../../src/core/play/leafwave.h"
#include "unit.h"
#include "multi_instance.h"

#include <fftw3.h>
#include <stdlib.h>
#include <string.h>

#define SR 48000.0
#define BLOCK 64

/* a small generated tree: 4 levels, 400 leaves of 8 x 5 cm */
static void small_tree(aero_tree *t, double leaf_scale)
{
    aero_tree_shape sh = {3, 400, 3.0, 0.08, 0.08 * leaf_scale,
                          0.05 * leaf_scale, 7};
    aero_tree_generate(t, &sh);
}

static void make(aero_leafwave *lw, double leaf_scale, uint32_t seed)
{
    aero_tree t;
    char err[128];
    small_tree(&t, leaf_scale);
    aero_leafwave_init(lw, SR, 1, seed);
    aero_leafwave_set_tree(lw, &t, err, sizeof err);
}

/* renders `seconds`; returns the rms in Pa; out (if given) gets the
   samples */
static double render(aero_leafwave *lw, double seconds, float *out)
{
    float buf[BLOCK];
    float *outs[1] = {buf};
    long n = (long)(seconds * SR) / BLOCK;
    double sum = 0.0;
    for (long b = 0; b < n; b++) {
        aero_leafwave_process(lw, NULL, outs, BLOCK);
        for (int s = 0; s < BLOCK; s++) {
            sum += (double)buf[s] * buf[s];
            if (out)
                out[b * BLOCK + s] = buf[s];
        }
    }
    return sqrt(sum / (n * BLOCK));
}

/* power spectrum of one table (FFTW), bin k at k * TABLE_RATE / LEN Hz */
static void table_power(const float *tab, double *power)
{
    int n = AERO_LEAFWAVE_TABLE_LEN;
    double *in = fftw_malloc(sizeof(double) * n);
    fftw_complex *out = fftw_malloc(sizeof(fftw_complex) * (n / 2 + 1));
    fftw_plan plan = fftw_plan_dft_r2c_1d(n, in, out, FFTW_ESTIMATE);
    for (int s = 0; s < n; s++)
        in[s] = tab[s];
    fftw_execute(plan);
    for (int k = 0; k <= n / 2; k++)
        power[k] = out[k][0] * out[k][0] + out[k][1] * out[k][1];
    fftw_destroy_plan(plan);
    fftw_free(in);
    fftw_free(out);
}

/* eq. 14: f_i = fm 2^(i/N); table i's spectrum starts at f_i (its
   strongest bin is the first at or above f_i, nothing below) */
UNIT_TEST(table_frequencies)
{
    aero_leafwave lw;
    aero_leafwave_init(&lw, SR, 1, 3);
    aero_leafwave_set_tables(&lw, 150.0, 6, 3);
    UNIT_CHECK(lw.ntables == 18, "N 6 per octave over 3 octaves: %d tables",
               lw.ntables);
    double df = AERO_LEAFWAVE_TABLE_RATE / AERO_LEAFWAVE_TABLE_LEN;
    double *power = malloc(sizeof(double) * (AERO_LEAFWAVE_TABLE_LEN / 2 + 1));
    int worst_i = -1;
    double worst = 0.0, leak = 0.0;
    for (int i = 0; i < lw.ntables; i++) {
        double want = 150.0 * pow(2.0, i / 6.0);
        table_power(aero_leafwave_table(&lw, i), power);
        int kmax = 1;
        double total = 0.0, below = 0.0;
        for (int k = 1; k <= AERO_LEAFWAVE_TABLE_LEN / 2; k++) {
            total += power[k];
            if (k * df < 0.97 * want)
                below += power[k];
            if (power[k] > power[kmax])
                kmax = k;
        }
        /* the table's basic frequency: its strongest bin (the pink
           spectrum falls from there), within one bin */
        double err = fabs(kmax * df - want);
        if (err > worst) {
            worst = err;
            worst_i = i;
        }
        if (below / total > leak)
            leak = below / total;
        UNIT_NEAR_REL(aero_leafwave_table_hz(&lw, i), want, 1e-12,
                      "aero_leafwave_table_hz = fm 2^(i/N)");
    }
    UNIT_CHECK(worst <= df, "every table's strongest bin within one bin "
               "(%.2f Hz) of fm 2^(i/N): worst %.2f Hz (table %d)", df, worst,
               worst_i);
    UNIT_CHECK(leak < 1e-6, "no power below f_i: worst fraction %.2g", leak);
    /* negative control: table 1 does not start at table 0's frequency */
    table_power(aero_leafwave_table(&lw, 1), power);
    int kmax = 1;
    for (int k = 1; k <= AERO_LEAFWAVE_TABLE_LEN / 2; k++)
        if (power[k] > power[kmax])
            kmax = k;
    UNIT_CHECK(fabs(kmax * df - 150.0) > df,
               "control: table 1 peaks at %.1f Hz, not at f_0 = 150 Hz",
               kmax * df);
    free(power);
    /* blade size -> table: twice the size, one octave down (N tables) */
    aero_leafwave_set_tables(&lw, 200.0, 12, 4);
    int a = aero_leafwave_table_for(&lw, 0.04, 0.03);
    int b = aero_leafwave_table_for(&lw, 0.08, 0.06);
    UNIT_CHECK(a - b == 12, "a blade twice as large plays 12 tables (one "
               "octave) lower: %d -> %d", a, b);
    UNIT_CHECK(aero_leafwave_table_for(&lw, 1e-6, 1e-6) == lw.ntables - 1 &&
                   aero_leafwave_table_for(&lw, 100, 100) == 0 &&
                   aero_leafwave_table_for(&lw, NAN, 1) == 0,
               "sizes beyond the range clamp to the end tables");
    aero_leafwave_free(&lw);
}

/* the transitions of fig. 12 */
static int allowed(int from, int to)
{
    switch (from) {
    case AERO_LEAFWAVE_PAIR_INITIAL:
        return to == AERO_LEAFWAVE_PAIR_CONTACT || to == AERO_LEAFWAVE_PAIR_NONCONTACT;
    case AERO_LEAFWAVE_PAIR_NONCONTACT:
        return to == AERO_LEAFWAVE_PAIR_NONCONTACT || to == AERO_LEAFWAVE_PAIR_KEYON;
    case AERO_LEAFWAVE_PAIR_KEYON:
        return to == AERO_LEAFWAVE_PAIR_CONTACT || to == AERO_LEAFWAVE_PAIR_KEYOFF;
    case AERO_LEAFWAVE_PAIR_CONTACT:
        return to == AERO_LEAFWAVE_PAIR_CONTACT || to == AERO_LEAFWAVE_PAIR_KEYOFF;
    case AERO_LEAFWAVE_PAIR_KEYOFF:
        return to == AERO_LEAFWAVE_PAIR_KEYON || to == AERO_LEAFWAVE_PAIR_NONCONTACT;
    }
    return 0;
}

UNIT_TEST(state_machine)
{
    aero_leafwave lw;
    make(&lw, 1.0, 11);
    aero_leafwave_set_wind(&lw, 8.0, 0.0, 0.0);
    int np = lw.npairs;
    int *prev = malloc(sizeof(int) * np);
    int seen[5][5];
    memset(seen, 0, sizeof seen);
    for (int p = 0; p < np; p++)
        prev[p] = lw.pairs[p].state;
    int bad = 0;
    float buf[480];
    float *outs[1] = {buf};
    for (int f = 0; f < 300; f++) { /* 3 s, one frame per call */
        aero_leafwave_process(&lw, NULL, outs, (int)lw.frame_samples);
        for (int p = 0; p < np; p++) {
            int s = lw.pairs[p].state;
            seen[prev[p]][s]++;
            if (!allowed(prev[p], s))
                bad++;
            prev[p] = s;
        }
    }
    UNIT_CHECK(bad == 0, "every transition is one of fig. 12 (%d were not)",
               bad);
    UNIT_CHECK(seen[AERO_LEAFWAVE_PAIR_INITIAL][AERO_LEAFWAVE_PAIR_NONCONTACT] > 0 &&
                   seen[AERO_LEAFWAVE_PAIR_INITIAL][AERO_LEAFWAVE_PAIR_CONTACT] > 0,
               "initial -> non-contact (%d) and -> contact (%d)",
               seen[0][1], seen[0][3]);
    UNIT_CHECK(seen[AERO_LEAFWAVE_PAIR_NONCONTACT][AERO_LEAFWAVE_PAIR_KEYON] > 0 &&
                   seen[AERO_LEAFWAVE_PAIR_KEYON][AERO_LEAFWAVE_PAIR_CONTACT] > 0 &&
                   seen[AERO_LEAFWAVE_PAIR_KEYON][AERO_LEAFWAVE_PAIR_KEYOFF] > 0 &&
                   seen[AERO_LEAFWAVE_PAIR_CONTACT][AERO_LEAFWAVE_PAIR_KEYOFF] > 0 &&
                   seen[AERO_LEAFWAVE_PAIR_KEYOFF][AERO_LEAFWAVE_PAIR_KEYON] > 0 &&
                   seen[AERO_LEAFWAVE_PAIR_KEYOFF][AERO_LEAFWAVE_PAIR_NONCONTACT] > 0,
               "in wind every transition occurs: non->on %d, on->contact "
               "%d, on->off %d, contact->off %d, off->on %d, off->non %d",
               seen[1][2], seen[2][3], seen[2][4], seen[3][4], seen[4][2],
               seen[4][1]);
    /* negative control: the checker refuses a jump fig. 12 does not have */
    UNIT_CHECK(!allowed(AERO_LEAFWAVE_PAIR_NONCONTACT, AERO_LEAFWAVE_PAIR_CONTACT) &&
                   !allowed(AERO_LEAFWAVE_PAIR_CONTACT, AERO_LEAFWAVE_PAIR_NONCONTACT),
               "control: non-contact <-> contact needs key on/off");
    free(prev);
    aero_leafwave_free(&lw);
}

/* no wind: the leaves stay apart, no key on, exact silence */
UNIT_TEST(still_air)
{
    aero_leafwave lw;
    make(&lw, 1.0, 4);
    double rms = render(&lw, 1.0, NULL);
    int counts[5];
    aero_leafwave_count_states(&lw, counts);
    UNIT_CHECK(rms == 0.0 && lw.keyons_total == 0,
               "no wind: rms %g Pa, %d key ons", rms, lw.keyons_total);
    UNIT_CHECK(counts[AERO_LEAFWAVE_PAIR_NONCONTACT] + counts[AERO_LEAFWAVE_PAIR_CONTACT] ==
                   lw.npairs,
               "no wind: pairs stay non-contact (%d) or contact (%d)",
               counts[AERO_LEAFWAVE_PAIR_NONCONTACT], counts[AERO_LEAFWAVE_PAIR_CONTACT]);
    aero_leafwave_free(&lw);
}

/* a collision is an onset: before the first key on the output is exactly
   0; the note starts at a zero crossing of its table, so its first
   samples are small against its peak */
UNIT_TEST(collision_onset)
{
    aero_leafwave lw;
    make(&lw, 1.0, 21);
    aero_leafwave_set_wind(&lw, 6.0, 0.0, 0.0);
    float buf[480];
    float *outs[1] = {buf};
    int fs = (int)lw.frame_samples, frame = -1;
    for (int f = 0; f < 300 && frame < 0; f++) {
        aero_leafwave_process(&lw, NULL, outs, fs);
        if (lw.keyons_total > 0)
            frame = f;
        else {
            double m = 0;
            for (int s = 0; s < fs; s++)
                m = fmax(m, fabs(buf[s]));
            if (m != 0.0) {
                UNIT_CHECK(0, "sound before any key on (frame %d)", f);
                break;
            }
        }
    }
    UNIT_CHECK(frame >= 0, "a key on within 3 s at 6 m/s (frame %d)", frame);
    /* find the voice and render its first samples (dry, through the
       voice only: its table start) */
    int v = -1;
    for (int k = 0; k < lw.nvoices; k++)
        if (lw.voices[k].table >= 0)
            v = k;
    UNIT_CHECK(v >= 0, "the key on started a voice");
    if (v >= 0) {
        const float *tab = aero_leafwave_table(&lw, lw.voices[v].table);
        double start = tab[(int)lw.voices[v].pos];
        UNIT_CHECK(fabs(start) < 0.1, "the note starts at a zero crossing: "
                   "table value %.3g (table rms 1)", start);
    }
    /* the onset: the next frames carry the sound */
    double peak = 0.0;
    long first = -1;
    for (int f = 0; f < 10; f++) {
        aero_leafwave_process(&lw, NULL, outs, fs);
        for (int s = 0; s < fs; s++) {
            if (first < 0 && buf[s] != 0.0f)
                first = (long)f * fs + s;
            peak = fmax(peak, fabs(buf[s]));
        }
    }
    UNIT_CHECK(peak > 0.0 && first >= 0, "the collision sounds: peak %g Pa, "
               "first sample %ld after the key-on frame", peak, first);
    aero_leafwave_free(&lw);
}

/* more wind: more collisions per second and a louder sound */
UNIT_TEST(wind)
{
    double winds[3] = {3.0, 6.0, 12.0}, keyons[3], level[3];
    for (int w = 0; w < 3; w++) {
        aero_leafwave lw;
        make(&lw, 1.0, 5);
        aero_leafwave_set_wind(&lw, winds[w], 0.0, 0.0);
        render(&lw, 0.5, NULL); /* settle */
        int k0 = lw.keyons_total;
        double rms = render(&lw, 2.0, NULL);
        keyons[w] = (lw.keyons_total - k0) / 2.0;
        level[w] = 20.0 * log10(rms / 2e-5);
        printf("  wind %4.1f m/s: %6.1f key ons/s, %5.1f dB SPL at 10 m\n",
               winds[w], keyons[w], level[w]);
        aero_leafwave_free(&lw);
    }
    UNIT_CHECK(keyons[0] < keyons[1] && keyons[1] < keyons[2],
               "key ons per second grow with wind: %.1f < %.1f < %.1f",
               keyons[0], keyons[1], keyons[2]);
    /* the margin: doubling the wind doubles the leaves' speeds at least
       (amplitude ~ U^2 before saturation), so at least +3 dB */
    UNIT_CHECK(level[1] > level[0] + 3.0 && level[2] > level[1] + 3.0,
               "louder with wind: %.1f, %.1f, %.1f dB", level[0], level[1],
               level[2]);
    /* the inlet speed adds along the wind's direction: the same result */
    aero_leafwave a, b;
    make(&a, 1.0, 5);
    make(&b, 1.0, 5);
    aero_leafwave_set_wind(&a, 6.0, 0.0, 0.0);
    float speed[BLOCK], ba[BLOCK], bb[BLOCK];
    float *oa[1] = {ba}, *ob[1] = {bb};
    for (int s = 0; s < BLOCK; s++)
        speed[s] = 6.0f;
    double diff = 0.0;
    for (int k = 0; k < 2000; k++) {
        aero_leafwave_process(&a, NULL, oa, BLOCK);
        aero_leafwave_process(&b, speed, ob, BLOCK);
        for (int s = 0; s < BLOCK; s++)
            diff = fmax(diff, fabs(ba[s] - bb[s]));
    }
    UNIT_CHECK(diff == 0.0 && a.keyons_total > 0, "inlet speed 6 = wind 6 0 0 "
               "(max difference %g, %d key ons)", diff, a.keyons_total);
    aero_leafwave_free(&a);
    aero_leafwave_free(&b);
}

/* friction plays the table at a speed set by the sliding speed: in more
   wind the blades in contact slide faster, so the contact voices' mean
   playback rate rises (a collision plays at rate 1) */
static double mean_contact_rate(double wind)
{
    aero_leafwave lw;
    make(&lw, 1.0, 13);
    aero_leafwave_set_wind(&lw, wind, 0.0, 0.0);
    float buf[480];
    float *outs[1] = {buf};
    double sum = 0.0;
    long n = 0;
    for (int f = 0; f < 300; f++) {
        aero_leafwave_process(&lw, NULL, outs, (int)lw.frame_samples);
        for (int v = 0; v < lw.nvoices; v++) {
            const aero_leaf_voice *vo = &lw.voices[v];
            if (vo->table < 0 || vo->pair < 0 ||
                lw.pairs[vo->pair].state != AERO_LEAFWAVE_PAIR_CONTACT)
                continue;
            /* the rate this voice reaches at the end of the frame */
            sum += (vo->inc + vo->inc_step * lw.frame_samples) * SR /
                   AERO_LEAFWAVE_TABLE_RATE;
            n++;
        }
    }
    aero_leafwave_free(&lw);
    return n ? sum / n : 0.0;
}

UNIT_TEST(friction_rate)
{
    double slow = mean_contact_rate(3.0), fast = mean_contact_rate(12.0);
    UNIT_CHECK(fast > 1.2 * slow && slow >= 0.25 && fast <= 2.0,
               "friction playback rate follows the sliding speed: %.3f x at "
               "3 m/s, %.3f x at 12 m/s (clamped to 0.25..2)", slow, fast);
}

/* determinism: the same seed gives the same samples, another seed not */
UNIT_TEST(seed)
{
    long n = (long)(1.0 * SR);
    float *x = malloc(sizeof(float) * n), *y = malloc(sizeof(float) * n),
          *z = malloc(sizeof(float) * n);
    aero_leafwave a, b, c;
    make(&a, 1.0, 77);
    make(&b, 1.0, 77);
    make(&c, 1.0, 78);
    aero_leafwave_set_wind(&a, 8.0, 2.0, 0.0);
    aero_leafwave_set_wind(&b, 8.0, 2.0, 0.0);
    aero_leafwave_set_wind(&c, 8.0, 2.0, 0.0);
    render(&a, 1.0, x);
    render(&b, 1.0, y);
    render(&c, 1.0, z);
    long same = 0, differ = 0;
    for (long s = 0; s < n; s++) {
        same += x[s] == y[s];
        differ += x[s] != z[s];
    }
    UNIT_CHECK(same == n, "same seed: identical samples (%ld of %ld)", same,
               n);
    UNIT_CHECK(differ > n / 2, "another seed: other samples (%ld differ)",
               differ);
    /* a seed message restarts from time 0: the same samples again */
    aero_leafwave_set_seed(&a, 77);
    render(&a, 1.0, z);
    same = 0;
    for (long s = 0; s < n; s++)
        same += x[s] == z[s];
    UNIT_CHECK(same == n, "seed 77 again restarts the same sound (%ld of %ld)",
               same, n);
    aero_leafwave_free(&a);
    aero_leafwave_free(&b);
    aero_leafwave_free(&c);
    free(x);
    free(y);
    free(z);
}

/* spectral centroid of a signal (FFTW, Hann segments of 4096) */
static double centroid(const float *x, long n)
{
    int m = 4096;
    double *in = fftw_malloc(sizeof(double) * m);
    fftw_complex *out = fftw_malloc(sizeof(fftw_complex) * (m / 2 + 1));
    fftw_plan plan = fftw_plan_dft_r2c_1d(m, in, out, FFTW_ESTIMATE);
    double num = 0.0, den = 0.0;
    for (long o = 0; o + m <= n; o += m / 2) {
        for (int s = 0; s < m; s++)
            in[s] = x[o + s] * (0.5 - 0.5 * cos(2.0 * 3.14159265358979 * s / m));
        fftw_execute(plan);
        for (int k = 1; k <= m / 2; k++) {
            double p = out[k][0] * out[k][0] + out[k][1] * out[k][1];
            num += p * k * SR / m;
            den += p;
        }
    }
    fftw_destroy_plan(plan);
    fftw_free(in);
    fftw_free(out);
    return den > 0.0 ? num / den : 0.0;
}

/* smaller blades, higher sound: the tables are chosen by blade size
   (f ~ 1/size), and a table's spectrum spans f_i..~8 f_i, so its centroid
   scales with f_i: twice, for half the size, less where the band meets
   the 10.8 kHz cut. The same tree with leaves half as large: the
   centroid rises by more than 1.3 (friction speeds and the different
   collisions spread it); the tables alone by more than 1.5 (a negative
   control: the same size gives the same table). */
UNIT_TEST(centroid_follows_size)
{
    long n = (long)(2.0 * SR);
    float *x = malloc(sizeof(float) * n), *y = malloc(sizeof(float) * n);
    aero_leafwave a, b;
    make(&a, 1.0, 9);
    make(&b, 0.5, 9);
    aero_leafwave_set_wind(&a, 10.0, 0.0, 0.0);
    aero_leafwave_set_wind(&b, 10.0, 0.0, 0.0);
    aero_leafwave_set_reach(&b, 3.0); /* small leaves: a wider search */
    render(&a, 2.0, x);
    render(&b, 2.0, y);
    double ca = centroid(x, n), cb = centroid(y, n);
    UNIT_CHECK(cb > 1.3 * ca, "blades half as large: centroid %.0f Hz > "
               "1.3 x %.0f Hz", cb, ca);
    /* the same from the tables alone */
    double *power = malloc(sizeof(double) * (AERO_LEAFWAVE_TABLE_LEN / 2 + 1));
    double cent[2];
    for (int k = 0; k < 2; k++) {
        int i = aero_leafwave_table_for(&a, 0.08 / (1 + k), 0.05 / (1 + k));
        table_power(aero_leafwave_table(&a, i), power);
        double num = 0.0, den = 0.0;
        for (int j = 1; j <= AERO_LEAFWAVE_TABLE_LEN / 2; j++) {
            num += power[j] * j;
            den += power[j];
        }
        cent[k] = num / den * AERO_LEAFWAVE_TABLE_RATE / AERO_LEAFWAVE_TABLE_LEN;
    }
    UNIT_CHECK(cent[1] > 1.5 * cent[0], "table centroid: 8 x 5 cm blade "
               "%.0f Hz, 4 x 2.5 cm blade %.0f Hz", cent[0], cent[1]);
    UNIT_CHECK(aero_leafwave_table_for(&a, 0.08, 0.05) ==
                   aero_leafwave_table_for(&a, 0.05, 0.08),
               "control: the same blade area, the same table");
    free(power);
    free(x);
    free(y);
    aero_leafwave_free(&a);
    aero_leafwave_free(&b);
}

/* the k-d tree's neighbour lists equal a brute-force search */
UNIT_TEST(neighbours)
{
    aero_leafwave lw;
    make(&lw, 1.0, 2);
    int n = lw.nleaves, missing = 0, extra = 0, brute_pairs = 0;
    char *in_list = calloc((size_t)n * n, 1);
    for (int p = 0; p < lw.npairs; p++)
        in_list[(size_t)lw.pairs[p].i * n + lw.pairs[p].j] = 1;
    /* brute force: each leaf's nearest MAX_NEIGHBOURS within reach */
    char *want = calloc((size_t)n * n, 1);
    for (int i = 0; i < n; i++) {
        int best[AERO_LEAFWAVE_MAX_NEIGHBOURS], nb = 0;
        double bestd[AERO_LEAFWAVE_MAX_NEIGHBOURS];
        for (int j = 0; j < n; j++) {
            if (j == i)
                continue;
            double d2 = 0.0;
            for (int k = 0; k < 3; k++) {
                double d = (double)lw.leaves[j].p[k] - lw.leaves[i].p[k];
                d2 += d * d;
            }
            double lim = lw.reach * (lw.leaves[i].reach + lw.leaves[j].reach);
            if (d2 > lim * lim)
                continue;
            int pos = nb;
            while (pos > 0 && bestd[pos - 1] > d2)
                pos--;
            if (pos >= AERO_LEAFWAVE_MAX_NEIGHBOURS)
                continue;
            int last = nb < AERO_LEAFWAVE_MAX_NEIGHBOURS ? nb
                                                     : AERO_LEAFWAVE_MAX_NEIGHBOURS - 1;
            for (int m = last; m > pos; m--) {
                best[m] = best[m - 1];
                bestd[m] = bestd[m - 1];
            }
            best[pos] = j;
            bestd[pos] = d2;
            if (nb < AERO_LEAFWAVE_MAX_NEIGHBOURS)
                nb++;
        }
        for (int m = 0; m < nb; m++) {
            int a = i < best[m] ? i : best[m], b = i < best[m] ? best[m] : i;
            want[(size_t)a * n + b] = 1;
        }
    }
    for (size_t k = 0; k < (size_t)n * n; k++) {
        brute_pairs += want[k];
        missing += want[k] && !in_list[k];
        extra += in_list[k] && !want[k];
    }
    UNIT_CHECK(missing == 0 && extra == 0 && brute_pairs == lw.npairs,
               "k-d tree neighbour lists = brute force: %d pairs, %d missing, "
               "%d extra", lw.npairs, missing, extra);
    free(in_list);
    free(want);
    aero_leafwave_free(&lw);
}

/* rendering: 1/r (-6 dB per doubling of distance) and the cardioid */
UNIT_TEST(rendering)
{
    double rms[3];
    double dist[3] = {5.0, 10.0, 20.0};
    for (int k = 0; k < 3; k++) {
        aero_leafwave lw;
        make(&lw, 1.0, 31);
        aero_leafwave_set_wind(&lw, 8.0, 0.0, 0.0);
        aero_leafwave_set_ears(&lw, &(aero_ears){1, {{lw.source[0],
                               lw.source[1] - dist[k], lw.source[2]}}});
        render(&lw, 0.1, NULL); /* past the longest delay */
        rms[k] = render(&lw, 2.0, NULL);
        aero_leafwave_free(&lw);
    }
    /* same dry sound, shifted by the delay: equal energy within a
       fraction of a dB over 2 s */
    UNIT_NEAR_REL(20 * log10(rms[1] / rms[0]), -6.02, 0.05,
                  "5 m -> 10 m, dB");
    UNIT_NEAR_REL(20 * log10(rms[2] / rms[1]), -6.02, 0.05,
                  "10 m -> 20 m, dB");
    /* cardioid S = ((1 + cos mu)/2)^k: facing 1, sideways 1/2, away 0 */
    double level[3];
    double axis[3][3] = {{0, 1, 0}, {1, 0, 0}, {0, -1, 0}};
    for (int k = 0; k < 3; k++) {
        aero_leafwave lw;
        make(&lw, 1.0, 31);
        aero_leafwave_set_wind(&lw, 8.0, 0.0, 0.0);
        aero_leafwave_set_ears(&lw, &(aero_ears){1, {{lw.source[0],
                               lw.source[1] - 5.0, lw.source[2]}}});
        aero_leafwave_set_mic(&lw, axis[k][0], axis[k][1], axis[k][2]);
        aero_leafwave_set_mic_k(&lw, 1.0);
        level[k] = render(&lw, 1.0, NULL);
        aero_leafwave_free(&lw);
    }
    UNIT_NEAR_REL(level[1] / level[0], 0.5, 1e-3,
                  "microphone sideways / facing the trunk (k = 1)");
    UNIT_CHECK(level[2] == 0.0 && level[0] > 0.0,
               "microphone turned away: %g Pa (facing %g Pa)", level[2],
               level[0]);
}

/* bad values are refused and change nothing; NaN speeds give silence,
   never NaN */
UNIT_TEST(bad_input)
{
    aero_leafwave lw;
    make(&lw, 1.0, 8);
    UNIT_CHECK(aero_leafwave_set_wind(&lw, NAN, 0, 0) == -1 &&
                   aero_leafwave_set_ears(&lw,
                           &(aero_ears){1, {{INFINITY, 0, 0}}}) == -1 &&
                   aero_leafwave_set_ears(&lw,
                           &(aero_ears){2, {{0, 0, 0}, {0, 0, 0}}}) == -1 &&
                   aero_leafwave_set_stiffness(&lw, 0) == -1 &&
                   aero_leafwave_set_beta(&lw, 7) == -1 &&
                   aero_leafwave_set_tables(&lw, 1e9, 12, 4) == -1 &&
                   aero_leafwave_set_reach(&lw, -1) == -1 &&
                   aero_leafwave_set_gain_db(&lw, NAN) == -1 &&
                   aero_leafwave_set_sample_rate(&lw, 0) == -1,
               "bad values are refused");
    float speed[BLOCK], buf[BLOCK];
    float *outs[1] = {buf};
    int bad = 0;
    for (int k = 0; k < 500; k++) {
        for (int s = 0; s < BLOCK; s++)
            speed[s] = k % 3 == 0 ? NAN : k % 3 == 1 ? 1e30f : -50.0f;
        aero_leafwave_process(&lw, speed, outs, BLOCK);
        for (int s = 0; s < BLOCK; s++)
            bad += !(fabs(buf[s]) < 1e3);
    }
    UNIT_CHECK(bad == 0, "NaN, 1e30 and -50 m/s speeds: %d bad samples", bad);
    /* no tree: silence */
    aero_leafwave_clear_tree(&lw);
    double rms = render(&lw, 0.2, NULL);
    UNIT_CHECK(rms == 0.0, "without a tree the object is silent (%g)", rms);
    aero_leafwave_free(&lw);
}

/* in step with [treebranch~]: the branch motion inside leafwave is the
   tree motion of the same tree, seed and wind, whatever the block size
   (tree_motion steps at a fixed rate): an independent aero_tree_motion
   advanced in other steps gives the same branch points */
UNIT_TEST(in_step)
{
    aero_leafwave lw;
    aero_tree t;
    aero_tree_motion m;
    make(&lw, 1.0, 123);
    small_tree(&t, 1.0);
    aero_tree_motion_init(&m, &t, 123);
    double wind[3] = {9.0, 3.0, 0.0};
    aero_leafwave_set_wind(&lw, wind[0], wind[1], wind[2]);
    aero_tree_motion_set_wind(&m, wind);
    render(&lw, 1.5, NULL);               /* 64-sample blocks */
    for (int k = 0; k < 150; k++)         /* 10 ms steps */
        aero_tree_motion_advance(&m, 0.01);
    double worst = 0.0, moved = 0.0;
    for (int i = 0; i < t.nbranches; i++) {
        double p1[3], v1[3], p2[3], v2[3];
        aero_tree_motion_point(&lw.motion, i, 1.0, p1, v1);
        aero_tree_motion_point(&m, i, 1.0, p2, v2);
        for (int k = 0; k < 3; k++) {
            worst = fmax(worst, fabs(p1[k] - p2[k]));
            moved = fmax(moved, fabs(p1[k] - t.branches[i].b[k]));
        }
    }
    UNIT_CHECK(worst < 1e-9 && moved > 1e-3, "same tree, seed and wind: "
               "branch tips agree within %.2g m (they moved up to %.3g m)",
               worst, moved);
    /* negative control: another seed sways otherwise */
    aero_tree_motion m2;
    aero_tree_motion_init(&m2, &t, 124);
    aero_tree_motion_set_wind(&m2, wind);
    for (int k = 0; k < 150; k++)
        aero_tree_motion_advance(&m2, 0.01);
    double other = 0.0;
    for (int i = 0; i < t.nbranches; i++) {
        double p1[3], v1[3], p2[3], v2[3];
        aero_tree_motion_point(&m, i, 1.0, p1, v1);
        aero_tree_motion_point(&m2, i, 1.0, p2, v2);
        for (int k = 0; k < 3; k++)
            other = fmax(other, fabs(p1[k] - p2[k]));
    }
    UNIT_CHECK(other > 1e-4, "control: seed 124 differs by %.3g m", other);
    aero_tree_motion_free(&m);
    aero_tree_motion_free(&m2);
    aero_tree_free(&t);
    aero_leafwave_free(&lw);
}

/* --- two instances at once (tests/unit/multi_instance.h) --- */
static void *mi_make(int variant)
{
    char err[128];
    aero_tree t;
    aero_leafwave *lw = calloc(1, sizeof(*lw));
    aero_leafwave_init(lw, 44100.0, 1, 13u + variant);
    aero_leafwave_set_tables(lw, 400.0, 4, 3);
    unit_mi_tree(&t, variant);
    aero_leafwave_set_tree(lw, &t, err, sizeof(err));
    aero_leafwave_set_ears(lw, &(aero_ears){1, {{0.0, variant ? -1.0 : -2.0,
                                                 1.5}}});
    return lw;
}
static void mi_run(void *s, const float *speed, float *out, int n)
{
    aero_leafwave_set_wind(s, 1.0, 0.0, 0.0);
    aero_leafwave_process(s, speed, (float *[]){out}, n);
}
static void mi_drop(void *s)
{
    aero_leafwave_free(s);
    free(s);
}

UNIT_TEST(multi_instance)
{
    unit_multi_instance("leafwave~", "a small tree", mi_make, mi_run,
                        mi_drop);
}

/* 20,000 leaves at one spot (a hostile file): every leaf keeps exactly
   its AERO_LEAFWAVE_MAX_NEIGHBOURS (all at distance 0, all within reach) and
   the list has each pair once. A spatial hash put them all in one cell and
   compared every leaf with every other: O(n^2). */
UNIT_TEST(neighbours_one_spot)
{
    const int n = 20000;
    aero_tree t;
    aero_leafwave lw;
    char err[256] = "";
    memset(&t, 0, sizeof t);
    t.nbranches = 1;
    t.branches = calloc(1, sizeof *t.branches);
    t.nleaves = n;
    t.leaves = calloc((size_t)n, sizeof *t.leaves);
    UNIT_CHECK(t.branches && t.leaves, "memory");
    if (!t.branches || !t.leaves)
        return;
    t.branches[0].parent = -1;
    t.branches[0].b[2] = 1.0;
    t.branches[0].d0 = t.branches[0].d1 = 0.1;
    for (int i = 0; i < n; i++) {
        aero_leaf *l = &t.leaves[i];
        l->s[2] = l->e[2] = 0.5;
        l->e[1] = 0.05;
        l->length = 0.1;
        l->width = 0.05;
        l->along = 0.5;
    }
    UNIT_CHECK(aero_leafwave_init(&lw, 48000.0, 1, 1) == 0, "init");
    int rc = aero_leafwave_set_tree(&lw, &t, err, sizeof err);
    UNIT_CHECK(rc == 0, "20,000 leaves at one spot load (%s)", err);
    int *count = calloc((size_t)n, sizeof(int)), fewer = 0, repeats = 0;
    for (int p = 0; rc == 0 && count && p < lw.npairs; p++) {
        count[lw.pairs[p].i]++;
        count[lw.pairs[p].j]++;
        if (p > 0 && lw.pairs[p].i == lw.pairs[p - 1].i &&
            lw.pairs[p].j == lw.pairs[p - 1].j)
            repeats++;
    }
    for (int i = 0; rc == 0 && count && i < n; i++)
        fewer += count[i] < AERO_LEAFWAVE_MAX_NEIGHBOURS;
    UNIT_CHECK(rc == 0 && fewer == 0 && repeats == 0 &&
                   lw.npairs >= n * AERO_LEAFWAVE_MAX_NEIGHBOURS / 2 &&
                   lw.npairs <= n * AERO_LEAFWAVE_MAX_NEIGHBOURS,
               "each leaf in at least %d pairs (%d leaves short), %d pairs, "
               "%d repeated", AERO_LEAFWAVE_MAX_NEIGHBOURS, fewer, lw.npairs,
               repeats);
    free(count);
    aero_leafwave_free(&lw);
}

/* An init that runs out of memory frees what it made, the state
 * aero_leafwave_free leaves (leafwave.c); the object must stay usable
 * and silent from there, as the wrapper keeps it (leafwave.h): setters
 * store or refuse, what needs the tables refuses, process writes zeros. */
UNIT_TEST(silent_after_failed_init)
{
    aero_leafwave lw;
    aero_tree t;
    char err[64] = "";
    UNIT_CHECK(aero_leafwave_init(&lw, 48000.0, 2, 3) == 0, "made");
    aero_leafwave_free(&lw); /* what a failed init leaves */
    UNIT_CHECK(aero_leafwave_set_gain_db(&lw, -6) == 0 &&
                   aero_leafwave_set_sway(&lw, 0.3) == 0 &&
                   aero_leafwave_set_wind(&lw, 10, 0, 0) == 0 &&
                   aero_leafwave_set_sample_rate(&lw, 44100.0) == 0 &&
                   aero_leafwave_set_voices(&lw, 8) == 0,
               "the plain setters still take their values");
    UNIT_CHECK(aero_leafwave_set_tables(&lw, 300, 6, 2) < 0 &&
                   aero_leafwave_set_seed(&lw, 9) < 0,
               "what rebuilds the tables is refused");
    unit_mi_tree(&t, 0);
    UNIT_CHECK(aero_leafwave_set_tree(&lw, &t, err, sizeof(err)) < 0,
               "a tree is refused (and freed): %s", err);
    float in[256], left[256], right[256];
    int loud = 0;
    for (int b = 0; b < 20; b++) {
        for (int i = 0; i < 256; i++)
            in[i] = 12.0f, left[i] = right[i] = 1.0f;
        aero_leafwave_process(&lw, in, (float *[]){left, right}, 256);
        for (int i = 0; i < 256; i++)
            loud += left[i] != 0.0f || right[i] != 0.0f;
    }
    UNIT_CHECK(loud == 0, "process writes zeros (%d samples not)", loud);
    aero_leafwave_free(&lw);
}

UNIT_MAIN(UNIT_CASE(table_frequencies), UNIT_CASE(state_machine), UNIT_CASE(still_air), UNIT_CASE(collision_onset), UNIT_CASE(wind), UNIT_CASE(friction_rate), UNIT_CASE(seed), UNIT_CASE(in_step), UNIT_CASE(centroid_follows_size), UNIT_CASE(neighbours), UNIT_CASE(neighbours_one_spot), UNIT_CASE(rendering), UNIT_CASE(bad_input), UNIT_CASE(silent_after_failed_init), UNIT_CASE(multi_instance))
