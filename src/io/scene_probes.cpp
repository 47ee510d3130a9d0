// output.probes: `- flow: {...}` and `- repose_angle: {...}` items, checked against the
// drivers and gravity of the scene.
#include "io/scene_probes.hpp"

#include <algorithm>
#include <cctype>
#include <map>

#include "io/scene_parts.hpp"
#include "polydem/error.hpp"
#include "shape/suggest.hpp"

namespace polydem {
namespace {

const std::vector<std::string> kProbeKinds = {"flow", "repose_angle"};

// A probe name becomes a file name beside energy.csv and driver_NAME.csv.
void check_name(const YamlMap& m, const std::string& name) {
  const bool safe = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
  if (!safe) m.fail("name", "'" + name + "' must be letters, digits, '_' or '-' (it names NAME.csv)");
  if (name == "energy" || name.rfind("driver_", 0) == 0)
    m.fail("name", "'" + name + "' would overwrite " + name + ".csv written by polydem; choose another name");
}

OutputSettings::FlowProbe read_flow(const YamlMap& m) {
  OutputSettings::FlowProbe p;
  p.name = m.text("name", "flow");
  p.loc = {m.file(), m.line()};
  m.require("point", "point: [0, 0, 0]");
  p.point = m.vec3("point", Dimension::length);
  m.require("normal", "normal: [0, 0, -1] (towards the side the discharged bodies reach)");
  p.normal = m.direction("normal", -Vec3::UnitZ());
  return p;
}

// The drum's name and axis (unit).
std::pair<std::string, Vec3> drum_driver(const YamlMap& m, const Scene& scene) {
  m.require("driver", "driver: drum (the name of a cylinder driver)");
  const std::string name = m.scalar("driver");
  std::vector<std::string> names;
  for (const DriverSettings& d : scene.drivers) {
    const CylinderSettings* cylinder = std::get_if<CylinderSettings>(&d.kind);
    if (d.name == name) {
      if (!cylinder) m.fail("driver", "'" + name + "' is not a cylinder: the angle of repose is measured in a drum");
      return {d.name, cylinder->axis};
    }
    if (cylinder) names.push_back(d.name);
  }
  m.fail("driver", "no cylinder driver named '" + name + "'" +
                       (names.empty() ? std::string(" (the scene has none)") : did_you_mean(name, names)));
}

OutputSettings::ReposeProbe read_repose(const YamlMap& m, const Scene& scene) {
  OutputSettings::ReposeProbe p;
  p.name = m.text("name", "angle");
  p.loc = {m.file(), m.line()};
  const auto [drum, axis] = drum_driver(m, scene);
  p.driver = drum;
  const std::optional<Vec3>& g = scene.forces.gravity;
  if (!g || g->norm() == 0.0)
    m.fail("driver", "the angle of repose is measured against gravity: add `- gravity_force: {}` to forces");
  if (g->cross(axis).norm() < 1e-6 * g->norm())
    m.fail("driver", "the drum '" + drum + "' has its axis along gravity: its free surface has no slope");
  if (m.has("column")) p.column = check_positive(m, "column", m.quantity("column", Dimension::length));
  p.fit = m.quantity("fit", Dimension::dimensionless, p.fit);
  if (!(p.fit > 0.0 && p.fit <= 1.0)) m.fail("fit", "must be in (0, 1], got " + m.scalar("fit"));
  return p;
}

// Reads one `- kind: {...}` item into the scene; returns its name and line.
std::pair<std::string, int> read_probe(const YAML::Node& item, int line, Scene& scene) {
  const auto [kind, body] = single_entry(item, scene.path, "probes", kProbeKinds);
  const bool flow = kind == "flow";
  const YamlMap m(body, kind, scene.path, line_of(item, line),
                  flow ? std::vector<std::string>{"name", "point", "normal"}
                       : std::vector<std::string>{"name", "driver", "column", "fit"});
  OutputSettings& out = scene.output;
  if (flow) out.flow_probes.push_back(read_flow(m));
  else out.repose_probes.push_back(read_repose(m, scene));
  const std::string& name = flow ? out.flow_probes.back().name : out.repose_probes.back().name;
  check_name(m, name);
  return {name, m.line()};
}

// The line of the `probes:` key (its list may start on the next line).
int probes_line(const YAML::Node& output, int fallback) {
  for (const auto& entry : output)
    if (entry.first.Scalar() == "probes") return line_of(entry.first, fallback);
  return fallback;
}

}  // namespace

void read_probes(const YamlMap& root, Scene& scene) {
  if (!root.has("output")) return;
  const YAML::Node list = root.node("output")["probes"];
  if (!list) return;
  const int line = probes_line(root.node("output"), root.line("output"));
  require_sequence(list, scene.path, line, "probes", "- flow: {point: [0, 0, 0], normal: [0, 0, -1]}");
  if (list.size() > 0 && !scene.output.csv_every)
    throw InputError(input_message(scene.path, line, "probes",
                                   "probes are written on the csv_every schedule: add `csv_every: \"1 ms\"` to output"));
  std::map<std::string, int> name_lines;
  for (const YAML::Node& item : list) {
    const auto [name, item_line] = read_probe(item, line, scene);
    const auto [it, fresh] = name_lines.emplace(name, item_line);
    if (!fresh)
      throw InputError(input_message(scene.path, item_line, "name",
                                     "probe name '" + name + "' is already used at line " +
                                         std::to_string(it->second) +
                                         "; each probe writes NAME.csv, so names must be unique"));
  }
}

}  // namespace polydem
