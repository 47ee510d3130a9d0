#pragma once
// Each body's contact force summed in the body-pair loop at any thread count, with the bits of
// one thread's pair-order sum: the list is cut into one contiguous chunk per thread, each pair
// is computed by its chunk's thread, and a body's sum is begun by the chunk holding its first
// pair (its home). A pair whose bodies are not both homed in its chunk (a foreign pair) adds the
// side homed there and keeps the other (a late term) for the closing pass, which adds a body's
// late terms after its sum in pair order (LateTerms): no pass before the walk, no barrier.
#include <array>
#include <cstdint>
#include <vector>

#include "contact/contact_lists.hpp"

namespace polydem {

// A body's force (N) and torque (N m) from its body pairs, each added in increasing pair order.
// 48 bytes, not a cache line each: two threads write neighbours' sums only where their chunks'
// home bodies meet, and every step streams each body's sum twice (the loop, the closing pass).
struct BodySum {
  Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
};

// A foreign pair's results, kept by its chunk's walk for the side homed in an earlier chunk.
struct ForeignResult {
  Vec3 force_i, torque_i, torque_j;  // N on i, N m on i and on j
};

// Each body's late terms (its pairs after its home chunk), added after its sum by the closing
// pass in pair order: one thread's bits. Addresses, for the closing pass's registers.
struct LateTerms {
  // per body + 1: its entries of `late`; null where there are none (one thread's cut): the
  // closing pass then reads no 4 bytes a body (issue 19)
  const std::uint32_t* begin = nullptr;
  const std::uint32_t* late = nullptr;   // foreign ordinal << 1 | (1 when the body is j), increasing
  const ForeignResult* foreign = nullptr;
  [[gnu::always_inline]] void add_to(std::size_t b, Vec3& force, Vec3& torque) const {
    if (!begin) return;
    for (std::uint32_t e = begin[b]; e < begin[b + 1]; ++e) {
      const ForeignResult& r = foreign[late[e] >> 1];
      if (late[e] & 1u) {
        force -= r.force_i;  // as add_as_j (pair_loop.hpp)
        torque += r.torque_j;
      } else {
        force += r.force_i;
        torque += r.torque_i;
      }
    }
  }
};

// The cut of a pair list for a team of `threads`, rebuilt with the list or the team size.
struct PairSplit {
  int threads = 0;                           // the team it was cut for; 0: to be cut
  std::vector<std::uint32_t> cut;            // threads + 1 pair indices, multiples of the list's block but the last
  std::vector<std::uint32_t> body_cut;       // threads + 1 bodies: chunk t's pairs' bodies i from body_cut[t] (TeamCut)
  std::vector<double> walk_weight;           // per chunk, its walk's weight (pairs apart; its bodies' left out, a trailed cut's in)
  std::vector<std::uint32_t> foreign;        // foreign pairs, increasing, then the list size (a sentinel)
  std::vector<std::uint32_t> foreign_begin;  // per chunk + 1: its foreign pairs' ordinals
  std::vector<std::uint8_t> foreign_side;    // per foreign pair: 1 its i is homed in its chunk, 2 its j
  std::vector<std::uint32_t> home_begin;     // per chunk + 1: its bodies in `homes`
  std::vector<std::uint32_t> homes;          // the bodies with pairs, by home chunk
  std::vector<std::uint32_t> late_begin;     // per body + 1: its late terms in `late` (LateTerms)
  std::vector<std::uint32_t> late;           // foreign ordinal << 1 | (1 when the body is j), by body
  std::vector<std::uint32_t> trail_from;     // per chunk: its first body no earlier chunk's pair reads (WalkTrail)
};

// Bodies [first, last) of one thread, increasing; empty where first == last.
struct BodyRange {
  std::uint32_t first = 0, last = 0;
};

// A pass run right behind the body pairs' walk (Simulation's trailing pass): a body is done once
// the walk has passed its pairs as i (pairs sorted by i < j: no later pair reads it) and no other
// chunk's pair reads it. Thread t runs `pass(context, first, last)` on its own done bodies as its
// walk finishes them, within done[t] (set by the caller to the bodies whose driver pairs thread t
// made, narrowed by the walk to those it moved: a thread whose pairs left a turn stops), the
// caller's next pass moves the others.
struct WalkTrail {
  void (*pass)(const void* context, std::uint32_t first, std::uint32_t last);
  const void* context;
  BodyRange* done;  // per thread of the team
};

// The work a cut adds where it crosses pairs, in split_pairs' unit (a pair apart): a foreign pair's
// result kept on top of its pair (the walk), and a late term added by its body's closing pass.
struct CrossWeights {
  double foreign = 0.0, late = 0.0;
};

// Cuts `pairs` (sorted by i) into `threads` chunks of blocks of `block_size` pairs, balanced by the work
// each chunk does in its walk: its pairs, each weighed by its contacts at the last step
// (`touching`, per pair, or empty: none), plus the work of the bodies it takes in the step's
// other passes (`body_weight`, per body in pairs apart, or empty: none). Chunk t gets the
// fraction shares[t] of the whole weight (`shares`: per thread, summing to 1, or empty: even
// shares). Thread t takes the bodies from the body i of chunk t's first pair (body_cut): each
// body with pairs as i is in the share of the chunk of its last one. With `cross`, the cut is made
// again once with the first cut's foreign pairs and late terms weighed where they run. `trailed`
// (> 0): each body's pass, that much of its weight, runs behind the walk (WalkTrail) but for the
// bodies an earlier chunk reads, which the next step's first region moves: the cut is made again
// without those passes until it stays.
void split_pairs(const std::vector<BodyPair>& pairs, const std::vector<std::uint16_t>& touching,
                 const std::vector<float>& body_weight, std::size_t n_bodies, int threads, PairSplit& split,
                 const std::vector<double>& shares = {}, CrossWeights cross = {},
                 std::size_t block_size = kPairBlock, double trailed = 0.0);

// One thread's walk times (s) since the last cut, the last kSteps kept. A cache line of its own
// start: each thread writes its own every step.
struct alignas(64) ThreadPace {
  static constexpr std::uint32_t kSteps = 512;  // more than a sphere bed's ~350 steps between rebuilds
  std::array<float, kSteps> seconds{};
  std::uint32_t steps = 0;
  void took(double s) { seconds[steps++ % kSteps] = float(s); }
};

// The shares of the next cut (split_pairs) from the threads' walk times under the last one
// (`split`): a thread's speed is its chunk's walk weight over its median walk time (the median:
// a thread that lost its core for a few steps is not slow), and each thread gets work in
// proportion to its speed, half-way from `shares` (smoothed: one interval's noise moves the cut
// half as far), each within [1/2, 3/2] of an even share. `shares` when too few steps were timed.
std::vector<double> paced_shares(const PairSplit& split, const std::vector<ThreadPace>& pace,
                                 const std::vector<double>& shares);

// One thread's flag: every sum its chunk begins is +0 (reset, or each taken and cleared by
// ForceSums since the loop), so its walk starts from them as they are, with no pass clearing
// them. A cache line each: set by sums_taken between the regions, read and cleared by its own
// thread at the loop's start (no barrier between the threads' reads and a clear).
struct alignas(64) SumsZero {
  bool on = false;
};

// The body pairs' sums (per body of the contact stage), made by their loop every step.
struct DirectSums {
  std::vector<BodySum> sums;
  std::vector<float> body_weight;  // per body, its other passes' work in pairs apart (split_pairs), or empty
  CrossWeights cross;              // the cut's crossing work (split_pairs)
  double trailed = 0.0;            // the trailing pass's part of each body_weight, behind the walk (split_pairs)
  PairSplit split;
  std::vector<ForeignResult> foreign;  // per foreign pair of `split`: its late terms
  // The cut follows the threads' measured speed: a vCPU slowed by the host (or another process
  // on its core) for seconds takes less of the next cut. `shares` is the last cut's (empty: even);
  // `follow_pace` false keeps them as set (tests force cuts with it).
  std::vector<ThreadPace> pace;  // per thread of the cut's team
  std::vector<double> shares;
  bool follow_pace = true;
  std::vector<SumsZero> zero;  // per thread of the cut's team
  void taken() {  // every sum was read and cleared (ForceSums)
    for (SumsZero& z : zero) z.on = true;
  }
  void reset(std::size_t n_bodies) {  // at each rebuild: the split is cut again in the loop
    sums.assign(n_bodies, BodySum{});
    split.threads = 0;
    split.late_begin.assign(n_bodies + 1, 0);  // no late terms until the loop (a closing pass may read)
    split.late.clear();
    zero.assign(1, SumsZero{true});
  }
  LateTerms late_terms() const {
    return {split.late.empty() ? nullptr : split.late_begin.data(), split.late.data(), foreign.data()};
  }
  // Cuts `list` for a team of `threads` (split_pairs, at the threads' pace): by the loop when its
  // team is not the cut's, or ahead by the rebuild, outside any region (no barrier in the loop).
  void cut(const PairList& list, int threads);
};

}  // namespace polydem
