// What a barrier costs on this machine, with work around it: each step, the team streams a
// 1.2 MB array (a sphere bed's reads, ~76 us at 1 thread) in three static loops, with 0, 1 or 3
// barriers between them. Prints microseconds a step; run at 1 and 2 threads.
// Build: g++ -O2 -fopenmp barrier_cost.cpp -o barrier_cost; OMP_NUM_THREADS=2 ./barrier_cost
#include <omp.h>

#include <cstdio>
#include <vector>

int main() {
  const int steps = 10000, n = 150000;
  const std::vector<double> a(n, 1.0);
  double sink = 0.0;
  for (int barriers : {0, 1, 3}) {
    const double t0 = omp_get_wtime();
#pragma omp parallel reduction(+ : sink)
    for (int s = 0; s < steps; ++s) {
      for (int part = 0; part < 3; ++part) {
#pragma omp for schedule(static) nowait
        for (int i = 0; i < n / 3; ++i) sink += a[i + part * (n / 3)];
        if (part < barriers) {
#pragma omp barrier
        }
      }
    }
    std::printf("barriers a step %d: %.2f us a step\n", barriers, (omp_get_wtime() - t0) / steps * 1e6);
  }
  return sink < 0.0;
}
