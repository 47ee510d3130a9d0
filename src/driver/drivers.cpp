#include "driver/drivers.hpp"

#include <algorithm>

#include "output/vtk.hpp"
#include "polydem/error.hpp"

namespace polydem {

namespace {

// Default servo gain: one contact's force error falls by this fraction per step.
constexpr double kServoFraction = 0.1;

// The one switch over kinds: each settings type makes its kind (a cylinder's `inside` picks
// the inside or the post).
DriverKind make_kind(const KindSettings& settings, Placement& at) {
  return std::visit(
      [&](const auto& s) -> DriverKind {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, CylinderSettings>) {
          if (s.inside) return Cylinder(s, at);
          return Post(s, at);
        } else {
          return typename S::Kind(s, at);
        }
      },
      settings);
}

}  // namespace

Drivers::Drivers(const std::vector<DriverSettings>& settings) {
  for (const DriverSettings& s : settings) {
    DriverState d;
    d.pivot = s.motion.rotation_center;
    kind_.push_back(make_kind(s.kind, d));
    state_.push_back(d);
    motion_.push_back(s.motion);
    name_.push_back(s.name);
    loc_.push_back(s.loc);
  }
}

const CylinderShape* Drivers::cylinder(std::uint32_t j) const {
  if (const Cylinder* c = std::get_if<Cylinder>(&kind_[j])) return &c->shape;
  if (const Post* p = std::get_if<Post>(&kind_[j])) return &p->shape;
  return nullptr;
}

Vec3 Drivers::servo_velocity(std::uint32_t j, double dt) const {
  const MotionSettings& m = motion_[j];
  if (!m.gain && !(stiffness_ > 0.0))
    throw InputError(input_message(loc_[j].file, loc_[j].line, "gain",
                                   "driver '" + name_[j] + "': a servo needs the contact stiffness or a gain "
                                   "(e.g. motion: {force: 10, gain: 0.001})"));
  const double gain = m.gain ? *m.gain : kServoFraction / (stiffness_ * std::max(dt, servo_dt_min_));  // m/(N s)
  return polydem::servo_velocity(m, servo_direction(j), state_[j].force, gain);
}

void Drivers::advance(double t, double dt) {
  for (std::uint32_t j = 0; j < state_.size(); ++j) {
    const MotionSettings& m = motion_[j];
    const bool servo = moving_at(m, t) && is_servo(m);
    const Vec3 v = servo ? servo_velocity(j, dt) : Vec3::Zero();  // m/s
    polydem::advance(m, servo ? &v : nullptr, t, dt, state_[j]);
  }
}

std::vector<DriverMesh> Drivers::meshes(const ViewFrame& frame) const {
  std::vector<DriverMesh> out;
  for (std::uint32_t j = 0; j < state_.size(); ++j)
    if (state_[j].active)
      out.push_back(std::visit([&](const auto& k) { return k.drawing(state_[j], name_[j], frame); }, kind_[j]));
  return out;
}

}  // namespace polydem
