#pragma once
// Where a value came from, for error messages: "scene.yaml:12: key 'radius': ...". Its own
// header, so a stage that names the input in its errors needs no scene header.
#include <string>

namespace polydem {

struct SourceLoc {
  std::string file;
  int line = 0;  // 1-based; 0 when unknown
};

}  // namespace polydem
