/* aerotex: what every command shares (clocks, the progress bar, the job
 * of a texture command and its parallel tasks); apart from aerotex.c's
 * main() so that the fuzz harness of the option parser links them
 * (its `aero-fuzz: sources` lines, fuzz/fuzz_aerotex_args.c). */
#include "aerotex.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* --- clocks and the progress bar ----------------------------------------- */

static double clock_seconds(clockid_t id)
{
    struct timespec ts;
    clock_gettime(id, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

double aerotex_now(void)
{
    return clock_seconds(CLOCK_MONOTONIC);
}

double aerotex_cpu_now(void)
{
    return clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
}

/* draws the bar (at most every 0.25 s unless final) */
static void progress_draw(aerotex_progress *p, int final)
{
    double t = aerotex_now(), frac, eta;
    int bar = 30, fill;
    if (!p->show || (!final && t - p->last < 0.25))
        return;
    p->last = t;
    frac = p->total ? (double)p->done / p->total : 1.0;
    if (frac > 1.0 || final) frac = 1.0;
    fill = (int)(frac * bar + 0.5);
    eta = frac > 0.01 ? (t - p->t0) * (1.0 - frac) / frac : 0.0;
    fprintf(stderr, "\r%-*s%s[%.*s%*s] %3d%%  %s %dm%02ds ",
            p->what ? 14 : 0, p->what ? p->what : "", p->what ? " " : "",
            fill, "##############################", bar - fill, "",
            (int)(100.0 * frac), final ? "took" : "ETA",
            (int)((final ? t - p->t0 : eta) / 60.0),
            (int)fmod(final ? t - p->t0 : eta, 60.0));
    if (final) fprintf(stderr, "\n");
    fflush(stderr);
}

void aerotex_progress_start(aerotex_progress *p, const char *what, long total,
                            int quiet)
{
    p->what = what;
    p->total = total;
    p->done = 0;
    p->t0 = p->last = aerotex_now();
    p->show = !quiet && isatty(fileno(stderr));
    omp_init_lock(&p->plan);
}

void aerotex_progress_add(aerotex_progress *p, long n)
{
#pragma omp atomic
    p->done += n;
    if (p->show) {
#pragma omp critical(aerotex_progress)
        progress_draw(p, 0);
    }
}

void aerotex_progress_end(aerotex_progress *p)
{
    progress_draw(p, 1);
    omp_destroy_lock(&p->plan);
}

/* --- the job of a texture command ---------------------------------------- */

aerotex_loop_plan aerotex_plan_loop(int l0)
{
    aerotex_loop_plan p;
    p.xfade = l0 / 10 > 8 ? l0 / 10 : 8;
    p.lmin = (int)floor(0.95 * l0) > 2 ? (int)floor(0.95 * l0) : 2;
    p.lmax = (int)ceil(1.05 * l0);
    p.avail = p.lmax + p.xfade;
    return p;
}

int aerotex_job_parse(const aerotex_command *cmd, void *job, int argc,
                      char **argv)
{
    aerotex_job *j = job;
    aerotex_defaults(cmd, job);
    j->name = cmd->name;
    if (!j->threads)
        j->threads = omp_get_max_threads();
    if (aerotex_parse(cmd, job, argc, argv))
        return -1;
    /* rank 0 of a task farm speaks for the job */
    if (aerotex_farm_rank())
        j->quiet = 1;
    if (!j->out) {
        aerotex_error("%s: no output file: add -o FILE.wav", cmd->name);
        return -1;
    }
    return 0;
}

/* "aerotex ARGV..." */
static void command_line(char *buf, size_t len, int argc, char **argv)
{
    size_t used = 0;
    buf[0] = 0;
    for (int i = -1; i < argc && used < len; i++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s",
                                 i < 0 ? "aerotex" : " ",
                                 i < 0 ? "" : argv[i]);
}

int aerotex_job_start(aerotex_job *j, int argc, char **argv, int channels)
{
    int l0 = (int)lround(j->duration * j->rate);
    if (l0 < 64) {
        aerotex_error("%s: --duration %g s at --rate %g Hz is under 64 "
                      "samples", j->name, j->duration, j->rate);
        return 2;
    }
    j->loop = aerotex_plan_loop(l0);
    command_line(j->command, sizeof j->command, argc, argv);
#ifdef AEROTEX_NO_PNG
    if (j->png_dir) {
        aerotex_error("%s: --png: this aerotex is built without libpng",
                      j->name);
        return 2;
    }
#endif
    if (j->png_dir && aerotex_mkdir(j->png_dir) && errno != EEXIST) {
        aerotex_error("%s: can't create %s: %s", j->name, j->png_dir,
                      strerror(errno));
        return 1;
    }
    j->channels = channels;
    j->raw = calloc((size_t)j->loop.avail * channels, sizeof(float));
    if (!j->raw)
        return aerotex_job_fail(j, "out of memory");
    j->t_start = aerotex_now();
    return 0;
}

int aerotex_job_run(aerotex_job *j, int argc, char **argv, int channels,
                    int runs, size_t task_size, void *state,
                    int (*run)(void *state, void *tasks),
                    int (*write)(void *state, void *tasks))
{
    void *tasks = NULL;
    int status = aerotex_job_start(j, argc, argv, channels);
    if (!status && !(tasks = calloc((size_t)runs, task_size)))
        status = aerotex_job_fail(j, "out of memory");
    if (!status)
        status = run(state, tasks);
    /* a task farm's rank 0 holds every task's result (aerotex_farm.c) */
    if (!status && !aerotex_farm_rank()) {
        status = write(state, tasks);
        if (!status)
            aerotex_farm_done(j);
    }
    free(tasks);
    aerotex_job_end(j);
    return status;
}

int aerotex_job_fail(const aerotex_job *j, const char *message)
{
    aerotex_error("%s: %s", j->name, message);
    return 1;
}

void aerotex_job_end(aerotex_job *j)
{
    free(j->raw);
    j->raw = NULL;
}

int aerotex_job_threads(const aerotex_job *j, int n)
{
    return j->threads < n ? j->threads : n;
}

int aerotex_job_loop(aerotex_job *j)
{
    int len = aero_texture_best_loop(j->raw, j->channels, j->loop.lmin,
                                     j->loop.lmax, j->loop.xfade);
    aero_texture_crossfade(j->raw, j->channels, len, j->loop.xfade);
    return len;
}

void aerotex_job_fill(const aerotex_job *j, aero_texture *tex, int len)
{
    memcpy(tex->data, j->raw, sizeof(float) * (size_t)len * j->channels);
}

void aerotex_job_loop_meta(const aerotex_job *j, aero_texture *tex)
{
    aero_texture_setd(tex, "rate", j->rate);
    aero_texture_setd(tex, "frames", tex->frames);
    aero_texture_set(tex, "loop", "seamless");
    aero_texture_setd(tex, "xfade", j->loop.xfade);
}

int aerotex_job_save(const aerotex_job *j, aero_texture *tex)
{
    char err[512];
    aero_texture_set(tex, "command", j->command);
    if (aero_texture_save(j->out, tex, err, sizeof err)) {
        aerotex_error("%s", err);
        return 1;
    }
    return 0;
}

/* --- a job's parallel tasks ---------------------------------------------- */

void aerotex_plan_lock(void *ctx, int on)
{
    aerotex_task *t = ctx;
    if (on)
        omp_set_lock(&t->job->prog.plan);
    else
        omp_unset_lock(&t->job->prog.plan);
}

void aerotex_task_progress(aerotex_task *t, long step)
{
    long add = step - t->last_step;
    t->last_step = step;
    aerotex_progress_add(&t->job->prog, add);
}

int aerotex_task_snapshot_due(aerotex_task *t, long step)
{
    if (!t->job->png_dir || step < t->snap * t->snap_every)
        return 0;
    t->snap = step / t->snap_every + 1;
    return 1;
}

void aerotex_join(char *buf, size_t len, const double *x, int n,
                  const char *fmt)
{
    size_t used = 0;
    buf[0] = 0;
    for (int k = 0; k < n && used < len; k++) {
        used += (size_t)snprintf(buf + used, len - used, k ? "," : "");
        if (used < len)
            used += (size_t)snprintf(buf + used, len - used, fmt, x[k]);
    }
}
