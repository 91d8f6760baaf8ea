/* aero: the OpenMP calls aerotex makes, for one thread, on macOS.
 * Zig's clang (platforms/zig.sh) has no OpenMP runtime for macOS, so the
 * macOS aerotex is compiled without -fopenmp: its `omp` pragmas are ignored
 * and its loops run in one thread; these stand in for the runtime calls
 * (the planner lock has nothing to serialise with one thread). Used only by
 * platforms/platform.mk for darwin-*, never by the externals. */
#ifndef AERO_DARWIN_OMP_H
#define AERO_DARWIN_OMP_H

typedef int omp_lock_t;

static inline void omp_init_lock(omp_lock_t *lock) { *lock = 0; }
static inline void omp_destroy_lock(omp_lock_t *lock) { *lock = 0; }
static inline void omp_set_lock(omp_lock_t *lock) { *lock = 1; }
static inline void omp_unset_lock(omp_lock_t *lock) { *lock = 0; }
static inline int omp_get_max_threads(void) { return 1; }

#endif
