#pragma once
#include <string>
#include <vector>

#include "sim/rank_link.hpp"

namespace polydem {

// Exit code of a run stopped by SIGINT or SIGTERM after writing its checkpoint.
constexpr int kExitInterrupted = 3;

// `polydem run SCENE.yaml [--out DIR] [--threads N] [--until T] [--resume CHECKPOINT]`
// `link`: the ranks of `mpirun -np N` (N > 1), null for one process; rank 0 prints and writes.
int cmd_run(const std::vector<std::string>& args, const RankLink* link = nullptr);
// `polydem check SCENE.yaml`
int cmd_check(const std::vector<std::string>& args);

}  // namespace polydem
