/* aero: loading work in a worker thread (see load_job.h). */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* pthreads */
#endif
#include "load_job.h"

#include <pthread.h>
#include <stdlib.h>

struct aero_load_job {
    pthread_mutex_t lock; /* guards done, result and drop */
    int done, result;
    void (*drop)(void *arg); /* set when abandoned */
    aero_load_fn fn;      /* read-only once started */
    void *arg;
    pthread_t thread;
    int thread_live;
};

static void job_run(aero_load_job *j)
{
    int r = j->fn(j->arg);
    pthread_mutex_lock(&j->lock);
    j->result = r;
    j->done = 1;
    pthread_mutex_unlock(&j->lock);
}

static void job_free(aero_load_job *j)
{
    pthread_mutex_destroy(&j->lock);
    free(j);
}

static void *job_thread(void *arg)
{
    aero_load_job *j = arg;
    int r = j->fn(j->arg);
    pthread_mutex_lock(&j->lock);
    j->result = r;
    j->done = 1;
    void (*drop)(void *) = j->drop;
    pthread_mutex_unlock(&j->lock);
    if (drop) { /* abandoned: nobody joins; clean up here */
        drop(j->arg);
        job_free(j);
    }
    return NULL;
}

aero_load_job *aero_load_job_start(aero_load_fn fn, void *arg, int threaded)
{
    aero_load_job *j = calloc(1, sizeof(*j));
    if (!j)
        return NULL;
    pthread_mutex_init(&j->lock, NULL);
    j->fn = fn;
    j->arg = arg;
    if (threaded && !pthread_create(&j->thread, NULL, job_thread, j))
        j->thread_live = 1;
    else
        job_run(j);
    return j;
}

int aero_load_job_done(aero_load_job *j)
{
    pthread_mutex_lock(&j->lock);
    int done = j->done;
    pthread_mutex_unlock(&j->lock);
    return done;
}

int aero_load_job_finish(aero_load_job *j)
{
    if (!j)
        return -1;
    if (j->thread_live)
        pthread_join(j->thread, NULL);
    int r = j->result; /* the join orders the worker's write before this */
    job_free(j);
    return r;
}

void aero_load_job_abandon(aero_load_job *j, void (*drop)(void *arg))
{
    if (!j)
        return;
    pthread_mutex_lock(&j->lock);
    int done = j->done;
    pthread_t thread = j->thread; /* j may be freed by the worker below */
    if (!done)
        j->drop = drop;
    pthread_mutex_unlock(&j->lock);
    if (done) {
        void *arg = j->arg;
        aero_load_job_finish(j);
        drop(arg);
    } else {
        pthread_detach(thread);
    }
}
