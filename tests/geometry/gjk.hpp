#pragma once
// Independent reference for the distance between two convex polytopes given by their vertices:
// Gilbert-Johnson-Keerthi on the Minkowski difference, with a brute-force simplex step (every
// face of the current simplex tried by a small least-squares solve). Slow and simple on purpose.
#include <Eigen/Dense>
#include <array>
#include <limits>
#include <vector>

#include "polydem/math.hpp"

namespace polydem::test {

// Point of the affine hull of `pts` (indices in `subset` mask) closest to the origin, if it lies
// strictly inside their convex hull; writes it and returns true.
inline bool closest_in_subset(const std::vector<Vec3>& pts, unsigned mask, Vec3& best) {
  using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;  // no heap
  using SmallVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
  std::array<Vec3, 4> p;
  int count = 0;
  for (unsigned k = 0; k < pts.size(); ++k)
    if (mask & (1u << k)) p[count++] = pts[k];
  const int m = count - 1;
  SmallVec mu = SmallVec::Zero(m);
  if (m > 0) {
    Small g(m, m);
    SmallVec rhs(m);
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < m; ++j) g(i, j) = (p[i + 1] - p[0]).dot(p[j + 1] - p[0]);
      rhs(i) = -(p[i + 1] - p[0]).dot(p[0]);
    }
    Eigen::FullPivLU<Small> lu(g);
    if (lu.rank() < m) return false;
    mu = lu.solve(rhs);
  }
  double lambda0 = 1.0 - mu.sum();
  if (lambda0 <= 0.0 || (m > 0 && mu.minCoeff() <= 0.0)) return false;
  best = p[0];
  for (int i = 0; i < m; ++i) best += mu(i) * (p[i + 1] - p[0]);
  return true;
}

// Distance between conv(a) and conv(b); 0 when they intersect.
inline double hull_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  auto support = [&](const Vec3& d) {  // support point of a - b in direction d
    std::size_t ia = 0, ib = 0;
    for (std::size_t i = 1; i < a.size(); ++i)
      if (a[i].dot(d) > a[ia].dot(d)) ia = i;
    for (std::size_t i = 1; i < b.size(); ++i)
      if (b[i].dot(d) < b[ib].dot(d)) ib = i;
    return Vec3(a[ia] - b[ib]);
  };
  std::vector<Vec3> simplex = {a[0] - b[0]};
  Vec3 v = simplex[0];
  for (int iter = 0; iter < 200; ++iter) {
    const double v2 = v.squaredNorm();
    if (v2 <= 1e-28) return 0.0;
    const Vec3 w = support(-v);
    if (v2 - v.dot(w) <= 1e-14 * v2) break;  // no support point gets closer: v is the closest
    simplex.push_back(w);
    if (simplex.size() == 5) return 0.0;  // a full tetrahedron holding the origin
    double best2 = std::numeric_limits<double>::infinity();
    unsigned best_mask = 0;
    for (unsigned mask = 1; mask < (1u << simplex.size()); ++mask) {
      Vec3 x;
      if (closest_in_subset(simplex, mask, x) && x.squaredNorm() < best2) {
        best2 = x.squaredNorm();
        best_mask = mask;
        v = x;
      }
    }
    std::vector<Vec3> kept;
    for (unsigned k = 0; k < simplex.size(); ++k)
      if (best_mask & (1u << k)) kept.push_back(simplex[k]);
    simplex = kept;
    if (simplex.size() == 4) return 0.0;  // origin inside the tetrahedron
  }
  return v.norm();
}

}  // namespace polydem::test
