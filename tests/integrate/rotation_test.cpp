// Rotation: exact flows of isotropic bodies, constant torque, second-order convergence of the
// splitting against an RK4 reference, and the frame conventions of the helpers.
#include <catch2/catch.hpp>

#include "integrate/free_rotor.hpp"
#include "integrate/integrate.hpp"

using namespace polydem;

namespace {

// Rotation angle (rad) between two unit quaternions, accurate for small angles.
double angle_between(const Quat& a, const Quat& b) {
  const Quat d = a.conjugate() * b;
  return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

Bodies one_body(const Vec3& inertia, const Quat& q0, const Vec3& w0_world) {
  Bodies b;
  b.resize(1);
  b.mass[0] = 1.0;
  b.inertia[0] = inertia;
  b.orientation[0] = q0.normalized();
  set_angular_velocity(b, 0, w0_world);
  return b;
}

// Torque-free steps (forces and torques stay zero).
void free_steps(Bodies& b, double dt, int steps) {
  for (int n = 0; n < steps; ++n) {
    kick(b, 0.5 * dt);
    drift(b, dt);
    kick(b, 0.5 * dt);
  }
}

// Reference rigid-body flow by classical RK4 on (q, w_body): dq/dt = q (0, w_body) / 2 and
// Euler's equations I1 dw1/dt = (I2 - I3) w2 w3 (and cyclic), Landau & Lifshitz Mechanics 36.5.
struct RotorState {
  Eigen::Vector4d q;  // (x, y, z, w) coefficients
  Vec3 w;             // rad/s, body frame
};

RotorState rotor_rate(const RotorState& s, const Vec3& inertia) {
  Quat q(s.q[3], s.q[0], s.q[1], s.q[2]);
  const Quat dq = q * Quat(0.0, s.w.x(), s.w.y(), s.w.z());
  const Vec3 dw((inertia.y() - inertia.z()) * s.w.y() * s.w.z() / inertia.x(),
                (inertia.z() - inertia.x()) * s.w.z() * s.w.x() / inertia.y(),
                (inertia.x() - inertia.y()) * s.w.x() * s.w.y() / inertia.z());
  return {0.5 * dq.coeffs(), dw};
}

Quat rk4_orientation(const Quat& q0, const Vec3& w0_body, const Vec3& inertia, double t_end,
                     int steps) {
  const double h = t_end / steps;
  RotorState s{q0.coeffs(), w0_body};
  auto axpy = [](const RotorState& a, double c, const RotorState& d) {
    return RotorState{a.q + c * d.q, a.w + c * d.w};
  };
  for (int n = 0; n < steps; ++n) {
    const RotorState k1 = rotor_rate(s, inertia);
    const RotorState k2 = rotor_rate(axpy(s, 0.5 * h, k1), inertia);
    const RotorState k3 = rotor_rate(axpy(s, 0.5 * h, k2), inertia);
    const RotorState k4 = rotor_rate(axpy(s, h, k3), inertia);
    s.q += h / 6.0 * (k1.q + 2.0 * k2.q + 2.0 * k3.q + k4.q);
    s.w += h / 6.0 * (k1.w + 2.0 * k2.w + 2.0 * k3.w + k4.w);
  }
  return Quat(s.q[3], s.q[0], s.q[1], s.q[2]).normalized();
}

}  // namespace

TEST_CASE("an isotropic body at constant w turns by the exact rotation", "[integrate]") {
  const Quat q0 = Quat(0.3, -0.5, 0.7, 0.2).normalized();
  const Vec3 w(1.3, -0.7, 2.1);  // rad/s, world
  const double dt = 1e-3;
  const int steps = 10000;
  Bodies b = one_body(Vec3::Constant(0.4), q0, w);
  free_steps(b, dt, steps);
  const double t = dt * steps;
  // Constant world w: R(t) = rot(w/|w|, |w| t) R0.
  const Quat q_exact = Quat(Eigen::AngleAxisd(w.norm() * t, w.normalized())) * q0;
  CHECK(angle_between(b.orientation[0], q_exact) < 1e-11);
  CHECK((b.angular_velocity[0] - w).norm() < 1e-13);
  CHECK(std::abs(b.orientation[0].norm() - 1.0) < 1e-14);
}

TEST_CASE("constant torque on a sphere: w grows as w0 + tau t / I", "[integrate]") {
  const double inertia = 0.02;     // kg m^2
  const Vec3 tau(0.1, -0.05, 0.2);  // N m, world, not parallel to w0
  const Vec3 w0(3.0, 1.0, -2.0);    // rad/s
  const double dt = 1e-3;
  const int steps = 5000;
  Bodies b = one_body(Vec3::Constant(inertia), Quat(0.9, 0.1, -0.3, 0.2), w0);
  for (int n = 0; n < steps; ++n) {
    b.torque[0] = tau;
    kick(b, 0.5 * dt);
    drift(b, dt);
    b.torque[0] = tau;
    kick(b, 0.5 * dt);
  }
  const Vec3 w_exact = w0 + tau * (dt * steps) / inertia;
  // Round-off only: L_world = I w0 + tau t exactly in the scheme, rotations add ~1e-13.
  CHECK((b.angular_velocity[0] - w_exact).norm() < 1e-10 * w_exact.norm());
}

TEST_CASE("orientation error of the splitting is second order in dt", "[integrate]") {
  const Vec3 inertia(1.0, 2.0, 3.0);  // kg m^2
  const Quat q0 = Quat(0.8, 0.2, -0.4, 0.1).normalized();
  const Vec3 w0_body(0.6, 1.0, 0.8);  // rad/s
  const double t_end = 2.0;           // s
  const Quat q_ref = rk4_orientation(q0, w0_body, inertia, t_end, 200000);
  double errors[3];
  const int step_counts[3] = {100, 200, 400};
  for (int k = 0; k < 3; ++k) {
    Bodies b = one_body(inertia, q0, q0 * w0_body);
    free_steps(b, t_end / step_counts[k], step_counts[k]);
    errors[k] = angle_between(b.orientation[0], q_ref);
  }
  INFO("errors " << errors[0] << " " << errors[1] << " " << errors[2]);
  // Global error C dt^2: halving dt divides it by 4; 10% covers the O(dt^4) remainder.
  CHECK(errors[0] / errors[1] == Approx(4.0).epsilon(0.1));
  CHECK(errors[1] / errors[2] == Approx(4.0).epsilon(0.1));
}

TEST_CASE("set_angular_velocity and update_angular_velocity are inverse", "[integrate]") {
  const Vec3 w(0.4, -1.5, 0.9);  // rad/s, world
  Bodies b = one_body(Vec3(1.0, 2.0, 3.0), Quat(0.5, 0.5, -0.1, 0.7), w);
  // L_body = I (R^T w) and the world angular momentum R L_body = R I R^T w.
  const Mat3 r = b.orientation[0].toRotationMatrix();
  const Mat3 inertia_world = r * Vec3(1.0, 2.0, 3.0).asDiagonal() * r.transpose();
  CHECK((r * b.angular_momentum[0] - inertia_world * w).norm() < 1e-14);
  b.angular_velocity[0].setZero();
  update_angular_velocity(b);
  CHECK((b.angular_velocity[0] - w).norm() < 1e-14);
}

TEST_CASE("isotropic inertia is detected within 1e-12 relative", "[integrate]") {
  CHECK(is_isotropic(Vec3(2.0, 2.0 * (1.0 + 1e-13), 2.0)));
  CHECK_FALSE(is_isotropic(Vec3(2.0, 2.0 * (1.0 + 1e-9), 2.0)));
  Bodies b;
  b.resize(3);
  b.inertia = {Vec3::Constant(1.0), Vec3(1.0, 2.0, 3.0), Vec3::Constant(5.0)};
  const RotorGroups groups = group_rotors(b);
  CHECK(groups.isotropic == std::vector<std::size_t>{0, 2});
  CHECK(groups.asymmetric == std::vector<std::size_t>{1});
}

TEST_CASE("the small-angle series give libm's sine and cosine to round-off", "[integrate]") {
  double worst = 0.0;  // relative error, over [-kSeriesAngle, kSeriesAngle]
  for (int k = -1000; k <= 1000; ++k) {
    const double x = free_rotor::kSeriesAngle * k / 1000.0;  // rad
    const double x2 = x * x;
    worst = std::max(worst, std::abs(free_rotor::cos_series(x2) - std::cos(x)));
    if (x != 0.0) worst = std::max(worst, std::abs(x * free_rotor::sin_over_x_series(x2) - std::sin(x)) / std::abs(std::sin(x)));
  }
  CHECK(worst <= 2.3e-16);  // one ulp of 1, whatever the last bit libm rounds to
  CHECK(free_rotor::sin_over_x_series(0.0) == 1.0);  // a body at rest: no division by w
}
