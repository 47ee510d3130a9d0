#pragma once
// Small known scenes for the output tests: shapes built by hand, bodies at chosen poses.
#include <vector>

#include "polydem/bodies.hpp"
#include "polydem/shape.hpp"

namespace polydem::test {

// Cube of half side h, vertex k at (+-h, +-h, +-h) by bits x=1, y=2, z=4; faces counter-clockwise from outside.
inline Shape cube_shape(double h, double radius) {
  Shape s;
  s.name = "cube";
  s.radius = radius;
  for (int k = 0; k < 8; ++k) s.vertices.emplace_back(k & 1 ? h : -h, k & 2 ? h : -h, k & 4 ? h : -h);
  s.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return s;
}

inline Shape sphere_shape(double radius) {
  Shape s;
  s.name = "sphere";
  s.radius = radius;
  s.vertices = {Vec3::Zero()};
  return s;
}

// Segment from -half_length to +half_length along z.
inline Shape capsule_shape(double half_length, double radius) {
  Shape s;
  s.name = "capsule";
  s.radius = radius;
  s.vertices = {Vec3(0, 0, -half_length), Vec3(0, 0, half_length)};
  s.edges = {{0, 1}};
  return s;
}

inline void add_body(Bodies& b, int shape, const Vec3& x, const Quat& q, double scale, const Vec3& v, const Vec3& w,
                     int group) {
  const std::size_t k = b.size();
  b.resize(k + 1);
  b.shape[k] = shape;
  b.position[k] = x;
  b.orientation[k] = q;
  b.scale[k] = scale;
  b.velocity[k] = v;
  b.angular_velocity[k] = w;
  b.group[k] = group;
}

inline Quat axis_angle(const Vec3& axis, double angle) { return Quat(Eigen::AngleAxisd(angle, axis.normalized())); }

}  // namespace polydem::test
