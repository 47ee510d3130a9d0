#pragma once
// Turns a scene's bodies and generators into the explicit list of bodies to simulate.
#include <vector>

#include "io/scene_settings.hpp"
#include "polydem/shape_library.hpp"

namespace polydem {

// Explicit bodies, then each generator's bodies, in file order. Reproducible: generator k
// draws from a stream seeded by (simulation.seed, k). `random` places non-overlapping
// bounding spheres (bounding_radius x scale) fully inside the region by random sequential
// insertion; `lattice` puts them on a cubic lattice of the largest bounding diameter. Both
// keep the bounding spheres clear of the drivers present at t = 0 (random: draws again;
// lattice: skips the site). Throws InputError for unknown shape names, for counts the region
// cannot hold and for unreadable STL files.
std::vector<BodySpec> expand_bodies(const Scene& scene, const ShapeLibrary& lib);

}  // namespace polydem
