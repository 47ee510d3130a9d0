#pragma once
// polydem's own YAML shape library format (described in shapes/README.md).
#include <string>
#include <vector>

#include "polydem/shape.hpp"

namespace polydem {

// A YAML list of shapes, each a mapping with `name`, `radius` and either `vertices`
// (+ optional `faces`, `edges`; two vertices without `edges` are a segment) or `points`
// (convex hull taken); optional `convex: false` (fast paths off) and `surface: true` (an open
// surface, as Rockable's isSurface). Optional precomputed
// `volume` + `inertia_per_mass` (+ `position`, `orientation` [w, x, y, z]) keep the vertices
// as given (principal frame); otherwise mass properties are computed.
// Throws InputError "FILE:LINE: key 'KEY': ..." with the nearest valid key for unknown ones.
std::vector<Shape> read_yaml_shapes(const std::string& path);

}  // namespace polydem
