#include "contact/candidate_memory.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "polydem/parallel.hpp"

namespace polydem {
namespace {

// Relative margin of the motion test, on the scale of the lengths the distances are made of:
// round-off must never keep a search that could have missed a candidate.
constexpr double kMotionMargin = 1e-9;

// At least sin(theta / 2), theta the angle of the turn from unit q_then to q_now: with
// c = q_now . q_then = +-cos(theta / 2), |q_now -+ q_then|^2 = 2 (1 -+ c) >= 1 - c^2. Cheaper
// than the relative quaternion (no product, one root).
double half_turn_sine_bound(const Quat& q_now, const Quat& q_then) {
  const double minus2 = (q_now.coeffs() - q_then.coeffs()).squaredNorm();
  const double plus2 = (q_now.coeffs() + q_then.coeffs()).squaredNorm();
  return std::sqrt(std::min(minus2, plus2));
}

}  // namespace

void PairSearches::add(BodyPair p, const BodyMotion& now, double reach, const std::vector<FeaturePair>& found,
                       const std::vector<double>& found2) {
  pairs.push_back(p);
  looked.push_back(reach);
  offset.push_back(now.position[p.j] - now.position[p.i]);
  turn_i.push_back(now.orientation[p.i]);
  turn_j.push_back(now.orientation[p.j]);
  features.insert(features.end(), found.begin(), found.end());
  for (double d2 : found2) {
    // Rounded to nearest, then a step down where that went up (f > d2 >= 0: the float below f).
    const float f = static_cast<float>(d2);
    distance2.push_back(static_cast<double>(f) > d2 ? std::bit_cast<float>(std::bit_cast<std::uint32_t>(f) - 1u) : f);
  }
  begin.push_back(std::uint32_t(features.size()));
}

void CandidateMemory::match(const std::vector<BodyPair>& near, std::size_t first, std::size_t last,
                            std::vector<std::int64_t>& old) const {
  const std::vector<BodyPair>& had = searches_.pairs;
  const auto less = [](BodyPair a, BodyPair b) { return a.i != b.i ? a.i < b.i : a.j < b.j; };
  auto e = std::size_t(std::lower_bound(had.begin(), had.end(), near[first], less) - had.begin());
  old.resize(last - first);
  for (std::size_t k = first; k < last; ++k) {
    while (e < had.size() && less(had[e], near[k])) ++e;
    old[k - first] = e < had.size() && had[e] == near[k] ? std::int64_t(e) : -1;
  }
}

double CandidateMemory::motion(std::size_t e, BodyPair p, const BodyMotion& now) const {
  const Vec3& xi = now.position[p.i];
  const Vec3& xj = now.position[p.j];
  // Any core point of j moved relative to any of i by at most this since the search (m).
  const double moved = ((xj - xi) - searches_.offset[e]).norm() +
                       2.0 * now.reach[p.i] * half_turn_sine_bound(now.orientation[p.i], searches_.turn_i[e]) +
                       2.0 * now.reach[p.j] * half_turn_sine_bound(now.orientation[p.j], searches_.turn_j[e]);
  return moved + kMotionMargin * (extra_ + xi.norm() + xj.norm() + now.reach[p.i] + now.reach[p.j]);
}

void CandidateMemory::find(const std::vector<BodyPair>& near, const std::vector<PosedBody>& posed,
                           const BodyMotion& now, PairRange pair_range, PairList& list) {
  const std::size_t n_blocks = (near.size() + kCandidateBlock - 1) / kCandidateBlock;
  std::vector<CandidateBlock> blocks(n_blocks);
  std::vector<PairSearches> made(n_blocks);  // the new searches, block by block
  std::vector<std::int64_t> from(near.size());  // as remember() reads it
  BlockLayout at;     // the list's, from the blocks
  PairSearches next;  // the searches kept, laid out
  const bool own_region = omp_get_level() == 0;  // its end is the loop's barrier
  in_team(near.size() >= kParallelMinItems, [&] {
    std::vector<FeaturePair> wide, found;
    std::vector<double> wide2, found2;  // m^2
    std::vector<std::uint32_t> order;
    std::vector<std::int64_t> old;  // the block's pairs' searches (match)
    CandidateBlock block;  // grown once per thread; each block is copied out at its exact size
#pragma omp for schedule(dynamic, 1)
    for (std::size_t blk = 0; blk < n_blocks; ++blk) {
      block.clear();
      const std::size_t first = blk * kCandidateBlock, last = std::min(near.size(), first + kCandidateBlock);
      match(near, first, last, old);
      for (std::size_t k = first; k < last; ++k) {
        const BodyPair p = near[k];
        const PosedBody& a = posed[p.i];
        const PosedBody& b = posed[p.j];
        const double range = pair_range(p);  // m
        const double cutoff = a.radius + b.radius + range;  // m, as candidate_features'
        const double cutoff2 = cutoff * cutoff;
        double nearest2 = std::numeric_limits<double>::infinity();  // m^2
        found.clear();
        found2.clear();
        const auto keep = [&](FeaturePair f, double d2) {
          if (d2 >= cutoff2) return;
          found.push_back(f);
          found2.push_back(d2);
          nearest2 = std::min(nearest2, d2);
        };
        const std::int64_t had = old[k - first];  // its last search, -1 when none
        const double moved = had >= 0 ? motion(std::size_t(had), p, now) : 0.0;  // m
        if (had >= 0 && moved < searches_.looked[std::size_t(had)] - range) {  // false for NaN
          const std::size_t e = std::size_t(had);
          // A candidate that far then is beyond the cutoff now: no distance to take.
          const double beyond2 = (cutoff + moved) * (cutoff + moved);  // m^2
          for (std::uint32_t c = searches_.begin[e]; c < searches_.begin[e + 1]; ++c)
            if (searches_.distance2[c] < beyond2)
              keep(searches_.features[c], candidate_distance_sq(a, b, searches_.features[c], cutoff2));
          from[k] = std::int64_t(e);
        } else {
          wide.clear();
          wide2.clear();
          candidate_features(a, b, range + extra_, wide, &wide2);
          from[k] = -1 - std::int64_t(made[blk].size());
          made[blk].add(p, now, range + extra_, wide, wide2);
          for (std::size_t c = 0; c < wide.size(); ++c) keep(wide[c], wide2[c]);
        }
        block.add_found(p, std::sqrt(nearest2) - a.radius - b.radius, a.radius + b.radius, found, found2, order);
      }
      blocks[blk] = block;
    }
    // The list's layout and the memory's on two threads at once (a team of one does both): two
    // serial stretches the other thread waited through (~0.19e6 instructions a pour's rebuild).
    on_two_threads([&] { at = lay_out_blocks(blocks, list); },
                   [&] {
                     // kept searches: from[k] >= 0 (counted here, not reduced in the loop: clang
                     // refuses a reduction over a lambda's captured reference)
                     recalled_ = std::size_t(std::count_if(from.begin(), from.end(), [](std::int64_t f) { return f >= 0; }));
                     next = laid_out(from, made);
                   });
#pragma omp barrier
#pragma omp for schedule(static) nowait
    for (std::size_t blk = 0; blk < n_blocks; ++blk) copy_block(blocks, blk, at, list);
#pragma omp for schedule(static) nowait
    for (std::size_t k = 0; k < from.size(); ++k) copy_search(from, made, k, next);
    barrier_unless_own_region(own_region);
  });
  searches_ = std::move(next);
  searched_ = near.size() - recalled_;
}

void CandidateMemory::relabel(const std::vector<std::uint32_t>& was, const std::vector<std::uint32_t>& now) {
  std::vector<std::int64_t> to(was.size(), -1);  // an old local index's new one, -1 when gone
  for (std::size_t a = 0, b = 0; a < was.size(); ++a) {
    while (b < now.size() && now[b] < was[a]) ++b;
    if (b < now.size() && now[b] == was[a]) to[a] = std::int64_t(b);
  }
  std::vector<std::int64_t> kept;  // as remember() reads it: every kept pair's old search
  for (std::size_t e = 0; e < searches_.size(); ++e)
    if (to[searches_.pairs[e].i] >= 0 && to[searches_.pairs[e].j] >= 0) kept.push_back(std::int64_t(e));
  remember(kept, {});
  for (BodyPair& p : searches_.pairs) p = {std::uint32_t(to[p.i]), std::uint32_t(to[p.j])};
}

// The searches' source for near pair k: e in searches_ or in its block's `made`.
const PairSearches& CandidateMemory::source(const std::vector<std::int64_t>& from, const std::vector<PairSearches>& made,
                                            std::size_t k, std::size_t& e) const {
  if (from[k] >= 0) {
    e = std::size_t(from[k]);
    return searches_;
  }
  e = std::size_t(-1 - from[k]);
  return made[k / kCandidateBlock];
}

PairSearches CandidateMemory::laid_out(const std::vector<std::int64_t>& from, const std::vector<PairSearches>& made) const {
  const std::size_t n = from.size();
  PairSearches next;
  next.begin.assign(n + 1, 0);  // assign, not resize: GCC 12 misreads resize of the one-element default (-Warray-bounds)
  for (std::size_t k = 0, e = 0; k < n; ++k) {
    const PairSearches& s = source(from, made, k, e);
    next.begin[k + 1] = next.begin[k] + (s.begin[e + 1] - s.begin[e]);
  }
  next.pairs.resize(n);
  next.offset.resize(n);
  next.turn_i.resize(n);
  next.turn_j.resize(n);
  next.looked.resize(n);
  next.features.resize(next.begin[n]);
  next.distance2.resize(next.begin[n]);
  return next;
}

void CandidateMemory::copy_search(const std::vector<std::int64_t>& from, const std::vector<PairSearches>& made,
                                  std::size_t k, PairSearches& next) const {
  std::size_t e = 0;
  const PairSearches& s = source(from, made, k, e);
  next.pairs[k] = s.pairs[e];
  next.offset[k] = s.offset[e];
  next.turn_i[k] = s.turn_i[e];
  next.turn_j[k] = s.turn_j[e];
  next.looked[k] = s.looked[e];
  std::copy(s.features.begin() + s.begin[e], s.features.begin() + s.begin[e + 1], next.features.begin() + next.begin[k]);
  std::copy(s.distance2.begin() + s.begin[e], s.distance2.begin() + s.begin[e + 1],
            next.distance2.begin() + next.begin[k]);
}

void CandidateMemory::remember(const std::vector<std::int64_t>& from, const std::vector<PairSearches>& made) {
  PairSearches next = laid_out(from, made);
  parallel_for(from.size(), [&](std::size_t k) { copy_search(from, made, k, next); });
  searches_ = std::move(next);
}

}  // namespace polydem
