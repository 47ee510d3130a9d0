#pragma once
// The sphere-wall kernel, chosen when every body is a sphere: a wall pair has one slot (the
// sphere's one vertex, its centre), weight 1, so the geometry is a height above the plane. It
// does the general path's arithmetic (pair_forces with a DriverPartner: Wall::contact, then
// apply_law) in the same order, so the bits are the same, without the candidate loop, the
// driver visit, the patch weights and the pair's dashpots computed when the law reads none.
#include "contact/pair_kernel.hpp"
#include "driver/drivers.hpp"

namespace polydem {

template <class Parts>
[[gnu::always_inline]] inline PairTotals sphere_wall_forces(const LawParams& law, double band, double dt,
                                                            const BodyView& bodies, const Drivers& drivers,
                                                            PairList& list, std::uint32_t k, PairScratch& scratch) {
  PairTotals totals;
  const std::uint32_t s = list.slot_begin[k];
  if (s == list.slot_begin[k + 1]) return totals;  // out of reach at the rebuild
  const BodyPair p = list.pairs[k];
  const DriverState& wall = drivers[p.j];
  const Vec3 xi = bodies.position[p.i];  // m, the sphere's vertex
  const double ri = bodies.radius[p.i];  // m
  const double gap = (xi - wall.point).dot(wall.normal) - ri;  // m, as Wall::contact
  const bool touches = wall.active && !(gap >= band);
  const int was_touching = list.touching[k];
  if (touches != bool(was_touching) || (touches && !list.active[s])) {  // starts or ends: as the general path
    scratch.found.clear();
    if (touches) scratch.found.emplace_back(s, ContactPoint{wall.normal, Vec3::Zero(), gap});
    totals.energy = hand_over_history(list, s, s + 1, was_touching, scratch.found, scratch.now_on, &law,
                                      Parts::Normal::kCurved ? ri : 0.0);  // a wall's R* is the sphere's radius
  }
  if (!touches) return totals;
  const Vec3 point = xi - wall.normal * (ri + 0.5 * gap);  // m, middle of the overlap
  // apply_law's arithmetic for one contact of weight 1 on a driver of infinite mass (m_eff = m_i).
  const Vec3 w_rel = bodies.angular_velocity[p.i] - wall.omega;                  // rad/s
  const Vec3 wall_at_xi = wall.velocity + wall.omega.cross(xi - wall.pivot);  // m/s, the wall's point at i's centre
  const Vec3 v_centre = bodies.velocity[p.i] - wall_at_xi;                      // m/s
  const Vec3 w_rel_end = bodies.angular_velocity_end[p.i] - wall.omega;          // rad/s
  const Vec3 v_centre_end = bodies.velocity_end[p.i] - wall_at_xi;              // m/s
  const double m_eff = bodies.mass[p.i];  // kg
  const double r_star = Parts::Normal::kCurved ? ri : 0.0;  // m
  const Vec3 lever = point - xi;  // m, from the centre
  double m_dashpot = m_eff;       // kg
  if (law.contact_mass) m_dashpot = 1.0 / (point_inverse_mass(bodies.posed[p.i], m_eff, lever, wall.normal) + 0.0);
  // nu < 0: the law computes the normal dashpot from m_dashpot only where it reads it (the
  // general path computes it per pair); the tangential one is on the pair's mass.
  const double nu_t = Parts::tangential_dashpot && law.tangential_damping ? pair_tangential_damping(law, m_eff) : -1.0;
  ContactKinematics kin{wall.normal,
                        gap,
                        v_centre + w_rel.cross(lever),
                        v_centre_end + w_rel_end.cross(lever),
                        w_rel,
                        m_dashpot,
                        Parts::rolling && law.rolling ? lever.norm() : 0.0,
                        1.0,
                        -1.0,
                        nu_t,
                        r_star,
                        law.exact_step,
                        law.contact_mass ? nullptr : &list.linear_steps[k]};
  SlotState& state = list.touch(s);  // a driver list is sparse
  // kLone: weights 1 at both steps, as every sphere-wall contact's (no division by them: the same bits).
  const ContactForce f = contact_force<Parts, true>(law, kin, state.history, dt);
  state.record = {point, f.force, f.fn};  // a driver list always records: the hand-over reads the point
  totals.force_i += f.force;  // from zero, as apply_law's sum: the same signed zeros
  totals.torque_i += lever.cross(f.force) + f.moment;
  totals.energy += energy_parts(f);
  totals.torque_j = -(totals.torque_i + (xi - wall.point).cross(totals.force_i));
  totals.contacts = 1;
  return totals;
}

}  // namespace polydem
