#include "shape/mass.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "geometry/face_planes.hpp"
#include "polydem/error.hpp"
#include "shape/moments.hpp"
#include "shape/topology.hpp"
#include "shape/union_mass.hpp"

// The rounded body is cut exactly into: the core polyhedron, one prism per face (face x [0, r]
// along its normal), one cylindrical wedge per edge (angle = exterior dihedral angle) and one
// spherical sector per vertex (its normal cone). Polyhedral pieces are summed tetrahedra; wedges
// and sectors have closed forms. Sector moments over a spherical polygon P bounded by great-circle
// arcs use Green's theorem on the sphere (n_j is a spherical harmonic of degree 1):
//   solid angle      W = 2 pi - sum of face angles at the vertex (angular defect),
//   int_P n dW       = -1/2 sum_arcs theta mu,
// with mu the outward conormal of the arc (the unit edge direction leaving the vertex).
// The cones tile the unit sphere, so the sectors' own r^5/5 int n n^T dW terms add up to
// 4 pi/3 r^5/5 I whichever vertex they belong to (each cone's share need not be computed).
// So the result is exact up to round-off (relative error ~1e-14, see tests/shape/mass_test.cpp).

namespace polydem {
namespace {

// Moments of a piece given about point p, moved to the origin.
Moments shifted(const Moments& local, const Vec3& p) {
  Moments m;
  m.volume = local.volume;
  m.first = local.volume * p + local.first;
  m.second = local.volume * p * p.transpose() + p * local.first.transpose() + local.first * p.transpose() +
             local.second;
  return m;
}

// Tetrahedron moments; `signed_volume` false takes |volume| (prisms: orientation unknown).
Moments tetrahedron(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, bool signed_volume) {
  double v = (b - a).cross(c - a).dot(d - a) / 6.0;
  if (!signed_volume) v = std::abs(v);
  const Vec3 sum = a + b + c + d;
  Moments m;
  m.volume = v;
  m.first = v * sum / 4.0;
  // int x x^T = V/20 (sum_i v_i v_i^T + S S^T), S = sum_i v_i (Tonon 2004, eq. for a simplex)
  Mat3 q = sum * sum.transpose();
  for (const Vec3* p : {&a, &b, &c, &d}) q += (*p) * p->transpose();
  m.second = v / 20.0 * q;
  return m;
}

Moments core_polyhedron(const Shape& s, const Vec3& origin) {
  Moments m;
  for (const auto& f : s.faces)
    for (size_t i = 1; i + 1 < f.size(); ++i)
      m.add(tetrahedron(origin, s.vertices[f[0]], s.vertices[f[i]], s.vertices[f[i + 1]], true));
  return m;
}

// Triangular prism (a, b, c) x [0, h] as three tetrahedra.
Moments prism(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& h) {
  Moments m = tetrahedron(a, b, c, a + h, false);
  m.add(tetrahedron(b, c, a + h, b + h, false));
  m.add(tetrahedron(c, a + h, b + h, c + h, false));
  return m;
}

Moments face_prisms(const Shape& s) {
  Moments m;
  for (size_t fi = 0; fi < s.faces.size(); ++fi) {
    const auto& f = s.faces[fi];
    const Vec3 h = s.radius * s.face_normals[fi];
    for (size_t i = 1; i + 1 < f.size(); ++i)
      m.add(prism(s.vertices[f[0]], s.vertices[f[i]], s.vertices[f[i + 1]], h));
  }
  return m;
}

// Cylindrical wedge of an edge: points a + s t + rho (cos phi u + sin phi w), phi in [0, theta].
struct Wedge {
  Vec3 t, u, w;         // unit edge direction; first face normal; rotation direction
  double theta = 0.0;   // rad, exterior dihedral angle (2 pi for a lone segment)
  double length = 0.0;  // m
};

Vec3 any_perpendicular(const Vec3& t) {
  const Vec3 trial = std::abs(t.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (trial - trial.dot(t) * t).normalized();
}

Vec3 face_centroid(const Shape& s, int f) {
  Vec3 c = Vec3::Zero();
  for (int i : s.faces[f]) c += s.vertices[i];
  return c / static_cast<double>(s.faces[f].size());
}

Wedge make_wedge(const Shape& s, int e, const EdgeFaces& ef) {
  const Vec3& a = s.vertices[s.edges[e][0]];
  const Vec3 d = s.vertices[s.edges[e][1]] - a;
  Wedge w;
  w.length = d.norm();
  w.t = d / w.length;
  if (ef.face1 < 0) {
    w.u = any_perpendicular(w.t);
    w.w = w.t.cross(w.u);
    w.theta = 2.0 * kPi;
    return w;
  }
  const Vec3 n1 = s.face_normals[ef.face1];
  const Vec3 n2 = s.face_normals[ef.face2];
  w.u = (n1 - n1.dot(w.t) * w.t).normalized();
  w.w = w.t.cross(w.u);
  // The wedge opens away from the body: w points out of face 1 across the edge.
  if (w.w.dot(face_centroid(s, ef.face1) - a) > 0.0) w.w = -w.w;
  w.theta = std::atan2(std::max(0.0, n2.dot(w.w)), n2.dot(w.u));
  return w;
}

Moments wedge_moments(const Wedge& w, double r) {
  const double area = 0.5 * w.theta * r * r;  // m^2, cross-section
  const double L = w.length;
  const double c = std::cos(w.theta), sn = std::sin(w.theta);
  const Vec3 e1 = sn * w.u + (1.0 - c) * w.w;  // int_0^theta e(phi) dphi
  const Mat3 e2 = (0.5 * w.theta + 0.25 * sn * 2.0 * c) * w.u * w.u.transpose() +
                  (0.5 * w.theta - 0.25 * sn * 2.0 * c) * w.w * w.w.transpose() +
                  0.5 * sn * sn * (w.u * w.w.transpose() + w.w * w.u.transpose());
  Moments m;
  m.volume = area * L;
  m.first = area * L * L / 2.0 * w.t + L * r * r * r / 3.0 * e1;
  const Vec3 g = L * L / 2.0 * r * r * r / 3.0 * e1;
  m.second = area * L * L * L / 3.0 * w.t * w.t.transpose() + w.t * g.transpose() + g * w.t.transpose() +
             L * std::pow(r, 4) / 4.0 * e2;
  return m;
}

double face_angle_at(const Shape& s, const std::vector<int>& f, size_t i) {
  const Vec3& v = s.vertices[f[i]];
  const Vec3 a = s.vertices[f[(i + f.size() - 1) % f.size()]] - v;
  const Vec3 b = s.vertices[f[(i + 1) % f.size()]] - v;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// Solid angle of each vertex's normal cone: 4 pi for a lone vertex, else the angular defect.
std::vector<double> normal_cone_angles(const Shape& s) {
  std::vector<double> omega(s.vertices.size(), s.edges.empty() ? 4.0 * kPi : 2.0 * kPi);
  for (const auto& f : s.faces)
    for (size_t i = 0; i < f.size(); ++i) omega[f[i]] -= face_angle_at(s, f, i);
  return omega;
}

Moments vertex_sectors(const Shape& s, const std::vector<Wedge>& wedges) {
  const size_t nv = s.vertices.size();
  const std::vector<double> omega = normal_cone_angles(s);
  std::vector<Vec3> mean(nv, Vec3::Zero());  // int n dW over each cone
  for (size_t e = 0; e < s.edges.size(); ++e) {
    const Vec3 mu = wedges[e].t;  // outward conormal at the first end; reversed at the second
    mean[s.edges[e][0]] -= 0.5 * wedges[e].theta * mu;
    mean[s.edges[e][1]] += 0.5 * wedges[e].theta * mu;
  }
  const double r = s.radius;
  Moments m;
  for (size_t v = 0; v < nv; ++v) {
    Moments local;
    local.volume = omega[v] * r * r * r / 3.0;
    local.first = std::pow(r, 4) / 4.0 * mean[v];
    m.add(shifted(local, s.vertices[v]));
  }
  m.second += std::pow(r, 5) / 5.0 * (4.0 * kPi / 3.0) * Mat3::Identity();
  return m;
}

// Moments about the origin of the shape's frame; call with vertices near the origin (round-off).
Moments rounded_body(const Shape& s) {
  Moments m = core_polyhedron(s, Vec3::Zero());
  m.add(face_prisms(s));
  const std::vector<EdgeFaces> adjacency = edge_faces(s);
  std::vector<Wedge> wedges;
  for (size_t e = 0; e < s.edges.size(); ++e) {
    wedges.push_back(make_wedge(s, static_cast<int>(e), adjacency[e]));
    m.add(shifted(wedge_moments(wedges.back(), s.radius), s.vertices[s.edges[e][0]]));
  }
  m.add(vertex_sectors(s, wedges));
  return m;
}

double max_vertex_norm(const Shape& s) {
  double r = 0.0;
  for (const Vec3& v : s.vertices) r = std::max(r, v.norm());
  return r;
}

void check_radius(const Shape& s) {
  if (!(s.radius >= 0.0) || !std::isfinite(s.radius))
    throw InputError("shape '" + s.name + "': radius " + std::to_string(s.radius) +
                     " must be >= 0 (the Minkowski radius, m)");
}

// Columns: principal axes, moments ascending, right-handed. A tensor already diagonal to
// round-off keeps the input axes (a cube or box stays aligned with the frame it was given in).
Mat3 principal_axes(const Mat3& inertia, Vec3& moments) {
  const Mat3 off = inertia - Mat3(inertia.diagonal().asDiagonal());
  Mat3 axes;
  if (off.norm() <= 1e-12 * inertia.trace()) {
    std::array<int, 3> order{0, 1, 2};
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return inertia(a, a) < inertia(b, b); });
    for (int k = 0; k < 3; ++k) {
      axes.col(k) = Vec3::Unit(order[k]);
      moments[k] = inertia(order[k], order[k]);
    }
  } else {
    Eigen::SelfAdjointEigenSolver<Mat3> solver(inertia);
    axes = solver.eigenvectors();
    moments = solver.eigenvalues();
  }
  if (axes.determinant() < 0.0) axes.col(2) = -axes.col(2);
  return axes;
}

// The quadrature's lines are too far apart for the swept elements: a mass or inertia off by
// percents would be simulated as if it were right.
std::string too_coarse(const Shape& s, double error, int cells) {
  char text[320];
  std::snprintf(text, sizeof(text),
                "its mass properties' quadrature error bound is %.2g (limit %g): elements of radius %.3g m "
                "are too thin for vertices up to %.3g m apart on %d x %d lines; give volume and inertia "
                "(preCompDone y)",
                error, kMassErrorLimit, s.radius, 2.0 * max_vertex_norm(s), cells, cells);
  return "shape '" + s.name + "': " + text;
}

}  // namespace

void compute_mass_properties(Shape& s, int quadrature_cells) {
  check_radius(s);
  prepare_topology(s);
  // Integrate about the vertex centroid: far-off inputs would lose digits to cancellation.
  Vec3 origin = Vec3::Zero();
  for (const Vec3& v : s.vertices) origin += v;
  origin /= static_cast<double>(s.vertices.size());
  for (Vec3& v : s.vertices) v -= origin;
  s.mass_error = 0.0;
  const Moments m = s.convex ? rounded_body(s) : union_moments(s, quadrature_cells, s.mass_error);
  if (!std::isfinite(m.volume) || !m.first.allFinite() || !m.second.allFinite()) {
    char sizes[96];
    std::snprintf(sizes, sizeof(sizes), "radius %.3g m and vertices up to %.3g m", s.radius, max_vertex_norm(s));
    throw InputError("shape '" + s.name + "': " + sizes + " from their centroid: its volume and inertia overflow "
                     "a double (sizes are in metres)");
  }
  if (!(m.volume > 0.0))
    throw InputError("shape '" + s.name + "': zero volume (give a radius > 0 or a solid polyhedron)");
  if (s.mass_error > kMassErrorLimit) throw InputError(too_coarse(s, s.mass_error, quadrature_cells));
  const Vec3 center = m.first / m.volume;
  const Mat3 spread = m.second / m.volume - center * center.transpose();  // m^2, about the centre
  const Mat3 inertia = spread.trace() * Mat3::Identity() - spread;        // m^2, I / mass
  Vec3 moments;
  const Mat3 axes = principal_axes(inertia, moments);
  for (Vec3& v : s.vertices) v = axes.transpose() * (v - center);
  for (Vec3& n : s.face_normals) n = axes.transpose() * n;
  s.volume = m.volume;
  s.inertia_per_mass = moments;
  s.input_center = origin + center;
  s.input_rotation = Quat(axes).normalized();
  s.bounding_radius = max_vertex_norm(s) + s.radius;
  derive_face_planes(s);
}

void compute_derived_geometry(Shape& s) {
  check_radius(s);
  prepare_topology(s);
  s.bounding_radius = max_vertex_norm(s) + s.radius;
  derive_face_planes(s);
}

}  // namespace polydem
