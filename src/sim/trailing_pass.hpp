#pragma once
// The next step's joined pass (close_and_start_step<true>'s, spheres' lists) run right behind this
// step's body-pair walk (issue 19): each body's closing kick, opening kick, drift and rebuild test
// while its state and sum are still in cache, not in a pass over all bodies a step later. One
// process, equal spheres in index order, nothing but gravity and the contacts acting: the same
// arithmetic, body by body, as the pass it replaces (the same bits).
#include <cstdint>
#include <vector>

#include "contact/contact_engine.hpp"
#include "integrate/integrate.hpp"
#include "neighbor/rebuild_trigger.hpp"

namespace polydem {

// True where `groups` lets a trailing pass move every body: equal spheres, spheres[k] == k.
bool trailing_fits(const RotorGroups& groups, std::size_t n);

class TrailingPass {
 public:
  // Before the step's second region: the next step's joined pass, h = dt/2 (s), gravity (m/s^2);
  // the hook for ContactEngine::forces.
  WalkTrail open(Bodies& b, double h, double dt, const Vec3& gravity, ForceSums sums, const PointWatch& watch);
  // After that region, outside any: the bodies no thread moved behind its walk (rest's).
  void close(std::size_t n);
  // In the next step's first region, on every thread of its team: the same pass on those bodies
  // (`sums` that step's closing_sums), then a barrier (the threads' next reads cross the cut).
  void rest(const ForceSums& sums) const;

 private:
  static void pass(const void* self, std::uint32_t first, std::uint32_t last);
  AlikeArrays arrays_{};
  double h_ = 0.0, dt_ = 0.0;  // s
  Vec3 gravity_ = Vec3::Zero();  // m/s^2
  ForceSums sums_{};
  PointWatch watch_{};
  std::vector<BodyRange> done_;  // per thread: the bodies it moved behind its walk
  std::vector<BodyRange> left_;  // the others, increasing (close)
  std::uint32_t left_count_ = 0;
};

}  // namespace polydem
