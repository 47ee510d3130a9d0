#pragma once
// A rebuild's lists laid out: the body pairs' candidate feature pairs found block by block and
// joined into a PairList's pairs, slot runs, keys and gaps, then the slots' state sized. No
// vector per pair: at 91k spheres two allocations of 32 bytes or more a pair were the
// rebuild's peak.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "contact/contact_lists.hpp"
#include "polydem/parallel.hpp"

namespace polydem {

// m, the gap rounded towards -inf to a float: stays a lower bound for the skip test.
float gap_below(double core_distance2, double radii);

// The order of a pair's candidates by key; `order` left empty when they are in it already
// (candidate_features gives body pairs sorted: then no index list is made and read).
void sorted_by_key(const std::vector<FeaturePair>& candidates, std::vector<std::uint32_t>& order);

// The candidates of kCandidateBlock near pairs: the pairs with some candidate, each one's
// smallest gap, its number of candidates, and the candidates in key order with their gaps.
constexpr std::size_t kCandidateBlock = 64;
struct CandidateBlock {
  std::vector<BodyPair> pairs;
  std::vector<double> pair_gap;  // m
  std::vector<std::uint32_t> count;
  std::vector<FeaturePair> features;
  std::vector<float> gaps;  // m, lower bounds
  // Adds pair p's candidates unless it has none (it cannot touch before the next rebuild).
  void add(BodyPair p, const PosedBody& a, const PosedBody& b, double range, std::vector<FeaturePair>& found,
           std::vector<double>& distances2, std::vector<std::uint32_t>& order);
  // The same for candidates found already: `smallest` their smallest gap (m), `radii` the
  // pair's (m), distances2 their core distances^2 (m^2).
  void add_found(BodyPair p, double smallest, double radii, const std::vector<FeaturePair>& found,
                 const std::vector<double>& distances2, std::vector<std::uint32_t>& order);
  void clear();
};

// The blocks joined as `list`'s pairs, slot_begin, features, slot_gap and gap_at_build, in block
// order (the near pairs' order), in two halves, for a team that runs the first on one thread (beside
// other serial work) and shares the second: each block's first pair and slot in `list`, its arrays sized...
struct BlockLayout {
  std::vector<std::size_t> first_pair, first_slot;  // per block, and the totals last
};
BlockLayout lay_out_blocks(const std::vector<CandidateBlock>& blocks, PairList& list);
// ... then block `blk` copied to its place and freed (the blocks apart: any thread, any order).
void copy_block(std::vector<CandidateBlock>& blocks, std::size_t blk, const BlockLayout& at, PairList& list);

// Candidates of the body pairs whose bounding spheres overlap, laid out in `list` (pairs with
// none stay out of the per-step loop: half the pairs in a pile). pose_of(b): body b's pose (a
// sphere's made on the spot). The blocks are found in parallel; the result is the same for
// any thread count.
template <class PoseOf>
void body_candidates(const std::vector<BodyPair>& near, const PoseOf& pose_of, double range, PairList& list) {
  std::vector<CandidateBlock> blocks((near.size() + kCandidateBlock - 1) / kCandidateBlock);
  BlockLayout at;  // the list's, from the blocks
  in_team(near.size() >= kParallelMinItems, [&] {
    std::vector<FeaturePair> found;
    std::vector<double> distances2;  // m^2
    std::vector<std::uint32_t> order;
    CandidateBlock scratch;  // grown once per thread; each block is copied out at its exact size
#pragma omp for schedule(dynamic, 1)
    for (std::size_t blk = 0; blk < blocks.size(); ++blk) {
      scratch.clear();
      for (std::size_t k = blk * kCandidateBlock; k < std::min(near.size(), (blk + 1) * kCandidateBlock); ++k)
        scratch.add(near[k], pose_of(near[k].i), pose_of(near[k].j), range, found, distances2, order);
      blocks[blk] = scratch;
    }
    // The list laid out on one thread, the blocks copied on the team (one region for all of it).
#pragma omp single
    at = lay_out_blocks(blocks, list);
#pragma omp for schedule(static) nowait
    for (std::size_t blk = 0; blk < blocks.size(); ++blk) copy_block(blocks, blk, at, list);
  });
}

// Frees what active_part does not read (the last step's results but the pending energies, the
// gaps at the build: ~70 bytes a pair), before it copies the active part: a rebuild's peak
// held the whole old list.
void free_results(PairList& list);

// Sizes the per-slot state (springs, records, active flags; a sparse list's state indexes and an
// empty store) and the pairs' contact counts and pending energies of a list whose pairs, runs
// and keys are laid out: what carry_history fills.
void size_slots(PairList& list);
// Then the per-pair results, keeping the counts and pending energies: sized once the old list
// is freed (a rebuild's peak held both, 98 bytes a pair). pair_steps: PairList::resize_results'.
void size_results(PairList& list, bool pair_steps = true);

// Sorts one pair's candidates by key in place (the order sorted_by_key gives).
void sort_by_key(std::vector<FeaturePair>& candidates);

// Lays out per-pair candidate lists, each sorted by key (sort_by_key), as the slots of a driver
// list, gaps -inf (never skipped: drivers move).
void fill_driver_slots(const std::vector<std::vector<FeaturePair>>& per_pair, PairList& list);

}  // namespace polydem
