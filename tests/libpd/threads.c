/* aero-libpd-threads: several Pd instances in several threads, the way a
 * multi-instance libpd host (PDINSTANCE, PDTHREADS: plugins, games) runs
 * them. The main thread registers aero once (aero_setup()), renders the
 * patch once in the main instance as the reference, makes one instance per
 * thread, and each thread opens the patch, renders, closes it, ROUNDS
 * times, all at once: every render must equal the reference bit for bit
 * (each instance is independent, whatever the others do). Run under
 * helgrind by tests/libpd/run.sh, which also judges the races.
 *
 *   aero-libpd-threads [-data DIR] THREADS ROUNDS TICKS PATCH
 *
 * Prints "ok ..." or "FAIL ..."; exit 0 when every render matched. */
#include "z_libpd.h"
#include "aero.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef PDINSTANCE
#error "build with -DPDINSTANCE -DPDTHREADS against a MULTI=true libpd"
#endif

#define RATE 48000
#define MAX_THREADS 16

typedef struct {
    t_pdinstance *pd;
    const char *dir, *name;
    int rounds, ticks;
    const float *reference;
    float *out;
    int mismatches, failures;
} job;

static void print_to_stderr(const char *s)
{
    fputs(s, stderr);
}

/* in the current instance: open, DSP on, TICKS blocks of audio, close */
static int render(const char *dir, const char *name, int ticks, float *out)
{
    void *patch = libpd_openfile(name, dir);
    if (!patch)
        return -1;
    libpd_start_message(1);
    libpd_add_float(1.0f);
    libpd_finish_message("pd", "dsp");
    libpd_process_float(ticks, NULL, out);
    libpd_closefile(patch);
    return 0;
}

static void *thread_main(void *arg)
{
    job *j = arg;
    size_t n = (size_t)j->ticks * libpd_blocksize() * 2;
    libpd_set_instance(j->pd);
    libpd_init_audio(0, 2, RATE);
    for (int r = 0; r < j->rounds; r++) {
        memset(j->out, 0, n * sizeof(float));
        if (render(j->dir, j->name, j->ticks, j->out))
            j->failures++;
        else if (memcmp(j->out, j->reference, n * sizeof(float)))
            j->mismatches++;
    }
    return NULL;
}

int main(int argc, char **argv)
{
    const char *data = NULL;
    int a = 1;
    if (argc > 2 && !strcmp(argv[1], "-data")) {
        data = argv[2];
        a = 3;
    }
    if (argc - a != 4) {
        fprintf(stderr, "usage: aero-libpd-threads [-data DIR] THREADS "
                        "ROUNDS TICKS PATCH\n");
        return 2;
    }
    int threads = atoi(argv[a]), rounds = atoi(argv[a + 1]);
    int ticks = atoi(argv[a + 2]);
    if (threads < 1 || threads > MAX_THREADS || rounds < 1 || ticks < 1) {
        fprintf(stderr, "aero-libpd-threads: 1..%d threads, rounds and "
                        "ticks >= 1\n", MAX_THREADS);
        return 2;
    }
    char dir[4096];
    const char *patch = argv[a + 3], *slash = strrchr(patch, '/');
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - patch) : 1,
             slash ? patch : ".");
    const char *name = slash ? slash + 1 : patch;

    libpd_set_printhook(print_to_stderr); /* before init: every instance's */
    libpd_init();
    aero_setup();
    if (data)
        aero_set_data_path(data);
    libpd_init_audio(0, 2, RATE);
    size_t n = (size_t)ticks * libpd_blocksize() * 2;
    float *reference = calloc(n, sizeof(float));
    if (!reference || render(dir, name, ticks, reference)) {
        printf("FAIL cannot render %s in the main instance\n", patch);
        return 1;
    }

    job jobs[MAX_THREADS];
    pthread_t tid[MAX_THREADS];
    for (int t = 0; t < threads; t++) {
        jobs[t] = (job){.pd = libpd_new_instance(), .dir = dir, .name = name,
                        .rounds = rounds, .ticks = ticks,
                        .reference = reference,
                        .out = calloc(n, sizeof(float))};
        if (!jobs[t].pd || !jobs[t].out) {
            printf("FAIL cannot make instance %d\n", t + 1);
            return 1;
        }
    }
    libpd_set_instance(libpd_main_instance());
    for (int t = 0; t < threads; t++)
        if (pthread_create(&tid[t], NULL, thread_main, &jobs[t])) {
            printf("FAIL cannot start thread %d\n", t + 1);
            return 1;
        }
    int mismatches = 0, failures = 0;
    for (int t = 0; t < threads; t++) {
        pthread_join(tid[t], NULL);
        mismatches += jobs[t].mismatches;
        failures += jobs[t].failures;
        libpd_free_instance(jobs[t].pd);
        free(jobs[t].out);
    }
    free(reference);
    int renders = threads * rounds;
    if (mismatches || failures) {
        printf("FAIL %d instances in %d threads x %d rounds of %s: %d renders "
               "differ from the main instance's, %d failed to open\n",
               threads, threads, rounds, name, mismatches, failures);
        return 1;
    }
    printf("ok %d instances in %d threads opened, rendered and closed %s %d "
           "times at once: all %d renders bit-identical to the main "
           "instance's\n", threads, threads, name, renders, renders);
    return 0;
}
