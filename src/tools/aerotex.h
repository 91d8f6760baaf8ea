/* aerotex: shared declarations of the command-line tool.
 *
 * Every command is an aerotex_command: a name, a one-line synopsis, what
 * it makes, and one option table from which both its parser
 * (aerotex_parse) and its part of `aerotex help` (aerotex_usage) come.
 * The commands that run solvers share one job (aerotex_job: output,
 * rate, duration, threads, the loop plan, the progress bar) and one task
 * per parallel run (aerotex_task: progress, FFTW planner lock, snapshot
 * schedule, error). */
#ifndef AEROTEX_H
#define AEROTEX_H

#include "texture.h"

#include <omp.h>
#include <stddef.h>
#include <stdio.h>
#include <sys/stat.h>

/* a folder (0 or -1 with errno): Windows' C library takes no mode */
#ifdef _WIN32
#include <direct.h>
#define aerotex_mkdir(path) _mkdir(path)
#else
#define aerotex_mkdir(path) mkdir(path, 0777)
#endif

/* --- option tables ----------------------------------------------------- */

typedef enum {
    AEROTEX_NUMBER,   /* double in [lo, hi] */
    AEROTEX_POSITIVE, /* double in (0, hi] */
    AEROTEX_WHOLE,    /* int, a whole number in [lo, hi] */
    AEROTEX_SEED,     /* uint32_t, a whole number in [0, 4294967295] */
    AEROTEX_TEXT,     /* const char *: a file or directory name */
    AEROTEX_CHOICE,   /* int: the index of the value among value "a|b|c" */
    AEROTEX_SWITCH,   /* int set to lo, no value */
    AEROTEX_CUSTOM    /* parse() reads the value(s) */
} aerotex_kind;

typedef struct aerotex_option {
    const char *name;   /* "--speed"; "" for the positional argument */
    aerotex_kind kind;
    const char *value;  /* the value's name in the usage ("m/s"); CHOICE:
                           the choices, "a|b|c" */
    double def;         /* the default, set before parsing; NAN: the
                           command's init sets it (core defaults) */
    double lo, hi;      /* range of numbers */
    size_t at;          /* destination: offset in the command's job */
    const char *help;   /* one line or two, '\n' between them */
    const char *shown;  /* the default as the usage says it; NULL: the
                           value at the destination after init */
    /* CUSTOM: reads argv[*i + 1...] into job, advancing *i; 0 or -1 with
       a message */
    int (*parse)(void *job, const char *cmd, int argc, char **argv, int *i);
} aerotex_option;

/* the last rows of a texture command's table (its job starts with an
   aerotex_job): what runs in parallel, what --png writes, -q, -o, the end */
#define AEROTEX_JOB_OPTIONS(runs, png)                                       \
    {"--threads", AEROTEX_WHOLE, "n", NAN, 1.0, 256.0,                       \
     offsetof(aerotex_job, threads), runs " run in parallel", "all cores",   \
     NULL},                                                                  \
    {"--png", AEROTEX_TEXT, "DIR", NAN, 0, 0, offsetof(aerotex_job, png_dir), \
     png, NULL, NULL},                                                       \
    {"-q", AEROTEX_SWITCH, NULL, NAN, 1, 0, offsetof(aerotex_job, quiet),    \
     "no progress bar", NULL, NULL},                                         \
    {"-o", AEROTEX_TEXT, "FILE.wav", NAN, 0, 0, offsetof(aerotex_job, out),  \
     "the texture", NULL, NULL},                                             \
    {NULL, 0, NULL, 0, 0, 0, 0, NULL, NULL, NULL}

typedef struct aerotex_command {
    const char *name;       /* "aeolian" */
    const char *synopsis;   /* after "aerotex NAME " in the usage */
    const char *about;      /* what it makes, a few lines */
    const aerotex_option *options; /* ends with name NULL; NULL: none */
    size_t job_size;        /* the job the options fill */
    void (*init)(void *job); /* defaults the table does not set (or NULL) */
    int (*run)(int argc, char **argv); /* the exit status */
} aerotex_command;

/* the commands (each file defines its own) */
extern const aerotex_command aerotex_aeolian_command, aerotex_cavity_command,
    aerotex_vortex_command, aerotex_object_command, aerotex_info_command,
    aerotex_tree_command, aerotex_field_demo_command,
    aerotex_auralize_command, aerotex_airfoil_command;

