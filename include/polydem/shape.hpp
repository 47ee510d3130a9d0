#pragma once
// A spheropolyhedron shape: vertices, edges and planar convex faces swept by a sphere of radius
// `radius`; convex or not (a polyline, a cluster of spheres, an open surface), decided at load.
#include <array>
#include <string>
#include <vector>

#include "polydem/math.hpp"

namespace polydem {

// The points x with normal . x = offset (m), in the principal frame at scale 1.
struct Plane {
  Vec3 normal;    // unit
  double offset;  // m
};

struct Shape {
  std::string name;
  double radius = 0.0;                      // m, Minkowski (rounding) radius, > 0
  std::vector<Vec3> vertices;               // m, principal frame, about the centre of mass
  std::vector<std::array<int, 2>> edges;    // vertex index pairs, each edge once
  std::vector<std::vector<int>> faces;      // convex polygons, counter-clockwise seen from outside
  // True when the core is a convex polyhedron, a segment or a point (decided at load): only
  // then do the contact fast paths hold (vertex-over-face shadowing, one patch per body pair).
  bool convex = true;
  bool surface = false;                     // an open surface (Rockable's isSurface): faces two-sided

  // Mass properties of the rounded body (filled by compute_mass_properties).
  double volume = 0.0;                      // m^3, volume of the rounded body (overlaps counted once)
  double mass_error = 0.0;                  // relative error bound of volume and inertia (0: closed form)
  Vec3 inertia_per_mass = Vec3::Zero();     // m^2, principal moments of inertia / mass
  double bounding_radius = 0.0;             // m, max |vertex| + radius (about the centre of mass)
  std::vector<Vec3> face_normals;           // outward unit normals, one per face
  // Face f owns edge_planes[edge_plane_begin[f] .. edge_plane_begin[f + 1]), one per edge in
  // face order (geometry/face_planes.hpp).
  std::vector<Plane> edge_planes;
  std::vector<int> edge_plane_begin;        // faces.size() + 1 entries

  // Placement of the principal frame in the frame the shape was given in:
  // x_input = input_center + input_rotation * x_principal.
  Vec3 input_center = Vec3::Zero();
  Quat input_rotation = Quat::Identity();

  bool is_sphere() const { return vertices.size() == 1; }
};

// A sphere as a spheropolyhedron: one vertex at the origin, rounded by `radius` (m); geometry
// only (the mass properties are for the caller, a driver has none).
inline Shape sphere_shape(const std::string& name, double radius) {
  Shape s;
  s.name = name;
  s.radius = radius;
  s.vertices = {Vec3::Zero()};
  s.bounding_radius = radius;
  return s;
}

}  // namespace polydem
