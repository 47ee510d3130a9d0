#pragma once
// A cylinder seen from outside (a post): its axis segment swept by its radius, so the
// body-body kernels give its contacts. A finite one has rounded (hemispherical) ends, the
// capsule around its axis segment; an infinite one is the segment through the body's
// projection on the axis, longer than the body, so its ends never touch.
#include <string>
#include <vector>

#include "driver/cylinder.hpp"

namespace polydem {

class Post {
 public:
  Post(const CylinderSettings& s, Placement& at);

  double rounding() const { return shape.radius; }  // m, a rounded segment
  void bounds(const Placement& at, Box3& box) const { shape.bounds(at, box); }
  // m, Hertz radius: the geometric mean of r_body along the axis and 1/(1/r_body + 1/R) across it.
  double r_star(double r_body) const { return std::sqrt(r_body / (1.0 / r_body + 1.0 / shape.radius)); }
  Vec3 reference(const Placement& at) const { return at.center; }  // m
  Vec3 servo_direction(const Placement& at, const MotionSettings&) const { return at.axis; }

  bool near(const Placement& at, const Vec3& center, double reach) const;
  bool overlaps(const Placement& at, const Vec3& center, double radius) const;
  void candidates(const Placement& at, const PosedBody& a, double range, std::vector<FeaturePair>& out) const;
  bool contact(const Placement& at, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out) const;
  DriverMesh drawing(const Placement& at, const std::string& name, const ViewFrame& frame) const;

  CylinderShape shape;

 private:
  // m, distance from `center` to the axis segment.
  double axis_distance(const Placement& at, const Vec3& center) const;
  // The post as a posed body: its axis segment, radius R; `ends` receives the ends.
  PosedBody axis_pose(const Placement& at, const PosedBody& a, Vec3* ends) const;

  Shape axis_shape_;  // two vertices, one edge, radius R
};

}  // namespace polydem
