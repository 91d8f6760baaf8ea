/* aero: the sound of leaves in the wind (Matsuyama et al. 2005, section
 * "Generation of Leaf Sound"), made fast enough for their large tree
 * (16380 leaves) in real time on one core.
 *
 * Leaves. Each leaf of the tree is a rectangular blade of length x width on
 * a stalk from s (on its branch) to e. The whole leaf swings rigidly about
 * s: lateral theta_x = W_x N_x(t), longitudinal theta_y = W_y N_y(t) and
 * torsion about the blade axis theta_r = W_r N_r(t) + a theta_x, the x-r
 * coupling of Matsuyama et al. (eqs. 9-13). N_* are unit-rms noises: each is
 * white noise through a damped resonance at the leaf's flutter frequency (a
 * leaf is a small spring-mass driven by turbulent buffeting), stepped at the
 * leaf frame rate. The amplitudes follow the wind's drag load, W ~ sway *
 * tanh((U/U0)^2 / stiffness): no wind, no motion. The stalk base rides on
 * the branch: it moves with aero_tree_motion_point() at the leaf's `along`
 * fraction, and the leaf turns with the branch (the smallest rotation from
 * the branch's rest axis to its moved axis), so the leaves follow the branch
 * motion of [treebranch~] exactly when both load the same tree with the same
 * seed and wind (tree_motion.h is deterministic in time).
 *
 * Pairs. Neighbour lists are built once at load from a k-d tree of the
 * blade centres (O(n log n) for any arrangement, leaves at one spot
 * included); each leaf keeps its nearest AERO_LEAFWAVE_MAX_NEIGHBOURS. Every frame, the blade
 * centre P_j of the neighbour is expressed in the blade frame of leaf i
 * (their eq. 15) and compared with an ellipsoid of the two blades' half
 * sizes (a thin one across the blade): inside is "A", outside "B" (their
 * fig. 12). The per-pair state machine is theirs: initial ->
 * contact (A) / non-contact (B); non-contact -A-> key on; key on -A->
 * contact, -B-> key off; contact -B-> key off; key off -A-> key on, -B->
 * non-contact.
 *
 * Sound. N wave tables per octave, octave count M, basic frequencies
 * f_i = fm 2^(i/N) (their eq. 14), made at init from seeded pink noise
 * whose spectrum starts at f_i. A leaf plays the table whose f_i is nearest
 * to c / size (size = sqrt(length width), c = AERO_LEAFWAVE_PITCH_HZ_M): small
 * blades sound higher. A key on raises an envelope in proportion to the
 * collision speed (the relative speed of the blades), starting at the
 * collision time interpolated within the frame and at a zero crossing of
 * the table (no click); contact plays the table at a speed set by the
 * sliding (in-plane) relative speed, with a level in proportion to it
 * (friction); key off lets the sound decay slowly (their fig. 13). The
 * sounding pairs share a fixed pool of voices (the quietest is replaced).
 *
 * Rendering (their section 5): the leaves' sound, as pressure
 * at 1 m, is delayed by the distance from the trunk (the midpoint of the
 * first root branch, their approximation and [treebranch~]'s) to each
 * ear, read with a moving stylus (Doppler for free),
 * scaled by 1/r (amplitude, not their 1/r^2 intensity
 * law) and by the cardioid microphone S(mu) = ((1 + cos mu)/2)^k, mu the
 * angle between the microphone's axis and the direction from the ear to
 * the trunk (their eq. 16, C = 0).
 *
 * Life cycle: init, set_tree (takes the tree), set_*, process, free.
 * No globals; everything allocated outside process. */
#ifndef AERO_LEAFWAVE_H
#define AERO_LEAFWAVE_H

#include "aero_ears.h"
#include "tree.h"
#include "tree_motion.h"

/* ranges of the settings, stated once: the core checks them, the hosts
   quote them (stiffness and beta: tree_motion.h; gain, ramp:
   aero_ranges.h) */
