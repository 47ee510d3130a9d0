#pragma once
// Temporary scene folders and error-message checks shared by the io tests.
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "polydem/error.hpp"

namespace polydem::test {

// A fresh folder under the system temp dir, removed with everything in it at the end.
struct TempDir {
  std::filesystem::path path;
  TempDir() {
    std::random_device device;
    path = std::filesystem::temp_directory_path() / ("polydem_io_" + std::to_string(device()));
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  std::string write(const std::string& name, const std::string& text) const {
    const auto file = path / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file.string();
  }
};

// The InputError message `f` throws, or "" when it does not throw one.
template <class F>
std::string input_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace polydem::test
