#pragma once
// An independent reference for a rounded body landing on one vertex on a frictionless floor:
// the rigid body (isotropic inertia, as a cube's) and the engine's clamped spring-dashpot at that
// vertex (nu on the body's mass m, the default; or on the vertex's own effective mass as it turns,
// damping_mass: contact), integrated by RK4 with a tiny step from the touch. The rigid-body
// impulse (test_cube_landing.cpp) ignores the turn during the contact, 5.6e-4 of the contact
// point's rebound (4.5e-4 with the contact's mass): this keeps it. Converged to 1e-10 of the
// rebound at t_c/20000 (t_c/5000 to t_c/80000 agree to 6e-9); with the inertia taken infinite it
// gives the closed form's en to 1e-14. Used by the accuracy slice and sweep.
// Several vertices (a face landing tilted): one patch, each overlapping vertex's clamped
// spring-dashpot scaled by its patch weight x_k / sum(x) (pair_kernel.hpp, band 0), so a vertex
// that joins mid-contact enters at weight 0 (the nu on m only).
#include <algorithm>
#include <cmath>
#include <vector>

#include "validation.hpp"

namespace polydem::validation {

struct CornerLanding {
  double m, inertia;        // kg, kg m^2 (isotropic)
  double kn, nu;            // N/m, N s/m (the pair's mass: fixed)
  std::vector<Vec3> vertices;  // m, from the centre at the touch (world frame): the lowest touches at t = 0
  double alpha_contact = 0.0;  // -, > 0: nu = 2 alpha sqrt(kn m*) on the vertex's m* now (damping_mass: contact)

  struct State {
    double z, vz;       // m, m/s: the centre's height change since the touch and its velocity
    Quat q;             // the turn since the touch
    Vec3 w;             // rad/s
  };
  // N and N m about the centre, the floor's: vertex k's overlap x = -(z + (q r_k).z - floor) at
  // rate -(vz + (w x q r_k).z), its force w_k max(kn x + nu rate, 0); w_k = x / sum(x), or
  // shared by the vertices touching at x = 0 when none overlaps (the start: the dashpot's jump).
  struct Load {
    double force;
    Vec3 torque;
  };
  Load load(const State& s) const {
    double floor = 1e300, total = 0.0;  // m
    for (const Vec3& v : vertices) floor = std::min(floor, v.z());
    int at_zero = 0;
    for (const Vec3& v : vertices) {
      const double x = -(s.z + (s.q * v).z() - floor);
      total += std::max(x, 0.0);
      at_zero += x == 0.0;
    }
    Load out{0.0, Vec3::Zero()};
    for (const Vec3& v : vertices) {
      const Vec3 r = s.q * v;
      const double x = -(s.z + r.z() - floor), rate = -(s.vz + s.w.cross(r).z());
      if (x < 0.0 || (x == 0.0 && rate <= 0.0)) continue;
      const double weight = total > 0.0 ? x / total : 1.0 / at_zero;
      const double f = weight * std::max(kn * x + dashpot(r) * rate, 0.0);
      out.force += f;
      out.torque += r.cross(Vec3(0.0, 0.0, f));
    }
    return out;
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
    const Load f = load(s);
    const Quat dq = Quat(0.0, s.w.x(), s.w.y(), s.w.z()) * s.q;  // dq/dt = (0, w) q / 2
    return {s.vz, f.force / m, 0.5 * dq.coeffs(), f.torque / inertia};
  }
  static State add(const State& s, const Rate& k, double h) {
    Quat q;
    q.coeffs() = s.q.coeffs() + h * k.q;
    return {s.z + h * k.z, s.vz + h * k.vz, q, s.w + h * k.w};
  }
  // The state from the touch at v0 (m/s) over `span` (s, past the release) in steps h (s). The
  // force starts at t = 0 and ends without a jump (the clamp).
  State land(double v0, double span, double h) const {
    State s{0.0, -v0, Quat::Identity(), Vec3::Zero()};
    const long steps = std::lround(span / h);
    for (long n = 0; n < steps; ++n) {
      const Rate k1 = rate(s), k2 = rate(add(s, k1, 0.5 * h)), k3 = rate(add(s, k2, 0.5 * h)), k4 = rate(add(s, k3, h));
      Rate sum{k1.z + 2 * k2.z + 2 * k3.z + k4.z, k1.vz + 2 * k2.vz + 2 * k3.vz + k4.vz,
               k1.q + 2 * k2.q + 2 * k3.q + k4.q, k1.w + 2 * k2.w + 2 * k3.w + k4.w};
      s = add(s, sum, h / 6.0);
      s.q.normalize();
    }
    return s;
  }
  // -, the first vertex's normal velocity after the impact over v0 (> 0: rebound), taken with
  // the lever at the touch as the engine's measure does.
  double rebound(double v0, double span, double h) const {
    const State s = land(v0, span, h);
    return (s.vz + s.w.cross(vertices[0]).z()) / v0;
  }
};

}  // namespace polydem::validation
