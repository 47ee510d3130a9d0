#pragma once
// Drivers: rigid boundaries the particles touch (walls, cylinders seen from inside or outside,
// balls, STL meshes), fixed or moving (constant velocity, rotation about an axis, removal at a
// time, servo on a force). Each kind gives candidate features and contacts through the same
// interface as a body partner.
//
// Servo (motion force / pressure): a first-order velocity servo along the servo direction d
// (wall: its normal; cylinder: its axis; ball, stl: motion.direction),
//   v = velocity + gain (F - P) d,   P = -(force of the particles on the driver) . d,
// P being the push the driver gives the particles along d, measured at the previous step. The
// driver acts as a dashpot of coefficient 1/gain holding the load F: passive, and stable
// while k gain dt < 2 for the stiffness k of its contacts. Default gain 0.1 / (kn dt), dt at
// least 0.1 x the critical step (set_contact_stiffness): one contact's force error falls by 10% a step; stable with up to
// 20 contacts in parallel on the driver (give motion.gain for more).
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/features.hpp"
#include "polydem/scene.hpp"

namespace polydem {

struct DriverMesh;
struct ViewFrame;
class MeshFeatures;

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
  Quat orientation = Quat::Identity();  // stl: mesh frame -> world (centre: where the mesh origin is)
  Shape ball_shape;                // ball: a one-vertex shape, so body-ball contacts reuse the body kernels
  Shape axis_shape;                // outer cylinder: its axis segment, radius R
  std::shared_ptr<const MeshFeatures> mesh;  // stl: shared, drivers are copied at every list rebuild
};

class Drivers {
 public:
  // Reads the STL meshes; throws InputError (file, line, key) for a missing or broken one.
  explicit Drivers(const std::vector<DriverSpec>& specs);

  // N/m, kn of config_driver: sets the default servo gain.
  // kn (N/m) and the normal contact's critical step (s): the default servo gain is
  // 0.1 / (kn max(dt, 0.1 critical)), so a small dt does not make the servo faster than the
  // particles it presses can follow (at 0.07 x critical the lid of a sphere rattles).
  void set_contact_stiffness(double kn, double critical_step = 0.0) { stiffness_ = kn; servo_dt_min_ = 0.1 * critical_step; }

  std::size_t size() const { return list_.size(); }
  bool empty() const { return list_.empty(); }
  const Driver& operator[](std::size_t j) const { return list_[j]; }
  Driver& operator[](std::size_t j) { return list_[j]; }

  // Applies the motions from time t to t + dt (removal, servo, translation, rotation).
  void advance(double t, double dt);
  // Unit direction along which driver j's servo holds its force.
  Vec3 servo_direction(std::uint32_t j) const;
  // N, the force driver j's servo holds (force, or pressure x area).
  double servo_target(std::uint32_t j) const;

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

  // Surface meshes of the active drivers for the VTK output; walls and infinite cylinders
  // are cut to the frame (output/frame.hpp).
  std::vector<DriverMesh> meshes(const ViewFrame& frame) const;

 private:
  Vec3 servo_velocity(const Driver& d, std::uint32_t j, double dt) const;

  std::vector<Driver> list_;
  double stiffness_ = 0.0;  // N/m, for the default servo gain
  double servo_dt_min_ = 0.0;  // s, the default gain reads max(dt, this)
};

}  // namespace polydem
