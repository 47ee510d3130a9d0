#pragma once
// Checked access to the YAML mappings of a scene file: unknown keys, wrong types and missing
// keys become InputError "FILE:LINE: key 'KEY': ..." with the nearest valid key suggested.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "io/units.hpp"
#include "shape/suggest.hpp"
#include "polydem/math.hpp"

namespace polydem {

// 1-based line of a node, or `fallback` when yaml-cpp has no mark for it.
int line_of(const YAML::Node& node, int fallback = 0);

// One mapping of the scene (`simulation`, `config`, a driver ...) and the keys it accepts.
class YamlMap {
 public:
  // `line`: of the key holding the mapping (0: the node's own). A null node is an empty
  // mapping; any other non-mapping is an InputError.
  YamlMap(const YAML::Node& node, std::string block, std::string file, int line,
          std::vector<std::string> allowed);

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int line(const std::string& key) const;  // the key's line, or the mapping's when absent
  SourceLoc loc(const std::string& key) const { return {file_, line(key)}; }
  bool has(const std::string& key) const { return key_lines_.count(key) > 0; }
  YAML::Node node(const std::string& key) const { return node_[key]; }
  std::string scalar(const std::string& key) const;  // required; the text of a scalar

  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  void require(const std::string& key, const std::string& example) const;

  double quantity(const std::string& key, Dimension dim) const;  // required
  double quantity(const std::string& key, Dimension dim, double fallback) const;
  std::optional<double> optional_quantity(const std::string& key, Dimension dim) const;
  Vec3 vec3(const std::string& key, Dimension dim, const Vec3& fallback) const;
  Vec3 vec3(const std::string& key, Dimension dim) const;              // required
  Vec3 direction(const std::string& key, const Vec3& fallback) const;  // normalized, non-zero
  long long integer(const std::string& key, long long fallback, long long min) const;
  std::uint64_t unsigned64(const std::string& key, std::uint64_t fallback) const;
  bool boolean(const std::string& key, bool fallback) const;
  std::string text(const std::string& key, const std::string& fallback) const;
  Quat orientation(const std::string& key) const;  // {axis, angle} or {quaternion}; identity

  YamlMap map(const std::string& key, const std::string& block,
              std::vector<std::string> allowed) const;

 private:
  double quantity_of(const YAML::Node& value, const std::string& key, Dimension dim) const;

  YAML::Node node_;
  std::string block_, file_;
  int line_;
  std::map<std::string, int> key_lines_;
};

// The single `name: {...}` of a list item such as `- wall: {...}`; checks the name is one
// of `names` (`what` says which list, for the message).
std::pair<std::string, YAML::Node> single_entry(const YAML::Node& item, const std::string& file,
                                                const std::string& what,
                                                const std::vector<std::string>& names);

}  // namespace polydem
