/* aero: the skeleton every Pd wrapper shares (src/pd/aero_pd.c).
 *
 * A wrapper is its struct, one table of messages, perform, dsp, new and
 * free. The table drives everything that used to be written per object:
 * class_addmethod for each message, the creation flags (`-name args` is the
 * message `name args`), and the list of flags named in errors. The base
 * struct holds what every object has: its canvas, mono or stereo, the
 * outlets and the Mach 0.3 clamp report. */
#ifndef AERO_PD_H
#define AERO_PD_H

#include "m_pd.h"
#include "g_canvas.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "aero.h"
#include "aero_ears.h"
#include "aero_ranges.h"
#include "load_job.h"
#include "texture.h"
#include "tree.h"

/* The only names an external (or the library) exports are Pd's entry
 * points, the *_setup functions: Pd loads externals with RTLD_GLOBAL, so
 * any other exported name could bind to another library's. The build hides
 * the rest (-fvisibility=hidden); on Windows a DLL with one dllexport
 * exports nothing else. */
#if defined(_WIN32)
#define AERO_PD_EXPORT __declspec(dllexport)
#elif defined(__GNUC__)
#define AERO_PD_EXPORT __attribute__((visibility("default")))
#else
#define AERO_PD_EXPORT
#endif

/* --- one table per object: its messages, each also a creation flag ------ */

typedef enum {
    AERO_PD_BANG,   /* fn(x) */
    AERO_PD_FLOAT,  /* fn(x, t_floatarg) */
    AERO_PD_SYMBOL, /* fn(x, t_symbol *) */
    AERO_PD_LIST,   /* fn(x, t_symbol *selector, int argc, t_atom *argv);
                       as a flag it takes `count` numbers */
    AERO_PD_SWITCH  /* a creation flag alone, no message (-stereo): new
                       reads it with aero_pd_has_flag */
} aero_pd_args;

enum {
    AERO_PD_EARLY = 1, /* as a flag, applied before all others (-d before
                          -texture, -n before -speeds) */
    AERO_PD_MESSAGE_ONLY = 2 /* no creation flag */
};

/* What a message accepts and what the object starts with, stated in the
 * table from the core's constants (the core's setter checks the same
 * constants, its init starts from the same defaults): the skeleton words
 * every refusal from it, the same way for every object (aero_pd_refused). */
typedef struct {
    double lo, hi;    /* accepted lo..hi; lo == hi: no range stated */
    const char *unit; /* "m", "dB", NULL for none */
    const char *note; /* what else the values mean ("0 = off"), or NULL */
    double def;       /* the default, when has_def */
    int has_def;
} aero_pd_rule;

/* a rule in a table line: AERO_PD_RANGE_DEF(AERO_GAIN_DB_MIN,
   AERO_GAIN_DB_MAX, AERO_GAIN_DB_DEFAULT, "dB") for a number the object
   starts with (its core's AERO_<OBJECT>_<SETTING>_DEFAULT);
   AERO_PD_RANGE_NOTE_DEF adds a note; AERO_PD_RANGE and AERO_PD_RANGE_NOTE
   for values without one default (a list, a count that depends on a
   file); AERO_PD_NOTE is a note alone (a list that must be finite, a
   direction); AERO_PD_NO_RULE for a message the core never refuses or
   words itself */
#define AERO_PD_RANGE_DEF(lo, hi, def, unit)                               \
    {(lo), (hi), (unit), NULL, (def), 1}
#define AERO_PD_RANGE_NOTE_DEF(lo, hi, def, unit, note)                    \
    {(lo), (hi), (unit), (note), (def), 1}
#define AERO_PD_RANGE(lo, hi, unit) {(lo), (hi), (unit), NULL, 0, 0}
#define AERO_PD_RANGE_NOTE(lo, hi, unit, note)                             \
    {(lo), (hi), (unit), (note), 0, 0}
