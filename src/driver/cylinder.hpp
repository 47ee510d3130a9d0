#pragma once
// A cylinder seen from inside (a drum, a silo): any axis, finite or infinite. The farthest
// point of a convex body from an axis is a vertex, so its candidates are the body's vertices.
// The `cylinder` settings with `inside: false` make a Post (post.hpp).
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "driver/motion.hpp"
#include "geometry/features.hpp"
#include "output/frame.hpp"

namespace polydem {

struct DriverMesh;

struct CylinderSettings {         // `cylinder: {center, axis, radius, length, inside}`
  Vec3 center = Vec3::Zero();     // m, middle of its axis
  Vec3 axis = Vec3::UnitZ();      // unit
  double radius = 0.0;            // m
  std::optional<double> length;   // m; empty: infinite
  bool inside = true;             // particles inside (Cylinder), or outside (Post)
};

struct CylinderShape {
  double radius = 0.0;            // m
  std::optional<double> length;   // m; empty: infinite

  struct AxisFrame {
    double axial;    // m, along the axis from the middle of the cylinder
    Vec3 radial;     // m, from the axis to the point
  };
  static AxisFrame axis_frame(const Placement& at, const Vec3& p) {
    const Vec3 rel = p - at.center;
    const double axial = rel.dot(at.axis);
    return {axial, rel - axial * at.axis};
  }
  // Its ends' discs (nothing for an infinite one: it is cut to the frame instead).
  void bounds(const Placement& at, Box3& box) const {
    if (length)
      for (double end : {-0.5, 0.5}) box.add(at.center + end * *length * at.axis, radius);
  }
  bool within_length(double axial, double margin) const { return !length || std::abs(axial) < 0.5 * *length + margin; }
  // Its mantle as 48 quads; an infinite one cut to the view frame.
  DriverMesh drawing(const Placement& at, const std::string& name, const ViewFrame& frame) const;
};

class Cylinder {
 public:
  Cylinder(const CylinderSettings& s, Placement& at);

  double rounding() const { return 0.0; }  // m
  void bounds(const Placement& at, Box3& box) const { shape.bounds(at, box); }
  // m, Hertz radius: the geometric mean of the principal radii, r_body along the axis and
  // 1/(1/r_body - 1/R) across it (the concave mantle).
  double r_star(double r_body) const { return std::sqrt(r_body / (1.0 / r_body - 1.0 / shape.radius)); }
  Vec3 reference(const Placement& at) const { return at.center; }  // m
  Vec3 servo_direction(const Placement& at, const MotionSettings&) const { return at.axis; }

  bool near(const Placement& at, const Vec3& center, double reach) const;
  bool overlaps(const Placement& at, const Vec3& center, double radius) const;
  void candidates(const Placement& at, const PosedBody& a, double range, std::vector<FeaturePair>& out) const;
  bool contact(const Placement& at, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out) const;
  DriverMesh drawing(const Placement& at, const std::string& name, const ViewFrame& frame) const;

  CylinderShape shape;
};

}  // namespace polydem
