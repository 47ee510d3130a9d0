#pragma once
// Test files written to a fresh temporary folder.
#include <filesystem>
#include <fstream>
#include <string>

namespace polydem::test {

inline std::string temp_path(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "polydem_tests_shape";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

inline std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = temp_path(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

}  // namespace polydem::test
