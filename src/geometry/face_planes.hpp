#pragma once
// The planes the vertex-face kernel tests a vertex against, in the shape's own frame: one
// rotation of the vertex per call instead of one per face edge in the world.
#include "polydem/shape.hpp"

namespace polydem {

// Fills s.edge_planes and s.edge_plane_begin from vertices, faces and face_normals: per face
// edge (from the previous vertex, as projects_inside_polygon walks them) the in-plane unit
// normal pointing into the face, its offset moved inwards by kInteriorMargin times the edge
// length, so that "normal . x > offset" is that test's "strictly inside" side.
// Call wherever face_normals are set or the vertices move.
void derive_face_planes(Shape& s);

}  // namespace polydem
