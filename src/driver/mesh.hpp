#pragma once
// A triangle-mesh driver (STL): welded vertices, each edge once, triangles, in the mesh frame
// (file coordinates x scale); placed in the world by a rotation and a translation.
//
// Contact features and the interior rule. Triangles are two-sided (open and non-convex
// meshes are accepted): a particle touches a face from the side its centre is on. Vertices
// and edges are features like a polyhedron's, except where the surface is locally flat:
// - an edge whose two triangles are coplanar (within kFlatSin) is not a feature; a point
//   above it is over exactly one of the two faces (FlatEdge);
// - a vertex whose edges are all flat is not a feature either.
// A feature pair holds only when its normal lies in the normal cone of the mesh feature
// (edge: n . t <= 0 for the in-face direction t into each triangle of the edge; vertex:
// n . (w - v) <= 0 for each neighbour w), the exact Voronoi rule: a concave edge or vertex
// never touches. With the engine's shadowing (a vertex-face contact drops the vertex-edge
// and vertex-vertex ones of the same particle vertex) a cube on a meshed floor has exactly
// the four vertex-face springs it has on a wall.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "polydem/math.hpp"

namespace polydem {

struct TriangleMesh;

class MeshFeatures {
 public:
  // Builds the topology and the spatial index; `scale` multiplies the file coordinates.
  // Skips zero-area triangles (their count in `skipped`); throws std::invalid_argument for
  // non-finite coordinates or a mesh with no triangle left.
  MeshFeatures(const TriangleMesh& mesh, double scale, std::size_t& skipped);

  std::vector<Vec3> vertices;                   // m, mesh frame
  std::vector<std::array<int, 3>> faces;        // counter-clockwise around face_normals
  std::vector<Vec3> face_normals;               // unit, from the file's vertex order
  std::vector<std::array<int, 2>> edges;        // the feature (non-flat) edges, each once
  std::vector<std::array<int, 3>> face_edges;   // per face, edge k (v_k -> v_k+1): index in `edges`, or -1 when flat

  // A flat edge is split between its faces by one test, p over the owner iff
  // (p - vertices[lo]) . inward >= -margin, evaluated alike from both faces: never both, never neither.
  struct FlatEdge {
    int lo;         // its lower vertex index
    Vec3 inward;    // unit, in the owner's plane, perpendicular to the edge, into the owner
    int owner;      // the lower face index
  };
  std::vector<FlatEdge> flat_edges;
  std::vector<std::array<int, 3>> face_flat;    // per face, edge k: index in `flat_edges`, or -1
  std::vector<std::uint8_t> vertex_feature;     // per vertex: 1 when it is a contact feature

  // Normal cones: per feature edge the unit in-face directions into its triangles; per
  // vertex its neighbours (CSR).
  std::vector<std::uint32_t> edge_inward_begin;
  std::vector<Vec3> edge_inward;
  std::vector<std::uint32_t> neighbour_begin;
  std::vector<int> neighbours;

  // Faces whose bounding box meets the box of the sphere (centre, radius), mesh frame, each
  // once, ascending. Returns how many cell entries it examined (the search cost).
  std::size_t faces_near(const Vec3& centre, double radius, std::vector<std::uint32_t>& out) const;
  bool any_face_near(const Vec3& centre, double radius) const;

  double area() const;  // m^2, total

 private:
  void build_topology();
  void build_grid();
  bool box_meets(std::uint32_t f, const Vec3& lo, const Vec3& hi) const;
  template <class Visit> void visit_cells(const Vec3& lo, const Vec3& hi, Visit visit) const;

  std::vector<Vec3> box_lo_, box_hi_;           // m, per face
  Vec3 grid_lo_ = Vec3::Zero();
  double cell_ = 1.0;                           // m
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<std::uint32_t> cell_begin_, cell_faces_;
};

// sin of the dihedral angle under which two triangles of an edge count as coplanar
// (1e-5 rad: float32 STL coordinates of a tilted plane tilt 1 cm triangles 1 m away by ~6e-6).
inline constexpr double kFlatSin = 1e-5;
// Slack of the normal-cone tests (unit vectors): boundaries between regions are covered twice
// rather than missed, and the shadowing rule removes the duplicate.
inline constexpr double kConeSlack = 1e-6;

}  // namespace polydem
