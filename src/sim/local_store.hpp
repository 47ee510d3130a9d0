#pragma once
// One process's share of the bodies as the contact stage reads them: the bodies it owns and
// ghosts of bodies owned elsewhere, in increasing global id (contact/local_bodies.hpp: why the
// order gives the bits of one process). A ghost carries only what contacts read: pose,
// velocities, shape, scale, mass and its global id. The set changes only at list rebuilds;
// the state is refreshed every step from the global arrays, where the ghosts' owners' parcels
// land (sim/ghost_plan.hpp).
#include <cstdint>
#include <vector>

#include "contact/local_bodies.hpp"
#include "polydem/bodies.hpp"

namespace polydem {

struct LocalStore {
  std::vector<std::uint32_t> global_id;  // increasing
  std::vector<std::uint8_t> ghost;       // 1: a copy of a body owned elsewhere
  std::vector<Vec3> position, velocity, angular_velocity;  // m, m/s, rad/s
  std::vector<Vec3> velocity_end, angular_velocity_end;   // m/s, rad/s, predicted for the step's end
  std::vector<Quat> orientation;
  std::vector<int> shape;
  std::vector<double> scale, mass;  // -, kg
  std::vector<Vec3> force, torque;  // N, N m: the contact sums of the owned bodies, when summed here

  // Holds the bodies `ids` of `all` (increasing), ghosts where `is_ghost` is 1, their state
  // copied and their forces zero.
  void select(const Bodies& all, std::vector<std::uint32_t> ids, std::vector<std::uint8_t> is_ghost);
  // Copies what changes every step (pose and velocities) from the global arrays; `turning`
  // false: no held body ever turns (spheres keep the identity), the orientations select()
  // copied stand.
  void refresh(const Bodies& all, bool turning = true);
  void clear_forces();  // zeroes force and torque (before the engine sums into them)
  LocalBodies view() {
    return {&position, &orientation, &velocity, &angular_velocity, &velocity_end, &angular_velocity_end,
            &shape,    &scale,       &mass,     &ghost,            &force,        &torque};
  }
};

}  // namespace polydem
