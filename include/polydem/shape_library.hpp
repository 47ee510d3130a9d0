#pragma once
// The shapes a scene can use, loaded from library files (.shp Rockable format, or .yaml).
#include <string>
#include <vector>

#include "polydem/shape.hpp"

namespace polydem {

struct ShapeLibrary {
  std::vector<Shape> shapes;

  // Index of the shape called `name`, or -1.
  int find(const std::string& name) const {
    for (int i = 0; i < static_cast<int>(shapes.size()); ++i)
      if (shapes[i].name == name) return i;
    return -1;
  }
};

// Reads one library file (.shp or .yaml by extension); computes mass properties that the
// file does not give. Throws InputError naming the file and line on bad input.
std::vector<Shape> read_shape_file(const std::string& path);

// Reads every file in order; a later shape with the same name is an InputError.
ShapeLibrary load_shape_library(const std::vector<std::string>& paths);

}  // namespace polydem
