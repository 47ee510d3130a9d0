#include "contact/list_build.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>

#include "polydem/release.hpp"

namespace polydem {

float gap_below(double core_distance2, double radii) {
  const double gap = std::sqrt(core_distance2) - radii;
  const float f = static_cast<float>(gap);
  if (!(static_cast<double>(f) > gap)) return f;
  // The float below f, as std::nextafter(f, -inf) gives it, without its libm call (~80
  // instructions a candidate): a step of the magnitude's bits, down above 0 and up below it.
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
  if (f == 0.0f) return -std::numeric_limits<float>::denorm_min();
  return std::bit_cast<float>(f > 0.0f ? bits - 1u : bits + 1u);
}

void sorted_by_key(const std::vector<FeaturePair>& candidates, std::vector<std::uint32_t>& order) {
  order.clear();
  std::uint64_t last = 0;  // each key made once (std::is_sorted made both of every neighbour pair)
  bool in_order = true;
  for (const FeaturePair& f : candidates) {
    const std::uint64_t key = feature_key(f);
    if (key < last) { in_order = false; break; }
    last = key;
  }
  if (in_order) return;
  const auto by_key = [](FeaturePair x, FeaturePair y) { return feature_key(x) < feature_key(y); };
  order.resize(candidates.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) { return by_key(candidates[x], candidates[y]); });
}

void CandidateBlock::add(BodyPair p, const PosedBody& a, const PosedBody& b, double range,
                         std::vector<FeaturePair>& found, std::vector<double>& distances2,
                         std::vector<std::uint32_t>& order) {
  found.clear();
  distances2.clear();
  const double smallest = candidate_features(a, b, range, found, &distances2);  // m
  add_found(p, smallest, a.radius + b.radius, found, distances2, order);
}

void CandidateBlock::clear() {
  pairs.clear();
  pair_gap.clear();
  count.clear();
  features.clear();
  gaps.clear();
}

void CandidateBlock::add_found(BodyPair p, double smallest, double radii, const std::vector<FeaturePair>& found,
                               const std::vector<double>& distances2, std::vector<std::uint32_t>& order) {
  if (found.empty()) return;
  pairs.push_back(p);
  pair_gap.push_back(smallest);
  count.push_back(std::uint32_t(found.size()));
  sorted_by_key(found, order);
  const std::size_t n = found.size();
  for (std::size_t r = 0; r < n; ++r) {
    const std::size_t c = order.empty() ? r : order[r];
    features.push_back(found[c]);
    gaps.push_back(gap_below(distances2[c], radii));
  }
}

BlockLayout lay_out_blocks(const std::vector<CandidateBlock>& blocks, PairList& list) {
  BlockLayout at{std::vector<std::size_t>(blocks.size() + 1, 0), std::vector<std::size_t>(blocks.size() + 1, 0)};
  for (std::size_t blk = 0; blk < blocks.size(); ++blk) {
    at.first_pair[blk + 1] = at.first_pair[blk] + blocks[blk].pairs.size();
    at.first_slot[blk + 1] = at.first_slot[blk] + blocks[blk].features.size();
  }
  list.pairs.resize(at.first_pair.back());
  list.gap_at_build.resize(at.first_pair.back());
  list.slot_begin.assign(at.first_pair.back() + 1, 0);
  list.features.resize(at.first_slot.back());
  list.slot_gap.resize(at.first_slot.back());
  return at;
}

void copy_block(std::vector<CandidateBlock>& blocks, std::size_t blk, const BlockLayout& at, PairList& list) {
  CandidateBlock& from = blocks[blk];
  std::copy(from.pairs.begin(), from.pairs.end(), list.pairs.begin() + at.first_pair[blk]);
  std::copy(from.pair_gap.begin(), from.pair_gap.end(), list.gap_at_build.begin() + at.first_pair[blk]);
  std::copy(from.features.begin(), from.features.end(), list.features.begin() + at.first_slot[blk]);
  std::copy(from.gaps.begin(), from.gaps.end(), list.slot_gap.begin() + at.first_slot[blk]);
  std::uint32_t end = std::uint32_t(at.first_slot[blk]);  // of the pair's run
  for (std::size_t k = 0; k < from.count.size(); ++k) list.slot_begin[at.first_pair[blk] + k + 1] = end += from.count[k];
  from = CandidateBlock{};
}

void free_results(PairList& list) {
  for (auto* v : {&list.force_i, &list.torque_i, &list.torque_j}) release(*v);
  release(list.touching);
  release(list.linear_steps);
  release(list.block_contacts);
  release(list.block_ended);
  release(list.gap_at_build);
  release(list.slot_gap);
}

void size_slots(PairList& list) {
  const std::size_t n_slots = list.slot_begin.back();
  if (list.sparse) {  // states made as slots touch
    list.state_of.assign(n_slots, kNoState);
    list.states.reset(n_slots, list.rolls, list.recording);
  } else {
    list.slots.assign(n_slots, ContactSlot{});
    list.records.assign(list.recording ? n_slots : 0, SlotRecord{});
  }
  list.active.assign(n_slots, 0);
  list.touching.assign(list.size(), 0);
  list.pending.assign(list.sparse ? list.size() : 0, EnergyParts{});  // dense: in the slots
}

void size_results(PairList& list, bool pair_steps) {
  std::vector<std::uint16_t> touching = std::move(list.touching);
  std::vector<EnergyParts> pending = std::move(list.pending);
  list.resize_results(pair_steps);  // zeroes `touching` and `pending` too
  list.touching = std::move(touching);
  list.pending = std::move(pending);
}

void sort_by_key(std::vector<FeaturePair>& candidates) {
  thread_local std::vector<std::uint32_t> order;
  sorted_by_key(candidates, order);
  if (order.empty()) return;
  thread_local std::vector<FeaturePair> sorted;
  sorted.clear();
  for (std::uint32_t c : order) sorted.push_back(candidates[c]);
  candidates.swap(sorted);
}

void fill_driver_slots(const std::vector<std::vector<FeaturePair>>& per_pair, PairList& list) {
  list.slot_begin.assign(per_pair.size() + 1, 0);
  for (std::size_t k = 0; k < per_pair.size(); ++k)
    list.slot_begin[k + 1] = list.slot_begin[k] + std::uint32_t(per_pair[k].size());
  list.features.resize(list.slot_begin.back());
  list.slot_gap.assign(list.slot_begin.back(), -std::numeric_limits<float>::infinity());
  for (std::size_t k = 0; k < per_pair.size(); ++k)  // a copy a slot: no region worth waking
    std::copy(per_pair[k].begin(), per_pair[k].end(), list.features.begin() + list.slot_begin[k]);
}

}  // namespace polydem
