#pragma once
// A wall: an infinite plane, particles on the side its normal points to. A plane meets a
// convex body first at its vertices, so its candidates are the body's vertices.
#include <optional>
#include <string>
#include <vector>

#include "driver/motion.hpp"
#include "geometry/features.hpp"
#include "output/frame.hpp"

namespace polydem {

struct DriverMesh;
class Wall;

struct WallSettings {             // `wall: {point, normal, size}`
  using Kind = Wall;
  Vec3 point = Vec3::Zero();      // m, a point on the plane
  Vec3 normal = Vec3::UnitZ();    // unit normal towards the particles
  std::optional<double> size;     // m, side of the square drawn about `point`; empty: cut to the view frame
};

class Wall {
 public:
  Wall(const WallSettings& s, Placement& at);

  double rounding() const { return 0.0; }  // m
  void bounds(const Placement& at, Box3& box) const { box.add(at.point); }  // its point: the plane is infinite
  double r_star(double r_body) const { return r_body; }  // m, Hertz radius: a flat surface
  Vec3 reference(const Placement& at) const { return at.point; }  // m, torques are about it
  Vec3 servo_direction(const Placement& at, const MotionSettings&) const { return at.normal; }

  bool near(const Placement& at, const Vec3& center, double reach) const { return (center - at.point).dot(at.normal) < reach; }
  bool overlaps(const Placement& at, const Vec3& center, double radius) const { return (center - at.point).dot(at.normal) <= radius; }
  void candidates(const Placement& at, const PosedBody& a, double range, std::vector<FeaturePair>& out) const;
  // Inline: every listed wall candidate of a step calls it (a call cost ~30% of it).
  bool contact(const Placement& at, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out) const {
    const Vec3& v = a.vertices[f.a];
    const double height = (v - at.point).dot(at.normal);  // m, vertex above the plane
    const double gap = height - a.radius;
    if (gap >= max_gap) return false;
    out.normal = at.normal;
    out.gap = gap;
    out.point = v - at.normal * (a.radius + 0.5 * gap);  // middle of the overlap
    return true;
  }
  // The part of its plane in the view frame, cut by the other walls (or a square of `size`).
  DriverMesh drawing(const Placement& at, const std::string& name, const ViewFrame& frame) const;

 private:
  std::optional<double> size_;  // m, drawn square's side; empty: the framed plane
};

}  // namespace polydem
