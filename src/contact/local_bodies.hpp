#pragma once
// The bodies the contact stage sees: what it reads of each body, for the bodies this process
// owns and for ghosts (copies of bodies owned elsewhere: another MPI rank's, later a periodic
// image), in increasing global id. Local index order is global id order, so the pairs (i < j),
// their order and each body's force sum (pairs (a, b) for a < b, then (b, c)) are the ones of a
// single process holding every body: the same bits for any decomposition. One process: every
// body owned, no ghost, the arrays are Bodies' own (no copy).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "polydem/bodies.hpp"

namespace polydem {

struct LocalBodies {
  // Read by the contact stage, per local body: the pose and velocities each step, the shape,
  // scale and mass (m_eff) constant.
  const std::vector<Vec3>* position;          // m
  const std::vector<Quat>* orientation;
  const std::vector<Vec3>* velocity;          // m/s
  const std::vector<Vec3>* angular_velocity;  // rad/s
  const std::vector<Vec3>* velocity_end;      // m/s, predicted for the end of the step (dashpots)
  const std::vector<Vec3>* angular_velocity_end;  // rad/s, likewise
  const std::vector<int>* shape;
  const std::vector<double>* scale;
  const std::vector<double>* mass;            // kg
  // Per local body, 1 for a ghost (null: every body owned). Ghosts get no force here and
  // pairs of two ghosts are not listed: their owners compute them.
  const std::vector<std::uint8_t>* ghost = nullptr;
  // Written for owned bodies only (N, N m): the contact forces and torques are added to them.
  std::vector<Vec3>* force;
  std::vector<Vec3>* torque;

  std::size_t size() const { return position->size(); }
  bool owned(std::size_t b) const { return !ghost || !(*ghost)[b]; }
};

// One process: every body of `bodies` owned, in its own order (index = global id).
inline LocalBodies all_owned(Bodies& bodies) {
  return {&bodies.position,     &bodies.orientation,          &bodies.velocity, &bodies.angular_velocity,
          &bodies.velocity_end, &bodies.angular_velocity_end, &bodies.shape,    &bodies.scale,
          &bodies.mass,         nullptr,                      &bodies.force,    &bodies.torque};
}

}  // namespace polydem