/* the table's defaults, then cmd->init, into job (cmd->job_size bytes) */
void aerotex_defaults(const aerotex_command *cmd, void *job);
/* argv[1..argc-1] into job by cmd's table: 0, or -1 with a message that
   names the option and the command */
int aerotex_parse(const aerotex_command *cmd, void *job, int argc,
                  char **argv);
/* cmd's part of `aerotex help`, from its table */
void aerotex_usage(FILE *f, const aerotex_command *cmd);

/* the number after argv[*i] into *x (advancing *i), checked against
   [lo, hi]: 0, or -1 with a message naming cmd and the option opt */
int aerotex_number(const char *cmd, const char *opt, int argc, char **argv,
                   int *i, double lo, double hi, double *x);

/* messages on stderr, prefixed "aerotex: " */
void aerotex_error(const char *fmt, ...);

/* --- clocks and the progress bar ----------------------------------------- */

/* monotonic seconds; processor seconds of this process (benchmark figures,
   which wall time would inflate on a shared machine) */
double aerotex_now(void);
double aerotex_cpu_now(void);

/* a progress bar on stderr, safe from parallel solvers (OpenMP) */
typedef struct {
    const char *what;     /* a label before the bar, or NULL */
    long total, done;     /* work units (solver steps, frames, samples) */
    double t0, last;      /* aerotex_now() at the start, last drawn */
    int show;             /* draw at all (a terminal, no -q) */
    omp_lock_t plan;      /* FFTW's planner is not thread-safe */
} aerotex_progress;
void aerotex_progress_start(aerotex_progress *p, const char *what, long total,
                            int quiet);
/* n more units done; redraws at most every 0.25 s */
void aerotex_progress_add(aerotex_progress *p, long n);
/* the final bar ("took"); releases the lock */
void aerotex_progress_end(aerotex_progress *p);

/* --- the job of a texture command ---------------------------------------- */

/* a seamless loop of about l0 frames: its length is searched in
   [lmin, lmax] (+-5 %) with xfade frames of cross-fade, so the simulation
   must deliver lmax + xfade frames */
typedef struct {
    int xfade, lmin, lmax, avail;
} aerotex_loop_plan;
aerotex_loop_plan aerotex_plan_loop(int l0);

typedef struct {
    const char *name;     /* the command, for messages */
    const char *out, *png_dir;
    double duration, rate;
    int threads, quiet;
    char command[4096];   /* "aerotex ARGV...", the `command` metadata */
    aerotex_loop_plan loop;
    float *raw;           /* loop.avail frames x channels, from the runs */
    int channels;
    aerotex_progress prog;
    double t_start;
} aerotex_job;

/* the table's defaults, cmd->init and the options into job (which starts
   with an aerotex_job), then -o required: 0, or -1 with a message */
int aerotex_job_parse(const aerotex_command *cmd, void *job, int argc,
                      char **argv);
/* after the command's own checks: duration * rate of 64 samples or more
   (else 2), the command line and the loop plan, the --png directory made
   and raw allocated (else 1), the clock started; 0 when the job can run.
   aerotex_job_end frees raw. */
int aerotex_job_start(aerotex_job *j, int argc, char **argv, int channels);
void aerotex_job_end(aerotex_job *j);
/* the stages of every texture command after its own checks: the job
   started with `channels`, `runs` zeroed tasks of task_size bytes, run()
   then write() on (state, tasks); the tasks freed and the job ended
   whatever happened. The exit status. */
int aerotex_job_run(aerotex_job *j, int argc, char **argv, int channels,
                    int runs, size_t task_size, void *state,
                    int (*run)(void *state, void *tasks),
                    int (*write)(void *state, void *tasks));
/* "NAME: message" on stderr: 1 (the exit status of a failed run) */
int aerotex_job_fail(const aerotex_job *j, const char *message);
/* the number of threads for n parallel runs */
int aerotex_job_threads(const aerotex_job *j, int n);
/* raw made a seamless loop: its length */
int aerotex_job_loop(aerotex_job *j);
/* the first len frames of raw into tex->data */
void aerotex_job_fill(const aerotex_job *j, aero_texture *tex, int len);
/* the loop's metadata: rate, frames, loop, xfade */
void aerotex_job_loop_meta(const aerotex_job *j, aero_texture *tex);
/* the command metadata, then the file: 0, or 1 with a message */
int aerotex_job_save(const aerotex_job *j, aero_texture *tex);

