#pragma once
// Closest points between points, segments and convex polygons. Pure inline helpers: the
// contact kernels call them every step. Callers pass differences (a local frame at a feature
// vertex) so that round-off scales with the feature size, not with the world coordinates.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "polydem/math.hpp"

namespace polydem {

// sin^2 of the angle under which two edges count as parallel (angle < 1e-6 rad): the
// line-line parameters are then ill-conditioned and the vertex-edge pairs carry the contact.
inline constexpr double kParallelSin2 = 1e-12;

// Relative margin of the "strictly inside" tests: features that meet exactly (stacked cubes,
// a vertex right above an edge) differ by round-off alone, and the lower-dimensional pair must
// win every time rather than by a coin flip of the last bit (one contact, never two).
inline constexpr double kInteriorMargin = 1e-9;

// True when the parameter tl / len2 of a point on a segment lies inside (margin, 1 - margin).
inline bool inside_segment(double tl, double len2) {
  return tl > kInteriorMargin * len2 && tl < (1.0 - kInteriorMargin) * len2;
}

// Parameter t in [0, 1] of the point of segment [a, a + ab] closest to p.
inline double clamped_segment_param(const Vec3& p, const Vec3& a, const Vec3& ab) {
  const double len2 = ab.squaredNorm();
  if (len2 <= 0.0) return 0.0;
  return std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
}

// Squared distance from p to segment [a, a + ab], ends included.
inline double point_segment_distance_sq(const Vec3& p, const Vec3& a, const Vec3& ab) {
  return (a + clamped_segment_param(p, a, ab) * ab - p).squaredNorm();
}

struct SegmentParams {
  double s;  // on the first segment, in [0, 1]
  double t;  // on the second segment, in [0, 1]
};

// Closest points of segments [p1, p1 + d1] and [p2, p2 + d2], ends included (Ericson,
// Real-Time Collision Detection, 5.1.9). Parallel segments get one of the closest pairs.
inline SegmentParams closest_segment_segment(const Vec3& p1, const Vec3& d1, const Vec3& p2, const Vec3& d2) {
  const Vec3 r = p1 - p2;
  const double a = d1.squaredNorm();
  const double e = d2.squaredNorm();
  const double b = d1.dot(d2);
  const double c = d1.dot(r);
  const double f = d2.dot(r);
  if (a <= 0.0 && e <= 0.0) return {0.0, 0.0};
  if (a <= 0.0) return {0.0, std::clamp(f / e, 0.0, 1.0)};
  if (e <= 0.0) return {std::clamp(-c / a, 0.0, 1.0), 0.0};
  const double denom = d1.cross(d2).squaredNorm();  // = a e - b^2 without its cancellation
  double s = denom > kParallelSin2 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return {s, t};
}

// Squared distance between segments [p1, p1 + d1] and [p2, p2 + d2], ends included.
inline double segment_segment_distance_sq(const Vec3& p1, const Vec3& d1, const Vec3& p2, const Vec3& d2) {
  const SegmentParams st = closest_segment_segment(p1, d1, p2, d2);
  return (p1 + st.s * d1 - p2 - st.t * d2).squaredNorm();
}

// True when p projects strictly inside the convex polygon `face` (indices into `vertices`,
// counter-clockwise around the outward normal n): p is left of every edge by more than
// kInteriorMargin times the edge length.
// Written out in scalars, each edge from the previous end (the vertex-face kernel's hot loop:
// Eigen's 3-vectors spend half of it in shuffles); the same operations in the same order as
// e.cross(p - v0).dot(n) <= kInteriorMargin * e.squaredNorm(), so the same bits.
inline bool projects_inside_polygon(const Vec3& p, const Vec3* vertices, const std::vector<int>& face,
                                    const Vec3& n) {
  const Vec3& last = vertices[face.back()];
  double x0 = last.x(), y0 = last.y(), z0 = last.z();  // m, the edge's first end
  for (const int v : face) {
    const double x1 = vertices[v].x(), y1 = vertices[v].y(), z1 = vertices[v].z();
    const double ex = x1 - x0, ey = y1 - y0, ez = z1 - z0;                    // m, edge
    const double wx = p.x() - x0, wy = p.y() - y0, wz = p.z() - z0;          // m, from its first end to p
    const double cx = ey * wz - ez * wy, cy = ez * wx - ex * wz, cz = ex * wy - ey * wx;  // m^2, e x w
    if (cx * n.x() + cy * n.y() + cz * n.z() <= kInteriorMargin * (ex * ex + ey * ey + ez * ez)) return false;
    x0 = x1, y0 = y1, z0 = z1;
  }
  return true;
}

// Squared distance from p to the convex polygon `face` (interior and boundary) of unit normal n.
inline double point_polygon_distance_sq(const Vec3& p, const Vec3* vertices, const std::vector<int>& face,
                                        const Vec3& n) {
  if (projects_inside_polygon(p, vertices, face, n)) {
    const double d = (p - vertices[face[0]]).dot(n);
    return d * d;
  }
  double best = point_segment_distance_sq(p, vertices[face.back()], vertices[face[0]] - vertices[face.back()]);
  for (std::size_t k = 0; k + 1 < face.size(); ++k) {
    const Vec3& v0 = vertices[face[k]];
    best = std::min(best, point_segment_distance_sq(p, v0, vertices[face[k + 1]] - v0));
  }
  return best;
}

}  // namespace polydem
