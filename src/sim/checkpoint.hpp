#pragma once
// Checkpoints: the full dynamic state of a run, so `--resume` continues bit for bit.
// The contact lists are rebuilt at every checkpoint step, in the uninterrupted run as in the
// resumed one, so only the active contacts (keys and histories) need to be stored.
#include <string>
#include <vector>

#include "sim/simulation.hpp"

namespace polydem {

struct OutputFrame {
  double time = 0.0;
  std::vector<std::string> files;   // relative to the output folder
};

struct OutputProgress {              // where the writers were, so a resumed run appends
  std::int64_t frame = 0;            // next VTK frame number
  std::vector<OutputFrame> frames;   // frames already in scene.pvd
};

void write_checkpoint(const std::string& path, const Simulation& sim, const OutputProgress& progress);
// Restores a checkpoint written for the same scene; throws InputError when it does not fit or
// is damaged. `force`: a checkpoint of another scene (fingerprint) resumes with a warning.
void read_checkpoint(const std::string& path, Simulation& sim, OutputProgress& progress, bool force = false);

// The body order a checkpoint (or a distributed run's manifest) holds: the user id of each
// stored body, the order its Simulation must be built in to resume it; the scene's order for
// files written before orders were stored, or of another body count than `bodies`.
std::vector<std::uint32_t> checkpoint_body_order(const std::string& path, std::size_t bodies);

}  // namespace polydem
