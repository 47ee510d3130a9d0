#pragma once
#include <string>
#include <vector>

namespace polydem {

// Exit code of a run stopped by SIGINT or SIGTERM after writing its checkpoint.
constexpr int kExitInterrupted = 3;

// `polydem run SCENE.yaml [--out DIR] [--threads N] [--until T] [--resume CHECKPOINT]`
int cmd_run(const std::vector<std::string>& args);
// `polydem check SCENE.yaml`
int cmd_check(const std::vector<std::string>& args);

}  // namespace polydem
