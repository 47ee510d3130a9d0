#pragma once
// Shared by the output tests: a fresh temporary folder and the real-VTK reader (read_vtk.py).
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "json_lite.hpp"

namespace polydem::test {

// A new empty folder under the system temp dir, unique per process and name, removed at scope end.
struct TempDir {
  std::string path;
  explicit TempDir(const std::string& name)
      : path((std::filesystem::temp_directory_path() / ("polydem_output_" + std::to_string(::getpid()) + "_" + name))
                 .string()) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ignored;  // cleanup only: a leftover folder must not fail the test
    std::filesystem::remove_all(path, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
};

inline std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Reads `path` with VTK's XML readers through /usr/bin/python3 and tests/output/read_vtk.py.
// A missing vtk module is a failure, not a skip: CI must have the real reader.
inline Json read_with_vtk(const std::string& path) {
  const std::string command = "/usr/bin/python3 " POLYDEM_SOURCE_DIR "/tests/output/read_vtk.py '" + path + "' 2>&1";
  std::FILE* pipe = ::popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::string out;
  char buf[65536];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof(buf), pipe)) > 0;) out.append(buf, n);
  const int status = ::pclose(pipe);
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  INFO("command: " << command << "\noutput: " << out.substr(0, 2000));
  if (code == 3 || code == 127) FAIL("the VTK reader is missing: apt-get install python3-vtk9 (for /usr/bin/python3)");
  REQUIRE(code == 0);
  return JsonParser(out).parse();
}

}  // namespace polydem::test
