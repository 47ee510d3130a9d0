#pragma once
// The sphere-wall kernel, chosen when every body is a sphere: a wall pair has one slot (the
// sphere's one vertex, its centre), weight 1, so the geometry is a height above the plane. It
// does the general path's arithmetic (pair_forces with a DriverPartner: Wall::contact, then
// apply_law) in the same order, so the bits are the same, without the candidate loop, the
// driver visit, the patch weights and the pair's dashpots computed when the law reads none.
#include <bit>

#include "contact/pair_kernel.hpp"
#include "driver/drivers.hpp"

namespace polydem {

// The spheres' radii (m) and masses (kg) and the pairs' k', c' of the exact step (cached at first
// use): each body's and pair's (mask ~0), or where every sphere is alike one value for all (mask 0,
// made once a step: the same values, the same bits), without a second copy of the loop.
struct WallSpheres {
  const double* radius;
  const double* mass;
  LinearStep* steps;
  std::uint32_t mask;
};

// Bit j set when driver j (j < 64) moves at +0 in every component of its velocity and spin: a
// sphere's velocity less the wall's is then the sphere's own, bit for bit (x - +0 is x, -0 too).
inline std::uint64_t drivers_at_rest(const Drivers& drivers) {
  const auto plus_zero = [](const Vec3& v) {
    return std::bit_cast<std::uint64_t>(v.x()) == 0 && std::bit_cast<std::uint64_t>(v.y()) == 0 &&
           std::bit_cast<std::uint64_t>(v.z()) == 0;
  };
  std::uint64_t at_rest = 0;
  for (std::size_t j = 0; j < std::min<std::size_t>(drivers.size(), 64); ++j)
    if (plus_zero(drivers[j].velocity) && plus_zero(drivers[j].omega)) at_rest |= std::uint64_t(1) << j;
  return at_rest;
}

// `at_rest`: drivers_at_rest(drivers), made once a step.
template <class Parts>
[[gnu::always_inline]] inline PairTotals sphere_wall_forces(const LawParams& law, double band, double dt,
                                                            const BodyView& bodies, const Drivers& drivers,
                                                            PairList& list, std::uint32_t k, PairScratch& scratch,
                                                            const WallSpheres& sizes, std::uint64_t at_rest) {
  PairTotals totals;
  const std::uint32_t s = list.slot_begin[k];
  if (s == list.slot_begin[k + 1]) return totals;  // out of reach at the rebuild
  const BodyPair p = list.pairs[k];
  const DriverState& wall = drivers[p.j];
  const Vec3 xi = bodies.position[p.i];  // m, the sphere's vertex
  const double ri = sizes.radius[p.i & sizes.mask];  // m
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
  Vec3 w_rel = bodies.angular_velocity[p.i], v_centre = bodies.velocity[p.i];                // rad/s, m/s
  Vec3 w_rel_end = bodies.angular_velocity_end[p.i], v_centre_end = bodies.velocity_end[p.i];  // rad/s, m/s
  if (p.j >= 64 || !(at_rest >> p.j & 1u)) {  // a wall at rest subtracts +0: nothing
    const Vec3 wall_at_xi = wall.velocity + wall.omega.cross(xi - wall.pivot);  // m/s, the wall's point at i's centre
    w_rel -= wall.omega;
    v_centre -= wall_at_xi;
    w_rel_end -= wall.omega;
    v_centre_end -= wall_at_xi;
  }
  const double m_eff = sizes.mass[p.i & sizes.mask];  // kg
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
                        law.contact_mass ? nullptr : &sizes.steps[k & sizes.mask]};
  SlotState& state = list.touch(s);  // a driver list is sparse
  Vec3* const moment = Parts::rolling && list.states.rolls() ? &list.states.moment(list.state_of[s]) : nullptr;  // N m
  ContactHistory h = state.history(moment ? *moment : Vec3::Zero());
  // kLone: weights 1 at both steps, as every sphere-wall contact's (no division by them: the same bits).
  const ContactForce f = contact_force<Parts, true, Stored::kSkip>(law, kin, h, dt);
  state.keep(h);
  if (moment) *moment = h.mr;
  state.point = point;  // a driver list keeps its points: the hand-over reads them
  if (list.recording) list.states.force(list.state_of[s]) = SlotForce{f.force, f.fn};
  totals.force_i += f.force;  // from zero, as apply_law's sum: the same signed zeros
  totals.torque_i += lever.cross(f.force) + f.moment;
  totals.energy += energy_parts(f);
  totals.torque_j = -(totals.torque_i + (xi - wall.point).cross(totals.force_i));
  totals.contacts = 1;
  return totals;
}

}  // namespace polydem
