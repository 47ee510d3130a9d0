#pragma once
// Loops over independent items, in parallel only when there are enough items to pay for
// waking the threads: even an `if(false)` OpenMP region costs a futex call, which dominates
// small scenes (a one-body run was 10x slower). Each item writes only its own outputs, so
// the result does not depend on the thread count.
#include <cstddef>

namespace polydem {

constexpr std::size_t kParallelMinItems = 256;

template <class Fn>
void parallel_for(std::size_t n, const Fn& fn) {
  if (n < kParallelMinItems) {
    for (std::size_t k = 0; k < n; ++k) fn(k);
    return;
  }
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < n; ++k) fn(k);
}

// For items of uneven cost (pairs with few or many candidate features).
template <class Fn>
void parallel_for_dynamic(std::size_t n, const Fn& fn) {
  if (n < kParallelMinItems) {
    for (std::size_t k = 0; k < n; ++k) fn(k);
    return;
  }
#pragma omp parallel for schedule(dynamic, 64)
  for (std::size_t k = 0; k < n; ++k) fn(k);
}

}  // namespace polydem
