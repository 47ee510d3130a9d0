#pragma once
// Fuzz targets: each feeds one input to a reader the user's files reach. Bad input must end in
// InputError (one clear line); any other exception, a crash or a sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace polydem::fuzz {

struct Target {
  std::string name;   // corpus/NAME and crashes/NAME hold its inputs
  void (*run)(const std::uint8_t* data, std::size_t size);
};

// scene (YAML), shp (shape library), stl (mesh), vti (fluid grid), checkpoint (resume).
const std::vector<Target>& targets();
const Target& target(const std::string& name);  // throws std::out_of_range

}  // namespace polydem::fuzz
