#pragma once
// The sphere fast path, chosen once when every body is a sphere: each pair has one
// vertex-vertex slot, weight 1 and nothing to hand over, so the geometry is a distance.
#include "contact/pair_kernel.hpp"
#include "contact/pair_split.hpp"

namespace polydem {

// Runs sphere_pair_forces over every pair of `list` (sphere_loop.cpp), summing its forces into
// each body's (`direct`) and its energies by block, as the general pair loop does.
// Inside a team the threads leave it without a barrier (all_pair_forces<true>): the caller meets
// them before reading the results. `equal`: every sphere alike, so no radius or mass is read per
// body and the list keeps no k', c' per pair (its linear_steps may be empty). `lanes`: steady
// pairs two at a time where the law allows (sphere_lanes.hpp; false: one at a time, the same bits).
void sphere_pair_loop(const LawParams& law, double band, double dt, const BodyView& bodies, PairList& list,
                      DirectSums& direct, const EqualSpheres* equal = nullptr, bool lanes = true);

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
  const double dist = std::sqrt(dist2);
  const Vec3 n = d / dist;
  const double gap = dist - ri - rj;
  // m, the arms from the centres to the middle of the overlap lie along n: -lever_i n and +lever_j n,
  // so w_i x arm_i - w_j x arm_j = -(lever_i w_i + lever_j w_j) x n, one cross product, not two.
  const double lever_i = ri + 0.5 * gap, lever_j = rj + 0.5 * gap;
  const Vec3 point = xi - n * lever_i;
  const Vec3 v_rel = bodies.velocity[p.i] - bodies.velocity[p.j] -
                     (lever_i * bodies.angular_velocity[p.i] + lever_j * bodies.angular_velocity[p.j]).cross(n);
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
  const ContactForce f = contact_force<Parts, true>(law, kin, slot.history, dt);
  list.active[s] = 1;
  if (list.recording) list.records[s] = {point, f.force, f.fn};
  totals.force_i = f.force;
  // N, arm x F = -lever_i n x F on i, +lever_j n x F on j. n x F in scalars, as Eigen's cross
  // makes it: a Vec3 of it lived on the stack, read back by one 16-byte load after two 8-byte
  // stores (a failed store forward, 13% of the loop's time on the sphere bed).
  const Vec3& F = f.force;
  const double nf_x = n.y() * F.z() - n.z() * F.y(), nf_y = n.z() * F.x() - n.x() * F.z();
  const double nf_z = n.x() * F.y() - n.y() * F.x();
  const Vec3& m = f.moment;  // N m
  totals.torque_i = Vec3(m.x() - lever_i * nf_x, m.y() - lever_i * nf_y, m.z() - lever_i * nf_z);
  totals.torque_j = Vec3(-(lever_j * nf_x + m.x()), -(lever_j * nf_y + m.y()), -(lever_j * nf_z + m.z()));
  // Weight 1: no patch work for the linear law; Hertz's tangential stiffness changes with the overlap.
  totals.energy = Parts::Normal::kCurved ? energy_parts(f) : EnergyParts{f.dissipated, f.sliding, f.rolling, 0.0};
  totals.contacts = 1;
  return totals;
}

}  // namespace polydem
