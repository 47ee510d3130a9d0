#pragma once
// An independent reference for a rounded body landing on one vertex on a frictionless floor:
// the rigid body (isotropic inertia, as a cube's) and the engine's clamped spring-dashpot at that
// vertex (nu on the body's mass m, the default; or on the vertex's own effective mass as it turns,
// damping_mass: contact), integrated by RK4 with a tiny step from the touch. The rigid-body
// impulse (test_cube_landing.cpp) ignores the turn during the contact, 5.6e-4 of the contact
// point's rebound (4.5e-4 with the contact's mass): this keeps it. Converged to 1e-10 of the
// rebound at t_c/20000 (t_c/5000 to t_c/80000 agree to 6e-9); with the inertia taken infinite it
// gives the closed form's en to 1e-14. Used by the accuracy slice and sweep.
#include <cmath>

#include "validation.hpp"

namespace polydem::validation {

struct CornerLanding {
  double m, inertia;        // kg, kg m^2 (isotropic)
  double kn, nu;            // N/m, N s/m (the pair's mass: fixed)
  Vec3 vertex;              // m, the touching vertex from the centre at the touch (world frame)
  double alpha_contact = 0.0;  // -, > 0: nu = 2 alpha sqrt(kn m*) on the vertex's m* now (damping_mass: contact)

  struct State {
    double z, vz;       // m, m/s: the centre's height change since the touch and its velocity
    Quat q;             // the turn since the touch
    Vec3 w;             // rad/s
  };
  // N, the floor's force: the vertex's overlap x = -(z + (q r - r).z) at rate -(vz + (w x q r).z).
  double force(const State& s) const {
    const Vec3 r = s.q * vertex;
    const double x = -(s.z + r.z() - vertex.z()), rate = -(s.vz + s.w.cross(r).z());
    if (x < 0.0 || (x == 0.0 && rate <= 0.0)) return 0.0;
    return std::max(kn * x + dashpot(r) * rate, 0.0);
  }
  // N s/m, the dashpot with the lever r (m) from the centre to the vertex now.
  double dashpot(const Vec3& r) const {
    if (alpha_contact <= 0.0) return nu;
    return 2.0 * alpha_contact * std::sqrt(kn * vertex_mass(m, inertia, r));
  }
  struct Rate {
    double z, vz;
    Eigen::Vector4d q;
    Vec3 w;
  };
  Rate rate(const State& s) const {
    const double f = force(s);
    const Quat dq = Quat(0.0, s.w.x(), s.w.y(), s.w.z()) * s.q;  // dq/dt = (0, w) q / 2
    return {s.vz, f / m, 0.5 * dq.coeffs(), (s.q * vertex).cross(Vec3(0.0, 0.0, f)) / inertia};
  }
  static State add(const State& s, const Rate& k, double h) {
    Quat q;
    q.coeffs() = s.q.coeffs() + h * k.q;
    return {s.z + h * k.z, s.vz + h * k.vz, q, s.w + h * k.w};
  }
  // -, the vertex's normal velocity after the impact over v0 (> 0: rebound), taken with the lever
  // at the touch as the engine's measure does; from the touch at v0 (m/s) over `span` (s, past
  // the release) in steps h (s). The force starts at t = 0 and ends without a jump (the clamp).
  double rebound(double v0, double span, double h) const {
    State s{0.0, -v0, Quat::Identity(), Vec3::Zero()};
    const long steps = std::lround(span / h);
    for (long n = 0; n < steps; ++n) {
      const Rate k1 = rate(s), k2 = rate(add(s, k1, 0.5 * h)), k3 = rate(add(s, k2, 0.5 * h)), k4 = rate(add(s, k3, h));
      Rate sum{k1.z + 2 * k2.z + 2 * k3.z + k4.z, k1.vz + 2 * k2.vz + 2 * k3.vz + k4.vz,
               k1.q + 2 * k2.q + 2 * k3.q + k4.q, k1.w + 2 * k2.w + 2 * k3.w + k4.w};
      s = add(s, sum, h / 6.0);
      s.q.normalize();
    }
    return (s.vz + s.w.cross(vertex).z()) / v0;
  }
};

}  // namespace polydem::validation
