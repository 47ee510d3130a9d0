#pragma once
// Faces, edges and their adjacency for a shape: checks, outward orientation, normals.
#include <array>
#include <vector>

#include "polydem/shape.hpp"

namespace polydem {

// The two faces bordering an edge (-1 when the shape has no faces: sphere, segment).
struct EdgeFaces {
  int face1 = -1;
  int face2 = -1;
};

// Unit normal of a polygon by Newell's method (robust for slightly non-planar polygons).
Vec3 polygon_normal(const std::vector<Vec3>& vertices, const std::vector<int>& face);

// Checks indices and topology, reverses faces that point inward (solids only), adds the
// back face of a lone polygon (a plate given with one face), fills
// `edges` from the faces when empty (or checks they match) and `face_normals`.
// Throws InputError "shape 'NAME': ..." on a topology the mass properties cannot handle.
void prepare_topology(Shape& s);

// For each edge of s.edges, the two faces that share it (after prepare_topology).
std::vector<EdgeFaces> edge_faces(const Shape& s);

}  // namespace polydem
