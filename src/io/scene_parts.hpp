#pragma once
// The block readers load_scene is made of, one file each (scene_*.cpp).
#include <yaml-cpp/yaml.h>

#include <string>

#include "io/scene_settings.hpp"
#include "io/yaml_reader.hpp"

namespace polydem {

// A relative path in the scene, resolved against the scene's folder; InputError at the key
// when the file cannot be opened.
std::string resolve_input_file(const YamlMap& map, const std::string& key,
                               const std::string& folder, const std::string& what);

// Resolves `name` the same way for a value that is not a key of a mapping (a list item).
std::string resolve_input_path(const std::string& name, const std::string& folder,
                               const SourceLoc& loc, const std::string& key,
                               const std::string& what);

// InputError at `key` unless value > 0 (or >= 0 when `zero_ok`); returns the value.
double check_positive(const YamlMap& map, const std::string& key, double value,
                      bool zero_ok = false);

void read_bodies(const YAML::Node& list, int line, Scene& scene);
void read_drivers(const YAML::Node& list, int line, Scene& scene);
void read_forces(const YAML::Node& list, int line, Scene& scene);

// A `- item` list; a single null value is an empty list.
void require_sequence(const YAML::Node& node, const std::string& file, int line,
                      const std::string& key, const std::string& example);

}  // namespace polydem
