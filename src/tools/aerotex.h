/* aerotex: shared declarations of the command-line tool. */
#ifndef AEROTEX_H
#define AEROTEX_H

#include <omp.h>

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

/* messages on stderr, prefixed "aerotex: " */
void aerotex_error(const char *fmt, ...);

#endif
