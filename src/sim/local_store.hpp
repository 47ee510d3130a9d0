#pragma once
// One process's share of the bodies as the contact stage reads them: the bodies it owns and
// ghosts of bodies owned elsewhere, in increasing global id (contact/local_bodies.hpp: why the
// order gives the bits of one process). A ghost carries only what contacts read: pose,
// velocities, shape, scale, mass and its global id. The set changes only at list rebuilds;
// the owned bodies' state is written by the step's opening pass (write_through) or refreshed
// from the global arrays, the ghosts' where their owners' parcels land (sim/ghost_plan.hpp).
#include <cstdint>
#include <vector>

#include "contact/local_bodies.hpp"
#include "integrate/integrate.hpp"
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
  // A step's opening pass hook (integrate.hpp's close_and_start_step `after`): writes owned body
  // i's new pose and velocities at its local index while they are in registers, so the step's
  // refresh (a second pass reading the global arrays back) is not needed.
  struct Write;
  Write write_through(const std::vector<std::int32_t>& local_of);
  LocalBodies view() {
    return {&position, &orientation, &velocity, &angular_velocity, &velocity_end, &angular_velocity_end,
            &shape,    &scale,       &mass,     &ghost,            &force,        &torque};
  }
};

struct LocalStore::Write {
  const std::int32_t* local_of;  // global id -> local index
  Vec3 *position, *velocity, *angular_velocity, *velocity_end, *angular_velocity_end;
  Quat* orientation;
  template <class Arrays, class Path>
  [[gnu::always_inline]] void operator()(const Arrays& a, std::size_t i, Path) const {
    const std::size_t l = std::size_t(local_of[i]);
    position[l] = a.position[i];
    velocity[l] = a.velocity[i];
    angular_velocity[l] = a.angular_velocity[i];
    velocity_end[l] = a.velocity_end[i];
    angular_velocity_end[l] = a.angular_velocity_end[i];
    if constexpr (Path::value != Rotor::sphere) orientation[l] = a.orientation[i];  // a sphere's never turns
  }
};

inline LocalStore::Write LocalStore::write_through(const std::vector<std::int32_t>& local_of) {
  return {local_of.data(),     position.data(),    velocity.data(), angular_velocity.data(),
          velocity_end.data(), angular_velocity_end.data(), orientation.data()};
}

}  // namespace polydem
