#pragma once
// Constants shared by the cell-list source files.
#include <cstddef>

namespace polydem::cells {

// Bodies below which loops run on one thread: forking costs more than the work saved.
constexpr std::size_t kMinParallel = 4096;

// Forward half of the 26 neighbour offsets (x, y, z): exactly one of each (+d, -d) couple.
constexpr int kOffsets[13][3] = {{1, 0, 0},  {-1, 1, 0}, {0, 1, 0},  {1, 1, 0}, {-1, -1, 1},
                                 {0, -1, 1}, {1, -1, 1}, {-1, 0, 1}, {0, 0, 1}, {1, 0, 1},
                                 {-1, 1, 1}, {0, 1, 1},  {1, 1, 1}};

}  // namespace polydem::cells
