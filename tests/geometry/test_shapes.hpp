#pragma once
// Hand-built shapes and posed bodies for the geometry tests (no hull builder needed).
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "geometry/face_planes.hpp"
#include "geometry/features.hpp"
#include "polydem/shape.hpp"

namespace polydem::test {

// A convex polytope from its vertices and faces (each face listed in order around it, either
// way): recentres on the vertex mean (the centre of mass of the symmetric solids used here),
// turns faces counter-clockwise seen from outside, derives edges, outward normals and face planes.
inline Shape make_polytope(const std::string& name, std::vector<Vec3> vertices,
                           std::vector<std::vector<int>> faces, double radius) {
  Shape s;
  s.name = name;
  s.radius = radius;
  Vec3 mean = Vec3::Zero();
  for (const Vec3& v : vertices) mean += v;
  mean /= static_cast<double>(vertices.size());
  for (Vec3& v : vertices) v -= mean;
  std::set<std::array<int, 2>> edges;
  for (std::vector<int>& f : faces) {
    Vec3 newell = Vec3::Zero();  // Newell's normal: robust for any planar polygon
    Vec3 centre = Vec3::Zero();
    for (std::size_t k = 0; k < f.size(); ++k) {
      const Vec3& p = vertices[f[k]];
      const Vec3& q = vertices[f[(k + 1) % f.size()]];
      newell += Vec3((p.y() - q.y()) * (p.z() + q.z()), (p.z() - q.z()) * (p.x() + q.x()),
                     (p.x() - q.x()) * (p.y() + q.y()));
      centre += p;
    }
    if (newell.dot(centre) < 0.0) {
      std::reverse(f.begin(), f.end());
      newell = -newell;
    }
    s.face_normals.push_back(newell.normalized());
    for (std::size_t k = 0; k < f.size(); ++k) {
      const int i = f[k], j = f[(k + 1) % f.size()];
      edges.insert({std::min(i, j), std::max(i, j)});
    }
  }
  s.edges.assign(edges.begin(), edges.end());
  s.faces = std::move(faces);
  s.vertices = std::move(vertices);
  double r2 = 0.0;
  for (const Vec3& v : s.vertices) r2 = std::max(r2, v.squaredNorm());
  s.bounding_radius = std::sqrt(r2) + radius;
  derive_face_planes(s);
  return s;
}

// Box of half sizes h; vertex i has sign bits (x, y, z) = (i & 1, i & 2, i & 4).
inline Shape make_box(const Vec3& h, double radius, const std::string& name = "box") {
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i)
    v.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
  return make_polytope(name, v, {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}},
                       radius);
}

inline Shape make_cube(double half, double radius) { return make_box(Vec3::Constant(half), radius, "cube"); }
inline Shape make_plate(double radius) { return make_box(Vec3(1.0, 0.8, 0.05), radius, "plate"); }
inline Shape make_needle(double radius) { return make_box(Vec3(1.5, 0.08, 0.08), radius, "needle"); }

inline Shape make_octahedron(double half, double radius) {
  std::vector<Vec3> v;
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {1.0, -1.0}) v.push_back(sign * half * Vec3::Unit(axis));
  std::vector<std::vector<int>> f;
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      for (int sz = 0; sz < 2; ++sz) f.push_back({sx, 2 + sy, 4 + sz});
  return make_polytope("octahedron", v, f, radius);
}

inline Shape make_tetrahedron(double size, double radius) {
  std::vector<Vec3> v = {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
  for (Vec3& p : v) p *= size;
  return make_polytope("tetrahedron", v, {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}, radius);
}

// Hexagonal prism along z: hexagon circumradius `half`, half height `half_height`.
inline Shape make_hex_prism(double half, double half_height, double radius) {
  std::vector<Vec3> v;
  for (double z : {-half_height, half_height})
    for (int k = 0; k < 6; ++k) v.emplace_back(half * std::cos(k * kPi / 3), half * std::sin(k * kPi / 3), z);
  std::vector<std::vector<int>> f = {{0, 1, 2, 3, 4, 5}, {6, 7, 8, 9, 10, 11}};
  for (int k = 0; k < 6; ++k) f.push_back({k, (k + 1) % 6, 6 + (k + 1) % 6, 6 + k});
  return make_polytope("hex_prism", v, f, radius);
}

inline Shape make_sphere(double radius) { return sphere_shape("sphere", radius); }

// A shape placed in the world, owning its posed vertices.
struct Posed {
  const Shape* shape;
  double scale;
  Vec3 position;
  Quat q;
  std::vector<Vec3> world;

  Posed(const Shape& s, double scale_, const Vec3& x, const Quat& q_ = Quat::Identity())
      : shape(&s), scale(scale_), position(x), q(q_.normalized()), world(s.vertices.size()) {
    pose_vertices(s, scale, position, q, world.data());
  }
  PosedBody body() const { return {shape, world.data(), q.toRotationMatrix(), position, scale * shape->radius, scale}; }
  // m, radius of the sphere about the centre holding the core polyhedron.
  double core_radius() const { return (shape->bounding_radius - shape->radius) * scale; }
};

inline Quat random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return Quat(g(rng), g(rng), g(rng), g(rng)).normalized();
}

inline Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return Vec3(g(rng), g(rng), g(rng)).normalized();
}

// One of the 24 rotations of the cube, so faces and edges come out parallel on purpose.
inline Quat random_axis_rotation(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> pick(0, 3);
  Quat q = Quat::Identity();
  for (int axis = 0; axis < 3; ++axis)
    q = Eigen::AngleAxisd(0.5 * kPi * pick(rng), Vec3::Unit(axis)) * q;
  return q;
}

}  // namespace polydem::test
