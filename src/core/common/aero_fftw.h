/* aero: FFTW's planner is process state. Making and destroying plans
 * (fftwf_plan_*, fftwf_destroy_plan) reads and writes FFTW's one planner and
 * its wisdom, so two threads doing it at once corrupt it (as four libpd
 * instances in four threads would);
 * executing a plan is thread-safe. Every plan aero makes or destroys calls
 * aero_fftw_serialise() first: it has FFTW take its own process-wide
 * planner lock around every later planner call
 * (fftwf_make_planner_thread_safe, libfftw3f_threads, FFTW >= 3.3.5; it
 * installs the lock once, later calls only check), so aero holds no lock
 * and no global of its own, and other FFTW users in the process are
 * serialised with aero too. Link with -lfftw3f_threads -lfftw3f.
 * -DAERO_FFTW_UNSERIALISED leaves the planner unserialised: only the
 * threads test's negative control builds it (tests/libpd). */
#ifndef AERO_FFTW_H
#define AERO_FFTW_H

#include <fftw3.h>

static inline void aero_fftw_serialise(void)
{
#ifndef AERO_FFTW_UNSERIALISED
    fftwf_make_planner_thread_safe();
#endif
}

#endif
