/* aerotex: shared declarations of the command-line tool. */
#ifndef AEROTEX_H
#define AEROTEX_H

#include <omp.h>
#include <stddef.h>

/* subcommands: each returns the process exit status */
int aerotex_aeolian(int argc, char **argv, int cavity);
int aerotex_info(int argc, char **argv);
int aerotex_tree(int argc, char **argv); /* aerotex_tree.c */
int aerotex_vortex(int argc, char **argv); /* aerotex_vortex.c */
int aerotex_object(int argc, char **argv); /* aerotex_object.c */
/* field auralization (paper 002): aerotex_field.c */
int aerotex_field_demo(int argc, char **argv);
int aerotex_auralize(int argc, char **argv);

/* vorticity picture: w (U/d) on nx x ny cells, solid fraction for the
   body; writes an RGB PNG (row 0 at the bottom); 0 or -1 */
int aerotex_png_vorticity(const char *path, const float *w,
                          const float *solid, int nx, int ny, float wmax);

/* a progress bar on stderr for solvers running in parallel (OpenMP) */
typedef struct {
    long total, done;     /* solver steps */
    double t0, last;      /* aerotex_now() at the start, last drawn */
    int show;             /* draw at all (a terminal, no -q) */
    omp_lock_t plan;      /* FFTW's planner is not thread-safe */
} aerotex_progress;
/* monotonic seconds */
double aerotex_now(void);
/* draws the bar (at most every 0.25 s unless final) */
void aerotex_progress_show(aerotex_progress *p, int final);

/* the number after option argv[*i] into *x (advancing *i), checked
   against [lo, hi]: 0, or -1 with a message */
int aerotex_number(int argc, char **argv, int *i, double lo, double hi,
                   double *x);

/* the command line as one string, "aerotex ARGV..." (the `command`
   metadata of every texture) */
void aerotex_command_line(char *buf, size_t len, int argc, char **argv);

/* a seamless loop of about l0 frames: its length is searched in
   [lmin, lmax] (+-5 %) with xfade frames of cross-fade, so the simulation
   must deliver lmax + xfade frames */
typedef struct {
    int xfade, lmin, lmax, avail;
} aerotex_loop_plan;
aerotex_loop_plan aerotex_plan_loop(int l0);

/* messages on stderr, prefixed "aerotex: " */
void aerotex_error(const char *fmt, ...);

#endif
