#pragma once
// The parallel loop over the pairs of a list, shared by the contact engine and the sphere fast
// path (sphere_loop.cpp: its own translation unit, so GCC's unit growth limit leaves every call
// in the sphere kernel inlined).
#include <algorithm>
#include <cassert>
#include <type_traits>
#include <utility>

#include "contact/pair_kernel.hpp"
#include "contact/pair_split.hpp"
#include "polydem/parallel.hpp"

namespace polydem {

namespace pair_loop_detail {

// A pair's terms in its bodies' sums: the index sum's bits (-x added is x subtracted).
[[gnu::always_inline]] inline void add_as_i(BodySum& s, const Vec3& force_i, const Vec3& torque_i) {
  s.force += force_i;
  s.torque += torque_i;
}
[[gnu::always_inline]] inline void add_as_j(BodySum& s, const Vec3& force_i, const Vec3& torque_j) {
  s.force -= force_i;
  s.torque += torque_j;
}

// Chunk t's home bodies' sums cleared, unless every sum is +0 already (SumsZero): a body's
// first term is then added to +0, as in one thread's pair-order sum.
inline void clear_home_sums(DirectSums& direct, int t) {
  const PairSplit& split = direct.split;
  for (std::uint32_t h = split.home_begin[t]; h < split.home_begin[t + 1]; ++h) direct.sums[split.homes[h]] = BodySum{};
}

// A pair's terms in its bodies' sums.
[[gnu::always_inline]] inline void add_pair(BodySum* sums, BodyPair p, const PairTotals& pt) {
  add_as_i(sums[p.i], pt.force_i, pt.torque_i);
  add_as_j(sums[p.j], pt.force_i, pt.torque_j);
}
// Whether a kernel's lists are always dense (Kernel::kDense: the sphere kernel's): their pairs'
// energies are on their first slots, with no test of PairList::sparse.
template <class Kernel>
constexpr bool dense_kernel() {
  if constexpr (requires { Kernel::kDense; }) return Kernel::kDense;
  return false;
}

// Pair k's own results: its touching count and pending energy, its block's contacts and ended flag.
// A pair touching neither at the last step nor now adds no energy (+0 to its +0: flushed when it
// ended), so its pending energy is not read: 32 bytes a pair not streamed (issue 19).
template <bool kDense = false>
[[gnu::always_inline]] inline void keep_pair(PairList& list, std::uint32_t k, const PairTotals& pt,
                                             std::uint32_t& contacts, bool& ended) {
  const bool was = list.touching[k] != 0;
  ended |= was & (pt.contacts == 0);  // touching at the last step, not now
  if (was | (pt.contacts != 0)) (kDense ? list.slots[list.slot_begin[k]].pending : list.open_energy(k)) += pt.energy;
  else assert(pt.energy.net == 0.0 && pt.energy.sliding == 0.0 && pt.energy.rolling == 0.0 && pt.energy.patch == 0.0);
  list.touching[k] = std::uint16_t(pt.contacts);
  contacts += std::uint32_t(pt.contacts);
}

// Candidate k without a partner: the kernel's steady code on one lane (the same bits as in a
// lane of two), its scalar code where the pair is not steady.
template <class Kernel>
[[gnu::always_inline]] inline PairTotals steady_alone(const Kernel& kernel, std::uint32_t k, PairScratch& scratch) {
  PairTotals totals;
  bool done = false;
  kernel.template steady<1>(&k, [&](int, const PairTotals* t) {
    if (t) totals = *t, done = true;
  });
  return done ? totals : kernel(k, scratch);
}

// An internal pair's terms added to both its bodies' sums; one out of reach adds +0 (nothing).
struct InternalAdd {
  BodySum* sums;
  const BodyPair* pairs;
  [[gnu::always_inline]] void operator()(std::uint32_t k, const PairTotals& pt) const { add_pair(sums, pairs[k], pt); }
  [[gnu::always_inline]] void out_of_reach(std::uint32_t, const PairTotals&) const {}
};

// A run of foreign pairs from pair k0 (ordinal f0): each one's side homed in this chunk added to
// its sum, its result kept for the other side (a late term, ForceSums adds it), +0 when out of reach.
struct ForeignAdd {
  BodySum* sums;
  const BodyPair* pairs;
  const std::uint8_t* side;
  ForeignResult* late;
  std::uint32_t k0, f0;
  [[gnu::always_inline]] void operator()(std::uint32_t k, const PairTotals& pt) const {
    const std::uint32_t f = f0 + (k - k0);
    if (side[f] & 1u) add_as_i(sums[pairs[k].i], pt.force_i, pt.torque_i);
    if (side[f] & 2u) add_as_j(sums[pairs[k].j], pt.force_i, pt.torque_j);
    late[f] = {pt.force_i, pt.torque_i, pt.torque_j};
  }
  [[gnu::always_inline]] void out_of_reach(std::uint32_t k, const PairTotals& pt) const {
    late[f0 + (k - k0)] = {pt.force_i, pt.torque_i, pt.torque_j};
  }
};

// Pairs [k, stop) through a kernel that steps two steady pairs side by side (sphere_lanes.hpp),
// each one's terms given to `add`: a candidate waits for the next; a pair between them that adds
// to a sum sends it alone first (kernel.one), so each sum takes its terms in list order (a pair
// out of reach adds +0, which changes no sum's bits: a sum is never -0).
template <class Kernel, class Add>
[[gnu::always_inline]] inline void paired_pairs(PairList& list, const Kernel& kernel, const Add& add,
                                                PairScratch& scratch, std::uint32_t k, std::uint32_t stop,
                                                std::uint32_t& contacts, bool& ended) {
  constexpr std::uint32_t kNone = ~0u;
  std::uint32_t waiting = kNone;
  const auto alone = [&](std::uint32_t a) __attribute__((noinline)) {  // not steady: the scalar kernel
    const PairTotals pt = kernel(a, scratch);
    add(a, pt);
    keep_pair<dense_kernel<Kernel>()>(list, a, pt, contacts, ended);
  };
  const auto lone = [&](std::uint32_t a) __attribute__((noinline)) {  // a candidate without a partner
    const PairTotals pt = steady_alone(kernel, a, scratch);
    add(a, pt);
    keep_pair<dense_kernel<Kernel>()>(list, a, pt, contacts, ended);
  };
  for (; k < stop; ++k) {
    if (kernel.candidate(k)) {
      if (waiting == kNone) {
        waiting = k;
        continue;
      }
      const std::uint32_t two[2] = {waiting, k};
      kernel.template steady<2>(two, [&](int l, const PairTotals* t) __attribute__((always_inline)) {
        if (!t) return alone(two[l]);
        add(two[l], *t);
        keep_pair<dense_kernel<Kernel>()>(list, two[l], *t, contacts, ended);
      });
      waiting = kNone;
      continue;
    }
    const PairTotals pt = kernel(k, scratch);
    keep_pair<dense_kernel<Kernel>()>(list, k, pt, contacts, ended);
    if (pt.contacts == 0) {  // out of reach: its terms are +0
      add.out_of_reach(k, pt);
      continue;
    }
    if (waiting != kNone) lone(std::exchange(waiting, kNone));
    add(k, pt);
  }
  if (waiting != kNone) lone(waiting);
}

// Pairs [k, stop) through a kernel that leaves a pair of one steady sub-contact waiting
// (lone_pairs.hpp): the next such pair takes the other lane. Each pair's terms go to `add` in
// list order: up to kHeld pairs with contacts between the two wait with them (their totals made
// in their slot); one more sends the waiting pair alone and the held ones after it.
template <class Kernel, class Add>
[[gnu::always_inline]] inline void lone_paired_pairs(PairList& list, const Kernel& kernel, const Add& add,
                                                     PairScratch& scratch, std::uint32_t k, std::uint32_t stop,
                                                     std::uint32_t& contacts, bool& ended) {
  using Lone = typename Kernel::Lone;
  constexpr int kHeld = 2;
  Lone slot[kHeld + 2];  // slot[0] the waiting pair, then the held ones in list order, then the next pair
  int used = 0;          // slots [0, used) wait
  const auto take = [&](const Lone& l) __attribute__((always_inline)) {
    add(l.k, l.totals);
    keep_pair(list, l.k, l.totals, contacts, ended);
  };
  const auto alone = [&]() __attribute__((noinline)) {  // the waiting pair without a partner, then the held ones
    kernel.alone(slot[0], scratch);
    take(slot[0]);
    for (int h = 1; h < used; ++h) add(slot[h].k, slot[h].totals);
    used = 0;
  };
  for (; k < stop; ++k) {
    Lone& next = slot[used];
    PairTotals& pt = next.totals;  // made in place: a waiting or held pair's stay there
    pt = PairTotals{};
    if (!kernel.forces(k, scratch, pt, next)) {
      if (used == 0) {
        kernel.park(next, scratch);
        used = 1;
        continue;
      }
      kernel.lanes(slot[0], next, scratch);
      take(slot[0]);
      for (int h = 1; h < used; ++h) add(slot[h].k, slot[h].totals);
      take(next);
      used = 0;
      continue;
    }
    keep_pair(list, k, pt, contacts, ended);
    if (pt.contacts == 0) {  // out of reach: its terms are +0
      add.out_of_reach(k, pt);
      continue;
    }
    if (used == 0) {
      add(k, pt);
      continue;
    }
    next.k = k;
    if (++used <= kHeld + 1) continue;  // held
    alone();
  }
  if (used) alone();
}

// Pairs [k, stop) of a chunk in order, each computed and its terms given to `add`.
template <class Kernel, class Add>
[[gnu::always_inline]] inline void chunk_pairs(PairList& list, const Kernel& kernel, const Add& add,
                                               PairScratch& scratch, std::uint32_t k, std::uint32_t stop,
                                               std::uint32_t& contacts, bool& ended) {
  if constexpr (requires { Kernel::kTwoLanes; }) {
    paired_pairs(list, kernel, add, scratch, k, stop, contacts, ended);
  } else if constexpr (requires { Kernel::kLonePairs; }) {
    lone_paired_pairs(list, kernel, add, scratch, k, stop, contacts, ended);
  } else {
    for (; k < stop; ++k) {
      const PairTotals pt = kernel(k, scratch);  // a pair out of reach adds +0: no sum's bits change
      add(k, pt);
      keep_pair<dense_kernel<Kernel>()>(list, k, pt, contacts, ended);
    }
  }
}

// The run of foreign pairs from pair k (ordinal f) to the next internal one or `end`, computed
// as the internal ones are (two lanes). Returns the pair after the run.
template <class Kernel>
[[gnu::always_inline]] inline std::uint32_t foreign_pairs(PairList& list, const Kernel& kernel, DirectSums& direct,
                                                          PairScratch& scratch, std::uint32_t k, std::uint32_t f,
                                                          std::uint32_t end, std::uint32_t& contacts, bool& ended) {
  const PairSplit& split = direct.split;
  std::uint32_t stop = k + 1;
  while (stop < end && split.foreign[f + (stop - k)] == stop) ++stop;
  const ForeignAdd add{direct.sums.data(), list.pairs.data(), split.foreign_side.data(), direct.foreign.data(), k, f};
  chunk_pairs(list, kernel, add, scratch, k, stop, contacts, ended);
  return stop;
}
// foreign_pairs out of line: the walk's loop over internal pairs stays as it was.
template <class Kernel>
[[gnu::noinline]] std::uint32_t foreign_run(PairList& list, const Kernel& kernel, DirectSums& direct,
                                            PairScratch& scratch, std::uint32_t k, std::uint32_t f, std::uint32_t end,
                                            std::uint32_t& contacts, bool& ended) {
  return foreign_pairs(list, kernel, direct, scratch, k, f, end, contacts, ended);
}
// foreign_run compiled for AVX, as walk_chunk_avx, which calls it (the same bits).
template <class Kernel>
[[gnu::noinline, gnu::target("avx"), gnu::flatten]] std::uint32_t foreign_run_avx(
    PairList& list, const Kernel& kernel, DirectSums& direct, PairScratch& scratch, std::uint32_t k, std::uint32_t f,
    std::uint32_t end, std::uint32_t& contacts, bool& ended) {
  return foreign_pairs(list, kernel, direct, scratch, k, f, end, contacts, ended);
}

// The bodies [next, last) a trailing pass may move on this thread (WalkTrail), handed to it in order.
struct ChunkTrail {
  // Bodies a pass call takes at least (but the last): its setup (~40 instructions) spread over
  // them, their state still in L1 (~13 KB).
  static constexpr std::uint32_t kBatch = 64;
  const WalkTrail* trail = nullptr;
  std::uint32_t next = 0, last = 0;
  // The walk is done with every body below `upto`; `all`: the chunk's end. Once this thread's pairs
  // left a turn (rare), it moves no more: the next step's pass moves the rest, turns and all.
  void done_below(std::uint32_t upto, bool all = false) {
    if (turns_left_here != 0) last = next;
    const std::uint32_t stop = std::min(upto, last);
    if (next < stop && (all || stop - next >= kBatch)) trail->pass(trail->context, next, stop), next = stop;
  }
};

// Chunk t's pairs in order, each computed and added to the sums of its bodies homed here; a
// foreign pair's other side kept as a late term (DirectSums::foreign); the blocks' contacts and
// ended flags. The runs of internal pairs between two foreign ones are plain loops (one thread:
// the whole list). After each block, the bodies it finished go to `behind`'s pass. kAvx: the
// foreign runs' AVX build (walk_chunk_avx's).
template <class Kernel, bool kAvx = false>
void walk_chunk(PairList& list, const Kernel& kernel, DirectSums& direct, PairScratch& scratch, int t,
                ChunkTrail& behind) {
  const PairSplit& split = direct.split;
  if (split.cut[t] == split.cut[t + 1]) return;
  const InternalAdd internal{direct.sums.data(), list.pairs.data()};
  const std::size_t n = list.size();
  std::uint32_t f = split.foreign_begin[t], next = split.foreign[f];  // the last is the list size
  for (std::size_t b = split.cut[t] / list.block; b * list.block < split.cut[t + 1]; ++b) {
    std::uint32_t contacts = 0;
    bool ended = false;
    const std::uint32_t end = std::uint32_t(std::min(n, (b + 1) * list.block));
    for (std::uint32_t k = std::uint32_t(b * list.block); k < end; ++k) {
      const std::uint32_t stop = std::min(end, next);
      chunk_pairs(list, kernel, internal, scratch, k, stop, contacts, ended);
      if ((k = stop) == end) break;
      const std::uint32_t after = kAvx ? foreign_run_avx(list, kernel, direct, scratch, k, f, end, contacts, ended)
                                       : foreign_run(list, kernel, direct, scratch, k, f, end, contacts, ended);  // k == next
      f += after - k;
      next = split.foreign[f];
      k = after - 1;
    }
    list.block_contacts[b] = contacts;
    list.block_ended[b] = ended;
    // Pairs are sorted by i: the bodies below the next block's first i have all their pairs done.
    if (behind.trail && end < split.cut[t + 1]) behind.done_below(list.pairs[end].i);
  }
}

// walk_chunk compiled for AVX (no FMA): the same IEEE operations in the same order in VEX's
// three-operand forms, without SSE2's register copies, through the kernel's four lanes where it
// has them (wide()); chosen where the CPU has it (the same bits).
template <class Kernel>
[[gnu::target("avx"), gnu::flatten]] void walk_chunk_avx(PairList& list, const Kernel& kernel, DirectSums& direct,
                                                         PairScratch& scratch, int t, ChunkTrail& behind) {
  if constexpr (requires { kernel.wide(); })
    walk_chunk<decltype(kernel.wide()), true>(list, kernel.wide(), direct, scratch, t, behind);
  else
    walk_chunk<Kernel, true>(list, kernel, direct, scratch, t, behind);
}

// Pair k's results kept in the list (its forces too), its block's contacts and ended flag.
[[gnu::always_inline]] inline void keep_results(PairList& list, std::uint32_t k, const PairTotals& t,
                                                std::uint32_t& contacts, bool& ended) {
  list.force_i[k] = t.force_i;
  list.torque_i[k] = t.torque_i;
  list.torque_j[k] = t.torque_j;
  keep_pair(list, k, t, contacts, ended);
}

// Entries [a, end) of a pair sequence (entry e is pair pair_of(e)) through a kernel that steps two
// steady pairs side by side: a candidate waits for the next one (each pair's results are its own,
// so any order gives the same bits); keep(e, totals) takes each entry's results.
template <class Kernel, class PairOf, class Keep>
[[gnu::always_inline]] inline void in_two_lanes(const Kernel& kernel, PairScratch& scratch, std::uint32_t a,
                                                std::uint32_t end, const PairOf& pair_of, const Keep& keep) {
  constexpr std::uint32_t kNone = ~0u;
  std::uint32_t waiting = kNone;
  const auto alone = [&](std::uint32_t e) __attribute__((noinline)) {  // a lane not steady: the scalar kernel
    keep(e, kernel(pair_of(e), scratch));
  };
  for (; a < end; ++a) {
    const std::uint32_t k = pair_of(a);
    if (!kernel.candidate(k)) {
      keep(a, kernel(k, scratch));
    } else if (waiting == kNone) {
      waiting = a;
    } else {
      const std::uint32_t entry[2] = {std::exchange(waiting, kNone), a};
      const std::uint32_t two[2] = {pair_of(entry[0]), k};
      kernel.template steady<2>(two, [&](int l, const PairTotals* t) __attribute__((always_inline)) {
        if (!t) return alone(entry[l]);
        keep(entry[l], *t);
      });
    }
  }
  if (waiting != kNone) keep(waiting, steady_alone(kernel, pair_of(waiting), scratch));
}

// Block b's pairs [k, end) in two lanes (in_two_lanes).
template <class Kernel>
[[gnu::always_inline]] inline void paired_block(PairList& list, const Kernel& kernel, PairScratch& scratch,
                                                std::uint32_t k, std::uint32_t end, std::uint32_t& contacts,
                                                bool& ended) {
  in_two_lanes(
      kernel, scratch, k, end, [](std::uint32_t e) { return e; },
      [&](std::uint32_t e, const PairTotals& t) __attribute__((always_inline)) {
        keep_results(list, e, t, contacts, ended);
      });
}

// A pair's forces kept in the list (block_forces through lone_paired_pairs): each pair's own, so
// their order is free.
struct KeepForces {
  PairList& list;
  [[gnu::always_inline]] void operator()(std::uint32_t k, const PairTotals& pt) const {
    list.force_i[k] = pt.force_i;
    list.torque_i[k] = pt.torque_i;
    list.torque_j[k] = pt.torque_j;
  }
  [[gnu::always_inline]] void out_of_reach(std::uint32_t k, const PairTotals& pt) const { (*this)(k, pt); }
};

// Block b's pairs: each one's forces kept in the list, its energy added to its pending sum in
// step order, the block's contacts counted and its ended contacts flagged.
template <class Kernel>
void block_forces(PairList& list, const Kernel& kernel, std::size_t b, PairScratch& scratch) {
  std::uint32_t contacts = 0;
  bool ended = false;
  const std::uint32_t begin = std::uint32_t(b * list.block), end = std::uint32_t(std::min(list.size(), (b + 1) * list.block));
  if constexpr (requires { Kernel::kTwoLanes; }) {
    paired_block(list, kernel, scratch, begin, end, contacts, ended);
  } else if constexpr (requires { Kernel::kLonePairs; }) {
    lone_paired_pairs(list, kernel, KeepForces{list}, scratch, begin, end, contacts, ended);
  } else {
    for (std::uint32_t k = begin; k < end; ++k) keep_results(list, k, kernel(k, scratch), contacts, ended);
  }
  list.block_contacts[b] = contacts;
  list.block_ended[b] = ended;
}

// even_pair_forces' block b, out of line as block_forces was before the blocks' range had a function
// of its own: inlined, the sphere bed's wall pairs took 6.6% more instructions.
template <class Kernel>
[[gnu::noinline]] void even_block(PairList& list, const Kernel& kernel, std::size_t b, PairScratch& scratch) {
  block_forces(list, kernel, b, scratch);
}
// even_block compiled for AVX, as walk_chunk_avx, through the kernel's four lanes where it has
// them (wide()): the same bits.
template <class Kernel>
[[gnu::noinline, gnu::target("avx"), gnu::flatten]] void even_block_avx(PairList& list, const Kernel& kernel, std::size_t b,
                                                                       PairScratch& scratch) {
  if constexpr (requires { kernel.wide(); })
    block_forces(list, kernel.wide(), b, scratch);
  else
    block_forces(list, kernel, b, scratch);
}

}  // namespace pair_loop_detail

// The body pairs with each body's sum made in the loop (pair_split.hpp), on every thread of the
// team: the list is cut for the team's size when that changes (or the list did: reset).
// With `trail`, thread t's pass runs behind its walk on the bodies of done[t] that no other chunk
// reads (PairSplit::trail_from), done[t] narrowed to them.
template <bool kNoWait, class Kernel>
void direct_pair_forces(PairList& list, const Kernel& kernel, DirectSums& direct, PairScratch& scratch,
                        const WalkTrail* trail) {
  const int threads = omp_get_num_threads();
  if (direct.split.threads != threads) {
#pragma omp barrier
#pragma omp single
    direct.cut(list, threads);  // every thread has read the old count (the barrier) before this one changes it
  }
  const int t = omp_get_thread_num();
  if (!std::exchange(direct.zero[t].on, false)) pair_loop_detail::clear_home_sums(direct, t);
  const double start = threads > 1 ? omp_get_wtime() : 0.0;  // s; two clock reads a thread-step (~50 ns of ~100 us)
  pair_loop_detail::ChunkTrail behind;
  if (trail) {
    BodyRange& done = trail->done[t];
    done.first = std::max(done.first, direct.split.trail_from[t]);
    done.last = std::max(done.first, std::min(done.last, direct.split.body_cut[t + 1]));
    behind = {trail, done.first, done.last};
  }
  if (kHasAvx) pair_loop_detail::walk_chunk_avx(list, kernel, direct, scratch, t, behind);
  else pair_loop_detail::walk_chunk(list, kernel, direct, scratch, t, behind);
  if (trail) {
    behind.done_below(direct.split.body_cut[t + 1], true);
    trail->done[t].last = behind.next;  // the bodies it moved (done_below may stop at a turn)
  }
  if (threads > 1) direct.pace[t].took(omp_get_wtime() - start);
  if constexpr (!kNoWait) {
#pragma omp barrier
  }
}

// Runs `kernel(k, scratch) -> PairTotals` over every pair, keeps the per-pair forces in the list,
// adds each pair's energy to its own list.open_energy(k) (in step order: the same bits whatever
// thread runs it), keeps each block's contact count in list.block_contacts and flags in
// list.block_ended the blocks where a pair's contact ended (sized by resize_results).
// kNoWait: the threads go on without meeting at the loop's end (the next loop reads none of
// this list's results; a later barrier comes before anything that does).
// With `direct` (body pairs) each pair's force and torques go into its bodies' sums instead
// (direct_pair_forces), not into the list.
template <bool kNoWait = false, class Kernel>
void all_pair_forces(PairList& list, const Kernel& kernel, DirectSums* direct = nullptr,
                     const WalkTrail* trail = nullptr) {
  const std::size_t n = list.size(), blocks = list.blocks();
  assert(list.block_contacts.size() == blocks && list.block_ended.size() == blocks);
  assert(list.pending.size() == (list.sparse ? n : 0));
  // Small scenes (one sphere block) wake no thread; inside a team the blocks are shared (parallel.hpp).
  in_team(n > kPairBlock, [&] {
    PairScratch scratch;
    if (direct) {
      direct_pair_forces<kNoWait>(list, kernel, *direct, scratch, trail);
      return;
    }
    if constexpr (kNoWait) {
#pragma omp for schedule(dynamic, 1) nowait
      for (std::size_t b = 0; b < blocks; ++b) pair_loop_detail::block_forces(list, kernel, b, scratch);
    } else {
#pragma omp for schedule(dynamic, 1)
      for (std::size_t b = 0; b < blocks; ++b) pair_loop_detail::block_forces(list, kernel, b, scratch);
    }
  });
}

// even_pair_forces' blocks [first, second) of thread t of `threads`.
inline std::pair<std::size_t, std::size_t> even_blocks(const PairList& list, const std::uint32_t* begin, TeamCut cut,
                                                       std::size_t t, std::size_t threads) {
  const std::size_t n = list.size();
  const bool by_bodies = begin && cut.threads == int(threads);
  auto first_pair = [&](std::size_t u) { return by_bodies ? std::size_t(begin[cut.at[u]]) : u * n / threads; };
  auto first_block = [&](std::size_t u) { return (first_pair(u) + list.block / 2) / list.block; };
  return {first_block(t), t + 1 == threads ? list.blocks() : first_block(t + 1)};
}

// all_pair_forces for pairs of like cost (spheres and walls) in a list sorted by body: each
// thread takes the run of blocks nearest the pairs of its bodies in `cut` (`begin`, per body + 1:
// its first pair), the bodies its passes move, or without a cut for this team its share of the
// pairs; the same every step, so a pair's arrays and its body's state stay in one core's cache
// (shared as they came, blocks moved between the cores each step). Inside a team the threads
// leave without a barrier: the caller meets where something reads the results (ContactEngine::forces).
template <class Kernel>
void even_pair_forces(PairList& list, const Kernel& kernel, const std::uint32_t* begin = nullptr, TeamCut cut = {}) {
  const std::size_t n = list.size(), blocks = list.blocks();
  assert(list.block_contacts.size() == blocks && list.block_ended.size() == blocks);
  in_team(n > kPairBlock, [&] {
    PairScratch scratch;
    const auto [first, end] = even_blocks(list, begin, cut, omp_get_thread_num(), omp_get_num_threads());
    for (std::size_t b = first; b < end; ++b) {
      if (kHasAvx) pair_loop_detail::even_block_avx(list, kernel, b, scratch);
      else pair_loop_detail::even_block(list, kernel, b, scratch);
    }
  });
}

// Calls run(flag), flag a std::bool_constant<on>: a run-time switch made a compile-time one.
template <class Run>
void with_flag(bool on, const Run& run) {
  if (on)
    run(std::true_type{});
  else
    run(std::false_type{});
}

// Calls run(parts), parts a LawParts naming the law's parts at compile time: the pair loops
// are compiled once per combination and chosen here, once per step (law.hpp). The alternative,
// one loop testing LawParams' flags per contact, costs a branch per part and contact.
template <class Run>
void with_law(const LawParams& law, const Run& run) {
  with_flag(law.normal == NormalModel::hertz, [&](auto hertz) {
    using Normal = std::conditional_t<decltype(hertz)::value, NormalHertz, NormalLinear>;
    with_flag(law.cohesion, [&](auto cohesion) {
      with_flag(law.rolling, [&](auto rolling) {
        with_flag(law.tangential_damping, [&](auto dashpot) {
          run(LawParts<Normal, decltype(cohesion)::value, decltype(rolling)::value, decltype(dashpot)::value>{});
        });
      });
    });
  });
}

}  // namespace polydem
