#include "output/frame.hpp"

#include <algorithm>
#include <cmath>

namespace polydem {

namespace {

// Two unit vectors spanning the plane of `normal`: the world axis least along the normal,
// projected, so a floor's rectangle has its sides along x and y.
std::pair<Vec3, Vec3> plane_axes(const Vec3& normal) {
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(normal[k]) < std::abs(normal[axis])) axis = k;
  const Vec3 u = (Vec3::Unit(axis) - normal[axis] * normal).normalized();
  return {u, normal.cross(u)};
}

// Sutherland-Hodgman: the part of a convex polygon on the kept side of one half space.
// `tolerance` (m): a corner that far outside still counts as on the plane (coplanar walls).
std::vector<Vec3> clip(const std::vector<Vec3>& polygon, const HalfSpace& h, double tolerance) {
  std::vector<Vec3> out;
  const std::size_t n = polygon.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3& a = polygon[k];
    const Vec3& b = polygon[(k + 1) % n];
    const double da = (a - h.point).dot(h.normal), db = (b - h.point).dot(h.normal);
    if (da >= -tolerance) out.push_back(a);
    if ((da >= -tolerance) != (db >= -tolerance)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

std::vector<HalfSpace> box_faces(const Box3& box) {
  std::vector<HalfSpace> faces;
  for (int k = 0; k < 3; ++k) {
    faces.push_back({box.lo, Vec3::Unit(k)});
    faces.push_back({box.hi, -Vec3::Unit(k)});
  }
  return faces;
}

bool same_plane(const HalfSpace& h, const Vec3& point, const Vec3& normal, double tolerance) {
  return std::abs(h.normal.dot(normal)) > 1.0 - 1e-12 && std::abs((h.point - point).dot(normal)) <= tolerance;
}

}  // namespace

std::vector<Vec3> plane_square(const Vec3& point, const Vec3& normal, double size) {
  const auto [u, w] = plane_axes(normal);
  const Vec3 a = 0.5 * size * u, b = 0.5 * size * w;
  return {point - a - b, point + a - b, point + a + b, point - a + b};
}

std::vector<Vec3> framed_plane(const Vec3& point, const Vec3& normal, const ViewFrame& frame) {
  if (frame.box.empty()) return {};
  const double diagonal = (frame.box.hi - frame.box.lo).norm();
  const double tolerance = 1e-12 * std::max(diagonal, 1.0);  // m, round-off of the corners
  const Vec3 middle = 0.5 * (frame.box.lo + frame.box.hi);
  // A square about the box's middle, projected on the plane, covering the whole box.
  std::vector<Vec3> polygon = plane_square(middle - (middle - point).dot(normal) * normal, normal, 4.0 * diagonal);
  for (const HalfSpace& h : box_faces(frame.box)) polygon = clip(polygon, h, tolerance);
  for (const HalfSpace& h : frame.walls)
    if (!same_plane(h, point, normal, tolerance)) polygon = clip(polygon, h, tolerance);
  if (polygon.size() < 3) return {};
  return polygon;
}

std::optional<std::pair<double, double>> framed_line(const Vec3& center, const Vec3& axis, const ViewFrame& frame) {
  if (frame.box.empty()) return std::nullopt;
  double t0 = -1e300, t1 = 1e300;
  auto keep = [&](const HalfSpace& h) {  // (center + t axis - point) . normal >= 0
    const double at_center = (center - h.point).dot(h.normal), slope = axis.dot(h.normal);
    if (slope > 0) t0 = std::max(t0, -at_center / slope);
    else if (slope < 0) t1 = std::min(t1, -at_center / slope);
    else if (at_center < 0) t1 = t0 - 1.0;  // parallel and outside
  };
  for (const HalfSpace& h : box_faces(frame.box)) keep(h);
  for (const HalfSpace& h : frame.walls) keep(h);
  if (!(t0 < t1)) return std::nullopt;
  return std::pair{t0, t1};
}

namespace {

double frame_width(const ViewFrame& frame) {  // m, the box's largest side
  return frame.box.empty() ? 1.0 : (frame.box.hi - frame.box.lo).maxCoeff();
}

}  // namespace

std::vector<Vec3> framed_wall(const Vec3& point, const Vec3& normal, std::optional<double> size, const ViewFrame& frame) {
  if (size) return plane_square(point, normal, *size);
  std::vector<Vec3> polygon = framed_plane(point, normal, frame);
  return polygon.empty() ? plane_square(point, normal, frame_width(frame)) : polygon;
}

std::pair<double, double> framed_axis(const Vec3& center, const Vec3& axis, std::optional<double> length,
                                      const ViewFrame& frame) {
  if (length) return {-0.5 * *length, 0.5 * *length};
  const auto span = framed_line(center, axis, frame);
  return span ? *span : std::pair{-0.5 * frame_width(frame), 0.5 * frame_width(frame)};
}

}  // namespace polydem
