// LD_PRELOAD counter of OpenMP synchronisation in libgomp: parallel regions (GOMP_parallel) and
// the barriers met inside them (GOMP_barrier: a static loop's or a single's end, an explicit
// barrier; GOMP_loop_end: a dynamic loop's end), counted on the calling thread 0 of each team
// alone, so the figures do not depend on the thread count. Prints them at exit to stderr.
// Build: cc -O2 -shared -fPIC count_regions.c -o count_regions.so -ldl -fopenmp
#define _GNU_SOURCE
#include <dlfcn.h>
#include <omp.h>
#include <stdatomic.h>
#include <stdio.h>

static atomic_long regions, barriers;

void GOMP_parallel(void (*fn)(void*), void* data, unsigned threads, unsigned flags) {
  static void (*real)(void (*)(void*), void*, unsigned, unsigned);
  if (!real) real = (void (*)(void (*)(void*), void*, unsigned, unsigned))dlsym(RTLD_NEXT, "GOMP_parallel");
  atomic_fetch_add(&regions, 1);
  real(fn, data, threads, flags);
}

void GOMP_barrier(void) {
  static void (*real)(void);
  if (!real) real = (void (*)(void))dlsym(RTLD_NEXT, "GOMP_barrier");
  if (omp_get_thread_num() == 0) atomic_fetch_add(&barriers, 1);
  real();
}

void GOMP_loop_end(void) {
  static void (*real)(void);
  if (!real) real = (void (*)(void))dlsym(RTLD_NEXT, "GOMP_loop_end");
  if (omp_get_thread_num() == 0) atomic_fetch_add(&barriers, 1);
  real();
}

__attribute__((destructor)) static void report(void) {
  fprintf(stderr, "omp_parallel_regions %ld\nomp_barriers %ld\n", (long)regions, (long)barriers);
}
