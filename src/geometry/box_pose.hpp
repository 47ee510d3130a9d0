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

// out[v] = position + (rotation scale) s.vertices[v], as pose_vertices, for a box's eight vertices.
void pose_box(const BoxCorners& box, double scale, const Vec3& position, const Mat3& rotation, Vec3* out);

}  // namespace polydem