/* one of a job's parallel runs (a direction, a speed): the first member
   of a command's run context, which the solver's hooks receive */
typedef struct {
    aerotex_job *job;
    int index;
    long last_step;       /* progress counted up to this step */
    long snap_every, snap; /* --png: every snap_every steps; the next */
    char err[256];
} aerotex_task;
/* for the solvers' plan_lock: ctx is an aerotex_task (or starts with one) */
void aerotex_plan_lock(void *ctx, int on);
/* progress up to step */
void aerotex_task_progress(aerotex_task *t, long step);
/* a --png snapshot is due at step (then counted): 1 or 0 */
int aerotex_task_snapshot_due(aerotex_task *t, long step);

/* --- the task farm over MPI ranks (aerotex_farm.c) ------------------------

   Built with AEROTEX_MPI (build/aerotex-mpi, `make MPI=1` or mpicc found),
   each rank of `mpirun -np N aerotex-mpi CMD ...` runs the tasks k of a
   job with k % N == its rank (its threads inside, as in one process), and
   rank 0 gathers every task (its record and its channels) and writes the
   texture. Every finished task is also kept in OUT.ckpt/ (a checkpoint),
   so that a job killed by a scheduler resumes where it was; rank 0
   removes it once the texture is written. Without AEROTEX_MPI: one rank
   of one, no checkpoint. */

/* MPI_Init (MPI_THREAD_FUNNELED: only the main thread calls MPI) and
   MPI_Finalize around main; nothing without AEROTEX_MPI */
void aerotex_farm_init(int *argc, char ***argv);
void aerotex_farm_finalize(void);
int aerotex_farm_rank(void);
int aerotex_farm_size(void);
/* task k of n runs on this rank */
int aerotex_farm_mine(int k);
/* how many of n tasks run on this rank */
int aerotex_farm_count(int n);
/* task k (task_size bytes at task, channels k*width..k*width+width-1 of
   the job's raw) restored from the checkpoint: 1, or 0 (none, or one of
   another command line) */
int aerotex_farm_resume(aerotex_job *j, int k, void *task, size_t task_size,
                        int width);
/* task k kept in the checkpoint (after it ran without error) */
void aerotex_farm_keep(aerotex_job *j, int k, const void *task,
                       size_t task_size, int width);
/* every rank's tasks of n (each task_size bytes, its aerotex_task first)
   and their channels into rank 0's tasks and raw: the records after
   their aerotex_task member, and its err; 0, or 1 with a message */
int aerotex_farm_gather(aerotex_job *j, void *tasks, int n, size_t task_size,
                        int width);
/* the solver state of a task in the checkpoint (ctx: its aerotex_task),
   the hooks of aero_body_flow_params: kept (replacing the last), and
   loaded (1, or 0: none of this command line and size) */
void aerotex_farm_save_state(void *ctx, const void *state, size_t bytes);
int aerotex_farm_load_state(void *ctx, void *state, size_t bytes);
#ifdef AEROTEX_MPI
/* object --slabs: every rank's window state of task k (ctx: its
   aerotex_task), kept per rank; loaded (1) only when every rank has one
   of the same step (collective); dropped once the direction is done */
void aerotex_farm_save_slab_state(void *ctx, const void *state,
                                  size_t bytes);
int aerotex_farm_load_slab_state(void *ctx, void *state, size_t bytes);
void aerotex_farm_drop_slab_state(aerotex_job *j, int k);
#endif
/* rank 0's n bytes at p to every rank */
void aerotex_farm_share(void *p, size_t n);
/* the checkpoint removed (rank 0, after the texture is written) */
void aerotex_farm_done(aerotex_job *j);

/* x[0..n-1] as "a,b,c" with fmt per number */
/* aerotex info: the table of what a texture matches (aerotex_matches.c) */
void aerotex_print_matches(const aero_texture *t);
void aerotex_join(char *buf, size_t len, const double *x, int n,
                  const char *fmt);

/* vorticity picture: w (U/d) on nx x ny cells, solid fraction for the
   body; writes an RGB PNG (row 0 at the bottom); 0 or -1 */
int aerotex_png_vorticity(const char *path, const float *w,
                          const float *solid, int nx, int ny, float wmax);

#endif
