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

// Checks indices, decides `convex` and prepares the faces. A convex core (closed convex
// faces, one polygon, a segment, a point): faces reversed to point outward, the back face of a
// lone polygon added, `edges` filled from the faces when empty (or checked to match). Any other
// set (polylines, clusters, open or non-convex faces): faces kept as given, `edges` the listed
// ones plus every face edge, each once. Fills `face_normals`.
// Throws InputError "shape 'NAME': ..." on bad indices, zero-length edges, zero-area faces.
void prepare_topology(Shape& s);

// For each edge of s.edges, the two faces that share it (after prepare_topology).
std::vector<EdgeFaces> edge_faces(const Shape& s);

}  // namespace polydem