#define AERO_LEAFWAVE_SR_MIN 1000.0        /* Hz */
#define AERO_LEAFWAVE_SR_MAX 1e6
#define AERO_LEAFWAVE_MIC_K_MIN 0.0
#define AERO_LEAFWAVE_MIC_K_MAX 100.0
#define AERO_LEAFWAVE_SWAY_MIN 0.0         /* rad */
#define AERO_LEAFWAVE_SWAY_MAX 1.5
#define AERO_LEAFWAVE_COUPLING_MAX 10.0    /* and its negative */
#define AERO_LEAFWAVE_FLUTTER_MIN 0.01     /* Hz */
#define AERO_LEAFWAVE_FLUTTER_MAX 30.0
#define AERO_LEAFWAVE_PA_MIN 0.0          /* hit and rub, Pa */
#define AERO_LEAFWAVE_PA_MAX 100.0
#define AERO_LEAFWAVE_REACH_MIN 0.1
#define AERO_LEAFWAVE_REACH_MAX 10.0
#define AERO_LEAFWAVE_VOICES_MIN 1
#define AERO_LEAFWAVE_VOICES_MAX 65536
#define AERO_LEAFWAVE_FM_MIN 20.0          /* Hz, the wave tables' fm */
#define AERO_LEAFWAVE_FM_MAX 10000.0
#define AERO_LEAFWAVE_PER_OCTAVE_MIN 1     /* tables per octave */
#define AERO_LEAFWAVE_PER_OCTAVE_MAX 128
#define AERO_LEAFWAVE_OCTAVES_MIN 1
#define AERO_LEAFWAVE_OCTAVES_MAX 8
#define AERO_LEAFWAVE_TABLES_MAX 512       /* per octave x octaves */
/* defaults (stiffness and beta: tree_motion.h; gain and ramp:
   aero_ranges.h) */
#define AERO_LEAFWAVE_MIC_K_DEFAULT 1.0     /* a cardioid */
#define AERO_LEAFWAVE_SWAY_DEFAULT 0.6      /* rad */
#define AERO_LEAFWAVE_COUPLING_DEFAULT 0.5
#define AERO_LEAFWAVE_FLUTTER_DEFAULT 2.0   /* Hz */
#define AERO_LEAFWAVE_HIT_DEFAULT 0.01      /* Pa */
#define AERO_LEAFWAVE_RUB_DEFAULT 0.003     /* Pa */
#define AERO_LEAFWAVE_REACH_DEFAULT 1.5
#define AERO_LEAFWAVE_VOICES_DEFAULT 256
#define AERO_LEAFWAVE_FM_DEFAULT 200.0      /* Hz */
#define AERO_LEAFWAVE_PER_OCTAVE_DEFAULT 12
#define AERO_LEAFWAVE_OCTAVES_DEFAULT 4
/* 10 m in front of the trunk, at ear height; stereo: ears at
   x -+AERO_EAR_HALF_SPACING */
#define AERO_LEAFWAVE_LISTENER_DEFAULT {0.0, -10.0, 1.7} /* m */

#include <stddef.h>
#include <stdint.h>

#define AERO_LEAFWAVE_FRAME_RATE 100.0   /* leaf frames per second */
#define AERO_LEAFWAVE_MAX_NEIGHBOURS 8   /* per leaf, nearest first */
#define AERO_LEAFWAVE_TABLE_LEN 16384    /* samples per wave table */
#define AERO_LEAFWAVE_TABLE_RATE 48000.0 /* rate the tables are made at */
#define AERO_LEAFWAVE_PITCH_HZ_M 40.0    /* basic frequency x blade size */
#define AERO_LEAFWAVE_MAX_DISTANCE 1000.0 /* m, longest delay kept */
#define AERO_LEAFWAVE_MAX_EARS 2
#define AERO_LEAFWAVE_FLUTTER_CLASSES 8

/* pair states (Matsuyama et al. 2005, fig. 12) */
enum {
    AERO_LEAFWAVE_PAIR_INITIAL,
    AERO_LEAFWAVE_PAIR_NONCONTACT,
    AERO_LEAFWAVE_PAIR_KEYON,
    AERO_LEAFWAVE_PAIR_CONTACT,
    AERO_LEAFWAVE_PAIR_KEYOFF
};

typedef struct {
    /* rest geometry */
    float base[3];       /* stalk start s */
    float branch_rest[3]; /* the branch point it rides on, at rest */
    float x[3], y[3], z[3]; /* rest frame: z along the leaf, y its normal */
    float reach;         /* stalk length + half the blade, m */
    float half_len, half_wid;
    int table;           /* wave table index */
    int flutter_class;
    /* noise resonators: two past values for N_x, N_y, N_r */
    float nx[2], ny[2], nr[2];
    /* now: blade centre, blade frame (t along, u across, n normal) */
    float p[3], t[3], u[3], n[3];
} aero_leaf_state;

typedef struct {
    int i, j;            /* leaf i is the instrument, j the input */
    int state;
    int voice;           /* -1: silent */
    float q;             /* ellipsoid measure at the last frame (<= 1: A) */
    float d[3];          /* P_j - P_i at the last frame, world frame */
} aero_leaf_pair;

