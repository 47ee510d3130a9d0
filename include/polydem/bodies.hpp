#pragma once
// Body state as structure-of-arrays, split by how hot each field is.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "polydem/math.hpp"
#include "polydem/release.hpp"

namespace polydem {

struct Bodies {
  // Hot: read by the contact loop every step.
  std::vector<Vec3> position;          // m, centre of mass, world frame
  std::vector<Quat> orientation;       // principal frame -> world frame, unit
  std::vector<Vec3> velocity;          // m/s, world frame
  std::vector<Vec3> angular_velocity;  // rad/s, world frame (derived from angular_momentum)
  // m/s, rad/s: the velocities predicted for the end of the step, v(n+1/2) + F(n) dt/(2m) (and
  // the same for w with the world inertia), which the dashpots read (integrate.hpp).
  std::vector<Vec3> velocity_end, angular_velocity_end;

  // Integration state.
  std::vector<Vec3> angular_momentum;  // kg m^2/s, principal (body) frame
  std::vector<Vec3> force;             // N, world frame, summed this step
  std::vector<Vec3> torque;            // N m, world frame, about the centre of mass

  // Constant per body.
  std::vector<int> shape;              // index into the shape table
  std::vector<double> scale;           // homothety factor applied to the library shape
  std::vector<double> mass;            // kg
  std::vector<Vec3> inertia;           // kg m^2, principal moments

  // Cold: output only.
  std::vector<int> group;
  // The user id of the body at each index: its place in the scene's body list (files and
  // messages name it); the indices follow space (sim/body_order.hpp) or that list.
  std::vector<std::uint32_t> id;

  // The bodies of the scene: `id` is kept on a distributed run's rank where the state arrays are
  // dropped (drop_state), so size() stays the scene's N.
  std::size_t size() const { return id.size(); }

  void resize(std::size_t n) {
    position.resize(n, Vec3::Zero());
    orientation.resize(n, Quat::Identity());
    velocity.resize(n, Vec3::Zero());
    angular_velocity.resize(n, Vec3::Zero());
    velocity_end.resize(n, Vec3::Zero());
    angular_velocity_end.resize(n, Vec3::Zero());
    angular_momentum.resize(n, Vec3::Zero());
    force.resize(n, Vec3::Zero());
    torque.resize(n, Vec3::Zero());
    shape.resize(n, 0);
    scale.resize(n, 1.0);
    mass.resize(n, 0.0);
    inertia.resize(n, Vec3::Zero());
    group.resize(n, 0);
    for (std::size_t b = id.size(); b < n; ++b) id.push_back(std::uint32_t(b));
    id.resize(n);
  }

  // A distributed run's rank frees the state arrays (position to torque: 224 B a body of the
  // scene) once its store holds its own bodies' (RankContacts::redistribute); the constants stay.
  void drop_state() {
    release(position), release(orientation), release(velocity), release(angular_velocity);
    release(velocity_end), release(angular_velocity_end), release(angular_momentum), release(force), release(torque);
  }
  bool has_state() const { return position.size() == id.size(); }
  // The state arrays back at size() rows (zeroed) where dropped: a gather or a checkpoint read writes them.
  void grow_state() { resize(size()); }

  // Bytes the arrays hold (their capacity): what a rank keeps of the scene's bodies.
  std::size_t held_bytes() const {
    auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    return bytes(position) + bytes(orientation) + bytes(velocity) + bytes(angular_velocity) + bytes(velocity_end) +
           bytes(angular_velocity_end) + bytes(angular_momentum) + bytes(force) + bytes(torque) + bytes(shape) +
           bytes(scale) + bytes(mass) + bytes(inertia) + bytes(group) + bytes(id);
  }

  // The body indices sorted by user id: the order files list bodies in.
  std::vector<std::uint32_t> by_user_id() const {
    std::vector<std::uint32_t> at(id.size());
    for (std::size_t b = 0; b < id.size(); ++b) at[id[b]] = std::uint32_t(b);
    return at;
  }
};

// The state integration moves (pose, velocity, angular momentum) of body b of `a` (Bodies, or a
// rank's LocalStore) is finite.
template <class Arrays>
bool finite_state(const Arrays& a, std::size_t b) {
  return a.position[b].allFinite() && a.velocity[b].allFinite() && a.angular_momentum[b].allFinite() &&
         a.orientation[b].coeffs().allFinite();
}

}  // namespace polydem
