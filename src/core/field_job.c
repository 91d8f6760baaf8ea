/* aero: field preprocessing in a worker thread (see field_job.h). */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* clock_gettime, pthreads */
#endif
#include "field_job.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

struct aero_field_job {
    pthread_mutex_t lock; /* guards the fields up to `result` */
    int done_frames, total_frames;
    int finished;         /* 0 running, 1 ok, -1 failed */
    int cancel;
    char err[512];
    double seconds;
    aero_field_sources result;
    /* read-only once started */
    aero_volume_info info;
    aero_field_demo demo;
    int use_demo;
    aero_field_params par;
    pthread_t thread;
    int thread_live;
};

static double wall_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int job_progress(void *ctx, int done, int total)
{
    aero_field_job *j = ctx;
    pthread_mutex_lock(&j->lock);
    j->done_frames = done;
    j->total_frames = total;
    int cancel = j->cancel;
    pthread_mutex_unlock(&j->lock);
    return cancel;
}

static void job_run(aero_field_job *j)
{
    double t0 = wall_seconds();
    char err[512] = "";
    aero_field_sources result;
    memset(&result, 0, sizeof(result));
    int rc = aero_field_prepare(&j->info, j->use_demo ? &j->demo : NULL,
                                &j->par, &result, job_progress, j, err,
                                sizeof err);
    pthread_mutex_lock(&j->lock);
    j->result = result;
    j->seconds = wall_seconds() - t0;
    j->finished = rc ? -1 : 1;
    memcpy(j->err, err, sizeof err);
    pthread_mutex_unlock(&j->lock);
}

static void *job_thread(void *arg)
{
    job_run(arg);
    return NULL;
}

aero_field_job *aero_field_job_start(const aero_volume_info *info,
                                     const aero_field_demo *demo,
                                     const aero_field_params *par,
                                     int threaded)
{
    aero_field_job *j = calloc(1, sizeof(*j));
    if (!j)
        return NULL;
    pthread_mutex_init(&j->lock, NULL);
    j->info = *info;
    if (demo) {
        j->demo = *demo;
        j->use_demo = 1;
    }
    j->par = *par;
    if (threaded && !pthread_create(&j->thread, NULL, job_thread, j))
        j->thread_live = 1;
    else
        job_run(j);
    return j;
}

int aero_field_job_poll(aero_field_job *j, int *done, int *total)
{
    pthread_mutex_lock(&j->lock);
    int finished = j->finished;
    *done = j->done_frames;
    *total = j->total_frames;
    pthread_mutex_unlock(&j->lock);
    return finished != 0;
}

static void job_free(aero_field_job *j)
{
    if (j->thread_live)
        pthread_join(j->thread, NULL);
    if (j->finished == 1)
        aero_field_sources_free(&j->result);
    pthread_mutex_destroy(&j->lock);
    free(j);
}

int aero_field_job_take(aero_field_job *j, aero_field_sources *out,
                        double *seconds, char *err, size_t errlen)
{
    if (j->thread_live) {
        pthread_join(j->thread, NULL);
        j->thread_live = 0;
    }
    int rc = j->finished == 1 ? 0 : -1;
    *seconds = j->seconds;
    if (rc == 0) {
        *out = j->result;
        j->finished = 0; /* the sources are the caller's now */
    } else if (err && errlen) {
        snprintf(err, errlen, "%s", j->err[0] ? j->err : "not finished");
    }
    job_free(j);
    return rc;
}

void aero_field_job_cancel(aero_field_job *j)
{
    if (!j)
        return;
    pthread_mutex_lock(&j->lock);
    j->cancel = 1;
    pthread_mutex_unlock(&j->lock);
    job_free(j);
}
