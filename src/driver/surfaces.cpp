#include "driver/surfaces.hpp"

#include <algorithm>
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

PosedBody ball_pose(const Driver& d) {
  return PosedBody{&d.ball_shape, &d.center, Mat3::Identity(), d.center, d.spec.radius, 1.0};
}

Shape axis_shape(const std::string& name, double radius) {
  Shape s = sphere_shape(name, radius);
  s.vertices.push_back(Vec3::Zero());
  s.edges = {{0, 1}};
  return s;
}

namespace {

// The outer cylinder as a posed body: its axis segment, radius R; `ends` receives the ends.
PosedBody axis_pose(const Driver& d, const PosedBody& a, Vec3* ends) {
  const double r = d.spec.radius;
  if (d.spec.length) {
    ends[0] = d.center - 0.5 * *d.spec.length * d.axis;
    ends[1] = d.center + 0.5 * *d.spec.length * d.axis;
    return PosedBody{&d.axis_shape, ends, Mat3::Identity(), d.center, r, 1.0};
  }
  double core = 0.0;  // m, farthest core vertex of the body from its centre
  for (std::size_t v = 0; v < a.shape->vertices.size(); ++v) core = std::max(core, (a.vertices[v] - a.position).norm());
  // Ends farther along the axis than any point of the body, by more than R: never the closest.
  const double half = r + 2.0 * (core + a.radius);
  const Vec3 foot = d.center + (a.position - d.center).dot(d.axis) * d.axis;
  ends[0] = foot - half * d.axis;
  ends[1] = foot + half * d.axis;
  return PosedBody{&d.axis_shape, ends, Mat3::Identity(), foot, r, 1.0};
}

}  // namespace

bool outer_cylinder_near(const Driver& d, const Vec3& center, double reach) {
  const AxisFrame f = axis_frame(d, center);
  const double beyond = d.spec.length ? std::max(0.0, std::abs(f.axial) - 0.5 * *d.spec.length) : 0.0;  // m, past an end
  return std::hypot(beyond, f.radial.norm()) < d.spec.radius + reach;
}

void outer_cylinder_candidates(const Driver& d, const PosedBody& a, double range, std::vector<FeaturePair>& out) {
  Vec3 ends[2];
  candidate_features(a, axis_pose(d, a, ends), range, out);
}

bool outer_cylinder_contact(const Driver& d, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out) {
  Vec3 ends[2];
  return feature_contact(a, axis_pose(d, a, ends), f, max_gap, out);
}

}  // namespace polydem
