#pragma once
// `polydem plot` and `polydem render`: pictures of a run's output folder, drawn by Python
// scripts (tools/view/plot.py with matplotlib, tools/view/render.py with VTK) that the
// program finds beside itself or in its source tree (README, "Pictures and plots").
#include <string>
#include <vector>

namespace polydem {

// args: OUT_DIR [-o DIR]. Returns the script's exit code (0 ok, 1 bad input, 2 failure).
int cmd_plot(const std::vector<std::string>& args);
// args: OUT_DIR [--time T | --every K] [--color NAME] [--size WxH] -o FILE.png|.mp4|.gif
int cmd_render(const std::vector<std::string>& args);

}  // namespace polydem