#define AERO_PD_NOTE(note) {0, 0, NULL, (note), 0, 0}
#define AERO_PD_NO_RULE {0, 0, NULL, NULL, 0, 0}
/* the rules of the settings every player shares (aero_ranges.h) */
#define AERO_PD_GAIN                                                       \
    AERO_PD_RANGE_DEF(AERO_GAIN_DB_MIN, AERO_GAIN_DB_MAX,                  \
                      AERO_GAIN_DB_DEFAULT, "dB")
#define AERO_PD_RAMP                                                       \
    AERO_PD_RANGE_DEF(AERO_RAMP_MS_MIN, AERO_RAMP_MS_MAX,                  \
                      AERO_RAMP_MS_DEFAULT, "ms")
/* a switch: 0 off, 1 on, starting at def */
#define AERO_PD_ON_OFF(def)                                                \
    AERO_PD_RANGE_NOTE_DEF(0, 1, (def), NULL, "0 off, 1 on")
/* a constant as a string, for a note: AERO_PD_STR(AERO_LEAFWAVE_TABLES_MAX) */
#define AERO_PD_STR_(x) #x
#define AERO_PD_STR(x) AERO_PD_STR_(x)

typedef struct {
    const char *name; /* the message; "-name" is its creation flag */
    aero_pd_args args;
    int count;        /* AERO_PD_LIST: how many numbers the flag takes */
    t_method fn;
    int options;      /* AERO_PD_EARLY, AERO_PD_MESSAGE_ONLY */
    aero_pd_rule rule; /* what it accepts (numbers and lists) */
} aero_pd_method;

/* An object's class and its table. `name` is the Pd name ("cavity~"),
 * `first` a leading non-flag argument named in errors ("<treefile>") or
 * NULL. */
typedef struct {
    const char *name;
    const aero_pd_method *methods;
    int count;
    const char *first;
} aero_pd_spec;

#define AERO_PD_COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* class_new with the table's methods, `dsp`, the help symbol, and the
 * main signal inlet's float at `f_offset` (-1: no signal inlet) */
t_class *aero_pd_class_new(const aero_pd_spec *spec, t_newmethod new_fn,
                           t_method free_fn, size_t size, int f_offset,
                           t_method dsp_fn);

/* Applies the creation flags of the object of `b` (aero_pd_base_init
 * first): `-name args` calls the table's method as the message `name
 * args` would (EARLY ones first). Unknown flags and missing or wrong
 * values are reported, naming the object and its flags, and skipped: the
 * object is still created, with the default of a refused value. */
struct aero_pd_base;
void aero_pd_parse_flags(struct aero_pd_base *b, int argc, t_atom *argv);

/* is `-name` among the creation arguments (a SWITCH such as -stereo)? */
int aero_pd_has_flag(const char *name, int argc, const t_atom *argv);

/* A leading argument that is not a flag (a tree file, a volume folder):
 * returned and consumed, or NULL. */
t_symbol *aero_pd_first_symbol(int *argc, t_atom **argv);

/* --- the base every object embeds ----------------------------------------- */

/* An object's block: renders n samples in float from `in` (the main signal
 * inlet, NULL without one) into out[0] (and out[1] with -stereo, else
 * NULL); returns 1 when the core clamped a speed above Mach 0.3. */
typedef int (*aero_pd_process)(void *x, const float *in, float *const *out,
                               int n);

typedef struct aero_pd_base {
    t_object *owner;
    const aero_pd_spec *spec; /* the table: the rules of refusals */
    const char *flag; /* the creation flag being applied, or NULL */
    int flag_again;   /* an earlier flag already set the same thing */
    const char *obj;  /* "[cavity~]", for messages */
    t_canvas *canvas; /* where files are looked for first */
    int stereo;       /* created with -stereo: two outlets, `ears` */
    int clamped;      /* set by perform, reported once by the clock */
    const char *clamp_words; /* what the core clamps, when not a flow speed
                                at Mach 0.3 ("blade tips at Mach 0.9") */
    int warned_clamp;
    int ceiling_hit;  /* set by perform: the output guard acted */
    int has_file;     /* a texture or tree was loaded and plays: a refused
                         file leaves it playing */
    int file_tried;   /* a texture or tree was asked for */
    int warned_ceiling;
    int near_hit;     /* set by perform: a listener within the near-field
                         limit (aero_pd_near) */
    double near_m;    /* that limit, m */
    int warned_near;
    t_clock *clock;
    t_outlet *out[2];
    aero_pd_process process;
    float *scratch;   /* float signals for a double-precision Pd */
    int scratch_n;
} aero_pd_base;

