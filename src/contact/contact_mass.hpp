#pragma once
// The contact point's effective mass, for the law option `damping_mass: contact`: the mass a
// normal impulse at the contact point sees, 1/m* = sum over the two bodies of
// 1/m + (r x n) . I^-1 (r x n), r the lever from the body's centre to the point and I its
// world inertia; a driver is infinitely massive and adds nothing. On a sphere r lies along n
// and m* is the pair's m_i m_j/(m_i + m_j). With the pair's mass (the default, SPEC) an
// eccentric impact sees a dashpot tuned to a heavier oscillator than the contact point's: a
// cube landing on a corner rebounds at 0.40 there for en 0.5; with m* at en.
#include "geometry/features.hpp"

namespace polydem {

// 1/kg, the normal speed a unit normal impulse (N s) along n at lever r (m) gives that point.
inline double point_inverse_mass(const PosedBody& b, double mass, const Vec3& lever, const Vec3& n) {
  const Vec3 u = b.rotation.transpose() * lever.cross(n);  // m, principal frame
  const Vec3 inertia = mass * b.shape->inertia_per_mass * (b.scale * b.scale);  // kg m^2, principal moments
  return 1.0 / mass + u.cwiseAbs2().cwiseQuotient(inertia).sum();
}

}  // namespace polydem
