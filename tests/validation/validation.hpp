#pragma once
// Shared pieces of the validation suite: closed forms of the clamped linear spring-dashpot,
// the result table every case prints, and impact runners on the Simulation API.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../sim/sim_fixtures.hpp"

namespace polydem::validation {

// Prints one row of the validation table and returns the error |polydem - answer| / scale:
// relative by default; quantities that may cross 0 pass the scale of the problem instead.
inline double table_row(const char* name, const char* quantity, double answer, double measured, double scale = 0.0) {
  const double error = std::abs(measured - answer) / (scale > 0.0 ? scale : std::abs(answer));
  std::printf("| %-34s | %-18s | %13.6g | %13.6g | %9.2e |\n", name, quantity, answer, measured, error);
  return error;
}

// Binary impact of the linear spring-dashpot with the no-pull clamp, in closed form.
// m x'' = -(kn x + nu x') with x(0) = 0, x'(0) = v0, nu = 2 z sqrt(kn m), w0 = sqrt(kn/m):
//   z < 1: x = v0/wd e^{-z w0 t} sin(wd t), wd = w0 sqrt(1 - z^2);
//   z > 1: x = v0/(2 s w0) (e^{-(z-s) w0 t} - e^{-(z+s) w0 t}), s = sqrt(z^2 - 1).
// The clamp releases when kn x + nu x' = 0, i.e. x + (2 z/w0) x' = 0:
//   z < 1: substituting x gives (1 - 2z^2) sin(wd t) = -2 z sqrt(1 - z^2) cos(wd t), i.e.
//          tan(wd t) = tan(2 phi) with cos(phi) = z: wd t_c = 2 acos(z);
//   z > 1: e^{2 s w0 t} = (2z^2 + 2zs - 1)/(2z^2 - 2zs - 1) = ((z+s)/(z-s))^2, w0 t_c = 2 acosh(z)/s.
// Then e = -x'(t_c)/v0, x_max at x' = 0 (half of t_c in both regimes: wd t = acos z, resp.
// w0 t = acosh(z)/s), and the force F = kn x + nu x' = -m x'' peaks either at t = 0
// (F = 2 z w0 m v0) or where x''' = 0: with x = Im(v0/wd e^{lambda t}), arg(lambda) = pi - acos z,
// Im(lambda^3 e^{i wd t}) = 0 gives wd t = 3 acos(z) - pi, inside the contact when z < 1/2.
struct ClampedImpact {
  double z, w0, v0, m;  // -, rad/s, m/s, kg

