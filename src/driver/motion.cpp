#include "driver/motion.hpp"

namespace polydem {

namespace {

Vec3 rotated(const Vec3& p, const Quat& q, const Vec3& pivot) { return pivot + q * (p - pivot); }

}  // namespace

Vec3 servo_velocity(const MotionSettings& m, const Vec3& direction, const Vec3& force, double gain) {
  const double push = -force.dot(direction);  // N, what the driver gives the particles along it
  return gain * (servo_target(m) - push) * direction;
}

void advance(const MotionSettings& m, const Vec3* servo, double t, double dt, DriverState& d) {
  if (m.remove_at && t + dt >= *m.remove_at) d.active = false;
  const bool moving = moving_at(m, t);
  d.velocity = moving ? m.velocity : Vec3::Zero();
  if (moving && servo) d.velocity += *servo;
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

}  // namespace polydem
