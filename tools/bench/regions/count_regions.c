// LD_PRELOAD counter of OpenMP parallel regions (libgomp's GOMP_parallel): prints the count at
// exit to stderr. Build: cc -O2 -shared -fPIC count_regions.c -o count_regions.so -ldl
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdatomic.h>
#include <stdio.h>

static atomic_long regions;

void GOMP_parallel(void (*fn)(void*), void* data, unsigned threads, unsigned flags) {
  static void (*real)(void (*)(void*), void*, unsigned, unsigned);
  if (!real) real = (void (*)(void (*)(void*), void*, unsigned, unsigned))dlsym(RTLD_NEXT, "GOMP_parallel");
  atomic_fetch_add(&regions, 1);
  real(fn, data, threads, flags);
}

__attribute__((destructor)) static void report(void) { fprintf(stderr, "omp_parallel_regions %ld\n", (long)regions); }
