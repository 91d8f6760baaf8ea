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
#include <string.h>

static inline void aero_fftw_serialise(void)
{
#ifndef AERO_FFTW_UNSERIALISED
    fftwf_make_planner_thread_safe();
#endif
}

/* n floats, zeroed and aligned for FFTW's SIMD (fftwf_free frees them);
 * NULL when out of memory */
static inline float *aero_fftw_zalloc(size_t n)
{
    float *a = fftwf_malloc(sizeof(float) * (n ? n : 1));
    if (a) memset(a, 0, sizeof(float) * (n ? n : 1));
    return a;
}

/* An inverse real FFT of n points with its buffers: signal[t] = the sum
 * over k of spectrum[k] e^(+2 pi i k t / n), from bins 0..n/2 (FFTW's
 * backward c2r, unscaled; it overwrites the spectrum). Made and freed
 * outside the audio thread; fftwf_execute(plan) is real-time safe. */
typedef struct aero_fftw_c2r {
    fftwf_complex *spectrum;
    float *signal;
    fftwf_plan plan;
} aero_fftw_c2r;

static inline void aero_fftw_c2r_free(aero_fftw_c2r *f)
{
    if (f->plan) {
        aero_fftw_serialise();
        fftwf_destroy_plan(f->plan);
    }
    fftwf_free(f->spectrum);
    fftwf_free(f->signal);
    f->spectrum = NULL;
    f->signal = NULL;
    f->plan = NULL;
}

/* 0, or -1 when out of memory (*f is then empty) */
static inline int aero_fftw_c2r_make(aero_fftw_c2r *f, int n)
{
    f->spectrum = fftwf_malloc(sizeof(fftwf_complex) * (size_t)(n / 2 + 1));
    f->signal = fftwf_malloc(sizeof(float) * (size_t)n);
    f->plan = NULL;
    if (f->spectrum && f->signal) {
        aero_fftw_serialise();
        f->plan = fftwf_plan_dft_c2r_1d(n, f->spectrum, f->signal,
                                        FFTW_ESTIMATE);
    }
    if (!f->plan) {
        aero_fftw_c2r_free(f);
        return -1;
    }
    return 0;
}

#endif
