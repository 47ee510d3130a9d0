#include "reference_body.hpp"

#include <algorithm>
#include <random>

namespace polydem::test {
namespace {

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (p - a - t * d).norm();
}

double halton(int index, int base) {
  double f = 1.0, r = 0.0;
  for (int i = index; i > 0; i /= base) {
    f /= base;
    r += f * (i % base);
  }
  return r;
}

bool inside_core(const Shape& s, const Vec3& x, const Vec3& centroid) {
  if (s.faces.size() < 4) return false;  // plates and lower have no interior
  for (const auto& f : s.faces) {
    Vec3 n = (s.vertices[f[1]] - s.vertices[f[0]]).cross(s.vertices[f[2]] - s.vertices[f[0]]);
    if (n.dot(s.vertices[f[0]] - centroid) < 0) n = -n;  // outward, whatever the stored order
    if (n.dot(x - s.vertices[f[0]]) > 0) return false;
  }
  return true;
}

}  // namespace

bool inside_rounded(const Shape& s, const Vec3& x) {
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& v : s.vertices) centroid += v;
  centroid /= static_cast<double>(s.vertices.size());
  if (inside_core(s, x, centroid)) return true;
  const double r = s.radius;
  for (const Vec3& v : s.vertices)
    if ((x - v).norm() <= r) return true;
  for (const auto& e : s.edges)
    if (distance_to_segment(x, s.vertices[e[0]], s.vertices[e[1]]) <= r) return true;
  for (const auto& f : s.faces)
    for (size_t i = 1; i + 1 < f.size(); ++i)
      if ((x - closest_on_triangle(x, s.vertices[f[0]], s.vertices[f[i]], s.vertices[f[i + 1]])).norm() <= r)
        return true;
  return false;
}

NumericMoments integrate_rounded(const Shape& s, int samples) {
  Vec3 lo = s.vertices[0], hi = s.vertices[0];
  for (const Vec3& v : s.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  lo.array() -= s.radius;
  hi.array() += s.radius;
  const Vec3 size = hi - lo;
  std::vector<Vec3> hits;
  for (int i = 1; i <= samples; ++i) {
    const Vec3 x = lo + Vec3(halton(i, 2), halton(i, 3), halton(i, 5)).cwiseProduct(size);
    if (inside_rounded(s, x)) hits.push_back(x);
  }
  NumericMoments m;
  m.volume = size.prod() * static_cast<double>(hits.size()) / samples;
  for (const Vec3& x : hits) m.center += x;
  m.center /= static_cast<double>(hits.size());
  Mat3 spread = Mat3::Zero();
  for (const Vec3& x : hits) spread += (x - m.center) * (x - m.center).transpose();
  spread /= static_cast<double>(hits.size());
  m.inertia_per_mass = spread.trace() * Mat3::Identity() - spread;
  return m;
}

std::vector<Vec3> rock_points(unsigned seed, int count, double a, double b, double c) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> bump(0.8, 1.15);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) {
    const Vec3 d = Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
    points.push_back(bump(rng) * Vec3(a * d.x(), b * d.y(), c * d.z()));
  }
  return points;
}

}  // namespace polydem::test
