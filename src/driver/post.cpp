#include "driver/post.hpp"

#include <algorithm>
#include <cmath>

#include "output/vtk.hpp"

namespace polydem {

Post::Post(const CylinderSettings& s, Placement& at) : shape{s.radius, s.length}, axis_shape_(sphere_shape("", s.radius)) {
  axis_shape_.vertices.push_back(Vec3::Zero());
  axis_shape_.edges = {{0, 1}};
  at.center = s.center;
  at.axis = s.axis.normalized();
}

DriverMesh Post::drawing(const Placement& at, const std::string& name, const ViewFrame& frame) const {
  return shape.drawing(at, name, frame);
}

PosedBody Post::axis_pose(const Placement& at, const PosedBody& a, Vec3* ends) const {
  const double r = shape.radius;
  if (shape.length) {
    ends[0] = at.center - 0.5 * *shape.length * at.axis;
    ends[1] = at.center + 0.5 * *shape.length * at.axis;
    return PosedBody{&axis_shape_, ends, Mat3::Identity(), at.center, r, 1.0};
  }
  double core = 0.0;  // m, farthest core vertex of the body from its centre
  for (std::size_t v = 0; v < a.shape->vertices.size(); ++v) core = std::max(core, (a.vertices[v] - a.position).norm());
  // Ends farther along the axis than any point of the body, by more than R: never the closest.
  const double half = r + 2.0 * (core + a.radius);
  const Vec3 foot = at.center + (a.position - at.center).dot(at.axis) * at.axis;
  ends[0] = foot - half * at.axis;
  ends[1] = foot + half * at.axis;
  return PosedBody{&axis_shape_, ends, Mat3::Identity(), foot, r, 1.0};
}

double Post::axis_distance(const Placement& at, const Vec3& center) const {
  const CylinderShape::AxisFrame f = CylinderShape::axis_frame(at, center);
  const double beyond = shape.length ? std::max(0.0, std::abs(f.axial) - 0.5 * *shape.length) : 0.0;  // m, past an end
  return std::hypot(beyond, f.radial.norm());
}

bool Post::near(const Placement& at, const Vec3& center, double reach) const {
  return axis_distance(at, center) < shape.radius + reach;
}

bool Post::overlaps(const Placement& at, const Vec3& center, double radius) const {
  return axis_distance(at, center) <= shape.radius + radius;
}

void Post::candidates(const Placement& at, const PosedBody& a, double range, std::vector<FeaturePair>& out) const {
  Vec3 ends[2];
  candidate_features(a, axis_pose(at, a, ends), range, out);
}

bool Post::contact(const Placement& at, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out) const {
  Vec3 ends[2];
  return feature_contact(a, axis_pose(at, a, ends), f, max_gap, out);
}

}  // namespace polydem
