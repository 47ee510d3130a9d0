#pragma once
// Shapes from point sets by convex hull (the only code that uses CGAL, kept out of headers).
#include <string>
#include <vector>

#include "polydem/shape.hpp"

namespace polydem {

// Convex hull of `points` swept by a sphere of `radius` (m), mass properties computed.
// Coplanar triangles are merged into convex polygon faces (counter-clockwise seen from
// outside); points that are not hull corners are dropped. Degenerate sets with radius > 0
// give a sphere (1 point), a segment (collinear points) or a two-sided plate (coplanar
// points, within 1e-9 of their extent). Throws InputError for radius < 0, no point, or a
// degenerate set with radius 0.
Shape build_hull_shape(const std::vector<Vec3>& points, double radius, const std::string& name);

}  // namespace polydem
