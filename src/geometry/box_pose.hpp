#pragma once
// Posing a box's corners: its vertices are (+-hx, +-hy, +-hz) in the principal frame, so the
// nine products of pose_vertices' R s v are shared by the eight corners up to their signs
// (exact: (-a) b = -(a b), (-a) + (-b) = -(a + b)), and each corner takes three sums. The same
// bits as pose_vertices (tests/geometry/box_pose_test.cpp), in a third of its arithmetic.
#include <array>
#include <cstdint>
#include <optional>

#include "geometry/features.hpp"

namespace polydem {

struct BoxCorners {
  Vec3 half;  // m, unscaled half extents
  std::array<std::uint8_t, 8> vertex;  // the shape's vertex at corner c = (x > 0) | (y > 0) << 1 | (z > 0) << 2
};

// The corners of s when its eight vertices are exactly the corners of a box about the centre.
std::optional<BoxCorners> box_corners(const Shape& s);

namespace box_pose_detail {
// +-a +- b for the four signs, [a > 0][b > 0], each as one sum of the signed terms (a zero
// keeps the sign Eigen's sum gives it).
struct SignedSums {
  double v[2][2];
  SignedSums(double a, double b) : v{{-a - b, -a + b}, {a - b, a + b}} {}
};

// Corner (sx, sy, sz) at position: Eigen's product rs v sums rows x and y as (a + b) + c and
// row z as a + (b + c), a, b, c the terms along the columns c0, c1, c2.
template <int sx, int sy, int sz>
[[gnu::always_inline]] inline Vec3 corner(const Vec3& position, const SignedSums& x01, const SignedSums& y01,
                                          const SignedSums& z12, const Vec3& c0, const Vec3& c2) {
  constexpr int i = sx > 0, j = sy > 0, k = sz > 0;
  const double x = sz > 0 ? x01.v[i][j] + c2.x() : x01.v[i][j] - c2.x();
  const double y = sz > 0 ? y01.v[i][j] + c2.y() : y01.v[i][j] - c2.y();
  const double z = sx > 0 ? c0.z() + z12.v[j][k] : -c0.z() + z12.v[j][k];
  return position + Vec3(x, y, z);
}
}  // namespace box_pose_detail

// out[v] = position + (rotation scale) s.vertices[v], as pose_vertices, for a box's eight vertices.
// Inline: posing calls it for every body and step.
// `at` by value: held in registers, not reloaded after each corner's store (out may alias it).
inline void pose_box(const BoxCorners& box, double scale, const Vec3 at, const Mat3& rotation, Vec3* out) {
  const Mat3 rs = rotation * scale;
  const Vec3 c0 = rs.col(0) * box.half.x(), c1 = rs.col(1) * box.half.y(), c2 = rs.col(2) * box.half.z();  // m
  using namespace box_pose_detail;
  const SignedSums x01(c0.x(), c1.x()), y01(c0.y(), c1.y()), z12(c1.z(), c2.z());
  out[box.vertex[0]] = corner<-1, -1, -1>(at, x01, y01, z12, c0, c2);
  out[box.vertex[1]] = corner<+1, -1, -1>(at, x01, y01, z12, c0, c2);
  out[box.vertex[2]] = corner<-1, +1, -1>(at, x01, y01, z12, c0, c2);
  out[box.vertex[3]] = corner<+1, +1, -1>(at, x01, y01, z12, c0, c2);
  out[box.vertex[4]] = corner<-1, -1, +1>(at, x01, y01, z12, c0, c2);
  out[box.vertex[5]] = corner<+1, -1, +1>(at, x01, y01, z12, c0, c2);
  out[box.vertex[6]] = corner<-1, +1, +1>(at, x01, y01, z12, c0, c2);
  out[box.vertex[7]] = corner<+1, +1, +1>(at, x01, y01, z12, c0, c2);
}

}  // namespace polydem
