// The `bodies:` list: explicit bodies, `generate: random | lattice` entries and body tables.
#include <cmath>

#include "io/scene_body_table.hpp"
#include "io/scene_parts.hpp"
#include "polydem/error.hpp"

namespace polydem {
namespace {

const std::vector<std::string> kBodyKeys = {
    "shape",   "position", "orientation", "velocity", "angular_velocity",
    "density", "scale",    "group"};
const std::vector<std::string> kTableKeys = {"file", "density", "scale", "group"};
const std::vector<std::string> kGeneratorKeys = {"generate", "shapes",  "count",
                                                 "region",   "scale",   "orientation",
                                                 "velocity", "density", "group"};

BodySpec read_body(const YAML::Node& item, const std::string& file, int line) {
  for (const char* key : {"shapes", "count", "region"})
    if (item[key])
      throw InputError(
          input_message(file, line_of(item[key], line), key,
                        "belongs to a generator: add `generate: random` (or lattice)"));
  const YamlMap m(item, "body", file, line, kBodyKeys);
  BodySpec b;
  m.require("shape", "shape: cube");
  b.shape = m.scalar("shape");
  b.position = m.vec3("position", Dimension::length);
  b.orientation = m.orientation("orientation");
  b.velocity = m.vec3("velocity", Dimension::velocity, Vec3::Zero());
  b.angular_velocity = m.vec3("angular_velocity", Dimension::angular_velocity, Vec3::Zero());
  b.density = check_positive(m, "density", m.quantity("density", Dimension::density, b.density));
  b.scale = check_positive(m, "scale", m.quantity("scale", Dimension::dimensionless, b.scale));
  b.group = static_cast<int>(m.integer("group", 0, 0));
  b.loc = {file, m.line()};
  return b;
}

std::vector<std::pair<std::string, double>> read_mix(const YamlMap& m) {
  m.require("shapes", "shapes: cube, or shapes: {cube: 0.7, octahedron: 0.3}");
  const YAML::Node node = m.node("shapes");
  if (node.IsScalar()) return {{node.Scalar(), 1.0}};
  if (!node.IsMap())
    m.fail("shapes",
           "expected a shape name or a mix by number fraction {cube: 0.7, octahedron: 0.3}");
  std::vector<std::string> names;
  for (auto it = node.begin(); it != node.end(); ++it) names.push_back(it->first.Scalar());
  const YamlMap mix(node, "shapes", m.file(), m.line("shapes"), names);
  std::vector<std::pair<std::string, double>> out;
  double sum = 0.0;
  for (const std::string& name : names) {
    const double f = check_positive(mix, name, mix.quantity(name, Dimension::dimensionless));
    out.emplace_back(name, f);
    sum += f;
  }
  // Round-off in hand-typed fractions (0.1 + 0.2 + 0.7) is fine; a missing share is not.
  if (std::abs(sum - 1.0) > 1e-6)
    m.fail("shapes", "the number fractions sum to " + std::to_string(sum) + ", expected 1");
  for (auto& entry : out) entry.second /= sum;
  return out;
}

BoxRegion read_box(const YamlMap& region) {
  const YamlMap m = region.map("box", "box", {"min", "max"});
  BoxRegion box{m.vec3("min", Dimension::length), m.vec3("max", Dimension::length)};
  if (!(box.min.array() < box.max.array()).all())
    m.fail("max", "each component of max must exceed that of min");
  return box;
}

CylinderRegion read_cylinder(const YamlMap& region) {
  const YamlMap m = region.map("cylinder", "cylinder", {"center", "axis", "radius", "length"});
  CylinderRegion c;
  c.center = m.vec3("center", Dimension::length);
  c.axis = m.direction("axis", Vec3::UnitZ());
  c.radius = check_positive(m, "radius", m.quantity("radius", Dimension::length));
  c.length = check_positive(m, "length", m.quantity("length", Dimension::length));
  return c;
}

std::variant<BoxRegion, CylinderRegion> read_region(const YamlMap& g) {
  g.require("region", "region: {box: {min: [0, 0, 0], max: [0.1, 0.1, 0.1]}}");
  const YamlMap m = g.map("region", "region", {"box", "cylinder"});
  if (m.has("box") == m.has("cylinder"))
    g.fail("region",
           "give exactly one of box: {min, max} or cylinder: {center, axis, radius, length}");
  if (m.has("box")) return read_box(m);
  return read_cylinder(m);
}

void read_scale(const YamlMap& g, GeneratorSpec& spec) {
  if (!g.has("scale")) return;
  if (g.node("scale").IsMap()) {
    const YamlMap m = g.map("scale", "scale", {"min", "max"});
    spec.scale_min = check_positive(m, "min", m.quantity("min", Dimension::dimensionless));
    spec.scale_max = check_positive(m, "max", m.quantity("max", Dimension::dimensionless));
    if (spec.scale_max < spec.scale_min) m.fail("max", "must be >= min");
    return;
  }
  spec.scale_min = spec.scale_max =
      check_positive(g, "scale", g.quantity("scale", Dimension::dimensionless));
}

GeneratorSpec read_generator(const YAML::Node& item, const std::string& file, int line) {
  const YamlMap m(item, "generator", file, line, kGeneratorKeys);
  GeneratorSpec g;
  const std::string kind = m.scalar("generate");
  if (kind == "lattice")
    g.kind = GeneratorSpec::Kind::lattice;
  else if (kind != "random")
    m.fail("generate", "unknown generator '" + kind + "', expected random or lattice" +
                           did_you_mean(kind, {"random", "lattice"}));
  g.shapes = read_mix(m);
  m.require("count", "count: 1000");
  g.count = static_cast<int>(m.integer("count", 0, 1));
  g.region = read_region(m);
  read_scale(m, g);
  const std::string orientation = m.text("orientation", "random");
  if (orientation != "random" && orientation != "fixed")
    m.fail("orientation",
           "expected random or fixed" + did_you_mean(orientation, {"random", "fixed"}));
  g.random_orientation = orientation == "random";
  g.velocity = m.vec3("velocity", Dimension::velocity, Vec3::Zero());
  g.density = check_positive(m, "density", m.quantity("density", Dimension::density, g.density));
  g.group = static_cast<int>(m.integer("group", 0, 0));
  g.loc = {file, m.line()};
  g.shapes_loc = {file, m.line("shapes")};
  return g;
}

}  // namespace

void read_bodies(const YAML::Node& list, int line, Scene& scene) {
  require_sequence(list, scene.path, line, "bodies", "- shape: cube");
  for (const YAML::Node& item : list) {
    const int item_line = line_of(item, line);
    if (!item.IsMap())
      throw InputError(
          input_message(scene.path, item_line, "bodies",
                        "each body is a mapping like `- shape: cube`, `- generate: random` or "
                        "`- file: bodies.csv`"));
    if (item["file"])
      read_body_table(YamlMap(item, "body table", scene.path, item_line, kTableKeys), scene.folder,
                      scene.bodies);
    else if (item["generate"])
      scene.generators.push_back(read_generator(item, scene.path, item_line));
    else
      scene.bodies.push_back(read_body(item, scene.path, item_line));
  }
}

}  // namespace polydem
