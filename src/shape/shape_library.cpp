// Shape library files: .shp (Rockable) or .yaml (polydem), chosen by extension.
#include "polydem/shape_library.hpp"

#include <algorithm>
#include <fstream>

#include "polydem/error.hpp"
#include "shape/shp_io.hpp"
#include "shape/yaml_shape.hpp"

namespace polydem {
namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && std::equal(tail.rbegin(), tail.rend(), s.rbegin(),
                                               [](char a, char b) { return std::tolower(a) == b; });
}

}  // namespace

std::vector<Shape> read_shape_file(const std::string& path) {
  if (!std::ifstream(path)) throw InputError(input_message(path, 0, "", "cannot open the shape file"));
  if (ends_with(path, ".shp")) return read_shp_file(path);
  if (ends_with(path, ".yaml") || ends_with(path, ".yml")) return read_yaml_shapes(path);
  throw InputError(input_message(path, 0, "", "unknown shape file type (use .shp or .yaml)"));
}

ShapeLibrary load_shape_library(const std::vector<std::string>& paths) {
  ShapeLibrary library;
  std::vector<std::string> origin;  // file each shape came from, for the duplicate message
  for (const std::string& path : paths)
    for (Shape& s : read_shape_file(path)) {
      const int previous = library.find(s.name);
      if (previous >= 0)
        throw InputError(input_message(path, 0, "name",
                                       "shape '" + s.name + "' is already defined in " + origin[previous] +
                                           " (shape names must be unique)"));
      origin.push_back(path);
      library.shapes.push_back(std::move(s));
    }
  return library;
}

}  // namespace polydem
