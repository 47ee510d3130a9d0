#include "shape/hull.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <cmath>

#include "polydem/error.hpp"
#include "shape/hull_faces.hpp"
#include "shape/mass.hpp"

namespace polydem {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

// Relative flatness (of the point set's extent) below which points count as collinear/coplanar.
constexpr double kFlatTolerance = 1e-9;
// rad, triangles of the hull closer than this to coplanar are one face (round-off of the inputs).
constexpr double kCoplanarAngle = 1e-8;

[[noreturn]] void fail(const std::string& name, const std::string& what) {
  throw InputError("shape '" + name + "': " + what);
}

size_t farthest_from(const std::vector<Vec3>& p, const Vec3& from) {
  size_t best = 0;
  for (size_t i = 1; i < p.size(); ++i)
    if ((p[i] - from).norm() > (p[best] - from).norm()) best = i;
  return best;
}

size_t farthest_from_line(const std::vector<Vec3>& p, const Vec3& a, const Vec3& dir) {
  size_t best = 0;
  double dmax = -1.0;
  for (size_t i = 0; i < p.size(); ++i) {
    const double d = (p[i] - a).cross(dir).norm();
    if (d > dmax) {
      dmax = d;
      best = i;
    }
  }
  return best;
}

Shape solid_hull(const std::vector<Vec3>& points) {
  std::vector<Kernel::Point_3> cgal_points;
  for (const Vec3& p : points) cgal_points.emplace_back(p.x(), p.y(), p.z());
  Mesh mesh;
  CGAL::convex_hull_3(cgal_points.begin(), cgal_points.end(), mesh);
  Shape s;
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    s.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  std::vector<std::array<int, 3>> triangles;
  for (auto f : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) t[k++] = static_cast<int>(v.idx());
    triangles.push_back(t);
  }
  s.faces = merge_coplanar(s.vertices, triangles, kCoplanarAngle);
  drop_non_corners(s.vertices, s.faces);
  return s;
}

Shape plate(const std::vector<Vec3>& points, const Vec3& normal) {
  Shape s;
  std::vector<int> corners = planar_hull(points, normal);
  for (int i : corners) s.vertices.push_back(points[i]);
  std::vector<int> top(corners.size());
  for (size_t i = 0; i < top.size(); ++i) top[i] = static_cast<int>(i);
  std::vector<int> bottom(top.rbegin(), top.rend());
  s.faces = {top, bottom};  // one face per side, opposite orders
  return s;
}

Shape degenerate_or_solid(const std::vector<Vec3>& points, const std::string& name, double radius) {
  const Vec3 a = points[farthest_from(points, points[0])];
  const Vec3 b = points[farthest_from(points, a)];
  const double extent = (b - a).norm();
  const std::string advice = " (give --radius > 0 or more points)";
  Shape s;
  if (extent == 0.0) {
    if (radius == 0.0) fail(name, "degenerate hull: a single point" + advice);
    s.vertices = {a};
    return s;
  }
  // Points dropped as round-off must stay inside the rounding, or the body is not their hull.
  auto check_dropped = [&](double off, const char* what) {
    if (off > radius)
      fail(name, std::string("points up to ") + std::to_string(off) + " m off the " + what + " through the farthest "
                 "points (" + std::to_string(extent) + " m apart) would be flattened into it, beyond the radius " +
                 std::to_string(radius) + " m: a stray point far from the others, or mixed units?");
  };
  const Vec3 dir = (b - a) / extent;
  const Vec3 c = points[farthest_from_line(points, a, dir)];
  if ((c - a).cross(dir).norm() <= kFlatTolerance * extent) {
    if (radius == 0.0) fail(name, "degenerate hull: collinear points" + advice);
    check_dropped((c - a).cross(dir).norm(), "line");
    s.vertices = {a, b};
    s.edges = {{0, 1}};
    return s;
  }
  const Vec3 normal = (b - a).cross(c - a).normalized();
  double thickness = 0.0;
  for (const Vec3& p : points) thickness = std::max(thickness, std::abs(normal.dot(p - a)));
  if (thickness > kFlatTolerance * extent) return solid_hull(points);
  if (radius == 0.0) fail(name, "degenerate hull: coplanar points" + advice);
  check_dropped(thickness, "plane");
  return plate(points, normal);
}

}  // namespace

Shape build_hull_shape(const std::vector<Vec3>& points, double radius, const std::string& name) {
  if (!(radius >= 0.0) || !std::isfinite(radius))
    fail(name, "radius " + std::to_string(radius) + " must be >= 0 (the Minkowski radius, m)");
  if (points.empty()) fail(name, "no point to take the hull of");
  for (const Vec3& p : points)
    if (!p.allFinite()) fail(name, "a point is not finite");
  Shape s = degenerate_or_solid(points, name, radius);
  s.name = name;
  s.radius = radius;
  compute_mass_properties(s);
  return s;
}

}  // namespace polydem
