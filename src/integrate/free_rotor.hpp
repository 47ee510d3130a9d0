#pragma once
// Exact flows of one torque-free rigid body over a time step, per body. Internal to integrate.
#include <cmath>

#include "polydem/math.hpp"

namespace polydem::free_rotor {

// rad: below it sin and cos come from Taylor series, truncated past round-off (< 3e-22
// relative), not from libm (~4 times dearer). A DEM step turns a body far less than this
// (1000 rad/s at dt = 1e-5 s is 5e-3 rad per half step).
constexpr double kSeriesAngle = 1e-2;

// rad^2: below it (1e-4 rad, settled bodies) two terms of each series reach round-off.
constexpr double kShortSeriesAngle2 = 1e-8;

// sin(x)/x and cos(x) for x^2 = x2 <= kSeriesAngle^2, by Horner: through x^6 and x^8.
inline double sin_over_x_series(double x2) {
  if (x2 <= kShortSeriesAngle2) return 1.0 - x2 / 6.0;
  return 1.0 - x2 * (1.0 / 6.0) * (1.0 - x2 * (1.0 / 20.0) * (1.0 - x2 * (1.0 / 42.0)));
}
inline double cos_series(double x2) {
  if (x2 <= kShortSeriesAngle2) return 1.0 - 0.5 * x2 * (1.0 - x2 / 12.0);
  return 1.0 - x2 * 0.5 * (1.0 - x2 * (1.0 / 12.0) * (1.0 - x2 * (1.0 / 30.0) * (1.0 - x2 * (1.0 / 56.0))));
}

// Exact flow of H_k = L_k^2 / (2 I_k) over tau: the body turns about its principal axis k by
// phi = L_k tau / I_k, so q <- q * rot(e_k, phi) and L_body <- rot(e_k, -phi) L_body
// (world angular momentum R L_body unchanged).
inline void rotate_about_axis(Quat& q, Vec3& l_body, double inertia_k, int k, double tau) {
  const double half = 0.5 * l_body[k] / inertia_k * tau;  // rad, phi / 2
  const bool small = std::abs(half) <= kSeriesAngle;
  const double h2 = half * half;
  const double c2 = small ? cos_series(h2) : std::cos(half);
  const double s2 = small ? half * sin_over_x_series(h2) : std::sin(half);
  const double c = c2 * c2 - s2 * s2;  // cos(phi) from the half angle: one sin/cos pair only
  const double s = 2.0 * s2 * c2;
  const int a = (k + 1) % 3;  // (a, b, k) is a right-handed cyclic triple
  const int b = (k + 2) % 3;
  const double la = l_body[a];
  const double lb = l_body[b];
  l_body[a] = c * la + s * lb;
  l_body[b] = -s * la + c * lb;
  Quat r(c2, 0.0, 0.0, 0.0);
  r.vec()[k] = s2;
  q = q * r;
}

// Second-order symmetric splitting 3(dt/2) 2(dt/2) 1(dt) 2(dt/2) 3(dt/2) (NO_SQUISH, Miller
// et al. 2002): symplectic, time-reversible; keeps |L| and R L_body up to round-off.
inline void rotate_asymmetric(Quat& q, Vec3& l_body, const Vec3& inertia, double dt) {
  const double h = 0.5 * dt;
  rotate_about_axis(q, l_body, inertia[2], 2, h);
  rotate_about_axis(q, l_body, inertia[1], 1, h);
  rotate_about_axis(q, l_body, inertia[0], 0, dt);
  rotate_about_axis(q, l_body, inertia[1], 1, h);
  rotate_about_axis(q, l_body, inertia[2], 2, h);
}

// Isotropic body: w is constant, so the exact flow is one rotation by |w| dt about w.
// L_body is unchanged (L_world is parallel to the rotation axis).
inline void rotate_isotropic(Quat& q, const Vec3& l_body, const Vec3& inertia, double dt) {
  const Vec3 w_body = l_body.cwiseQuotient(inertia);  // rad/s
  const double w = w_body.norm();
  const double half = 0.5 * w * dt;  // rad
  // Small angles by series: no libm call, and no division by w = 0 for a body at rest.
  const bool small = half <= kSeriesAngle;
  const double h2 = half * half;
  const double s_over_w = small ? 0.5 * dt * sin_over_x_series(h2) : std::sin(half) / w;
  const double c = small ? cos_series(h2) : std::cos(half);
  const Vec3 v = s_over_w * w_body;
  q = q * Quat(c, v.x(), v.y(), v.z());
}

// One Newton step towards |q| = 1: branch-free and enough, as each step drifts by ~1e-16 only.
inline void renormalize(Quat& q) { q.coeffs() *= 1.5 - 0.5 * q.squaredNorm(); }

}  // namespace polydem::free_rotor
