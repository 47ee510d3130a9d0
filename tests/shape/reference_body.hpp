#pragma once
// Independent numeric integration of a rounded body, to check the exact mass properties.
#include <vector>

#include "polydem/shape.hpp"

namespace polydem::test {

struct NumericMoments {
  double volume = 0.0;
  Vec3 center = Vec3::Zero();
  Mat3 inertia_per_mass = Mat3::Zero();  // m^2, about the centre
};

// True when x is within `radius` of the convex polygon-faced core of `s` (brute force over
// every triangle, edge and vertex; no use of the code under test).
bool inside_rounded(const Shape& s, const Vec3& x);

// Quasi-Monte-Carlo (Halton 2,3,5) over the bounding box with `samples` points.
NumericMoments integrate_rounded(const Shape& s, int samples);

// Seeded random points on a perturbed ellipsoid (semi-axes a, b, c), for rock-like hulls.
std::vector<Vec3> rock_points(unsigned seed, int count, double a, double b, double c);

}  // namespace polydem::test
