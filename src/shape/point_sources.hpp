#pragma once
// Point sets and triangle meshes read from files: point lists, OBJ, STL (ASCII and binary).
#include <array>
#include <string>
#include <vector>

#include "polydem/math.hpp"

namespace polydem {

struct TriangleMesh {
  std::vector<Vec3> vertices;                 // file units, each distinct point once
  std::vector<std::array<int, 3>> triangles;  // vertex indices, in the file's order
};

// Text, one "x y z" per line; '#' starts a comment; blank lines skipped.
std::vector<Vec3> read_point_list(const std::string& path);

// The "v x y z" lines of a Wavefront OBJ (faces and the rest ignored).
std::vector<Vec3> read_obj_points(const std::string& path);

// STL, binary or ASCII: binary when the size is 84 + 50 n with n the count at byte 80
// (binary files may begin with "solid" too). Identical vertices are welded into one; triangles
// that collapse after welding are dropped. Errors name the file (and the line, for ASCII).
TriangleMesh read_stl(const std::string& path);

// By extension: .stl, .obj, anything else a point list.
std::vector<Vec3> read_points(const std::string& path);

}  // namespace polydem
