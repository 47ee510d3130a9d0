#include "driver/surfaces.hpp"

#include <cmath>

namespace polydem {

void wall_candidates(const Driver& d, const PosedBody& a, double range, std::vector<FeaturePair>& out) {
  for (std::size_t v = 0; v < a.shape->vertices.size(); ++v)
    if ((a.vertices[v] - d.point).dot(d.normal) < a.radius + range)
      out.push_back({PairType::vertex_face, std::uint16_t(v), 0});
}

bool wall_contact(const Driver& d, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out) {
  const Vec3& v = a.vertices[f.a];
  const double height = (v - d.point).dot(d.normal);  // m, vertex above the plane
  const double gap = height - a.radius;
  if (gap >= max_gap) return false;
  out.normal = d.normal;
  out.gap = gap;
  out.point = v - d.normal * (a.radius + 0.5 * gap);  // middle of the overlap
  return true;
}

namespace {

struct AxisFrame {
  double axial;    // m, along the axis from the middle of the cylinder
  Vec3 radial;     // m, from the axis to the point
};

AxisFrame axis_frame(const Driver& d, const Vec3& p) {
  const Vec3 rel = p - d.center;
  const double axial = rel.dot(d.axis);
  return {axial, rel - axial * d.axis};
}

bool within_length(const Driver& d, double axial, double margin) {
  return !d.spec.length || std::abs(axial) < 0.5 * *d.spec.length + margin;
}

}  // namespace

bool cylinder_near(const Driver& d, const Vec3& center, double reach) {
  const AxisFrame f = axis_frame(d, center);
  return within_length(d, f.axial, reach) && f.radial.norm() + reach > d.spec.radius;
}

void cylinder_candidates(const Driver& d, const PosedBody& a, double range, std::vector<FeaturePair>& out) {
  for (std::size_t v = 0; v < a.shape->vertices.size(); ++v) {
    const AxisFrame f = axis_frame(d, a.vertices[v]);
    if (within_length(d, f.axial, range) && d.spec.radius - f.radial.norm() - a.radius < range)
      out.push_back({PairType::vertex_face, std::uint16_t(v), 0});
  }
}

bool cylinder_contact(const Driver& d, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out) {
  const Vec3& v = a.vertices[f.a];
  const AxisFrame frame = axis_frame(d, v);
  if (!within_length(d, frame.axial, 0.0)) return false;  // beyond the end of a finite cylinder
  const double rho = frame.radial.norm();                  // m, vertex distance from the axis
  const double gap = d.spec.radius - rho - a.radius;
  if (gap >= max_gap || rho == 0.0) return false;
  const Vec3 outward = frame.radial / rho;
  out.normal = -outward;  // from the surface towards the axis, where the body is
  out.gap = gap;
  out.point = v + outward * (a.radius + 0.5 * gap);  // middle of the overlap
  return true;
}

Shape ball_shape(const std::string& name, double radius) {
  Shape s;
  s.name = name;
  s.radius = radius;
  s.vertices = {Vec3::Zero()};
  s.bounding_radius = radius;
  return s;
}

PosedBody ball_pose(const Driver& d) {
  return PosedBody{&d.ball_shape, &d.center, Mat3::Identity(), d.center, d.spec.radius};
}

}  // namespace polydem
