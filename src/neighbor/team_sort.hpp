#pragma once
// The counting sort a team shares (the cell grids' spheres, the broad phase's pairs): each thread
// takes a run of keys, counts its items and lays them out within the run; once the team has met,
// each run starts after the runs before it. The layout is the serial sort's, stable in item
// order, at any team size.
#include <omp.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace polydem {

struct KeyRun {
  std::size_t first = 0, last = 0;  // this thread's keys
  std::vector<std::uint32_t> next;  // each key's first item, then its next free slot
  std::uint32_t items = 0;          // items in the run

  bool holds(std::size_t key) const { return key >= first && key < last; }
  std::uint32_t take(std::size_t key) { return next[key - first]++; }
};

// This thread's run of keys 0 .. keys - 1, counted by each_key(count), which calls count(key) for
// every item in order; the slots are relative to the run until place_run.
template <class EachKey>
KeyRun count_run(std::size_t keys, const EachKey& each_key) {
  const std::size_t t = std::size_t(omp_get_thread_num()), team = std::size_t(omp_get_num_threads());
  KeyRun run{keys * t / team, keys * (t + 1) / team, {}, 0};
  run.next.assign(run.last - run.first, 0);
  each_key([&run](std::size_t key) {
    if (run.holds(key)) ++run.next[key - run.first];
  });
  for (std::uint32_t& count : run.next) run.items += std::exchange(count, run.items);
  return run;
}

// After the team met: moves the run after the runs before it (items[u]: thread u's run.items)
// and writes its keys' first slots into start[first .. last).
inline void place_run(KeyRun& run, const std::vector<std::uint32_t>& items, std::uint32_t* start) {
  std::uint32_t before = 0;
  for (int u = 0; u < omp_get_thread_num(); ++u) before += items[std::size_t(u)];
  for (std::size_t key = run.first; key < run.last; ++key) start[key] = run.next[key - run.first] += before;
}

}  // namespace polydem
