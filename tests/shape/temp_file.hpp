#pragma once
// Test files written to a temporary folder of this process (removed at exit).
#include <filesystem>
#include <fstream>
#include <string>

#include "../unique_temp_dir.hpp"

namespace polydem::test {

inline std::string temp_path(const std::string& name) {
  static const UniqueTempDir dir("shape");
  return (dir.path / name).string();
}

inline std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = temp_path(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

}  // namespace polydem::test
