#pragma once
// The frame a view is drawn in: infinite walls and cylinders are cut to it, so a wall is a
// finite rectangle framing the particles rather than a square about its point.
#include <optional>
#include <utility>
#include <vector>

#include "polydem/math.hpp"

namespace polydem {

struct Box3 {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);  // m; empty until a point is added
  bool empty() const { return (lo.array() > hi.array()).any(); }
  void add(const Vec3& p, double reach = 0.0) {  // a ball of radius reach (m) about p
    lo = lo.cwiseMin(p - Vec3::Constant(reach));
    hi = hi.cwiseMax(p + Vec3::Constant(reach));
  }
  void add(const Box3& b) { if (!b.empty()) { lo = lo.cwiseMin(b.lo); hi = hi.cwiseMax(b.hi); } }
  Box3 padded(double margin) const { return {lo - Vec3::Constant(margin), hi + Vec3::Constant(margin)}; }
};

// The side of a wall the particles are on: (x - point) . normal >= 0.
struct HalfSpace {
  Vec3 point = Vec3::Zero();     // m
  Vec3 normal = Vec3::UnitZ();   // unit, towards the particles
};

struct ViewFrame {
  Box3 box;                      // m, the region shown
  std::vector<HalfSpace> walls;  // the active walls: particles are on their inner side
};

// The convex polygon where the plane (point, normal) meets the frame's box and the inner side of
// every other wall, counter-clockwise about `normal`. Walls of a box thus meet at its edges and
// do not cross. Empty when the plane misses that region.
std::vector<Vec3> framed_plane(const Vec3& point, const Vec3& normal, const ViewFrame& frame);

// A square of side `size` (m) in the plane, centred on `point`, counter-clockwise about `normal`.
std::vector<Vec3> plane_square(const Vec3& point, const Vec3& normal, double size);

// The parameters [t0, t1] of the line center + t axis inside the frame's box and walls; empty
// when the line misses them.
std::optional<std::pair<double, double>> framed_line(const Vec3& center, const Vec3& axis, const ViewFrame& frame);

// What a wall draws: the square of side `size` (m) when given, else the framed polygon, else
// (the plane misses the frame) a square as wide as the frame about `point`.
std::vector<Vec3> framed_wall(const Vec3& point, const Vec3& normal, std::optional<double> size, const ViewFrame& frame);

// m, the stretch [from, to] of a cylinder's axis to draw, about its centre: +-length/2 when
// finite, else the framed line, else (the line misses the frame) +-half the frame's width.
std::pair<double, double> framed_axis(const Vec3& center, const Vec3& axis, std::optional<double> length,
                                      const ViewFrame& frame);

}  // namespace polydem
