#pragma once
// VTK image data (.vti) of cell values on a regular grid: the fluid and its void fraction.
#include <string>
#include <vector>

#include "polydem/math.hpp"

namespace polydem {

struct ImageArray {
  std::string name;
  int components = 1;             // 1 (scalar) or 3 (vector)
  std::vector<double> values;     // cell after cell, x fastest
};

// Writes CellData arrays (Float64, binary appended raw, UInt64 headers) on the grid of
// `cells` cells of size `spacing` from `origin` (m).
void write_image_vti(const std::string& path, const Vec3& origin, const Vec3& spacing,
                     const Eigen::Vector3i& cells, const std::vector<ImageArray>& arrays);

}  // namespace polydem
