/* aero: field preprocessing in a worker thread (Shin and Bajaj): a host
 * starts a job, polls its progress from its own thread (e.g. Pd's clock),
 * then takes the sources or cancels. The worker makes core calls only;
 * the host never blocks except in cancel, which waits for the frame in
 * progress. No globals: every job is its own. */
#ifndef AERO_FIELD_JOB_H
#define AERO_FIELD_JOB_H

#include "fieldsound.h"

typedef struct aero_field_job aero_field_job;

/* Starts preprocessing `info` (or the synthetic `demo`, when not NULL)
 * with `par`: in a new thread, or in the caller's thread when `threaded`
 * is 0 or no thread can be made (then the job is finished on return).
 * NULL when out of memory. */
aero_field_job *aero_field_job_start(const aero_volume_info *info,
                                     const aero_field_demo *demo,
                                     const aero_field_params *par,
                                     int threaded);

/* 0 while running, 1 when finished (ok or not); frames done and total */
int aero_field_job_poll(aero_field_job *j, int *done, int *total);

/* A finished job: its sources moved into `out` (0), or -1 with the error
 * in err; the seconds it took. The job is freed either way. */
int aero_field_job_take(aero_field_job *j, aero_field_sources *out,
                        double *seconds, char *err, size_t errlen);

/* Stops a job (waits for its current frame) and frees it. NULL is fine. */
void aero_field_job_cancel(aero_field_job *j);

#endif
