#pragma once
// STL files written by the tests (ASCII and binary), simple meshes, posed particles, and the
// contacts a particle has with a driver after the engine's shadowing rule.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "driver/drivers.hpp"
#include "geometry/face_planes.hpp"
#include "geometry/shadowing.hpp"
#include "polydem/error.hpp"

namespace polydem::test {

struct Tri {
  Vec3 a, b, c;  // counter-clockwise seen from the side the normal points to
};

struct TempFolder {
  std::filesystem::path path;
  TempFolder() {
    std::random_device device;
    path = std::filesystem::temp_directory_path() / ("polydem_driver_" + std::to_string(device()));
    std::filesystem::create_directories(path);
  }
  ~TempFolder() { std::filesystem::remove_all(path); }
  std::string file(const std::string& name) const { return (path / name).string(); }
};

inline void write_ascii_stl(const std::string& path, const std::vector<Tri>& tris) {
  std::ofstream out(path);
  out.precision(17);
  out << "solid test\n";
  for (const Tri& t : tris) {
    out << " facet normal 0 0 0\n  outer loop\n";
    for (const Vec3& v : {t.a, t.b, t.c}) out << "   vertex " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid test\n";
}

inline void write_binary_stl(const std::string& path, const std::vector<Tri>& tris) {
  std::ofstream out(path, std::ios::binary);
  const std::string header(80, ' ');
  out.write(header.data(), 80);
  const std::uint32_t n = std::uint32_t(tris.size());
  out.write(reinterpret_cast<const char*>(&n), 4);
  for (const Tri& t : tris) {
    float xyz[12] = {0, 0, 0};
    int k = 3;
    for (const Vec3& v : {t.a, t.b, t.c})
      for (int c = 0; c < 3; ++c) xyz[k++] = float(v[c]);
    out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
    const std::uint16_t attribute = 0;
    out.write(reinterpret_cast<const char*>(&attribute), 2);
  }
}

// An n x n grid of squares of side `cell` at height z, centred on the origin, two triangles
// each (normal +z).
inline std::vector<Tri> floor_triangles(int n, double cell, double z = 0.0) {
  std::vector<Tri> tris;
  auto at = [&](int i, int j) { return Vec3((i - 0.5 * n) * cell, (j - 0.5 * n) * cell, z); };  // exact corners: they weld
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      tris.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      tris.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return tris;
}

// The closed surface of the cube [-h, h]^3, normals outward.
inline std::vector<Tri> cube_triangles(double h) {
  std::vector<Tri> tris;
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-1.0, 1.0}) {
      Vec3 n = Vec3::Zero(), u = Vec3::Zero(), w = Vec3::Zero();
      n[axis] = side;
      u[(axis + 1) % 3] = 1.0;
      w[(axis + 2) % 3] = 1.0;
      if (side < 0) std::swap(u, w);  // counter-clockwise around the outward normal
      const Vec3 c = h * n;
      const Vec3 p0 = c - h * u - h * w, p1 = c + h * u - h * w, p2 = c + h * u + h * w, p3 = c - h * u + h * w;
      tris.push_back({p0, p1, p2});
      tris.push_back({p0, p2, p3});
    }
  return tris;
}

inline DriverSettings stl_spec(const std::string& file, const char* name = "mesh") {
  DriverSettings d;
  d.name = name;
  MeshSettings mesh;
  mesh.file = file;
  mesh.where = input_message("scene.yaml", 7, "file", "driver '" + d.name + "': ");
  d.kind = mesh;
  d.loc = {"scene.yaml", 7};
  return d;
}

inline Shape one_vertex_shape(double radius) { return sphere_shape("sphere", radius); }

// A cube particle of core half-side h rounded by r: vertices, edges, faces, outward normals.
inline Shape cube_particle(double h, double r) {
  Shape s;
  s.name = "cube";
  s.radius = r;
  for (int k = 0; k < 8; ++k) s.vertices.push_back(h * Vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1));
  for (int k = 0; k < 8; ++k)
    for (int bit : {1, 2, 4})
      if (!(k & bit)) s.edges.push_back({k, k | bit});
  s.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  s.face_normals = {-Vec3::UnitZ(), Vec3::UnitZ(), -Vec3::UnitY(), Vec3::UnitY(), -Vec3::UnitX(), Vec3::UnitX()};
  s.bounding_radius = std::sqrt(3.0) * h + r;
  derive_face_planes(s);
  return s;
}

// A shape placed at x with rotation q; `vertices` holds the world vertices.
struct Placed {
  std::vector<Vec3> vertices;
  PosedBody body;
  Placed(const Shape& s, const Vec3& x, const Quat& q = Quat::Identity()) {
    for (const Vec3& v : s.vertices) vertices.push_back(x + q * v);
    body = PosedBody{&s, vertices.data(), q.toRotationMatrix(), x, s.radius, 1.0};
  }
};

// The contacts of a body with driver j within max_gap, candidates from `range`, after the
// shadowing rule of the engine (a vertex-face contact drops the other pairs of its vertex).
inline std::vector<std::pair<FeaturePair, ContactPoint>> driver_contacts(const Drivers& drivers, std::uint32_t j,
                                                                         const PosedBody& a, double range = 1e-3,
                                                                         double max_gap = 0.0) {
  std::vector<FeaturePair> candidates;
  drivers.candidates(a, j, range, candidates);
  std::vector<std::pair<FeaturePair, ContactPoint>> found;
  for (FeaturePair f : candidates) {
    ContactPoint c;
    if (drivers.contact(a, j, f, max_gap, c)) found.emplace_back(f, c);
  }
  std::vector<std::uint8_t> drop(found.size(), 0);
  mark_shadowed(found.size(), [&](std::size_t k) { return found[k].first; },
                [&](std::size_t k) { return found[k].second.gap; }, a.radius, drop.data());
  std::vector<std::pair<FeaturePair, ContactPoint>> kept;
  for (std::size_t k = 0; k < found.size(); ++k)
    if (!drop[k]) kept.push_back(found[k]);
  return kept;
}

}  // namespace polydem::test
