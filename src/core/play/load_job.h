/* aero: one piece of loading work (a tree file read and the object's core
 * built from it) in a worker thread, so the host's own thread (Pd's, where
 * audio runs too) never waits for it: the host starts the job, polls it
 * from its own thread (Pd's clock), then takes the result. The worker runs
 * the host's function only, which makes core calls and touches nothing the
 * host's thread uses. No globals: every job is its own. The same pattern
 * as field_job.h, for any function. */
#ifndef AERO_LOAD_JOB_H
#define AERO_LOAD_JOB_H

typedef struct aero_load_job aero_load_job;

/* the work: returns 0 or -1; runs once, in the worker (or in the caller
   when no thread can be made) */
typedef int (*aero_load_fn)(void *arg);

/* Starts fn(arg) in a new thread when `threaded`, else (or when no thread
   can be made) runs it now, in the caller. NULL when out of memory (then
   fn has not run). arg stays the caller's, untouched by it until taken. */
aero_load_job *aero_load_job_start(aero_load_fn fn, void *arg, int threaded);

/* 1 when fn has returned, 0 while it runs; never blocks for long */
int aero_load_job_done(aero_load_job *j);

/* Waits for fn to return (at once when done), frees the job and returns
   fn's result; the caller owns arg again. NULL: -1. */
int aero_load_job_finish(aero_load_job *j);

/* Gives the job up without waiting (an object deleted while it loads):
   when fn returns, the worker calls drop(arg) and frees the job itself;
   at once here when fn has already returned. The caller must not touch
   arg or the job again. NULL is fine. */
void aero_load_job_abandon(aero_load_job *j, void (*drop)(void *arg));

#endif