/* Reads -stereo, keeps the current canvas, makes the clamp clock. */
void aero_pd_base_init(aero_pd_base *b, void *owner, const aero_pd_spec *spec,
                       int argc, const t_atom *argv);
/* one signal outlet, two with -stereo */
void aero_pd_base_outlets(aero_pd_base *b);
void aero_pd_base_free(aero_pd_base *b);

/* The dsp method's common part, after the object set its sample rate:
 * adds the one perform routine of every aero object, which calls
 * `process` on each block. `inlet`: the object has a main signal inlet.
 * The core computes in float: a double-precision Pd (PD_FLOATSIZE 64)
 * hands double buffers, converted here through float scratch allocated in
 * dsp, never in perform; with single precision Pd's own buffers pass
 * through (in and out may then be the same buffer: every core reads a
 * chunk of its input before it writes that chunk of its output). */
void aero_pd_dsp(aero_pd_base *b, t_signal **sp, int inlet,
                 aero_pd_process process);

/* The last guard at every object's output (aero_pd_guard, called by the
 * one perform routine on every block): no sample leaves an aero object
 * beyond AERO_PD_CEILING_PA, and NaN or an infinity leaves as 0. An
 * acoustic pressure amplitude beyond the ambient pressure, 101325 Pa
 * (194 dB SPL re 20 uPa), would need a negative absolute pressure in the
 * rarefaction: no sound in air reaches it, at any distance (Beranek and
 * Mellow 2012). A value there is a fault (a corrupt file, a runaway
 * state), so it is clamped and reported once per object. */
#define AERO_PD_CEILING_PA 101325.0f

/* Called by perform when the core clamped a speed above Mach 0.3: the
 * warning is posted once, from the clock (never from perform). */
static inline void aero_pd_clamped(aero_pd_base *b)
{
    if (!b->clamped) {
        b->clamped = 1;
        clock_delay(b->clock, 0);
    }
}

/* --- a listener at the source: one near-field policy ---------------------
 * Closer to a source than its near-field limit (about its size: the
 * compact far field does not hold inside it), a listener is heard as at
 * the limit along its own direction; exactly at the source, along the
 * source's lift (aero_near_field, src/core/common/aero_util.h; the limits
 * per object in docs/objects.md). Every object's process calls this with
 * its core's record; the first time a listener came within the limit, it
 * is reported once, from the clock (never from perform):
 * "[body~]: listener within 0.025 m of the source: heard as at 0.025 m (the
 * far field does not hold closer)". */
static inline void aero_pd_near(aero_pd_base *b, const aero_near *n)
{
    if (n->hit && !b->near_hit) {
        b->near_hit = 1;
        b->near_m = n->limit;
        clock_delay(b->clock, 0);
    }
}

/* --- refusals, worded from the table ------------------------------------- */

/* The rule of the message `name` in the object's table (the first line of
 * that name), or NULL. */
const aero_pd_rule *aero_pd_rule_of(const aero_pd_base *b, const char *name);

/* A number the core refused for the message `name`, worded from its rule:
 * "[cavity~]: length 500 m out of range (0.0001..100 m; default 0.02 m)".
 * The old value stays; from a creation flag, that is the default, and
 * the message says so: "...: flag -L ignored, the default stays". */
void aero_pd_refused(const aero_pd_base *b, const char *name, t_float f);

