#pragma once
// The join step's turn of one body (issue 16: pair_kernel.hpp's PairTurn), and how a joined
// pass (integrate.hpp's close_and_start_step) finds the bodies that take one: applied after the
// body's closing kick, before its opening kick and drift, alone (turn_table.hpp's turn_bodies)
// or inside the pass, with the same arithmetic.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "integrate/free_rotor.hpp"
#include "polydem/math.hpp"

namespace polydem {

// Turns the body of orientation q, principal angular momentum `momentum` and principal inertia
// by I_world^-1 moment (rad; moment in N m s^2, world), keeping its world angular momentum (an
// isotropic body its w, an asymmetric one's w made anew). Returns the angle (rad, world), or
// nothing where it is zero (the body untouched).
inline std::optional<Vec3> turn_body(Quat& q, Vec3& momentum, Vec3& w, const Vec3& inertia, bool isotropic,
                                     const Vec3& moment) {
  const Vec3 angle = q * (q.conjugate() * moment).cwiseQuotient(inertia);  // rad, world
  const double size = angle.norm();
  if (!(size > 0.0)) return std::nullopt;
  const Vec3 world = q * momentum;  // kg m^2/s
  q = Quat(Eigen::AngleAxisd(size, angle / size)) * q;
  free_rotor::renormalize(q);
  momentum = q.conjugate() * world;
  if (!isotropic) w = q * momentum.cwiseQuotient(inertia);
  return angle;
}

// One body's turn in a joined pass: its moment in, its work out.
struct PassTurn {
  Vec3 moment;                 // N m s^2, world (ContactEngine::take_turns)
  std::optional<double> work;  // J, -torque . angle (what the springs gain), where the body turned
};

// Where a joined pass finds the turn of body i: `slot[i]` indexes `turn`, kNone for most bodies.
struct PassTurns {
  static constexpr bool kAny = true;
  static constexpr std::uint32_t kNone = ~std::uint32_t(0);
  const std::uint32_t* slot;
  PassTurn* turn;
  PassTurn* at(std::size_t i) const { return slot[i] == kNone ? nullptr : turn + slot[i]; }
};

// A joined pass with no turn to apply: its bodies' loop tests nothing.
struct NoTurns {
  static constexpr bool kAny = false;
  PassTurn* at(std::size_t) const { return nullptr; }
};

}  // namespace polydem
