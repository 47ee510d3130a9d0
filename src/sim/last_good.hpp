#pragma once
// What the run loop keeps of the state at each finiteness check, to write it
// (bodies_last_good.vtu) when a later step blows up.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "polydem/bodies.hpp"
#include "polydem/release.hpp"
#include "sim/rank_link.hpp"

namespace polydem {

// The moving state of the last finiteness check, all a blow-up report writes: 104 bytes a body
// where a copy of Bodies is 272 (shape, scale and group are constant: the run's own are read),
// 72 while every orientation is exactly the identity (spheres: Rotor::sphere never turns one).
// A rank of a distributed run keeps the bodies it owns (`ids`), gathered only on a blow-up.
struct LastGood {
  std::vector<std::uint32_t> ids;  // a rank's bodies, increasing; empty: every body
  std::vector<Vec3> position, velocity, angular_velocity;  // m, m/s, rad/s
  std::vector<Quat> orientation;  // empty while every kept body's is the identity

  void keep(const Bodies& b) {
    release(ids);
    position = b.position;
    velocity = b.velocity;
    angular_velocity = b.angular_velocity;
    if (std::all_of(b.orientation.begin(), b.orientation.end(), is_identity)) release(orientation);
    else orientation = b.orientation;
  }
  // The bodies `ids` only (a rank's), at `rows` of `a` (Bodies, or the rank's LocalStore).
  template <class Arrays>
  void keep(const Arrays& a, const std::vector<std::uint32_t>& rows, std::vector<std::uint32_t> own) {
    ids = std::move(own);
    const std::size_t n = rows.size();
    position.resize(n);
    velocity.resize(n);
    angular_velocity.resize(n);
    orientation.resize(n);
    bool turned = false;
    for (std::size_t k = 0; k < n; ++k) {
      position[k] = a.position[rows[k]];
      velocity[k] = a.velocity[rows[k]];
      angular_velocity[k] = a.angular_velocity[rows[k]];
      orientation[k] = a.orientation[rows[k]];
      turned |= !is_identity(orientation[k]);
    }
    if (!turned) release(orientation);
  }
  // Every rank's kept bodies on rank 0, as one process keeps them (a collective; empty on the others).
  LastGood gathered(const RankLink& link) const;
  // The bodies as they were: the constant fields from `now`, the moving ones kept (every body's).
  Bodies with_constants_of(const Bodies& now) const {
    Bodies then = now;
    then.position = position;
    then.velocity = velocity;
    then.angular_velocity = angular_velocity;
    if (orientation.empty()) then.orientation.assign(position.size(), Quat::Identity());
    else then.orientation = orientation;
    return then;
  }
  // Bit for bit (a -0 is kept as it was).
  static bool is_identity(const Quat& q) {
    const Quat one = Quat::Identity();
    return std::memcmp(q.coeffs().data(), one.coeffs().data(), sizeof(double) * 4) == 0;
  }
};

}  // namespace polydem
