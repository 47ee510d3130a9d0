#pragma once
// Each body's contact force summed in the body-pair loop at any thread count, with the bits of
// one thread's pair-order sum: the list is cut into one contiguous chunk per thread, a body's
// sum is made by the chunk holding its last pair (its home), and only the pairs whose bodies
// are not both homed in their own chunk (foreign pairs) go through memory (all_pair_forces).
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

// A foreign pair's results, computed before the chunks' walks (which read them).
struct ForeignResult {
  Vec3 force_i, torque_i, torque_j;  // N on i, N m on i and on j
  bool ended;                        // its contact ended this step (PairList::block_ended)
};

// The cut of a pair list for a team of `threads`, rebuilt with the list or the team size.
struct PairSplit {
  int threads = 0;                           // the team it was cut for; 0: to be cut
  std::vector<std::uint32_t> cut;            // threads + 1 pair indices, multiples of kPairBlock but the last
  std::vector<std::uint32_t> body_cut;       // threads + 1 bodies: chunk t's pairs' bodies i from body_cut[t] (TeamCut)
  std::vector<double> walk_weight;           // per chunk, its walk's weight (pairs apart; its bodies' left out)
  std::vector<std::uint32_t> foreign;        // foreign pairs, increasing, then the list size (a sentinel)
  std::vector<std::uint32_t> foreign_begin;  // per chunk + 1: its foreign pairs' ordinals
  std::vector<std::uint8_t> foreign_side;    // per foreign pair: 1 its i is homed in its chunk, 2 its j
  std::vector<std::uint32_t> home_begin;     // per chunk + 1: its bodies in `homes`
  std::vector<std::uint32_t> homes;          // the bodies with pairs, by home chunk
  std::vector<std::uint32_t> early_begin;    // per entry of `homes` + 1: its pairs in earlier chunks
  std::vector<std::uint32_t> early;          // foreign ordinal << 1 | (1 when the body is j), increasing
  std::vector<std::uint32_t> early_homes_begin;  // per chunk + 1: its entries of `homes` with early pairs
  std::vector<std::uint32_t> early_homes;        // those entries (indices of `homes`), by chunk
};

// Cuts `pairs` (sorted by i) into `threads` chunks of kPairBlock blocks, balanced by the work
// each chunk does in its walk: its internal pairs, each weighed by its contacts at the last step
// (`touching`, per pair, or empty: none), and the foreign ones' adds (computed before, shared out),
// plus the work of the bodies it takes in the step's other passes (`body_weight`, per body in
// pairs apart, or empty: none). Chunk t gets the fraction shares[t] of the whole weight (`shares`:
// per thread, summing to 1, or empty: even shares). Thread t takes the bodies from the body i of
// chunk t's first pair (body_cut): each body with pairs as i is in the share of the chunk of its last one.
void split_pairs(const std::vector<BodyPair>& pairs, const std::vector<std::uint16_t>& touching,
                 const std::vector<float>& body_weight, std::size_t n_bodies, int threads, PairSplit& split,
                 const std::vector<double>& shares = {});

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

// The body pairs' sums (per body of the contact stage), made by their loop every step.
struct DirectSums {
  std::vector<BodySum> sums;
  std::vector<float> body_weight;  // per body, its other passes' work in pairs apart (split_pairs), or empty
  PairSplit split;
  std::vector<ForeignResult> foreign;  // per foreign pair of `split`
  // The cut follows the threads' measured speed: a vCPU slowed by the host (or another process
  // on its core) for seconds takes less of the next cut. `shares` is the last cut's (empty: even);
  // `follow_pace` false keeps them as set (tests force cuts with it).
  std::vector<ThreadPace> pace;  // per thread of the cut's team
  std::vector<double> shares;
  bool follow_pace = true;
  // Every sum is +0 (reset, or each taken and cleared by ForceSums since the loop): the first
  // chunk's walk then starts from them as they are, no pass to clear its home bodies' sums.
  // Read by every thread at the loop's start (then only the sums with early pairs are started),
  // cleared by the first chunk's thread after the foreign pairs' barrier.
  bool zero = false;
  void reset(std::size_t n_bodies) {  // at each rebuild: the split is cut again in the loop
    sums.assign(n_bodies, BodySum{});
    split.threads = 0;
    zero = true;
  }
};

}  // namespace polydem
