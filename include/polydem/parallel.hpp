#pragma once
// Loops over independent items, in parallel only when there are enough items to pay for
// waking the threads: even an `if(false)` OpenMP region costs a futex call, which dominates
// small scenes (a one-body run was 10x slower). Each item writes only its own outputs, so
// the result does not depend on the thread count.
//
// The loops are orphaned work-sharing: called inside a team (in_team, one region for a whole
// stage or step) they share the items among its threads and end at a barrier, with no thread
// wake-up; called outside any team they open their own region. Every thread of a team must
// reach the same loops in the same order (the counts are the same on every thread).
#include <cstddef>

#include <omp.h>

namespace polydem {

constexpr std::size_t kParallelMinItems = 256;

// Runs `fn` on every thread of one parallel region when `worth_waking`, else on this thread
// alone; inside a team already, `fn` runs on the team's threads (no nested region).
template <class Fn>
void in_team(bool worth_waking, const Fn& fn) {
  if (omp_get_level() > 0 || !worth_waking) {
    fn();
    return;
  }
#pragma omp parallel
  fn();
}

template <class Fn>
void parallel_for(std::size_t n, const Fn& fn) {
  if (n == 0) return;  // the same on every thread: no barrier skipped by some only
  in_team(n >= kParallelMinItems, [&] {
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < n; ++k) fn(k);
  });
}

// For items of uneven cost (pairs with few or many candidate features).
template <class Fn>
void parallel_for_dynamic(std::size_t n, const Fn& fn) {
  if (n == 0) return;
  in_team(n >= kParallelMinItems, [&] {
#pragma omp for schedule(dynamic, 64)
    for (std::size_t k = 0; k < n; ++k) fn(k);
  });
}

}  // namespace polydem
