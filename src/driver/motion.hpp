#pragma once
// How a driver moves, whatever its kind: constant translation, rotation about an axis, removal
// at a time, start and stop times, and a servo on a force.
//
// Servo (motion force / pressure): a first-order velocity servo along the servo direction d
// (wall: its normal; cylinder: its axis; ball, mesh: motion.direction),
//   v = velocity + gain (F - P) d,   P = -(force of the particles on the driver) . d,
// P being the push the driver gives the particles along d, measured at the previous step. The
// driver acts as a dashpot of coefficient 1/gain holding the load F: passive, and stable
// while k gain dt < 2 for the stiffness k of its contacts. Default gain 0.1 / (kn dt), dt at
// least 0.1 x the critical step (Drivers::set_contact_stiffness): one contact's force error
// falls by 10% a step; stable with up to 20 contacts in parallel on the driver (give
// motion.gain for more).
#include <optional>

#include "polydem/math.hpp"

namespace polydem {

struct MotionSettings {           // the `motion:` block; fixed when all are unset
  Vec3 velocity = Vec3::Zero();   // m/s, constant translation
  bool rotates = false;
  Vec3 rotation_axis = Vec3::UnitZ();     // unit
  Vec3 rotation_center = Vec3::Zero();    // m
  double omega = 0.0;             // rad/s
  std::optional<double> force;    // N along the driver normal/axis (servo)
  std::optional<double> pressure; // Pa (servo, force = pressure x area)
  std::optional<double> area;     // m^2, the area the servo pressure acts on
  std::optional<double> gain;     // m/(N s), servo speed per newton of force error; empty: 0.1 / (kn dt)
  std::optional<Vec3> direction;  // unit, servo direction of a ball or mesh (wall: normal; cylinder: axis)
  std::optional<double> remove_at;  // s, the driver disappears at this time
  double start = 0.0;             // s, motion begins
  std::optional<double> stop;     // s, motion ends
};

// Where a driver is. The motion moves every field alike (points rotate about the pivot and
// translate, directions rotate) and the rebuild trigger compares them all, whichever its kind
// reads: wall point and normal; cylinder centre and axis; ball centre; mesh centre (where its
// origin is) and orientation, with normal and axis as two orthogonal turn markers.
struct Placement {
  Vec3 point = Vec3::Zero();       // m
  Vec3 normal = Vec3::UnitZ();     // unit
  Vec3 center = Vec3::Zero();      // m
  Vec3 axis = Vec3::UnitZ();       // unit
  Quat orientation = Quat::Identity();  // mesh frame -> world
};

// The moving state of a driver (checkpointed): its placement, motion and reactions.
struct DriverState : Placement {
  bool active = true;              // false once removed (remove_at)
  Vec3 velocity = Vec3::Zero();    // m/s, current translation velocity
  Vec3 omega = Vec3::Zero();       // rad/s, current angular velocity about `pivot`
  Vec3 pivot = Vec3::Zero();       // m, a point on the rotation axis
  Vec3 force = Vec3::Zero();       // N, exerted by the particles this step
  Vec3 torque = Vec3::Zero();      // N m, about the driver's reference point, exerted by the particles this step
};

// True when the motion runs at time t (s): after `start`, before `stop`.
inline bool moving_at(const MotionSettings& m, double t) { return t >= m.start && (!m.stop || t < *m.stop); }
inline bool is_servo(const MotionSettings& m) { return m.force || m.pressure; }
// N, the force a servo holds (force, or pressure x area).
inline double servo_target(const MotionSettings& m) {
  return m.force ? *m.force : m.pressure.value_or(0.0) * m.area.value_or(0.0);
}
// Unit servo direction of a kind with no direction of its own (ball, mesh).
inline Vec3 given_servo_direction(const MotionSettings& m) { return m.direction.value_or(Vec3::UnitZ()).normalized(); }

// m/s, the servo's velocity along `direction` (unit) for the particles' `force` (N) on the
// driver at the last step and a gain in m/(N s).
Vec3 servo_velocity(const MotionSettings& m, const Vec3& direction, const Vec3& force, double gain);

// Moves d from t to t + dt: removal, velocity (plus `servo`, m/s, when given), exact rotation
// about the pivot, translation.
void advance(const MotionSettings& m, const Vec3* servo, double t, double dt, DriverState& d);

}  // namespace polydem
