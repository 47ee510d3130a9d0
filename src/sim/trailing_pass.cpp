#include "sim/trailing_pass.hpp"

#include <omp.h>

#include "polydem/parallel.hpp"

namespace polydem {

bool trailing_fits(const RotorGroups& groups, std::size_t n) {
  return groups.spheres_alike && groups.spheres_in_order && groups.spheres.size() == n && groups.isotropic.empty() &&
         groups.asymmetric.empty();
}

// Every body isotropic, isotropic[k] == k (a pile of cubes).
static bool isotropic_in_order(const RotorGroups& groups, std::size_t n) {
  if (n == 0 || groups.isotropic.size() != n || !groups.spheres.empty() || !groups.asymmetric.empty()) return false;
  for (std::size_t k = 0; k < n; ++k)
    if (groups.isotropic[k] != k) return false;
  return true;
}

// Every body of body 0's mass and inertia (equal cubes: the pass reads neither array, 32 bytes a body).
static bool all_alike(const Bodies& b) {
  for (std::size_t i = 1; i < b.size(); ++i)
    if (b.mass[i] != b.mass[0] || b.inertia[i] != b.inertia[0]) return false;
  return true;
}

// The closing sums of a body moved behind its walk: every pair of it in its home chunk, so no late
// term is read (3 instructions a body-step).
struct HomeSums {
  ForceSums sums;
  [[gnu::always_inline]] void add_to(std::size_t b, Vec3& f_to, Vec3& t_to) const { sums.add_to<false>(b, f_to, t_to); }
};

void TrailingPass::choose(const RotorGroups& groups, const Bodies& b) {
  kind_ = trailing_fits(groups, b.size()) ? TrailKind::spheres
          : isotropic_in_order(groups, b.size()) ? TrailKind::isotropic
                                                 : TrailKind::none;
  alike_ = kind_ == TrailKind::spheres || (kind_ == TrailKind::isotropic && all_alike(b));
}

template <>
const AlikeArrays& TrailingPass::arrays<AlikeArrays>() const {
  return arrays_;
}
template <>
const BodyArrays& TrailingPass::arrays<BodyArrays>() const {
  return body_arrays_;
}

WalkTrail TrailingPass::open_common(double h, double dt, const Vec3& gravity, ForceSums sums) {
  h_ = h, dt_ = dt, gravity_ = gravity;
  sums_ = sums;
  done_.assign(std::size_t(omp_get_max_threads()), BodyRange{});
  void (*pass)(const void*, std::uint32_t, std::uint32_t) =
      kind_ == TrailKind::spheres ? (kHasAvx ? &TrailingPass::pass_spheres_avx : &TrailingPass::pass_spheres)
      : alike_ ? (kHasAvx ? &TrailingPass::pass_isotropic_avx<AlikeArrays> : &TrailingPass::pass_isotropic<AlikeArrays>)
               : (kHasAvx ? &TrailingPass::pass_isotropic_avx<BodyArrays> : &TrailingPass::pass_isotropic<BodyArrays>);
  return {pass, this, done_.data()};
}

WalkTrail TrailingPass::open(Bodies& b, double h, double dt, const Vec3& gravity, ForceSums sums,
                             const PointWatch& watch) {
  arrays_ = alike_arrays_of(b, 0);
  watch_ = watch;
  return open_common(h, dt, gravity, sums);
}

WalkTrail TrailingPass::open(Bodies& b, double h, double dt, const Vec3& gravity, ForceSums sums,
                             const BoundWatch& watch, const ListedPoses& poses) {
  if (alike_) arrays_ = alike_arrays_of(b, 0);
  else body_arrays_ = arrays_of(b);
  bounds_ = watch;
  poses_ = poses;
  return open_common(h, dt, gravity, sums);
}

void TrailingPass::pass_spheres(const void* self, std::uint32_t first, std::uint32_t last) {
  const TrailingPass& p = *static_cast<const TrailingPass*>(self);
  // Copies, as over_group's: the arrays' stores may alias `p`, whose members would be reloaded each body.
  const AlikeArrays a = p.arrays_;
  const HomeSums sums{p.sums_};
  const PointWatch watch = p.watch_;
  const double h = p.h_, dt = p.dt_;  // s
  const Vec3 gravity = p.gravity_;    // m/s^2
  for (std::uint32_t i = first; i < last; ++i)
    integrate_detail::close_and_start_from_gravity<Rotor::sphere>(a, i, h, dt, gravity, sums, watch);
}

template <class Arrays>
void TrailingPass::pass_isotropic(const void* self, std::uint32_t first, std::uint32_t last) {
  const TrailingPass& p = *static_cast<const TrailingPass*>(self);
  const Arrays a = p.arrays<Arrays>();  // copies, as pass_spheres'
  const HomeSums sums{p.sums_};
  const BoundWatch bounds = p.bounds_;
  const double h = p.h_, dt = p.dt_;  // s
  const Vec3 gravity = p.gravity_;    // m/s^2
  for (std::uint32_t i = first; i < last; ++i)
    integrate_detail::close_and_start_from_gravity<Rotor::isotropic>(a, i, h, dt, gravity, sums, bounds);
  p.poses_.pose(first, last);  // the bodies' state still in L1 (ChunkTrail::kBatch)
}

void TrailingPass::pass_spheres_avx(const void* self, std::uint32_t first, std::uint32_t last) {
  pass_spheres(self, first, last);
}

template <class Arrays>
void TrailingPass::pass_isotropic_avx(const void* self, std::uint32_t first, std::uint32_t last) {
  pass_isotropic<Arrays>(self, first, last);
}

void TrailingPass::close(std::size_t n) {
  left_.clear();
  left_count_ = 0;
  std::uint32_t at = 0;  // the threads' ranges are increasing with the thread
  for (const BodyRange& d : done_) {
    if (d.first == d.last) continue;
    if (at < d.first) left_.push_back({at, d.first}), left_count_ += d.first - at;
    at = d.last;
  }
  if (at < n) left_.push_back({at, std::uint32_t(n)}), left_count_ += std::uint32_t(n) - at;
}

// f(first, last) on each run of this thread's even share of the left bodies, increasing.
template <class F>
void TrailingPass::for_my_left(F&& f) const {
  const auto [first, last] = team_shares(left_count_, TeamCut{})[0];
  std::size_t skipped = 0;  // bodies of the gaps before this one
  for (const BodyRange& g : left_) {
    const std::size_t size = g.last - g.first;
    const std::size_t from = std::max(first, skipped), to = std::min(last, skipped + size);
    if (from < to) f(std::uint32_t(g.first + (from - skipped)), std::uint32_t(g.first + (to - skipped)));
    skipped += size;
  }
}

void TrailingPass::rest(const ForceSums& sums, const PassTurns* turns) const {
  if (kHasAvx) move_left_avx(sums, turns);
  else move_left(sums, turns);
#pragma omp barrier
}

void TrailingPass::move_left(const ForceSums& sums, const PassTurns* turns) const {
  if (kind_ == TrailKind::isotropic) {
    if (alike_) rest_isotropic(arrays_, sums, turns);
    else rest_isotropic(body_arrays_, sums, turns);
    return;
  }
  const AlikeArrays a = arrays_;  // copies, as pass_spheres'
  const PointWatch watch = watch_;
  const double h = h_, dt = dt_;  // s
  const Vec3 gravity = gravity_;  // m/s^2
  for_my_left([&](std::uint32_t first, std::uint32_t last) {
    for (std::uint32_t i = first; i < last; ++i)
      integrate_detail::close_and_start_from_gravity<Rotor::sphere>(a, i, h, dt, gravity, sums, watch);
  });
}

void TrailingPass::move_left_avx(const ForceSums& sums, const PassTurns* turns) const { move_left(sums, turns); }

// rest's isotropic bodies: this thread's share of the left ones moved (a turn of `turns` between
// its body's kicks, as close_and_start_step's), then posed.
template <class Arrays>
void TrailingPass::rest_isotropic(const Arrays& arrays, const ForceSums& sums, const PassTurns* turns) const {
  const Arrays a = arrays;  // copies, as pass_spheres'
  const BoundWatch bounds = bounds_;
  const double h = h_, dt = dt_;  // s
  const Vec3 gravity = gravity_;  // m/s^2
  for_my_left([&](std::uint32_t first, std::uint32_t last) {
    for (std::uint32_t i = first; i < last; ++i) {
      if (PassTurn* turn = turns ? turns->at(i) : nullptr) {
        integrate_detail::turn_between_kicks<Rotor::isotropic>(a, i, h, dt, gravity, sums, *turn);
        bounds(i, a.position[i]);
      } else {
        integrate_detail::close_and_start_from_gravity<Rotor::isotropic>(a, i, h, dt, gravity, sums, bounds);
      }
    }
    poses_.pose(first, last);
  });
}

}  // namespace polydem
