#pragma once
// A fresh folder under the system's temp folder (mkdtemp: unique across processes, so tests
// run side by side by ctest -j never share one), removed with everything in it at scope end.
#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace polydem::test {

struct UniqueTempDir {
  std::filesystem::path path;
  explicit UniqueTempDir(const std::string& stem) {
    std::string pattern = (std::filesystem::temp_directory_path() / ("polydem_" + stem + "_XXXXXX")).string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
    path = pattern;
  }
  ~UniqueTempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  UniqueTempDir(const UniqueTempDir&) = delete;
  UniqueTempDir& operator=(const UniqueTempDir&) = delete;
};

}  // namespace polydem::test