typedef struct {
    int pair;            /* -1: free */
    int table;
    int wait;            /* samples before it starts (collision time) */
    double pos;          /* read position in the table, samples */
    double inc, inc_step; /* table samples per output sample, its ramp */
    float hit, hit_step, hit_decay; /* collision envelope */
    int attack_left;
    float rub, rub_step; /* friction level, ramped per frame */
    int releasing;
    float rel_decay;
} aero_leaf_voice;

typedef struct aero_leafwave {
    double sample_rate;
    int n_ears;
    uint32_t seed, rng;

    /* the tree and its branch motion (owned) */
    aero_tree tree;
    int has_tree;
    aero_tree_motion motion;
    int has_motion;
    double *branch_rot;  /* per branch, its rotation now (row-major 3x3) */

    int nleaves, npairs;
    aero_leaf_state *leaves;
    aero_leaf_pair *pairs;
    double crown[3];     /* centroid of the blade centres at rest */
    double source[3];    /* where distances are measured from: the trunk */

    /* wave tables */
    int tables_per_octave, octaves, ntables;
    double fm;
    float *tables;       /* ntables x (AERO_LEAFWAVE_TABLE_LEN + 1) */
    int *crossings;      /* zero crossings of every table, in order */
    int *crossing_start; /* table i's are crossings[start[i]..start[i+1]) */
    struct aero_fftw_c2r *fft; /* the FFTW plan that makes them */

    /* voices */
    int nvoices;
    aero_leaf_voice *voices;
    int *free_voices, nfree; /* stack of free voice indices */
    int steal_cursor;

    /* parameters */
    double wind[3];      /* from the `wind` message */
    double inlet_speed;  /* added along the wind's direction (or +x) */
    double speed_dir[3]; /* unit direction of the speed; 0 0 0: the wind's */
    double stiffness, beta;
    double sway;         /* rad, largest lateral amplitude */
    double coupling;     /* x-r coupling a (eq. 12) */
    double flutter_hz;   /* leaf resonance at no wind, stiffness 1 */
    double reach;        /* neighbour search factor */
    double hit_pa, rub_pa; /* Pa at 1 m per m/s of collision / sliding */
    double gain;         /* linear */
    double mic[3];       /* microphone axis (0 0 0: facing the trunk) */
    double mic_k;

    /* frame clock */
    double frame_samples;  /* output samples per leaf frame */
    double to_next_frame;  /* samples until the next frame */
    long frames;
    double flutter_coef[AERO_LEAFWAVE_FLUTTER_CLASSES][3]; /* a1, a2, g */
    int keyons_total;      /* key-on events since init (for tests) */

    /* the rendering delay line of the dry sound (pressure at 1 m) */
    float *line;           /* circular delay line */
    int line_len, line_pos;
    double ear[AERO_LEAFWAVE_MAX_EARS][3], ear_target[AERO_LEAFWAVE_MAX_EARS][3];
    double ramp_samples, ramp_left;
    double delay_prev[AERO_LEAFWAVE_MAX_EARS], amp_prev[AERO_LEAFWAVE_MAX_EARS];
    int render_primed;
    aero_near near; /* a listener came within 0.1 m (aero_near_field) */
} aero_leafwave;

/* Defaults: no tree (silent), listener AERO_LEAFWAVE_LISTENER_DEFAULT
 * (two ears AERO_EAR_HALF_SPACING to either side), wind 0, microphone facing the trunk, the constants
 * above (sway 0.6 rad, coupling 0.5, flutter 2 Hz, reach 1.5, fm 200 Hz,
 * 12 tables per octave over 4 octaves, 256 voices, hit 0.01 Pa, rub 0.003
 * Pa, k 1), stiffness and beta from tree_motion.h, gain and ramp from
 * aero_ranges.h.
 * A sample rate out of AERO_LEAFWAVE_SR_MIN..MAX is taken as
 * AERO_SAMPLE_RATE_FALLBACK. 0, or -1 when out of memory: the core is then
 * silent (no tables, no voices, no delay line) but safe to use: its
 * setters store or refuse, set_tree and the setters that rebuild refuse,
 * process writes zeros, free frees. */
int aero_leafwave_init(aero_leafwave *lw, double sample_rate, int n_ears,
                       uint32_t seed);
void aero_leafwave_free(aero_leafwave *lw);

/* Takes the tree (even on failure, when it is freed): builds the leaf
 * frames, neighbour lists, wave tables and the branch motion. A tree
 * without leaves is accepted (silent). 0, or -1 with a message. */
int aero_leafwave_set_tree(aero_leafwave *lw, aero_tree *t, char *err,
                           size_t errlen);
void aero_leafwave_clear_tree(aero_leafwave *lw);

/* Setters: 0 when accepted, -1 when invalid (the old value stays). */
int aero_leafwave_set_sample_rate(aero_leafwave *lw, double sr);
int aero_leafwave_set_wind(aero_leafwave *lw, double vx, double vy,
                           double vz);
