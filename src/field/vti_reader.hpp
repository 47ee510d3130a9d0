#pragma once
// Reads VTK XML image data (.vti): ASCII, inline base64 and appended (raw or base64) arrays,
// uncompressed or zlib-compressed, as ParaView and python vtk write them. One piece covering
// the whole extent, axis-aligned (identity Direction), little-endian.
#include <map>
#include <string>
#include <vector>

#include "polydem/math.hpp"

namespace polydem {

struct VtiArray {
  int components = 1;
  std::vector<double> values;     // tuple after tuple, x fastest
};

struct VtiImage {
  Vec3 origin = Vec3::Zero();     // m, the point of index (0, 0, 0)
  Vec3 spacing = Vec3::Ones();    // m, between points
  Eigen::Vector3i points = Eigen::Vector3i::Ones();  // points per axis (WholeExtent)
  bool cell_data = false;         // arrays are CellData (else PointData)
  std::map<std::string, VtiArray> arrays;
};

// Throws InputError "PATH: what is wrong" for a missing or unreadable file, a file that is not
// VTK image data, a non-positive spacing, an unsupported encoding or a short array. Arrays come
// from CellData when it holds any, else from PointData.
VtiImage read_vti(const std::string& path);

}  // namespace polydem
