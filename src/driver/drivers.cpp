#include "driver/drivers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "driver/mesh.hpp"
#include "driver/surfaces.hpp"
#include "polydem/error.hpp"
#include "shape/point_sources.hpp"

namespace polydem {

namespace {

// Default servo gain: one contact's force error falls by this fraction per step.
constexpr double kServoFraction = 0.1;

Vec3 rotated(const Vec3& p, const Quat& q, const Vec3& pivot) { return pivot + q * (p - pivot); }

// The STL mesh of a driver, in its frame; errors name the scene's `file` key and the STL's line.
std::shared_ptr<const MeshFeatures> load_mesh(const DriverSpec& s) {
  const SourceLoc& at = s.file_loc.file.empty() ? s.loc : s.file_loc;
  auto fail = [&](const std::string& what) {
    throw InputError(input_message(at.file, at.line, "file", "driver '" + s.name + "': " + what));
  };
  try {
    std::size_t skipped = 0;
    auto mesh = std::make_shared<const MeshFeatures>(read_stl(s.file), s.scale, skipped);
    if (skipped > 0)
      std::fprintf(stderr, "warning: %s\n",
                   input_message(at.file, at.line, "file", "driver '" + s.name + "': " + std::to_string(skipped) +
                                 " zero-area triangle(s) of " + s.file + " skipped").c_str());
    return mesh;
  } catch (const InputError& e) {
    fail(e.what());
  } catch (const std::invalid_argument& e) {
    fail(s.file + ": " + e.what());
  }
  return nullptr;
}

}  // namespace

Drivers::Drivers(const std::vector<DriverSpec>& specs) {
  for (const DriverSpec& s : specs) {
    Driver d;
    d.spec = s;
    d.point = s.point;
    d.normal = s.normal.normalized();
    d.center = s.center;
    d.axis = s.axis.normalized();
    d.pivot = s.motion.rotation_center;
    if (s.kind == DriverSpec::Kind::ball) d.ball_shape = sphere_shape(s.name, s.radius);
    if (s.kind == DriverSpec::Kind::cylinder && !s.inside) d.axis_shape = axis_shape(s.name, s.radius);
    if (s.kind == DriverSpec::Kind::stl) {
      d.mesh = load_mesh(s);
      d.center = s.translation;
      d.orientation = s.rotation.normalized();
      d.normal = d.orientation * Vec3::UnitX();  // two orthogonal markers: any turn moves one (list rebuilds)
      d.axis = d.orientation * Vec3::UnitY();
    }
    list_.push_back(d);
  }
}

Vec3 Drivers::servo_direction(std::uint32_t j) const {
  const Driver& d = list_[j];
  switch (d.spec.kind) {
    case DriverSpec::Kind::wall: return d.normal;
    case DriverSpec::Kind::cylinder: return d.axis;
    default: return d.spec.motion.direction.value_or(Vec3::UnitZ()).normalized();
  }
}

double Drivers::servo_target(std::uint32_t j) const {
  const Motion& m = list_[j].spec.motion;
  return m.force ? *m.force : m.pressure.value_or(0.0) * m.area.value_or(0.0);
}

Vec3 Drivers::servo_velocity(const Driver& d, std::uint32_t j, double dt) const {
  const Motion& m = d.spec.motion;
  if (!m.gain && !(stiffness_ > 0.0))
    throw InputError(input_message(d.spec.loc.file, d.spec.loc.line, "gain",
                                   "driver '" + d.spec.name + "': a servo needs the contact stiffness or a gain "
                                   "(e.g. motion: {force: 10, gain: 0.001})"));
  const double gain = m.gain ? *m.gain : kServoFraction / (stiffness_ * std::max(dt, servo_dt_min_));  // m/(N s)
  const Vec3 dir = servo_direction(j);
  const double push = -d.force.dot(dir);  // N, what the driver gives the particles along dir
  return gain * (servo_target(j) - push) * dir;
}

void Drivers::advance(double t, double dt) {
  for (std::uint32_t j = 0; j < list_.size(); ++j) {
    Driver& d = list_[j];
    const Motion& m = d.spec.motion;
    if (m.remove_at && t + dt >= *m.remove_at) d.active = false;
    const bool moving = t >= m.start && (!m.stop || t < *m.stop);
    d.velocity = moving ? m.velocity : Vec3::Zero();
    if (moving && (m.force || m.pressure)) d.velocity += servo_velocity(d, j, dt);
    d.omega = moving && m.rotates ? Vec3(m.omega * m.rotation_axis) : Vec3::Zero();
    if (d.omega != Vec3::Zero()) {  // exact rotation by |omega| dt about the axis through the pivot
      const Quat q(Eigen::AngleAxisd(d.omega.norm() * dt, d.omega.normalized()));
      d.point = rotated(d.point, q, d.pivot);
      d.center = rotated(d.center, q, d.pivot);
      d.normal = q * d.normal;
      d.axis = q * d.axis;
      d.orientation = (q * d.orientation).normalized();
    }
    d.point += d.velocity * dt;
    d.center += d.velocity * dt;
    d.pivot += d.velocity * dt;
  }
}

Vec3 Drivers::center(std::uint32_t j) const {
  const Driver& d = list_[j];
  return d.spec.kind == DriverSpec::Kind::wall ? d.point : d.center;  // stl: where the mesh origin is
}

bool Drivers::near(std::uint32_t j, const Vec3& c, double reach) const {
  const Driver& d = list_[j];
  if (!d.active) return false;
  switch (d.spec.kind) {
    case DriverSpec::Kind::wall: return (c - d.point).dot(d.normal) < reach;
    case DriverSpec::Kind::cylinder: return d.spec.inside ? cylinder_near(d, c, reach) : outer_cylinder_near(d, c, reach);
    case DriverSpec::Kind::ball: return (c - d.center).norm() < d.spec.radius + reach;
    case DriverSpec::Kind::stl: return mesh_near(d, c, reach);
  }
  return false;
}

void Drivers::candidates(const PosedBody& a, std::uint32_t j, double range, std::vector<FeaturePair>& out) const {
  const Driver& d = list_[j];
  switch (d.spec.kind) {
    case DriverSpec::Kind::wall: return wall_candidates(d, a, range, out);
    case DriverSpec::Kind::cylinder:
      return d.spec.inside ? cylinder_candidates(d, a, range, out) : outer_cylinder_candidates(d, a, range, out);
    case DriverSpec::Kind::ball: candidate_features(a, ball_pose(d), range, out); return;
    case DriverSpec::Kind::stl: return mesh_candidates(d, a, range, out);
  }
}

bool Drivers::contact(const PosedBody& a, std::uint32_t j, FeaturePair f, double max_gap, ContactPoint& out) const {
  const Driver& d = list_[j];
  if (!d.active) return false;  // removed since the lists were built
  switch (d.spec.kind) {
    case DriverSpec::Kind::wall: return wall_contact(d, a, f, max_gap, out);
    case DriverSpec::Kind::cylinder:
      return d.spec.inside ? cylinder_contact(d, a, f, max_gap, out) : outer_cylinder_contact(d, a, f, max_gap, out);
    case DriverSpec::Kind::ball: return feature_contact(a, ball_pose(d), f, max_gap, out);
    case DriverSpec::Kind::stl: return mesh_contact(d, a, f, max_gap, out);
  }
  return false;
}

}  // namespace polydem
