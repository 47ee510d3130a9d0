#pragma once
// Runs a simulation to its end: the output schedule (VTK, CSV, checkpoints), the progress
// line, and the stop on a non-finite state.
#include <optional>
#include <string>
#include <vector>

#include "sim/simulation.hpp"

namespace polydem {

struct RunOptions {
  std::string out_dir;               // the output folder (created)
  std::optional<double> until;       // s, stop at this time instead of simulation.duration
  std::string resume;                // checkpoint file to continue from
  bool force = false;                // resume a checkpoint written for another scene (with a warning)
  bool progress = true;              // print a progress line to stderr
  // Up to the allowed threads, fewer while fewer step faster (sim/thread_governor.hpp);
  // false: exactly the allowed threads (benchmarks of the thread efficiency).
  bool adapt_threads = true;
};

struct RunSummary {
  std::int64_t steps = 0;
  double wall_seconds = 0.0;
  std::size_t rebuilds = 0;
  bool interrupted = false;          // stopped by SIGINT or SIGTERM (a checkpoint written)
  std::vector<std::int64_t> steps_at_threads;  // steps run at each thread count (index = threads)
};

// Throws InputError for limits the run cannot honour (check_run_limits) or a checkpoint that
// does not fit; RunError when the state turns non-finite (after writing the last good state).
RunSummary run_simulation(Simulation& sim, const RunOptions& options);

}  // namespace polydem
