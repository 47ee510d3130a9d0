#pragma once
// Each body's contact force summed in the body-pair loop at any thread count, with the bits of
// one thread's pair-order sum: the list is cut into one contiguous chunk per thread, a body's
// sum is made by the chunk holding its last pair (its home), and only the pairs whose bodies
// are not both homed in their own chunk (foreign pairs) go through memory (all_pair_forces).
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
// pairs apart, or empty: none). Thread t takes the bodies from the body i of chunk t's first pair
// (body_cut): each body with pairs as i is in the share of the chunk of its last one.
void split_pairs(const std::vector<BodyPair>& pairs, const std::vector<std::uint16_t>& touching,
                 const std::vector<float>& body_weight, std::size_t n_bodies, int threads, PairSplit& split);

// The body pairs' sums (per body of the contact stage), made by their loop every step.
struct DirectSums {
  std::vector<BodySum> sums;
  std::vector<float> body_weight;  // per body, its other passes' work in pairs apart (split_pairs), or empty
  PairSplit split;
  std::vector<ForeignResult> foreign;  // per foreign pair of `split`
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
