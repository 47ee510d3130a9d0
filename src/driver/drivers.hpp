#pragma once
// Drivers: rigid boundaries the particles touch (walls now; cylinders, balls, STL meshes
// plug in through the same contact/candidate interface).
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
  Vec3 velocity = Vec3::Zero();    // m/s, current translation velocity
  Vec3 force = Vec3::Zero();       // N, exerted by the particles this step
  Vec3 torque = Vec3::Zero();      // N m, about `point`, exerted by the particles this step
  double work = 0.0;               // J, work done by the driver on the particles so far
};

class Drivers {
 public:
  explicit Drivers(const std::vector<DriverSpec>& specs);

  std::size_t size() const { return list_.size(); }
  bool empty() const { return list_.empty(); }
  const Driver& operator[](std::size_t j) const { return list_[j]; }
  Driver& operator[](std::size_t j) { return list_[j]; }

  // Applies the motions from time t to t + dt (removal, constant velocity).
  void advance(double t, double dt);

  // True when body `a` (bounding sphere `reach` around its centre) may touch driver j.
  bool near(std::uint32_t j, const Vec3& center, double reach) const;
  // Feature pairs (vertex of a, feature of the driver) within rA + range of driver j.
  void candidates(const PosedBody& a, std::uint32_t j, double range, std::vector<FeaturePair>& out) const;
  // One feature pair; normal from the driver to the body, same conventions as feature_contact.
  bool contact(const PosedBody& a, std::uint32_t j, FeaturePair f, double max_gap, ContactPoint& out) const;

  Vec3 center(std::uint32_t j) const { return list_[j].point; }
  Vec3 velocity_at(std::uint32_t j, const Vec3&) const { return list_[j].velocity; }
  Vec3 angular_velocity(std::uint32_t) const { return Vec3::Zero(); }

  // A square patch of half-size `extent` for each active wall, for the VTK output.
  std::vector<DriverMesh> meshes(double extent) const;

 private:
  std::vector<Driver> list_;
};

}  // namespace polydem
