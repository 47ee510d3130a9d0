#include "driver/cylinder.hpp"

#include <cmath>

#include "output/vtk.hpp"

namespace polydem {

namespace {

constexpr int kSegments = 48;  // around the mantle: smooth enough to look round

}  // namespace

DriverMesh CylinderShape::drawing(const Placement& at, const std::string& name, const ViewFrame& frame) const {
  const auto [from, to] = framed_axis(at.center, at.axis, length, frame);  // m along the axis
  const Vec3 u = at.axis.unitOrthogonal(), w = at.axis.cross(u);
  DriverMesh m{name, {}, {}};
  for (int k = 0; k < kSegments; ++k) {
    const double angle = 2.0 * kPi * k / kSegments;
    const Vec3 r = radius * (std::cos(angle) * u + std::sin(angle) * w);
    m.points.push_back(at.center + r + from * at.axis);
    m.points.push_back(at.center + r + to * at.axis);
  }
  for (int k = 0; k < kSegments; ++k) {
    const int next = (k + 1) % kSegments;
    m.polygons.push_back({2 * k, 2 * next, 2 * next + 1, 2 * k + 1});
  }
  return m;
}

DriverMesh Cylinder::drawing(const Placement& at, const std::string& name, const ViewFrame& frame) const {
  return shape.drawing(at, name, frame);
}

Cylinder::Cylinder(const CylinderSettings& s, Placement& at) : shape{s.radius, s.length} {
  at.center = s.center;
  at.axis = s.axis.normalized();
}

bool Cylinder::near(const Placement& at, const Vec3& center, double reach) const {
  const CylinderShape::AxisFrame f = CylinderShape::axis_frame(at, center);
  return shape.within_length(f.axial, reach) && f.radial.norm() + reach > shape.radius;
}

bool Cylinder::overlaps(const Placement& at, const Vec3& center, double radius) const {
  const CylinderShape::AxisFrame f = CylinderShape::axis_frame(at, center);
  return shape.within_length(f.axial, radius) && f.radial.norm() + radius >= shape.radius;
}

void Cylinder::candidates(const Placement& at, const PosedBody& a, double range, std::vector<FeaturePair>& out) const {
  for (std::size_t v = 0; v < a.shape->vertices.size(); ++v) {
    const CylinderShape::AxisFrame f = CylinderShape::axis_frame(at, a.vertices[v]);
    if (shape.within_length(f.axial, range) && shape.radius - f.radial.norm() - a.radius < range)
      out.push_back({PairType::vertex_face, std::uint16_t(v), 0});
  }
}

bool Cylinder::contact(const Placement& at, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out) const {
  const Vec3& v = a.vertices[f.a];
  const CylinderShape::AxisFrame frame = CylinderShape::axis_frame(at, v);
  if (!shape.within_length(frame.axial, 0.0)) return false;  // beyond the end of a finite cylinder
  const double rho = frame.radial.norm();                      // m, vertex distance from the axis
  const double gap = shape.radius - rho - a.radius;
  if (gap >= max_gap || rho == 0.0) return false;
  const Vec3 outward = frame.radial / rho;
  out.normal = -outward;  // from the surface towards the axis, where the body is
  out.gap = gap;
  out.point = v + outward * (a.radius + 0.5 * gap);  // middle of the overlap
  return true;
}

}  // namespace polydem
