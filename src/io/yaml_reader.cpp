#include "io/yaml_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "polydem/error.hpp"

namespace polydem {

int line_of(const YAML::Node& node, int fallback) {
  if (!node.IsDefined()) return fallback;  // Mark() throws on a missing node
  const int line = node.Mark().line;
  return line >= 0 ? line + 1 : fallback;
}

YamlMap::YamlMap(const YAML::Node& node, std::string block, std::string file, int line,
                 std::vector<std::string> allowed)
    : node_(node),
      block_(std::move(block)),
      file_(std::move(file)),
      line_(line > 0 ? line : line_of(node)) {
  if (!node.IsDefined() || node.IsNull()) return;
  if (!node.IsMap())
    throw InputError(
        input_message(file_, line_, block_, "expected a mapping of keys, like {key: value}"));
  for (auto it = node.begin(); it != node.end(); ++it) {
    const std::string key = it->first.Scalar();
    const int key_line = line_of(it->first, line_);
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      throw InputError(input_message(
          file_, key_line, key, "unknown key in '" + block_ + "'" + did_you_mean(key, allowed)));
    if (!key_lines_.emplace(key, key_line).second)
      throw InputError(input_message(file_, key_line, key, "given twice in '" + block_ + "'"));
  }
}

int YamlMap::line(const std::string& key) const {
  const auto it = key_lines_.find(key);
  return it == key_lines_.end() ? line_ : it->second;
}

void YamlMap::fail(const std::string& key, const std::string& message) const {
  throw InputError(input_message(file_, line(key), key, message));
}

void YamlMap::require(const std::string& key, const std::string& example) const {
  if (!has(key)) fail(key, "missing in '" + block_ + "' (e.g. " + example + ")");
}

std::string YamlMap::scalar(const std::string& key) const {
  const YAML::Node value = node_[key];
  if (!value.IsScalar()) fail(key, "expected a single value, not a list or a mapping");
  return value.Scalar();
}

double YamlMap::quantity_of(const YAML::Node& value, const std::string& key, Dimension dim) const {
  if (!value.IsScalar())
    fail(key, "expected a number or a quantity string like \"" + dimension_example(dim) + "\" (" +
                  dimension_name(dim) + ")");
  return parse_quantity(value.Scalar(), dim, loc(key), key);
}

double YamlMap::quantity(const std::string& key, Dimension dim) const {
  require(key, key + ": \"" + dimension_example(dim) + "\"");
  return quantity_of(node_[key], key, dim);
}

double YamlMap::quantity(const std::string& key, Dimension dim, double fallback) const {
  return has(key) ? quantity_of(node_[key], key, dim) : fallback;
}

std::optional<double> YamlMap::optional_quantity(const std::string& key, Dimension dim) const {
  if (!has(key)) return std::nullopt;
  return quantity_of(node_[key], key, dim);
}

Vec3 YamlMap::vec3(const std::string& key, Dimension dim, const Vec3& fallback) const {
  if (!has(key)) return fallback;
  const YAML::Node value = node_[key];
  if (!value.IsSequence() || value.size() != 3)
    fail(key, "expected a list of 3 numbers like [0, 0, \"" + dimension_example(dim) + "\"]" +
                  (value.IsSequence() ? ", got " + std::to_string(value.size()) : std::string()));
  Vec3 v;
  for (int i = 0; i < 3; ++i) v[i] = quantity_of(value[i], key, dim);
  return v;
}

Vec3 YamlMap::vec3(const std::string& key, Dimension dim) const {
  require(key, key + ": [0, 0, 1]");
  return vec3(key, dim, Vec3::Zero());
}

Vec3 YamlMap::direction(const std::string& key, const Vec3& fallback) const {
  const Vec3 v = vec3(key, Dimension::dimensionless, fallback);
  if (!(v.norm() > 0.0)) fail(key, "a direction must not be the zero vector (e.g. [0, 0, 1])");
  return v.normalized();
}

long long YamlMap::integer(const std::string& key, long long fallback, long long min) const {
  if (!has(key)) return fallback;
  const std::string s = scalar(key);
  long long value = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || ptr != s.data() + s.size())
    fail(key, "expected a whole number, got \"" + s + "\"");
  if (value < min) fail(key, "must be at least " + std::to_string(min) + ", got " + s);
  return value;
}

std::uint64_t YamlMap::unsigned64(const std::string& key, std::uint64_t fallback) const {
  if (!has(key)) return fallback;
  const std::string s = scalar(key);
  std::uint64_t value = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || ptr != s.data() + s.size())
    fail(key, "expected a whole number >= 0, got \"" + s + "\"");
  return value;
}

bool YamlMap::boolean(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  bool value = false;
  if (!YAML::convert<bool>::decode(node_[key], value))
    fail(key, "expected true or false, got \"" + scalar(key) + "\"");
  return value;
}

std::string YamlMap::text(const std::string& key, const std::string& fallback) const {
  if (!has(key)) return fallback;
  const std::string s = scalar(key);
  if (s.empty()) fail(key, "must not be empty");
  return s;
}

Quat YamlMap::orientation(const std::string& key) const {
  if (!has(key)) return Quat::Identity();
  const YamlMap m = map(key, key, {"axis", "angle", "quaternion"});
  if (m.has("quaternion")) {
    if (m.has("axis") || m.has("angle"))
      m.fail("quaternion", "give either quaternion: [w, x, y, z] or {axis, angle}, not both");
    const YAML::Node q = m.node_["quaternion"];
    if (!q.IsSequence() || q.size() != 4)
      m.fail("quaternion", "expected a list of 4 numbers [w, x, y, z]");
    double c[4];
    for (int i = 0; i < 4; ++i) c[i] = m.quantity_of(q[i], "quaternion", Dimension::dimensionless);
    const Quat quat(c[0], c[1], c[2], c[3]);
    if (!(quat.norm() > 0.0)) m.fail("quaternion", "must not be zero (identity: [1, 0, 0, 0])");
    return quat.normalized();
  }
  m.require("axis", "orientation: {axis: [0, 0, 1], angle: \"30 deg\"}");
  m.require("angle", "angle: \"30 deg\"");
  const Vec3 axis = m.direction("axis", Vec3::UnitZ());
  return Quat(Eigen::AngleAxisd(m.quantity("angle", Dimension::angle), axis));
}

YamlMap YamlMap::map(const std::string& key, const std::string& block,
                     std::vector<std::string> allowed) const {
  return YamlMap(has(key) ? node_[key] : YAML::Node(), block, file_, line(key), std::move(allowed));
}

std::pair<std::string, YAML::Node> single_entry(const YAML::Node& item, const std::string& file,
                                                const std::string& what,
                                                const std::vector<std::string>& names) {
  const int line = line_of(item);
  if (!item.IsMap() || item.size() != 1)
    throw InputError(input_message(
        file, line, what, "each item must be one `name: {...}`, like `- " + names[0] + ": {...}`"));
  const auto it = item.begin();
  const std::string name = it->first.Scalar();
  if (std::find(names.begin(), names.end(), name) == names.end())
    throw InputError(input_message(file, line_of(it->first, line), name,
                                   "unknown item in '" + what + "'" + did_you_mean(name, names)));
  return {name, it->second};
}

}  // namespace polydem
