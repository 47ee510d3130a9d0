#pragma once
// The next step's joined pass (close_and_start_step<true>'s) run right behind this step's body-pair
// walk (issue 19): each body's closing kick, opening kick, drift and rebuild test while its state
// and sum are still in cache, not in a pass over all bodies a step later. One process, nothing but
// gravity and the contacts acting: equal spheres in index order (spheres' lists), or isotropic
// polyhedra in index order (cubes), whose next pose is made there too. The same arithmetic, body
// by body, as the passes it replaces (the same bits). Counted at 216,000 tiled cubes, a cube-step's
// last-level misses 24.7 -> 18.5 (spheres at 216,000: 8.24 -> 5.98).
#include <cstdint>
#include <vector>

#include "contact/contact_engine.hpp"
#include "integrate/integrate.hpp"
#include "neighbor/rebuild_trigger.hpp"

namespace polydem {

// Which bodies a trailing pass can move (TrailingPass::choose).
enum class TrailKind {
  none,
  spheres,    // equal spheres, spheres[k] == k: points watched (PointWatch)
  isotropic,  // isotropic bodies, isotropic[k] == k: bounds watched (BoundWatch), poses made
};

// True where `groups` lets a trailing pass move every body: equal spheres, spheres[k] == k.
bool trailing_fits(const RotorGroups& groups, std::size_t n);

class TrailingPass {
 public:
  // Once the bodies are grouped: the kind of pass that can move them all.
  void choose(const RotorGroups& groups, const Bodies& b);
  TrailKind kind() const { return kind_; }
  // Before the step's second region: the next step's joined pass, h = dt/2 (s), gravity (m/s^2);
  // the hook for ContactEngine::forces. Spheres:
  WalkTrail open(Bodies& b, double h, double dt, const Vec3& gravity, ForceSums sums, const PointWatch& watch);
  // Isotropic bodies, each listed one posed for the next step's forces once moved:
  WalkTrail open(Bodies& b, double h, double dt, const Vec3& gravity, ForceSums sums, const BoundWatch& watch,
                 const ListedPoses& poses);
  // After that region, outside any: the bodies no thread moved behind its walk (rest's).
  void close(std::size_t n);
  // In the next step's first region, on every thread of its team: the same pass on those bodies
  // (`sums` that step's closing_sums; isotropic bodies: each turn of `turns`, null: none, between
  // its body's kicks, and the poses), then a barrier (the threads' next reads cross the cut).
  void rest(const ForceSums& sums, const PassTurns* turns = nullptr) const;

 private:
  static void pass_spheres(const void* self, std::uint32_t first, std::uint32_t last);
  template <class Arrays>
  static void pass_isotropic(const void* self, std::uint32_t first, std::uint32_t last);
  // The two passes compiled for AVX, as walk_chunk_avx (the same bits): the walk calls these where the CPU has it.
  [[gnu::target("avx"), gnu::flatten]] static void pass_spheres_avx(const void* self, std::uint32_t first, std::uint32_t last);
  template <class Arrays>
  [[gnu::target("avx"), gnu::flatten]] static void pass_isotropic_avx(const void* self, std::uint32_t first,
                                                                      std::uint32_t last);
  // rest's moves of this thread's share, without its barrier; and compiled for AVX, as the passes.
  void move_left(const ForceSums& sums, const PassTurns* turns) const;
  [[gnu::target("avx"), gnu::flatten]] void move_left_avx(const ForceSums& sums, const PassTurns* turns) const;
  template <class Arrays>
  void rest_isotropic(const Arrays& a, const ForceSums& sums, const PassTurns* turns) const;
  template <class F>
  void for_my_left(F&& f) const;
  template <class Arrays>
  const Arrays& arrays() const;
  WalkTrail open_common(double h, double dt, const Vec3& gravity, ForceSums sums);
  TrailKind kind_ = TrailKind::none;
  bool alike_ = false;  // one mass and inertia for all (spheres always): arrays_, else body_arrays_
  AlikeArrays arrays_{};
  BodyArrays body_arrays_{};
  double h_ = 0.0, dt_ = 0.0;  // s
  Vec3 gravity_ = Vec3::Zero();  // m/s^2
  ForceSums sums_{};
  PointWatch watch_{};
  BoundWatch bounds_{};
  ListedPoses poses_{};
  std::vector<BodyRange> done_;  // per thread: the bodies it moved behind its walk
  std::vector<BodyRange> left_;  // the others, increasing (close)
  std::uint32_t left_count_ = 0;
};

}  // namespace polydem