/* A list message (`wind`, `mic`, `pose`) the core refused:
 * "[body~]: wind out of range (0..1029 m/s; finite)" (from a creation
 * flag: "...: flag -wind ignored"). */
void aero_pd_refused_list(const aero_pd_base *b, const char *name);

/* A number from a patch as a whole number within the rule of `name`: 0
 * with *n set, else -1 (see aero_pd_whole). */
int aero_pd_whole_of(const aero_pd_base *b, const char *name, t_float f,
                     int *n);

/* A number from a patch checked against the rule of `name`: a float that
 * rounds to the same single-precision value as the rule's lo or hi is
 * that bound (Pd's 1e-05 is 9.99999975e-06 as a float, below the double
 * 1e-05: the stated minimum must be accepted); any other value as it is. */
double aero_pd_at_bound(const aero_pd_base *b, const char *name, t_float f);

/* One message per setter: `prefix_msg(x, f)` hands f to
 * `setter(&x->core, f)` (0 accepted, -1 refused) and reports a refusal
 * from the rule of `msg`; `type` is the object's struct. */
#define AERO_PD_SETTER(prefix, type, msg, core, setter)                    \
    static void prefix##_##msg(type *x, t_floatarg f)                      \
    {                                                                      \
        if (setter(&x->core, aero_pd_at_bound(&x->x_base, #msg, f)))      \
            aero_pd_refused(&x->x_base, #msg, f);                          \
    }

/* the same for a whole number within the rule's range */
#define AERO_PD_SETTER_WHOLE(prefix, type, msg, core, setter)              \
    static void prefix##_##msg(type *x, t_floatarg f)                      \
    {                                                                      \
        int n;                                                             \
        if (aero_pd_whole_of(&x->x_base, #msg, f, &n) ||                   \
            setter(&x->core, n))                                           \
            aero_pd_refused(&x->x_base, #msg, f);                          \
    }

/* `seed f` through aero_pd_seed_of (the one seed policy) to the core's
   int set_seed (0 accepted) */
#define AERO_PD_SEED_SETTER(prefix, type, core, setter)                    \
    static void prefix##_seed(type *x, t_floatarg f)                       \
    {                                                                      \
        uint32_t seed;                                                     \
        if (!aero_pd_seed_of(&x->x_base, f, &seed) &&                      \
            setter(&x->core, seed))                                        \
            aero_pd_refused(&x->x_base, "seed", f);                        \
    }

/* `listener x y z` (mono) or `ears lx ly lz rx ry rz` (-stereo): checks the
 * selector against the object's outlets and reads the numbers into e.
 * Returns the number of ears (1 or 2), or 0 after reporting an error. */
int aero_pd_ears(aero_pd_base *b, t_symbol *s, int argc, const t_atom *argv,
                 aero_ears *e);

/* the error for a listener or ears setter that refused the positions */
void aero_pd_bad_ears(aero_pd_base *b, int ears);

/* --- a wind along a direction ([treebranch~], [leafwave~]) ---------------
 * The inlet is the speed along the direction of the last `wind vx vy vz`
 * (+x until then); the cores take the block's mean. */
typedef struct {
    double dir[3]; /* unit vector */
} aero_pd_wind;

void aero_pd_wind_init(aero_pd_wind *w);
/* `wind vx vy vz`: keeps its direction (unless zero) and returns its
 * speed, or -1 after reporting an error */
double aero_pd_wind_message(aero_pd_base *b, aero_pd_wind *w, t_symbol *s,
                            int argc, const t_atom *argv);

/* --- a core rebuilt in a worker and swapped in ([treebranch~], [leafwave~])
 * A tree file read (or the live tree rebuilt) and a new core built in a
 * worker (load_job.h); Pd's clock swaps it in while the old core fades
 * out under it, so that Pd's thread, where audio runs too, never waits
 * for it. The object starts the job, takes it in its finish function
 * (called from the clock) and plays the old core, faded by
 * aero_pd_swap_gain, until it is dropped. */
#define AERO_PD_SWAP_FADE_MS 10.0 /* the old core fades out over this */
#define AERO_PD_SWAP_WAIT_MS 20.0 /* a job is swapped in this late, or later */
#define AERO_PD_SWAP_POLL_MS 5.0
/* bytes: a file read at creation, at once (the shipped trees; ~0.1 s for
   2 MB) */
#define AERO_PD_SWAP_SMALL_FILE (2L << 20)

typedef struct {
    void *owner;
    void (*finish)(void *owner); /* takes the finished job (swap_take) */
    void (*free_core)(void *core);
    aero_load_job *job;   /* the job running, or NULL */
    void *load;           /* its argument, the object's */
    t_symbol *next;       /* the latest 'open' asked during a job */
    t_clock *poll;
    double logical, real; /* when the job started: logical, real (s) */
    void *old;            /* the core fading out (malloc'd), or NULL */
    int fade, fade_len;   /* samples of the fade done, its length */
    int fade_seen;        /* fade at the last poll */
} aero_pd_swap;

void aero_pd_swap_init(aero_pd_swap *s, void *owner,
                       void (*finish)(void *owner),
                       void (*free_core)(void *core));
/* the clock freed, the old core dropped, a running job given up to
   drop_load (load_job.h: the worker calls it when done) */
void aero_pd_swap_free(aero_pd_swap *s, void (*drop_load)(void *load));
/* 1 when the file is small enough to read at creation, at once */
int aero_pd_swap_small(const char *path);
/* Starts fn(load): in a worker, swapped in by the clock
 * AERO_PD_SWAP_WAIT_MS later, or as soon after as it is ready (in batch
 * mode it waits for it then: the same logical time in every run); `now`,
 * in the caller, and finished at once (nothing played yet: no fade).
 * 0, or -1 when out of memory (nothing started, load still the
 * caller's). */
int aero_pd_swap_start(aero_pd_swap *s, aero_load_fn fn, void *load,
                       int now);
/* in finish: the job done (waited for), its load handed back */
void *aero_pd_swap_take(aero_pd_swap *s);
/* in finish, to swap a new core in: the old one dropped, a slot of
   `size` bytes for the live core to move into, faded out over
   AERO_PD_SWAP_FADE_MS at sr (NULL when out of memory: the live core is
   to be freed instead) */
void *aero_pd_swap_fade_slot(aero_pd_swap *s, size_t size, double sr);
void aero_pd_swap_drop_old(aero_pd_swap *s);
/* the old core's gain for its next sample: 1 down to 0 over the fade */
static inline float aero_pd_swap_gain(aero_pd_swap *s)
{
    float g = s->fade < s->fade_len
        ? 1.0f - (float)s->fade / s->fade_len : 0.0f;
    s->fade++;
    return g;
}

/* --- textures: one loader, one failure policy ------------------------------
 * A texture that can't be found or read, or that the core refuses, is
 * reported once (the name, the places looked in or the reason) and changes
 * nothing: the texture that played plays on (a performer's working state
 * is not lost to a typing error), and the message says so; an object
 * without one goes on with what it plays without one (`fallback`: "using
 * the Strouhal/Reynolds model", "silent"), and says that. A folder is
 * named as a folder. b->has_file is set when a texture was taken; a
 * wrapper that drops its texture (`model`) clears it. The loaded texture
 * is malloc'd: the core takes it and releases it with free(). */
typedef int (*aero_pd_set_texture)(void *core, aero_texture *t, char *err,
                                   size_t len);

void aero_pd_load_texture(aero_pd_base *b, t_class *cls, t_symbol *name,
                          aero_pd_set_texture set, void *core,
                          const char *fallback);

/* --- trees: one loader, one failure policy ---------------------------------
 * Finds a tree file (aero_pd_find_tree) and reads it. Each bad line is
 * reported with its line number and skipped, the first
 * AERO_PD_TREE_LINES_SHOWN of them, then how many more; a file that can't
 * be found or read, or holds no branch, is reported once, ending
 * "silent", or, when a tree plays (b->has_file), "the previous tree
 * stays". A file that is not text (a WAV given for a tree) or a folder is
 * named as such. Returns 0 with the tree in t, for the caller's core to
 * take (has_file is then set), or -1 after the report: the caller keeps
 * the tree it plays, if any. */
#define AERO_PD_TREE_LINES_SHOWN 20

int aero_pd_load_tree(aero_pd_base *b, t_class *cls, t_symbol *name,
                      aero_tree *t);

/* The same in three steps, so that the reading can run in a worker
 * thread: find (Pd's thread: the search path; -1 reported), read (any
 * thread: no Pd call; the bad lines are kept), report (Pd's thread: the
 * same words as aero_pd_load_tree; 0, or -1 when the read failed). */
typedef struct {
    char path[MAXPDSTRING];
    char err[MAXPDSTRING + 100];
    int bad, count;
    int line[AERO_PD_TREE_LINES_SHOWN];
    char message[AERO_PD_TREE_LINES_SHOWN][256];
} aero_pd_tree_file;
int aero_pd_tree_find(aero_pd_base *b, t_class *cls, t_symbol *name,
                      aero_pd_tree_file *r);
int aero_pd_tree_read(aero_pd_tree_file *r, aero_tree *t);
int aero_pd_tree_report(aero_pd_base *b, const aero_pd_tree_file *r);

/* --- no file given ----------------------------------------------------------
 * At the end of new, for an object that is silent without a file: when
 * none was asked for, one line says so and how to give one, the same words
 * from every object ("[body~]: no texture given: silent until 'texture
 * NAME'"). Not an error: an object may be made first and fed a file
 * later. */
void aero_pd_no_file(const aero_pd_base *b, const char *what,
                     const char *message);

/* --- numbers from a patch ------------------------------------------------- */

/* A default seed that differs between objects but is the same every time
 * the patch is loaded: from $0 and the object's index in its canvas. */
uint32_t aero_pd_default_seed(void);

/* A number from a patch as a 32-bit seed, the one seed policy of every
 * object: any finite number, its whole part modulo 2^32 (-5 is
 * 4294967291, 1e30 is 0: fmod is exact, no conversion out of range); NaN
 * and the infinities give 0 (aero_pd_seed_of refuses them). */
static inline uint32_t aero_pd_seed(t_float f)
{
    if (!(f > -HUGE_VAL && f < HUGE_VAL))
        return 0;
    return (uint32_t)(int64_t)fmod(trunc((double)f), 4294967296.0);
}

/* `seed f` of every object: 0 with *seed set; NaN or an infinity refused
 * (-1 after the report, from the rule AERO_PD_SEED) */
int aero_pd_seed_of(const struct aero_pd_base *b, t_float f, uint32_t *seed);

/* a core's init returned -1 in new(), at Pd's sample rate sr: either that
 * rate was not usable (the core takes its default rate, 44.1 or 48 kHz,
 * until the DSP starts) or memory ran out (the core is silent) */
void aero_pd_init_failed(const struct aero_pd_base *b, double sr);
/* a core's set_sample_rate returned -1 in dsp, at Pd's rate sr: out of the
 * core's range, or memory ran out making its buffers */
void aero_pd_rate_failed(const struct aero_pd_base *b, double sr);
#define AERO_PD_SEED                                                       \
    AERO_PD_NOTE("any finite number, its whole part modulo 2^32")

/* A number from a patch as a whole number in lo..hi: 0 with *n set, else
 * -1. NaN, infinities, fractions and numbers out of range are refused
 * before any conversion (a float outside int's range converted to int is
 * undefined behaviour). */
static inline int aero_pd_whole(t_float f, int lo, int hi, int *n)
{
    if (!(f >= lo && f <= hi) || f != floor(f))
        return -1;
    *n = (int)f;
    return 0;
}

/* the clock of a posed body's stream ([aeolian~], [body~]): when the
 * last pose came, when the last DSP block was performed, that block's
 * rate and size */
typedef struct {
    double pose_time, block_time, sr;
    int n;
} aero_pd_pose_clock;

static inline void aero_pd_pose_clock_init(aero_pd_pose_clock *c)
{
    c->pose_time = c->block_time = clock_getlogicaltime();
    c->sr = sys_getsr();
    c->n = sys_getblksize();
}

/* in the dsp method */
static inline void aero_pd_pose_clock_dsp(aero_pd_pose_clock *c,
                                          const t_signal *s)
{
    c->sr = s->s_sr;
    c->n = s->s_n;
}

/* in perform: the poses that follow count from here */
static inline void aero_pd_pose_clock_block(aero_pd_pose_clock *c)
{
    c->block_time = clock_getlogicaltime();
}

/* a pose now (place: a jump): the seconds since the previous pose (-1 for
 * a jump), and in *offset its sample in the next DSP block: the logical
 * time since the last block's, as [vline~] times its segments, in
 * [0, max(n, Pd's tick)): blocks of n smaller than the tick are all
 * performed at one logical time, and the player counts them off
 * (pose_glide.h) */
static inline double aero_pd_pose_clock_pose(aero_pd_pose_clock *c,
                                             int place, int *offset)
{
    double interval = clock_gettimesince(c->pose_time) * 0.001;
    double at = clock_gettimesince(c->block_time) * c->sr * 0.001;
    int limit = c->n > sys_getblksize() ? c->n : sys_getblksize();
    c->pose_time = clock_getlogicaltime();
    *offset = at > 0.0 ? (at < limit - 1 ? (int)at : limit - 1) : 0;
    return place ? -1.0 : interval;
}

/* pose|place x y z [rx ry rz | qw qx qy qz] (s the selector): a position
 * alone keeps the orientation `current` (w x y z); three more numbers are
 * a rotation vector (axis times angle in degrees), four a quaternion.
 * Writes the position, the quaternion (not yet normalised: the core's
 * setter does it and refuses a zero one), and the interval and block
 * offset of aero_pd_pose_clock_pose (place: a jump). 0, or -1 when refused
 * (reported, naming the object). [body~]'s and [rotor~]'s. */
int aero_pd_pose(aero_pd_base *b, aero_pd_pose_clock *c, t_symbol *s,
                 int argc, const t_atom *argv, const double current[4],
                 double pos[3], double q[4], double *interval, int *offset);

/* exactly `want` numbers from a message, else an error naming the object */
int aero_pd_floats(void *x, const char *obj, const char *what, int argc,
                   const t_atom *argv, int want, double *v);

/* --- files ----------------------------------------------------------------- */

/* Finds a data file (a texture in textures/, a tree in trees/), in this
 * order (docs/libpd.md):
 *   1. next to the patch, its [declare -path] folders and Pd's search path
 *      (canvas_open; a libpd host adds folders with libpd_add_to_search_path)
 *   2. DIR/`folder` for DIR in the AERO_DATA environment variable
 *   3. DIR/`folder` for the DIR a host set with aero_set_data_path() (aero.h)
 *   4. `folder` in the folder aero was loaded from (class_gethelpdir: the
 *      installed library; empty for classes a host registers itself).
 * `ext` (".wav") is appended unless the name has it. Writes the full path
 * and returns 0 when found; else -1 with the places it tried written to
 * `path`, for the caller's error message. */
int aero_pd_find_file(const t_canvas *canvas, const t_class *cls,
                      const char *name, const char *ext, const char *folder,
                      char *path, size_t len);

/* a texture (.wav): next to the patch, on the path, then in textures/ */
#define aero_pd_find_texture(canvas, cls, name, path, len)                 \
    aero_pd_find_file(canvas, cls, name, ".wav", "textures", path, len)

/* a tree file (.tree) the same way, then in trees/ */
#define aero_pd_find_tree(canvas, cls, name, path, len)                    \
    aero_pd_find_file(canvas, cls, name, ".tree", "trees", path, len)

#endif
