#pragma once
// Two steady sphere-wall pairs at once, one in each lane (geometry/lanes.hpp), or one alone through
// the same code: the driver pairs of a resting sphere bed. Each lane does sphere_wall_forces'
// operations in its order (the law: steady_linear_law, shared with the sphere pairs' lanes), so a
// lane has its pair's bits. Steady as a sphere pair's (sphere_lanes.hpp), on an active wall at rest
// (its velocity and spin +0: nothing subtracted), the dashpot on the sphere's mass (damping_mass: pair).
#include "contact/sphere_lanes.hpp"
#include "contact/sphere_wall.hpp"

namespace polydem {

// Whether this step's sphere-wall pairs may take the lanes (a driver list always records: the
// lanes write the record too).
template <class Parts>
bool wall_lanes_fit(const LawParams& law) {
  return steady_law_fits<Parts>(law) && !law.contact_mass;
}

// Whether driver pair k may be steady: a sphere on an active wall at rest (`at_rest`:
// drivers_at_rest), touching at the last step, its k', c' made.
[[gnu::always_inline]] inline bool steady_wall_candidate(const Drivers& drivers, const PairList& list, std::uint32_t k,
                                                         const WallSpheres& sizes, std::uint64_t at_rest) {
  const std::uint32_t s = list.slot_begin[k], j = list.pairs[k].j;
  return s != list.slot_begin[k + 1] && j < 64 && (at_rest >> j & 1u) && drivers.is_wall(j) && drivers[j].active &&
         list.touching[k] != 0 && list.active[s] && list.history(s).gap < 0.0 && sizes.steps[k & sizes.mask].k != 0.0;
}

// Driver pairs ks[0..N) (steady wall candidates) side by side, N = 2, or one alone, N = 1; then for
// each l in turn take(l, &totals) where lane l was steady (its slot advanced, its record written) or
// take(l, nullptr) where not (its slot untouched, for sphere_wall_forces).
template <int N, class Take>
[[gnu::always_inline]] inline void steady_wall_pairs(const LawParams& law, double band, double dt,
                                                     const BodyView& bodies, const Drivers& drivers, PairList& list,
                                                     const std::uint32_t ks[N], const WallSpheres& sizes,
                                                     const Take& take) {
  using namespace lanes;
  using V = typename Types<N>::V;
  using V3 = Vec3Of<V>;
  std::uint32_t body[N];
  const DriverState* wall[N];
  SlotState* state[N];
  LastSteps<N, SlotState> last;
  for (int l = 0; l < N; ++l) {
    body[l] = list.pairs[ks[l]].i;
    wall[l] = &drivers[list.pairs[ks[l]].j];
    state[l] = &list.touch(list.slot_begin[ks[l]]);  // made: the slot is active
    last.h[l] = state[l];
    last.step[l] = &sizes.steps[ks[l] & sizes.mask];
  }
  const auto each = [&](auto get) { return gather<V>(get); };
  const auto of_body = [&](const Vec3* a) { return load<V>([&](int l) -> const Vec3& { return a[body[l]]; }); };
  const V zero = splat<V>(0.0);
  const V3 zeros{zero, zero, zero};
  // sphere_wall_forces: the height above the plane, the middle of the overlap, the motions
  const V3 xi = of_body(bodies.position);
  const V3 n = load<V>([&](int l) -> const Vec3& { return wall[l]->normal; });
  const V3 from_wall = xi - load<V>([&](int l) -> const Vec3& { return wall[l]->point; });  // m
  const V ri = each([&](int l) { return sizes.radius[body[l] & sizes.mask]; });            // m
  const V gap = dot(from_wall, n) - ri;  // m, < 0 where steady
  const V3 point = xi - (ri + 0.5 * gap) * n;
  const V3 lever = point - xi;  // m
  const V3 v_rel = of_body(bodies.velocity) + cross(of_body(bodies.angular_velocity), lever);
  const V3 v_end = of_body(bodies.velocity_end) + cross(of_body(bodies.angular_velocity_end), lever);
  const V m = each([&](int l) { return sizes.mass[body[l] & sizes.mask]; });  // kg
  const SteadyLawOf<V> f = steady_linear_law(law, dt, n, gap, v_rel, v_end, m, last);
  const auto steady = (gap < splat<V>(band)) & f.steady;  // in reach (gap < 0 where f.steady: no NaN)
  // The totals from zero, as sphere_wall_forces' sums: the same signed zeros (no rolling moment).
  const V3 force_i = zeros + f.force;                               // N
  const V3 torque_i = zeros + (cross(lever, f.force) + zeros);      // N m
  const V3 about_wall = torque_i + cross(from_wall, force_i);           // N m, about the wall's point
  const V3 torque_j{-about_wall.x, -about_wall.y, -about_wall.z};       // N m, negated (not 0 - x: signed zeros)
  const V net = zero + f.dissipated;  // J, energy_parts: the patch is +0 at weight 1
  for (int l = 0; l < N; ++l) {
    if (!at(steady, l)) {
      take(l, nullptr);
      continue;
    }
    SlotState& hl = *state[l];
    hl.ft = lane(f.ft, l);
    hl.fd = at(f.fd, l);
    hl.gap = at(gap, l);
    hl.weight = 1.0;
    hl.slipping = false;  // under its cap
    const Vec3 force = lane(f.force, l);
    hl.point = lane(point, l);
    if (list.recording) list.states.force(list.state_of[list.slot_begin[ks[l]]]) = SlotForce{force, at(f.fn, l)};
    PairTotals t;
    t.force_i = lane(force_i, l);
    t.torque_i = lane(torque_i, l);
    t.torque_j = lane(torque_j, l);
    t.energy = EnergyParts{at(net, l), 0.0, 0.0, 0.0};
    t.contacts = 1;
    take(l, &t);
  }
}

// The driver list's kernel with its steady sphere-wall pairs two at a time (pair_loop.hpp's
// paired_block): `scalar`, the list's own kernel, for every other pair and lane.
template <class Scalar>
struct WallLanesKernel {
  static constexpr bool kTwoLanes = true;
  const Scalar& scalar;
  const LawParams& law;
  double band, dt;  // m, s
  const BodyView& bodies;
  const Drivers& drivers;
  PairList& list;
  const WallSpheres& sizes;
  std::uint64_t at_rest;  // drivers_at_rest
  [[gnu::always_inline]] PairTotals operator()(std::uint32_t k, PairScratch& scratch) const { return scalar(k, scratch); }
  [[gnu::always_inline]] bool candidate(std::uint32_t k) const {
    return steady_wall_candidate(drivers, list, k, sizes, at_rest);
  }
  template <int N, class Take>
  [[gnu::always_inline]] void steady(const std::uint32_t pairs[N], const Take& take) const {
    steady_wall_pairs<N>(law, band, dt, bodies, drivers, list, pairs, sizes, take);
  }
};

}  // namespace polydem
