// ContactEngine's cuts of a step's work among the team's threads: each body's weight in the
// walk's body cut, and the first region's own cut of the passes (issue 19).
#include <algorithm>
#include <numeric>
#include <utility>
#include <vector>

#include "contact/contact_engine.hpp"

namespace polydem {

namespace {

// A body's passes (closing and opening kicks, drift, the rebuild check; a polyhedron's pose) and a
// sphere-wall pair, in body pairs apart (split_pairs' unit: a sphere pair out of reach; a polyhedron
// pair): callgrind --separate-threads on the beds (README, "One body cut"). Recounted on the peers'
// bed (bfd00df, 2 threads, 300 steps): a pair unit ~79.5 instructions (the walk over 8,826 pairs,
// 8,013 touching), a sphere's passes ~114 (1.4), a sphere-wall pair in two lanes ~392 (4.9; 7.4
// before the wall lanes, which left the floor's thread short of work).
constexpr double kSpherePassWeight = 1.4;
constexpr double kWallPairWeight = 4.9;
constexpr double kPolyhedronPassWeight = 2.9;
// Behind the walk (trail_walks), in the same unit: a polyhedron's trailing pass (kicks, drift, bound,
// pose) and a driver pair, shared by bodies there. Counted on the settled cubes (bb48e35, 2 threads,
// 100 steps): a pair unit ~247 instructions (the walk over 7,742 pairs), a cube's pass ~558 (2.25),
// a driver pair ~786 (3.2).
constexpr double kTrailedPolyhedronWeight = 2.25;
constexpr double kPolyhedronDriverPairWeight = 3.2;
// The first region's work a body, in instructions a step (callgrind, the pour at 1 thread, 400
// steps from boxfill_t0.1.bin; the kicks and drift: pass_weights): a polyhedron's rebuild check
// (displacement_bound) and a listed polyhedron's pose (rotation and world vertices).
constexpr double kMeasureInstructions = 97.0, kPoseInstructions = 400.0;
// A thread this far above an even share of the first region takes a cut of its own (pass_cut):
// the settled cubes' walk cut leaves +13% there, the bed's +18%; the pour's +58%.
constexpr double kOwnPassCut = 1.25;
// A cut's crossing work in the same units (CrossWeights), from the bed's instructions at 1 and 2
// threads (callgrind, 300 steps): a foreign pair's kept result ~62 instructions on top of its pair
// (0.7 of a sphere pair's ~87, 0.2 of a polyhedron pair's ~290), a late term ~20 (0.2; 0.07).
constexpr CrossWeights kSphereCross{0.7, 0.2}, kPolyhedronCross{0.2, 0.07};

}  // namespace

// Each body's passes and (spheres) wall pairs, in body pairs apart (split_pairs' unit), so the
// body cut of the walk shares the passes too and evens out the walk and the wall pairs (no barrier
// between them). Polyhedra's wall pairs are shared as they come, but by bodies ahead of a trailing
// pass. `passes` false: the passes have a cut of their own (cut_passes), the walk's weighs its
// pairs and wall pairs alone; trailed, the passes run in the walk's region whatever their cut.
void ContactEngine::weigh_bodies(bool passes) {
  passes |= trailed_;
  const double sphere = passes ? kSpherePassWeight : 0.0;
  const double polyhedron = !passes ? 0.0 : trailed_ ? kTrailedPolyhedronWeight : kPolyhedronPassWeight;
  // driver_begin_ read only after the driver list is made (rebuild): a polyhedron's untrailed cut is made beside it
  const bool by_drivers = spheres_only_ || trailed_;
  const double driver_pair = spheres_only_ ? kWallPairWeight : kPolyhedronDriverPairWeight;
  direct_.body_weight.resize(direct_.sums.size());
  for (std::size_t b = 0; b < direct_.body_weight.size(); ++b)
    direct_.body_weight[b] = float((spheres_only_ ? sphere : polyhedron) +
                                   (by_drivers ? driver_pair * (driver_begin_[b + 1] - driver_begin_[b]) : 0.0));
  direct_.cross = spheres_only_ ? kSphereCross : kPolyhedronCross;
  direct_.trailed = !trailed_ ? 0.0 : spheres_only_ ? sphere : polyhedron;
}

namespace {

// The passes' cut folded on the walk's body cut `walk` (TeamCut::folded), from `before` (per body + 1,
// the passes' work of the bodies before it): thread t keeps its walk chunk's bodies, the last one
// only up to an even share, and the bodies past that are dealt to the threads from the last but
// one to the first, each up to an even share (thread 0 takes the rest). Returns the heaviest
// thread's work: a pour's pile, cut by the walk, stays on the cores that walk it (issue 19).
double fold_cut(const std::uint32_t* walk, const std::vector<double>& before, int threads,
                std::vector<std::uint32_t>& at) {
  const std::size_t n = before.size() - 1;
  const double even = before[n] / threads;
  auto reach = [&](std::uint32_t from, double work) {  // the body where the work from `from` reaches `work`
    const auto b = std::lower_bound(before.begin() + from, before.end(), before[from] + work) - before.begin();
    return std::uint32_t(std::min(std::size_t(b), n));
  };
  at.assign(2 * threads + 1, std::uint32_t(n));
  std::copy(walk, walk + threads, at.begin());
  at[threads] = at[threads + 1] = reach(walk[threads - 1], even);
  for (int t = threads - 2; t > 0; --t) {  // thread t's second piece: 2 threads - 1 - t
    const double need = even - (before[walk[t + 1]] - before[walk[t]]);
    const std::uint32_t from = at[2 * threads - 1 - t];
    at[2 * threads - t] = need > 0.0 ? reach(from, need) : from;
  }
  double heaviest = 0.0;
  for (int t = 0; t < threads; ++t) {
    const int u = 2 * threads - 1 - t;
    heaviest = std::max(heaviest, before[at[t + 1]] - before[at[t]] + before[at[u + 1]] - before[at[u]]);
  }
  return heaviest;
}

}  // namespace

// The first region's own cut where the walk's leaves some thread kOwnPassCut times an even share
// of its passes or more: below that, a body moved and then walked by one thread stays in its cache.
void ContactEngine::cut_passes(int threads) {
  const bool walk_weighed_passes = !std::exchange(own_pass_cut_, false);
  const std::size_t n = pass_weight_.size();
  if (threads < 2 || n != direct_.sums.size() || direct_.split.threads != threads) return;
  std::vector<double> before(n + 1, 0.0);  // instructions a step of the bodies before b
  const double measure = spheres_only_ ? 0.0 : kMeasureInstructions;
  for (std::size_t b = 0; b < n; ++b) before[b + 1] = pass_weight_[b] + measure;
  if (!spheres_only_)
    for (std::uint32_t b : listed_) before[b + 1] += kPoseInstructions;
  std::partial_sum(before.begin(), before.end(), before.begin());
  const std::uint32_t* walk = direct_.split.body_cut.data();
  double heaviest = 0.0;
  for (int t = 0; t < threads; ++t) heaviest = std::max(heaviest, before[walk[t + 1]] - before[walk[t]]);
  if (heaviest < kOwnPassCut * before[n] / threads) return;
  if (walk_weighed_passes && !trailed_) {  // trailed, the walk's weights stay (weigh_bodies)
    weigh_bodies(false);  // the walk's cut again, without the passes (once a switch: ~0.2e6 instructions)
    direct_.cut(body_list_, threads);
  }
  pass_threads_ = threads;
  own_pass_cut_ = true;
  pass_folded_ = fold_cut(direct_.split.body_cut.data(), before, threads, pass_cut_) < kOwnPassCut * before[n] / threads;
  if (pass_folded_) return;
  pass_cut_.assign(threads + 1, std::uint32_t(n));  // the walk's chunks are uneven in themselves: an even cut
  pass_cut_[0] = 0;
  for (int t = 1; t < threads; ++t)
    pass_cut_[t] = std::uint32_t(std::lower_bound(before.begin(), before.end(), before[n] * t / threads) - before.begin());
}

}  // namespace polydem
