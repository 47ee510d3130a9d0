#include "geometry/box_pose.hpp"

#include <cmath>

namespace polydem {

std::optional<BoxCorners> box_corners(const Shape& s) {
  if (s.vertices.size() != 8) return std::nullopt;
  BoxCorners box{s.vertices[0].cwiseAbs(), {}};
  std::uint8_t seen = 0;  // bit c: corner c taken
  for (std::size_t v = 0; v < 8; ++v) {
    const Vec3& p = s.vertices[v];
    if (p.cwiseAbs() != box.half || (box.half.array() == 0.0).any()) return std::nullopt;
    const int c = (p.x() > 0.0) | (p.y() > 0.0) << 1 | (p.z() > 0.0) << 2;
    if (seen & (1u << c)) return std::nullopt;
    seen |= std::uint8_t(1u << c);
    box.vertex[c] = std::uint8_t(v);
  }
  return box;
}

}  // namespace polydem
