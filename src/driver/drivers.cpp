#include "driver/drivers.hpp"

#include <cmath>

#include "driver/surfaces.hpp"
#include "polydem/error.hpp"

namespace polydem {

namespace {

[[noreturn]] void unsupported(const DriverSpec& s, const std::string& key, const std::string& what) {
  throw InputError(input_message(s.loc.file, s.loc.line, key, what + " is not supported yet"));
}

// What this version of the engine cannot simulate stops at start-up, never silently.
void check_supported(const DriverSpec& s) {
  if (s.kind == DriverSpec::Kind::stl) unsupported(s, "stl", "driver '" + s.name + "': an STL mesh driver");
  if (s.kind == DriverSpec::Kind::cylinder && !s.inside)
    unsupported(s, "inside", "driver '" + s.name + "': contact on the outer surface of a cylinder (inside: false)");
  if (s.motion.force || s.motion.pressure)
    unsupported(s, s.motion.force ? "force" : "pressure", "driver '" + s.name + "': a servo (force or pressure) motion");
}

Vec3 rotated(const Vec3& p, const Quat& q, const Vec3& pivot) { return pivot + q * (p - pivot); }

}  // namespace

Drivers::Drivers(const std::vector<DriverSpec>& specs) {
  for (const DriverSpec& s : specs) {
    check_supported(s);
    Driver d;
    d.spec = s;
    d.point = s.point;
    d.normal = s.normal.normalized();
    d.center = s.center;
    d.axis = s.axis.normalized();
    d.pivot = s.motion.rotation_center;
    if (s.kind == DriverSpec::Kind::ball) d.ball_shape = ball_shape(s.name, s.radius);
    list_.push_back(d);
  }
}

void Drivers::advance(double t, double dt) {
  for (Driver& d : list_) {
    const Motion& m = d.spec.motion;
    if (m.remove_at && t + dt >= *m.remove_at) d.active = false;
    const bool moving = t >= m.start && (!m.stop || t < *m.stop);
    d.velocity = moving ? m.velocity : Vec3::Zero();
    d.omega = moving && m.rotates ? Vec3(m.omega * m.rotation_axis) : Vec3::Zero();
    if (d.omega != Vec3::Zero()) {  // exact rotation by |omega| dt about the axis through the pivot
      const Quat q(Eigen::AngleAxisd(d.omega.norm() * dt, d.omega.normalized()));
      d.point = rotated(d.point, q, d.pivot);
      d.center = rotated(d.center, q, d.pivot);
      d.normal = q * d.normal;
      d.axis = q * d.axis;
    }
    d.point += d.velocity * dt;
    d.center += d.velocity * dt;
    d.pivot += d.velocity * dt;
  }
}

Vec3 Drivers::center(std::uint32_t j) const {
  const Driver& d = list_[j];
  return d.spec.kind == DriverSpec::Kind::wall ? d.point : d.center;
}

bool Drivers::near(std::uint32_t j, const Vec3& c, double reach) const {
  const Driver& d = list_[j];
  if (!d.active) return false;
  switch (d.spec.kind) {
    case DriverSpec::Kind::wall: return (c - d.point).dot(d.normal) < reach;
    case DriverSpec::Kind::cylinder: return cylinder_near(d, c, reach);
    case DriverSpec::Kind::ball: return (c - d.center).norm() < d.spec.radius + reach;
    case DriverSpec::Kind::stl: return false;
  }
  return false;
}

void Drivers::candidates(const PosedBody& a, std::uint32_t j, double range, std::vector<FeaturePair>& out) const {
  const Driver& d = list_[j];
  switch (d.spec.kind) {
    case DriverSpec::Kind::wall: return wall_candidates(d, a, range, out);
    case DriverSpec::Kind::cylinder: return cylinder_candidates(d, a, range, out);
    case DriverSpec::Kind::ball: candidate_features(a, ball_pose(d), range, out); return;
    case DriverSpec::Kind::stl: return;
  }
}

bool Drivers::contact(const PosedBody& a, std::uint32_t j, FeaturePair f, double max_gap, ContactPoint& out) const {
  const Driver& d = list_[j];
  if (!d.active) return false;  // removed since the lists were built
  switch (d.spec.kind) {
    case DriverSpec::Kind::wall: return wall_contact(d, a, f, max_gap, out);
    case DriverSpec::Kind::cylinder: return cylinder_contact(d, a, f, max_gap, out);
    case DriverSpec::Kind::ball: return feature_contact(a, ball_pose(d), f, max_gap, out);
    case DriverSpec::Kind::stl: return false;
  }
  return false;
}

}  // namespace polydem
