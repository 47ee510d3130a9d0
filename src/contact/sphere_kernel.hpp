#pragma once
// The sphere fast path, chosen once when every body is a sphere: each pair has one
// vertex-vertex slot, weight 1 and nothing to hand over, so the geometry is a distance.
#include "contact/pair_kernel.hpp"
#include "contact/pair_split.hpp"
#include "geometry/lanes.hpp"
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace polydem {

// Runs sphere_pair_forces over every pair of `list` (sphere_loop.cpp), summing its forces into
// each body's (`direct`) and its energies by block, as the general pair loop does.
// Inside a team the threads leave it without a barrier (all_pair_forces<true>): the caller meets
// them before reading the results. `equal`: every sphere alike, so no radius or mass is read per
// body and the list keeps no k', c' per pair (its linear_steps may be empty). `lanes`: steady
// pairs two at a time where the law allows (sphere_lanes.hpp; false: one at a time, the same bits).
// `trail`: a pass right behind the walk (WalkTrail).
void sphere_pair_loop(const LawParams& law, double band, double dt, const BodyView& bodies, PairList& list,
                      DirectSums& direct, const EqualSpheres* equal = nullptr, bool lanes = true,
                      const WalkTrail* trail = nullptr);

// The radii and pair masses the sphere kernel reads: each body's, and k', c' cached per pair.
struct EachSphere {
  const BodyView& bodies;
  PairList& list;
  double radius(std::uint32_t b) const { return bodies.radius[b]; }  // m
  double pair_mass(BodyPair p) const {  // kg
    const double mi = bodies.mass[p.i], mj = bodies.mass[p.j];
    return mi * mj / (mi + mj);
  }
  double r_star(double ri, double rj) const { return ri * rj / (ri + rj); }  // m
  LinearStep* linear_step(std::uint32_t k) const { return &list.linear_steps[k]; }
};
// Every sphere alike: the same values (the same bits) made once a step, not read at j per pair.
struct SameSpheres {
  double r, m, r_pair;  // m, kg (the pair mass), m (R*)
  LinearStep* step;     // k', c' of every pair, set before the loop (written by no thread in it)
  double radius(std::uint32_t) const { return r; }
  double pair_mass(BodyPair) const { return m; }
  double r_star(double, double) const { return r_pair; }
  LinearStep* linear_step(std::uint32_t) const { return step; }
};

// What sphere_pair_forces and the two-lane steady kernel (sphere_lanes.hpp) compute alike, written
// once over the lane type V: a double, or two doubles for two pairs side by side (each lane by the
// same operations, so the same bits).
namespace sphere_detail {
using lanes::Vec3Of;
using Lanes = lanes::Types<2>::V;
inline double root(double a) { return std::sqrt(a); }
inline Lanes root(Lanes a) {  // sqrtpd: each lane std::sqrt's correctly rounded result
#if defined(__SSE2__)
  return (Lanes)_mm_sqrt_pd((__m128d)a);
#else
  return lanes::sqrt(a);
#endif
}
inline Vec3Of<double> of(const Vec3& a) { return {a.x(), a.y(), a.z()}; }
}  // namespace sphere_detail

// A sphere pair's contact (V: one pair, or two side by side).
template <class V>
struct SphereContactOf {
  lanes::Vec3Of<V> n;  // unit, from j to i
  V gap;               // m, negative: overlap
  V lever_i, lever_j;  // m, from the centres to the middle of the overlap, along -n and +n
  lanes::Vec3Of<V> v_rel;  // m/s, i's contact point's velocity less j's, at the half step
};
// From d = x_i - x_j (m), dist2 = |d|^2 > 0, the radii ri, rj (m), velocities (m/s) and spins (rad/s).
// The arms lie along n, so w_i x arm_i - w_j x arm_j = -(lever_i w_i + lever_j w_j) x n: one cross product.
template <class V>
[[gnu::always_inline]] inline SphereContactOf<V> sphere_contact(const lanes::Vec3Of<V>& d, V dist2, V ri, V rj,
                                                                const lanes::Vec3Of<V>& vi, const lanes::Vec3Of<V>& vj,
                                                                const lanes::Vec3Of<V>& wi, const lanes::Vec3Of<V>& wj) {
  const V dist = sphere_detail::root(dist2);  // m
  SphereContactOf<V> c;
  c.n = {d.x / dist, d.y / dist, d.z / dist};
  c.gap = dist - ri - rj;
  c.lever_i = ri + 0.5 * c.gap, c.lever_j = rj + 0.5 * c.gap;
  c.v_rel = (vi - vj) - cross(c.lever_i * wi + c.lever_j * wj, c.n);
  return c;
}
// N m, the torques of force F (N, on i) and moment m (N m) about the centres: arm x F = -lever_i n x F
// on i, +lever_j n x F on j. In scalars, not an Eigen Vec3 on the stack read back by one 16-byte load
// after two 8-byte stores (a failed store forward, 13% of the loop's time on the sphere bed).
template <class V>
struct PairTorquesOf {
  lanes::Vec3Of<V> i, j;
};
template <class V>
[[gnu::always_inline]] inline PairTorquesOf<V> sphere_torques(const lanes::Vec3Of<V>& n, const lanes::Vec3Of<V>& force,
                                                              const lanes::Vec3Of<V>& m, V lever_i, V lever_j) {
  const lanes::Vec3Of<V> nf = cross(n, force);  // N
  return {{m.x - lever_i * nf.x, m.y - lever_i * nf.y, m.z - lever_i * nf.z},
          {-(lever_j * nf.x + m.x), -(lever_j * nf.y + m.y), -(lever_j * nf.z + m.z)}};
}

// Always inlined into the pair loop: the totals go straight into the list, not through memory.
template <class Parts, class Sizes>
[[gnu::always_inline]] inline PairTotals sphere_pair_forces(const LawParams& law, double band, double dt,
                                                            const BodyView& bodies, PairList& list, std::uint32_t k,
                                                            const Sizes& sizes) {
  PairTotals totals;
  if (list.slot_begin[k] == list.slot_begin[k + 1]) return totals;  // out of reach at the rebuild
  const BodyPair p = list.pairs[k];
  const Vec3& xi = bodies.position[p.i];
  const Vec3& xj = bodies.position[p.j];
  const double ri = sizes.radius(p.i), rj = sizes.radius(p.j);  // m
  const Vec3 d = xi - xj;  // m, from j to i
  const double reach = ri + rj + band;
  const double dist2 = d.squaredNorm();
  const std::uint32_t s = list.slot_begin[k];
  ContactSlot& slot = list.slots[s];
  if (dist2 >= reach * reach || dist2 == 0.0) {
    if (list.active[s]) {  // the contact ends: its springs let go
      totals.energy = released_energy<Parts>(law, slot.history, Parts::Normal::kCurved ? sizes.r_star(ri, rj) : 0.0);
      list.active[s] = 0;
      slot.history = ContactHistory{};
    }
    return totals;
  }
  using sphere_detail::of;
  const SphereContactOf<double> c = sphere_contact(of(d), dist2, ri, rj, of(bodies.velocity[p.i]), of(bodies.velocity[p.j]),
                                                   of(bodies.angular_velocity[p.i]), of(bodies.angular_velocity[p.j]));
  const Vec3 n = lanes::lane(c.n, 0);
  const double gap = c.gap, lever_i = c.lever_i, lever_j = c.lever_j;  // m
  const Vec3 point = xi - n * lever_i;
  const Vec3 v_rel = lanes::lane(c.v_rel, 0);
  // m/s, for the dashpots. The arms lie along n, so spin moves the contact point along the
  // tangent only: without a tangential dashpot the centres' velocities are all the normal one reads.
  const Vec3 v_end = Parts::tangential_dashpot
                         ? Vec3(bodies.velocity_end[p.i] - bodies.velocity_end[p.j] -
                                (lever_i * bodies.angular_velocity_end[p.i] +
                                 lever_j * bodies.angular_velocity_end[p.j]).cross(n))
                         : Vec3(bodies.velocity_end[p.i] - bodies.velocity_end[p.j]);
  ContactKinematics kin{n, gap, v_rel, v_end, bodies.angular_velocity[p.i] - bodies.angular_velocity[p.j],
                        sizes.pair_mass(p), lever_i, 1.0};
  if constexpr (Parts::Normal::kCurved) kin.r_star = sizes.r_star(ri, rj);
  kin.linear_step = sizes.linear_step(k);  // the pair's mass is fixed: k', c' once per list
  if (!list.active[s]) slot.history = ContactHistory{};
  const ContactForce f = contact_force<Parts, true, Stored::kSkip>(law, kin, slot.history, dt);
  list.active[s] = 1;
  if (list.recording) list.records[s] = {point, f.force, f.fn};
  totals.force_i = f.force;
  const PairTorquesOf<double> torques = sphere_torques(c.n, of(f.force), of(f.moment), lever_i, lever_j);  // N m
  totals.torque_i = lanes::lane(torques.i, 0);
  totals.torque_j = lanes::lane(torques.j, 0);
  // Weight 1: no patch work for the linear law; Hertz's tangential stiffness changes with the overlap.
  totals.energy = Parts::Normal::kCurved ? energy_parts(f) : EnergyParts{f.dissipated, f.sliding, f.rolling, 0.0};
  totals.contacts = 1;
  return totals;
}

}  // namespace polydem
