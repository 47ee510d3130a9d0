#pragma once
// A ball: a one-vertex spheropolyhedron of its radius, so the body-body kernels give its
// contacts.
#include <string>
#include <vector>

#include "driver/motion.hpp"
#include "geometry/features.hpp"
#include "output/frame.hpp"

namespace polydem {

struct DriverMesh;
class Ball;

struct BallSettings {             // `ball: {center, radius}`
  using Kind = Ball;
  Vec3 center = Vec3::Zero();     // m
  double radius = 0.0;            // m
};

class Ball {
 public:
  Ball(const BallSettings& s, Placement& at);

  double rounding() const { return shape_.radius; }  // m
  void bounds(const Placement& at, Box3& box) const { box.add(at.center, shape_.radius); }
  double r_star(double r_body) const { return r_body * shape_.radius / (r_body + shape_.radius); }  // m, Hertz radius
  Vec3 reference(const Placement& at) const { return at.center; }  // m
  Vec3 servo_direction(const Placement&, const MotionSettings& m) const { return given_servo_direction(m); }

  bool near(const Placement& at, const Vec3& center, double reach) const {
    return (center - at.center).norm() < shape_.radius + reach;
  }
  bool overlaps(const Placement& at, const Vec3& center, double radius) const {
    return (center - at.center).norm() <= shape_.radius + radius;
  }
  void candidates(const Placement& at, const PosedBody& a, double range, std::vector<FeaturePair>& out) const {
    candidate_features(a, pose(at), range, out);
  }
  bool contact(const Placement& at, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out) const {
    return feature_contact(a, pose(at), f, max_gap, out);
  }
  // A UV sphere of 48 x 24 quads.
  DriverMesh drawing(const Placement& at, const std::string& name, const ViewFrame& frame) const;

 private:
  // The ball as a posed body: its one vertex at its current centre.
  PosedBody pose(const Placement& at) const { return PosedBody{&shape_, &at.center, Mat3::Identity(), at.center, shape_.radius, 1.0}; }

  Shape shape_;
};

}  // namespace polydem