/* the speed used when process gets none (NULL); 1 when it is beyond Mach
   0.3 (process clamps it) */
int aero_leafwave_set_speed(aero_leafwave *lw, double speed);
/* the direction the speed blows along, instead of the wind vector's own
   (a later set_wind goes back to the wind's); 0, or -1 when zero or not
   finite */
int aero_leafwave_set_direction(aero_leafwave *lw, double x, double y,
                                double z);
/* ears 0..e->n-1 (e->n at most the ears it was made with) */
int aero_leafwave_set_ears(aero_leafwave *lw, const aero_ears *e);
int aero_leafwave_set_gain_db(aero_leafwave *lw, double db);
int aero_leafwave_set_ramp_ms(aero_leafwave *lw, double ms);
int aero_leafwave_set_stiffness(aero_leafwave *lw, double s);
int aero_leafwave_set_beta(aero_leafwave *lw, double beta);
int aero_leafwave_set_mic(aero_leafwave *lw, double x, double y, double z);
int aero_leafwave_set_mic_k(aero_leafwave *lw, double k);
int aero_leafwave_set_sway(aero_leafwave *lw, double rad);
int aero_leafwave_set_coupling(aero_leafwave *lw, double a);
int aero_leafwave_set_flutter(aero_leafwave *lw, double hz);
int aero_leafwave_set_hit(aero_leafwave *lw, double pa);
int aero_leafwave_set_rub(aero_leafwave *lw, double pa);
/* these rebuild (neighbour lists, tables, voice pool): message domain */
int aero_leafwave_set_reach(aero_leafwave *lw, double factor);
int aero_leafwave_set_tables(aero_leafwave *lw, double fm, int per_octave,
                             int octaves);
/* the tables' settings, for a host that changes one of the three */
static inline void aero_leafwave_tables(const aero_leafwave *lw, double *fm,
                                        int *per_octave, int *octaves)
{
    *fm = lw->fm;
    *per_octave = lw->tables_per_octave;
    *octaves = lw->octaves;
}
int aero_leafwave_set_voices(aero_leafwave *lw, int n);
/* restarts motion, leaf noises and tables from the seed (time back to 0) */
int aero_leafwave_set_seed(aero_leafwave *lw, uint32_t seed);

/* basic frequency of table i: fm 2^(i/N) (eq. 14) */
double aero_leafwave_table_hz(const aero_leafwave *lw, int i);
/* table index for a blade of this length and width */
int aero_leafwave_table_for(const aero_leafwave *lw, double length,
                            double width);
const float *aero_leafwave_table(const aero_leafwave *lw, int i);

/* n samples; speed (m/s along the set direction, else the wind's; its
 * block's mean, NaN samples skipped; NULL: set_speed's, 0 until set) is
 * added to the wind; outs[ear] get the pressure in Pa. speed may alias
 * outs[0]. Returns 1 if the wind was clamped (Mach 0.3). */
int aero_leafwave_process(aero_leafwave *lw, const float *speed,
                          float *const *outs, int n);

/* number of pairs in each state now (tests, inspection) */
void aero_leafwave_count_states(const aero_leafwave *lw, int counts[5]);

/* For a host that builds a new core in a worker and swaps it in (Pd's
 * [leafwave~]). What rebuilds the tables or the neighbour lists: */
typedef struct {
    double fm;
    int per_octave, octaves;
    double reach;
    uint32_t seed;
} aero_leafwave_rebuild;
/* the checks of set_tables and set_reach, without setting: 1 valid */
int aero_leafwave_tables_valid(double fm, int per_octave, int octaves);
int aero_leafwave_reach_valid(double factor);
/* src's settings that rebuild nothing (wind, speed, ears, gain, ramp,
   stiffness, beta, mic, sway, coupling, flutter, hit, rub, voices) given
   to dst, reading only src's numbers (src may be a copy of a live core
   made in the host's thread) */
void aero_leafwave_copy_settings(aero_leafwave *dst, const aero_leafwave *src);
/* a new core in lw (initialised here) with src's settings, `want`'s
   tables, reach and seed, and the tree t (taken; NULL: none): what a
   worker runs; 0, or -1 with err (lw is then freed) */
int aero_leafwave_build(aero_leafwave *lw, const aero_leafwave *src,
                        const aero_leafwave_rebuild *want, aero_tree *t,
                        char *err, size_t errlen);
/* moves src's whole state into dst (dst's own is overwritten, not freed);
   src is left empty */
void aero_leafwave_move(aero_leafwave *dst, aero_leafwave *src);

#endif
