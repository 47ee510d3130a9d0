#pragma once
// Drivers: rigid boundaries the particles touch, one kind a file (wall.hpp, cylinder.hpp,
// post.hpp, ball.hpp, mesh_driver.hpp), each fixed or moving (motion.hpp). A kind is a small
// immutable type with the same few calls (reach test, candidate features, the contact of one
// feature pair, its drawing) on the driver's placement; Drivers holds one std::variant of the
// kinds per driver and visits it, so the per-contact call is a jump, not a virtual call.
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "driver/driver_settings.hpp"
#include "driver/post.hpp"

namespace polydem {

using DriverKind = std::variant<Wall, Cylinder, Post, Ball, MeshDriver>;

class Drivers {
 public:
  // The factory: makes each driver's kind from its settings (reads the STL meshes; throws
  // InputError, file, line and key, for a missing or broken one).
  explicit Drivers(const std::vector<DriverSettings>& settings);

  // kn (N/m) of config_driver and the normal contact's critical step (s): the default servo
  // gain is 0.1 / (kn max(dt, 0.1 critical)), so a small dt does not make the servo faster than
  // the particles it presses can follow (at 0.07 x critical the lid of a sphere rattles).
  void set_contact_stiffness(double kn, double critical_step = 0.0) { stiffness_ = kn; servo_dt_min_ = 0.1 * critical_step; }

  std::size_t size() const { return state_.size(); }
  bool empty() const { return state_.empty(); }
  const DriverState& operator[](std::size_t j) const { return state_[j]; }
  DriverState& operator[](std::size_t j) { return state_[j]; }
  const DriverKind& kind(std::uint32_t j) const { return kind_[j]; }
  const std::string& name(std::uint32_t j) const { return name_[j]; }
  const MotionSettings& motion(std::uint32_t j) const { return motion_[j]; }
  // The radius and length of a cylinder driver (inside or a post); null for another kind.
  const CylinderShape* cylinder(std::uint32_t j) const;

  // Applies the motions from time t to t + dt (removal, servo, translation, rotation).
  void advance(double t, double dt);
  // Unit direction along which driver j's servo holds its force.
  Vec3 servo_direction(std::uint32_t j) const {
    return std::visit([&](const auto& k) { return k.servo_direction(state_[j], motion_[j]); }, kind_[j]);
  }
  // N, the force driver j's servo holds (force, or pressure x area).
  double servo_target(std::uint32_t j) const { return polydem::servo_target(motion_[j]); }

  // True when a body whose bounding sphere of radius `reach` is centred at `center` may touch driver j.
  bool near(std::uint32_t j, const Vec3& center, double reach) const {
    return state_[j].active && std::visit([&](const auto& k) { return k.near(state_[j], center, reach); }, kind_[j]);
  }
  // True when a sphere of `radius` (m) at `center` overlaps driver j or touches it (placement).
  bool overlaps(std::uint32_t j, const Vec3& center, double radius) const {
    return state_[j].active && std::visit([&](const auto& k) { return k.overlaps(state_[j], center, radius); }, kind_[j]);
  }
  // Feature pairs (feature of a, feature of the driver) within rA + range of driver j.
  void candidates(const PosedBody& a, std::uint32_t j, double range, std::vector<FeaturePair>& out) const {
    std::visit([&](const auto& k) { k.candidates(state_[j], a, range, out); }, kind_[j]);
  }
  // One feature pair; normal from the driver to the body, same conventions as feature_contact.
  bool contact(const PosedBody& a, std::uint32_t j, FeaturePair f, double max_gap, ContactPoint& out) const {
    if (!state_[j].active) return false;  // removed since the lists were built
    return std::visit([&](const auto& k) { return k.contact(state_[j], a, f, max_gap, out); }, kind_[j]);
  }
  // m, the rounding of driver j's core (a ball's or a post's radius; 0 for a surface).
  double rounding(std::uint32_t j) const {
    return std::visit([](const auto& k) { return k.rounding(); }, kind_[j]);
  }
  // Adds what driver j occupies to `box` (m): a wall its point, a finite cylinder its ends.
  void bounds(std::uint32_t j, Box3& box) const {
    std::visit([&](const auto& k) { k.bounds(state_[j], box); }, kind_[j]);
  }
  bool is_wall(std::uint32_t j) const { return std::holds_alternative<Wall>(kind_[j]); }
  // m, the Hertz contact radius R* of a body rounded by r_body (m) on driver j's surface.
  double r_star(std::uint32_t j, double r_body) const {
    return std::visit([&](const auto& k) { return k.r_star(r_body); }, kind_[j]);
  }

  // m, the point driver j's torque is about (wall: its point; mesh: where its origin is).
  Vec3 center(std::uint32_t j) const {
    return std::visit([&](const auto& k) { return k.reference(state_[j]); }, kind_[j]);
  }
  Vec3 velocity_at(std::uint32_t j, const Vec3& p) const {
    const DriverState& d = state_[j];
    return d.velocity + d.omega.cross(p - d.pivot);
  }
  Vec3 angular_velocity(std::uint32_t j) const { return state_[j].omega; }

  // Surface meshes of the active drivers for the VTK output; walls and infinite cylinders
  // are cut to the frame (output/frame.hpp).
  std::vector<DriverMesh> meshes(const ViewFrame& frame) const;

 private:
  Vec3 servo_velocity(std::uint32_t j, double dt) const;

  std::vector<DriverState> state_;
  std::vector<DriverKind> kind_;
  std::vector<MotionSettings> motion_;
  std::vector<std::string> name_;
  std::vector<SourceLoc> loc_;
  double stiffness_ = 0.0;     // N/m, for the default servo gain
  double servo_dt_min_ = 0.0;  // s, the default gain reads max(dt, this)
};

}  // namespace polydem
