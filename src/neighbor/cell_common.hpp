#pragma once
// Constants shared by the cell-list source files.
#include <cstddef>

namespace polydem::cells {

// Bodies below which loops run on one thread: forking (~10 us) costs more than the work saved
// (the pair search ~600 instructions a body: a 2,000-body pour's rebuild gains from 2 threads).
constexpr std::size_t kMinParallel = 1024;

// Forward half of the 26 neighbour offsets (x, y, z): exactly one of each (+d, -d) couple.
constexpr int kOffsets[13][3] = {{1, 0, 0},  {-1, 1, 0}, {0, 1, 0},  {1, 1, 0}, {-1, -1, 1},
                                 {0, -1, 1}, {1, -1, 1}, {-1, 0, 1}, {0, 0, 1}, {1, 0, 1},
                                 {-1, 1, 1}, {0, 1, 1},  {1, 1, 1}};

}  // namespace polydem::cells
