#pragma once
// Turning a triangulated convex hull into a shape's polygon faces (no CGAL here).
#include <array>
#include <vector>

#include "polydem/math.hpp"
#include "polydem/shape.hpp"

namespace polydem {

// Merges edge-adjacent triangles whose normals differ by less than `angle_tolerance` (rad)
// into convex polygons, keeping the triangles' (counter-clockwise) order.
std::vector<std::vector<int>> merge_coplanar(const std::vector<Vec3>& vertices,
                                             const std::vector<std::array<int, 3>>& triangles,
                                             double angle_tolerance);

// Convex hull of points lying in the plane with unit normal `normal`: indices of its corners,
// counter-clockwise seen from the side `normal` points to (collinear points dropped).
std::vector<int> planar_hull(const std::vector<Vec3>& points, const Vec3& normal);

// Drops polygon vertices where the boundary goes straight on (points on an edge), then the
// vertices no face uses, renumbering the faces.
void drop_non_corners(std::vector<Vec3>& vertices, std::vector<std::vector<int>>& faces);

}  // namespace polydem