  double x(double t) const {
    if (z < 1.0) {
      const double wd = w0 * std::sqrt(1.0 - z * z);
      return v0 / wd * std::exp(-z * w0 * t) * std::sin(wd * t);
    }
    const double s = std::sqrt(z * z - 1.0);
    return v0 / (2.0 * s * w0) * (std::exp(-(z - s) * w0 * t) - std::exp(-(z + s) * w0 * t));
  }
  double v(double t) const {
    if (z < 1.0) {
      const double s = std::sqrt(1.0 - z * z), wd = w0 * s;
      return v0 * std::exp(-z * w0 * t) * (std::cos(wd * t) - z / s * std::sin(wd * t));
    }
    const double s = std::sqrt(z * z - 1.0);
    return v0 / (2.0 * s) * (-(z - s) * std::exp(-(z - s) * w0 * t) + (z + s) * std::exp(-(z + s) * w0 * t));
  }
  double force(double t) const { return m * w0 * w0 * x(t) + 2.0 * z * w0 * m * v(t); }  // N
  double release_time() const {  // s, t_c
    return z < 1.0 ? 2.0 * std::acos(z) / (w0 * std::sqrt(1.0 - z * z))
                   : 2.0 * std::acosh(z) / (w0 * std::sqrt(z * z - 1.0));
  }
  double restitution() const { return -v(release_time()) / v0; }
  double max_overlap() const { return x(0.5 * release_time()); }
  double max_force() const {
    double f = force(0.0);
    if (z < 0.5) f = std::max(f, force((3.0 * std::acos(z) - kPi) / (w0 * std::sqrt(1.0 - z * z))));
    return f;
  }
};

// kg, the effective mass of a body (mass m, isotropic inertia) at a point r (m) from its centre
// along the floor's normal z: 1 / (1/m + |r x z|^2 / I).
inline double vertex_mass(double m, double inertia, const Vec3& r) {
  return 1.0 / (1.0 / m + r.cross(Vec3::UnitZ()).squaredNorm() / inertia);
}

// What a run of the engine measured over one impact.
struct MeasuredImpact {
  double restitution = 0, duration = 0, max_overlap = 0, max_force = 0;  // -, s, m, N
  Vec3 velocity = Vec3::Zero(), angular_velocity = Vec3::Zero();         // of body 0 after it
};

// Steps until contact has come and gone. `gap` gives the current gap (m), `force` the contact
// force (N), `vn` the separation speed (m/s); duration counts the steps with a force. The
// peak force skips the first step with a force: it carries the impulse of the part of the step
// before the touch (contact/law/second_order.hpp), not a sample of the force.
template <class Gap, class Force, class Vn>
MeasuredImpact run_impact(Simulation& sim, double v0, Gap gap, Force force, Vn vn, long max_steps = 2000000) {
  MeasuredImpact r;
  bool touched = false;
  long force_steps = 0;
  for (long s = 0; s < max_steps; ++s) {
    sim.step();
    const std::size_t contacts = sim.engine().stats().contacts;
    touched = touched || contacts > 0;
    r.max_overlap = std::max(r.max_overlap, -gap());
    const double f = force();
    if (force_steps > 0) r.max_force = std::max(r.max_force, f);
    force_steps += f > 0.0;
    if (touched && contacts == 0) {
      r.restitution = vn() / v0;
      r.duration = double(force_steps) * sim.dt();
      r.velocity = sim.bodies.velocity[0];
      r.angular_velocity = sim.bodies.angular_velocity[0];
      return r;
    }
  }
  r.restitution = -1.0;  // never ended: every check on it fails
  return r;
}

// Flip period of a free asymmetric top with principal moments i (ascending), energy e and
// |L|^2 = l2, from the elliptic-function solution of Euler's equations (Landau & Lifshitz,
// Mechanics, 37.10-37.12): for l2 > 2 e I2, T = 4 K(k) sqrt(I1 I2 I3 / ((I3 - I2)(l2 - 2 e I1))),
// k^2 = (I2 - I1)(2 e I3 - l2) / ((I3 - I2)(l2 - 2 e I1)); for l2 < 2 e I2 swap I1 and I3.
// K(k) = pi / (2 AGM(1, sqrt(1 - k^2))) (Abramowitz & Stegun 17.6.1 with 17.6.2).
inline double elliptic_k(double k2) {
  double a = 1.0, g = std::sqrt(1.0 - k2);
  for (int it = 0; it < 40 && std::abs(a - g) > 1e-16 * a; ++it) {
    const double next = 0.5 * (a + g);
    g = std::sqrt(a * g);
    a = next;
  }
  return kPi / (2.0 * a);
}

inline double flip_period(Vec3 i, double e, double l2) {  // i sorted ascending, kg m^2; e J; l2 (kg m^2/s)^2
  if (l2 < 2.0 * e * i[1]) std::swap(i[0], i[2]);
  const double k2 = (i[1] - i[0]) * (2.0 * e * i[2] - l2) / ((i[2] - i[1]) * (l2 - 2.0 * e * i[0]));
  return 4.0 * elliptic_k(k2) * std::sqrt(i[0] * i[1] * i[2] / ((i[2] - i[1]) * (l2 - 2.0 * e * i[0])));
}

// A rounded box: the unit cube's topology with its vertices stretched.
inline Shape box_shape(const Vec3& sides, double r) {
  Shape s = test::cube_shape(1.0, r);
  s.name = "box";
  for (Vec3& v : s.vertices) v = v.cwiseProduct(sides);
  compute_mass_properties(s);
  return s;
}

}  // namespace polydem::validation
