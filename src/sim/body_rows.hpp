#pragma once
// Rows of a table of bodies, read by field name from Bodies (index = global id) or from a rank's
// LocalStore (index = local), so a rank's writers read its own bodies where they live.
#include <cstdint>
#include <vector>

#include "polydem/bodies.hpp"

namespace polydem {

// `all` at `rows`, in that order.
template <class T>
std::vector<T> subset(const std::vector<T>& all, const std::vector<std::uint32_t>& rows) {
  std::vector<T> part;
  part.reserve(rows.size());
  for (std::uint32_t b : rows) part.push_back(all[b]);
  return part;
}

// The bodies at `rows` of `a` (Bodies or LocalStore) as a Bodies of their own, user ids kept.
template <class Arrays>
Bodies rows_of(const Arrays& a, const std::vector<std::uint32_t>& rows) {
  Bodies b;
  b.position = subset(a.position, rows);
  b.orientation = subset(a.orientation, rows);
  b.velocity = subset(a.velocity, rows);
  b.angular_velocity = subset(a.angular_velocity, rows);
  b.velocity_end = subset(a.velocity_end, rows);
  b.angular_velocity_end = subset(a.angular_velocity_end, rows);
  b.angular_momentum = subset(a.angular_momentum, rows);
  b.force = subset(a.force, rows);
  b.torque = subset(a.torque, rows);
  b.shape = subset(a.shape, rows);
  b.scale = subset(a.scale, rows);
  b.mass = subset(a.mass, rows);
  b.inertia = subset(a.inertia, rows);
  b.group = subset(a.group, rows);
  b.id = subset(a.id, rows);
  return b;
}

}  // namespace polydem
