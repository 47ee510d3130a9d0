#pragma once
// Body pairs' feature candidates kept from one rebuild to the next (issue 19: a pour rebuilds
// every ~13 steps, mostly for the few bodies that fall). A pair's search looks `extra` beyond
// the range; until the pair's relative motion since then reaches `extra`, every feature pair
// within range now was found by it, so their exact distances now pick the list's candidates:
// the same candidates, distances and bits as a new search, for the cost of those distances.
#include <cstdint>
#include <vector>

#include "contact/list_build.hpp"

namespace polydem {

// What the motion bound reads of each local body.
struct BodyMotion {
  const Vec3* position;     // m
  const Quat* orientation;
  const double* reach;      // m, the farthest core point from the centre
};

// m, how far beyond touching a body pair's features are listed: `base` (the scene's skin plus the
// band), or with per-body skins s_i (the engine's, set at each rebuild) base + (s_i + s_j) / 2.
struct PairRange {
  PairRange(double all, const double* per_body = nullptr) : base(all), skin(per_body) {}
  double base;         // m
  const double* skin;  // m, per body; null: `base` alone
  double operator()(BodyPair p) const { return skin ? base + 0.5 * (skin[p.i] + skin[p.j]) : base; }
};

// Searches of body pairs: the poses they were made at and what they found, pair by pair.
struct PairSearches {
  std::vector<BodyPair> pairs;
  std::vector<Vec3> offset;  // m, x_j - x_i at the search
  std::vector<Quat> turn_i, turn_j;  // orientations at the search
  std::vector<double> looked;  // m, how far beyond touching the search looked (its range + extra)
  std::vector<std::uint32_t> begin{0};  // pair k's candidates: [begin[k], begin[k + 1])
  std::vector<FeaturePair> features;  // within range + extra then
  // m^2, per feature: its core distance^2 then, rounded down to a float (a lower bound: the recall's
  // filter then passes every candidate the exact one did; 4 bytes a candidate fewer held).
  std::vector<float> distance2;
  std::size_t size() const { return pairs.size(); }
  void add(BodyPair p, const BodyMotion& now, double reach, const std::vector<FeaturePair>& found,
           const std::vector<double>& found2);
};

class CandidateMemory {
 public:
  // extra: m, how far beyond the range a search looks.
  explicit CandidateMemory(double extra) : extra_(extra) {}
  // body_candidates(near, posed, range, list) with the same result (each pair at its own range),
  // searching anew only the pairs whose last search is out of reach (or absent); remembers this
  // rebuild's searches. A kept search holds while the pair moved less than it looked beyond the range now.
  void find(const std::vector<BodyPair>& near, const std::vector<PosedBody>& posed, const BodyMotion& now,
            PairRange range, PairList& list);
  // Forgets every search: the bodies' indices or shapes changed.
  void clear() { searches_ = PairSearches{}; }
  // Renumbers the searches for a new set of local bodies (a rank's after a migration): `was`
  // and `now` give each local index's global id, both increasing, so the kept pairs stay sorted.
  // Pairs with a body no longer local are dropped.
  void relabel(const std::vector<std::uint32_t>& was, const std::vector<std::uint32_t>& now);
  std::size_t searched() const { return searched_; }  // pairs searched anew by the last find
  std::size_t recalled() const { return recalled_; }  // pairs whose search was kept

 private:
  // old[k - first]: the index in searches_ of near pair k's search, -1 when none, for k in
  // [first, last) (both lists sorted by (i, j)): a block's own, so the blocks match on the team.
  void match(const std::vector<BodyPair>& near, std::size_t first, std::size_t last,
             std::vector<std::int64_t>& old) const;
  // m, how far pair p's core points may have come closer since its search e, with a margin
  // for round-off (NaN for a NaN state).
  double motion(std::size_t e, BodyPair p, const BodyMotion& now) const;
  // Keeps the near pairs' searches: pair k's is searches_'s from[k] when from[k] >= 0, else the
  // new one -1 - from[k] of its block's `made`.
  void remember(const std::vector<std::int64_t>& from, const std::vector<PairSearches>& made);
  // remember's two halves: the layout (one thread) and pair k's search copied to it (any thread).
  PairSearches laid_out(const std::vector<std::int64_t>& from, const std::vector<PairSearches>& made) const;
  void copy_search(const std::vector<std::int64_t>& from, const std::vector<PairSearches>& made, std::size_t k,
                   PairSearches& next) const;
  const PairSearches& source(const std::vector<std::int64_t>& from, const std::vector<PairSearches>& made,
                             std::size_t k, std::size_t& e) const;

  double extra_;  // m
  PairSearches searches_;
  std::size_t searched_ = 0, recalled_ = 0;
};

}  // namespace polydem
