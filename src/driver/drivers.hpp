#pragma once
// Drivers: rigid boundaries the particles touch (walls, cylinders seen from inside, balls),
// fixed or moving (constant velocity, rotation about an axis, removal at a time). Each kind
// gives candidate features and contacts through the same interface as a body partner.
#include <cstdint>
#include <vector>

#include "geometry/features.hpp"
#include "polydem/scene.hpp"

namespace polydem {

struct DriverMesh;

struct Driver {
  DriverSpec spec;
  bool active = true;              // false once removed (remove_at)
  Vec3 point = Vec3::Zero();       // m, wall: current point on the plane
  Vec3 normal = Vec3::UnitZ();     // wall: unit normal towards the particles
  Vec3 center = Vec3::Zero();      // m, cylinder: middle of its axis; ball: centre
  Vec3 axis = Vec3::UnitZ();       // cylinder: unit axis
  Vec3 velocity = Vec3::Zero();    // m/s, current translation velocity
  Vec3 omega = Vec3::Zero();       // rad/s, current angular velocity about `pivot`
  Vec3 pivot = Vec3::Zero();       // m, a point on the rotation axis
  Vec3 force = Vec3::Zero();       // N, exerted by the particles this step
  Vec3 torque = Vec3::Zero();      // N m, about center(j) (wall: its point), exerted by the particles this step
  Shape ball_shape;                // ball: a one-vertex shape, so body-ball contacts reuse the body kernels
};

class Drivers {
 public:
  // Throws InputError (file, line) for what the engine cannot do yet (STL meshes, servo
  // motions, contact on the outer surface of a cylinder).
  explicit Drivers(const std::vector<DriverSpec>& specs);

  std::size_t size() const { return list_.size(); }
  bool empty() const { return list_.empty(); }
  const Driver& operator[](std::size_t j) const { return list_[j]; }
  Driver& operator[](std::size_t j) { return list_[j]; }

  // Applies the motions from time t to t + dt (removal, translation, rotation).
  void advance(double t, double dt);

  // True when a body whose bounding sphere of radius `reach` is centred at `center` may touch driver j.
  bool near(std::uint32_t j, const Vec3& center, double reach) const;
  // Feature pairs (feature of a, feature of the driver) within rA + range of driver j.
  void candidates(const PosedBody& a, std::uint32_t j, double range, std::vector<FeaturePair>& out) const;
  // One feature pair; normal from the driver to the body, same conventions as feature_contact.
  bool contact(const PosedBody& a, std::uint32_t j, FeaturePair f, double max_gap, ContactPoint& out) const;

  Vec3 center(std::uint32_t j) const;
  Vec3 velocity_at(std::uint32_t j, const Vec3& p) const {
    const Driver& d = list_[j];
    return d.velocity + d.omega.cross(p - d.pivot);
  }
  Vec3 angular_velocity(std::uint32_t j) const { return list_[j].omega; }

  // Surface meshes of the active drivers for the VTK output; infinite walls and cylinders
  // are cut at `extent` (m) around their reference point.
  std::vector<DriverMesh> meshes(double extent) const;

 private:
  std::vector<Driver> list_;
};

}  // namespace polydem
