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
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

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

// A loop's closing barrier, needed only inside a wider region: a region of the loop's own ends at
// its own barrier (one meeting, not two).
inline void barrier_unless_own_region(bool own_region) {
  if (!own_region) {
#pragma omp barrier
  }
}

// Inside a team: `first` on thread 0 and `second` on thread 1 (both on thread 0 in a team of one,
// or outside any region), with no barrier after them: two serial tasks the other thread would
// otherwise wait through.
template <class First, class Second>
void on_two_threads(const First& first, const Second& second) {
  const int t = omp_get_thread_num(), second_on = omp_get_num_threads() > 1 ? 1 : 0;
  if (t == 0) first();
  if (t == second_on) second();
}

// Runs two independent tasks (each writes only its own outputs) at once on two threads of a region
// of their own when `worth_waking` and two threads are allowed, else `first` then `second` here
// (inside a team too: its loops are not to be split by one thread): the same results either way.
// For serial stretches the other thread would wait through asleep (issue 19).
template <class First, class Second>
void two_tasks(bool worth_waking, const First& first, const Second& second) {
  if (omp_get_level() > 0 || !worth_waking || omp_get_max_threads() < 2) {
    first();
    second();
    return;
  }
#pragma omp parallel num_threads(2)
  on_two_threads(first, second);
}

// Items of a thousand instructions or more (a polyhedron's driver candidates, ~800 a wall pair,
// callgrind on the pour): fewer of them already pay for waking the threads.
constexpr std::size_t kParallelMinHeavyItems = 16;

template <class Fn>
void parallel_for(std::size_t n, const Fn& fn, std::size_t min_items = kParallelMinItems) {
  if (n == 0) return;  // the same on every thread: no barrier skipped by some only
  const bool own_region = omp_get_level() == 0;
  in_team(n >= min_items, [&] {
#pragma omp for schedule(static) nowait
    for (std::size_t k = 0; k < n; ++k) fn(k);
    barrier_unless_own_region(own_region);
  });
}

// For items of uneven cost (pairs with few or many candidate features).
template <class Fn>
void parallel_for_dynamic(std::size_t n, const Fn& fn) {
  if (n == 0) return;
  const bool own_region = omp_get_level() == 0;
  in_team(n >= kParallelMinItems, [&] {
#pragma omp for schedule(dynamic, 64) nowait
    for (std::size_t k = 0; k < n; ++k) fn(k);
    barrier_unless_own_region(own_region);
  });
}

// Where a team cuts the bodies 0 .. n - 1 among its threads: thread t takes [at[t], at[t + 1]).
// The step's passes over bodies and its pair loops take the same cut (pair_split.hpp), so a body's
// state stays in the cache of the core that writes it. Made for a team of `threads`: another team
// (the thread governor changed it) takes the static shares. Folded, the cut has 2 threads pieces
// and thread t takes pieces t and 2 threads - 1 - t: its walk's bodies, then a share of the bodies
// past the walk's (a pour's falling bodies), so the passes are even and move each walked body on
// the core that walks it (issue 19: one line fetched from the other core costs ~266 ns here).
struct TeamCut {
  const std::uint32_t* at = nullptr;  // pieces() + 1 bodies, increasing, 0 first
  int threads = 0;
  bool folded = false;
  std::size_t pieces() const { return std::size_t(folded ? 2 * threads : threads); }
};

// A thread's share of a cut: up to two ranges [first, last) (the second empty unless folded).
using Shares = std::array<std::pair<std::size_t, std::size_t>, 2>;

// This thread's shares of the items 0 .. n - 1 (bodies) under `cut`: the static schedule's
// (libgomp's) without a cut for this team and these n.
inline Shares team_shares(std::size_t n, TeamCut cut) {
  const std::size_t t = omp_get_thread_num(), threads = omp_get_num_threads();
  if (cut.threads == int(threads) && cut.at[cut.pieces()] == n) {
    const std::size_t u = cut.folded ? 2 * threads - 1 - t : t;
    return {{{cut.at[t], cut.at[t + 1]}, {cut.at[u], cut.folded ? cut.at[u + 1] : cut.at[u]}}};
  }
  const std::size_t q = n / threads, r = n % threads;
  const std::size_t first = t * q + std::min(t, r);
  return {{{first, first + q + (t < r)}, {0, 0}}};
}

// The same for items that are bodies `ids` (increasing): the shares of the ids in this thread's bodies.
template <class Id>
Shares team_shares(const std::vector<Id>& ids, TeamCut cut) {
  const int threads = omp_get_num_threads();
  if (cut.threads != threads) return team_shares(ids.size(), cut);
  const std::size_t t = omp_get_thread_num();
  auto range = [&](std::size_t p) {
    const auto first = std::lower_bound(ids.begin(), ids.end(), Id(cut.at[p]));
    return std::pair{std::size_t(first - ids.begin()),
                     std::size_t(std::lower_bound(first, ids.end(), Id(cut.at[p + 1])) - ids.begin())};
  };
  return {range(t), cut.folded ? range(2 * threads - 1 - t) : std::pair<std::size_t, std::size_t>{0, 0}};
}

}  // namespace polydem
