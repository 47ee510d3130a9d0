#pragma once
// A 64-bit fingerprint of a scene's physics, stored in checkpoints so that resuming another
// scene's checkpoint is refused: the time step, gravity, the contact law, each body's shape,
// mass, inertia and scale, each driver's kind, place, size (a mesh's vertices) and motion, drag
// and the fluid. Output settings, the duration, threads and skin (results do not depend on
// them) and names are left out.
#include <cstdint>
#include <string>

#include "sim/simulation.hpp"

namespace polydem {

std::uint64_t scene_fingerprint(const Simulation& sim);

// FNV-1a, 64 bits: the checksum of a checkpoint's bytes.
std::uint64_t fnv1a(const char* data, std::size_t size, std::uint64_t hash = 14695981039346656037ull);

}  // namespace polydem
