#pragma once
// The sphere fast path, chosen once when every body is a sphere: each pair has one
// vertex-vertex slot, weight 1 and nothing to hand over, so the geometry is a distance.
#include "sim/pair_kernel.hpp"

namespace polydem {

inline PairTotals sphere_pair_forces(const LawParams& law, double band, double dt, const BodyView& bodies,
                                     PairList& list, std::uint32_t k) {
  PairTotals totals;
  if (list.slot_begin[k] == list.slot_begin[k + 1]) return totals;  // out of reach at the rebuild
  const BodyPair p = list.pairs[k];
  ContactSlot& slot = list.slots[list.slot_begin[k]];
  const PosedBody& a = bodies.posed[p.i];
  const PosedBody& b = bodies.posed[p.j];
  const Vec3 d = a.position - b.position;  // m, from j to i
  const double reach = a.radius + b.radius + band;
  const double dist2 = d.squaredNorm();
  if (dist2 >= reach * reach || dist2 == 0.0) {
    slot.active = false;
    slot.history = ContactHistory{};
    slot.fn = 0.0;
    slot.force = Vec3::Zero();
    return totals;
  }
  const double dist = std::sqrt(dist2);
  const Vec3 n = d / dist;
  const double gap = dist - a.radius - b.radius;
  const Vec3 point = a.position - n * (a.radius + 0.5 * gap);  // middle of the overlap
  const Vec3 ri = point - a.position, rj = point - b.position;
  const Vec3 v_rel = bodies.velocity[p.i] + bodies.angular_velocity[p.i].cross(ri) - bodies.velocity[p.j] -
                     bodies.angular_velocity[p.j].cross(rj);
  const double mi = bodies.mass[p.i], mj = bodies.mass[p.j];
  const ContactKinematics kin{n, gap, v_rel, bodies.angular_velocity[p.i] - bodies.angular_velocity[p.j],
                              mi * mj / (mi + mj), a.radius + 0.5 * gap, 1.0};
  if (!slot.active) slot.history = ContactHistory{};
  const ContactForce f = contact_force(law, kin, slot.history, dt);
  slot.active = true;
  slot.point = point;
  slot.force = f.force;
  slot.fn = f.fn;
  slot.gap = gap;
  totals.force_i = f.force;
  totals.torque_i = ri.cross(f.force) + f.moment;
  totals.torque_j = -(rj.cross(f.force) + f.moment);
  totals.elastic = f.elastic;
  totals.dissipated = f.dissipated;
  totals.contacts = 1;
  return totals;
}

}  // namespace polydem
