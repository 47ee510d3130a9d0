#pragma once
// Turns a scene's bodies and generators into the explicit list of bodies to simulate.
#include <vector>

#include "polydem/scene.hpp"
#include "polydem/shape_library.hpp"

namespace polydem {

// Explicit bodies, then each generator's bodies, in file order. Reproducible: generator k
// draws from a stream seeded by (simulation.seed, k). `random` places non-overlapping
// bounding spheres (bounding_radius x scale) fully inside the region by random sequential
// insertion; `lattice` puts them on a cubic lattice of the largest bounding diameter.
// Throws InputError for unknown shape names and for counts the region cannot hold.
std::vector<BodySpec> expand_bodies(const Scene& scene, const ShapeLibrary& lib);

}  // namespace polydem
