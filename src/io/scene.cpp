#include "io/scene.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/scene_parts.hpp"
#include "io/scene_probes.hpp"
#include "polydem/error.hpp"

namespace polydem {
namespace fs = std::filesystem;

std::string resolve_input_path(const std::string& name, const std::string& folder,
                               const SourceLoc& loc, const std::string& key,
                               const std::string& what) {
  const fs::path p(name);
  const fs::path resolved = p.is_absolute() ? p : (fs::path(folder) / p).lexically_normal();
  std::ifstream in(resolved);
  if (!in || fs::is_directory(resolved))
    throw InputError(input_message(loc.file, loc.line, key,
                                   "cannot open " + what + " '" + resolved.string() +
                                       "' (relative paths start at the scene's folder)"));
  return resolved.string();
}

std::string resolve_input_file(const YamlMap& map, const std::string& key,
                               const std::string& folder, const std::string& what) {
  map.require(key, key + ": file.ext");
  return resolve_input_path(map.scalar(key), folder, map.loc(key), key, what);
}

double check_positive(const YamlMap& map, const std::string& key, double value, bool zero_ok) {
  if (zero_ok ? value < 0.0 : !(value > 0.0))
    map.fail(key,
             std::string("must be ") + (zero_ok ? ">= 0" : "> 0") + ", got " + map.scalar(key));
  return value;
}

void require_sequence(const YAML::Node& node, const std::string& file, int line,
                      const std::string& key, const std::string& example) {
  if (!node.IsNull() && !node.IsSequence())
    throw InputError(
        input_message(file, line_of(node, line), key,
                      "expected a list of items, each starting with '- ' (e.g. " + example + ")"));
}

namespace {

constexpr long long kMaxThreads = 65536;  // an int for OpenMP; far beyond any machine's cores

// yaml-cpp's message for a tab in the indentation does not say so.
std::string tab_hint(const std::string& text, int line) {
  std::istringstream lines(text);
  std::string l;
  for (int i = 0; i < line && std::getline(lines, l); ++i) {
  }
  return l.find('\t') != std::string::npos ? " (YAML does not allow tabs: indent with spaces)" : "";
}

YAML::Node load_yaml(const std::string& path) {
  if (!fs::exists(path))
    throw InputError(input_message(path, 0, "", "cannot open the scene file (no such file)"));
  if (!fs::is_regular_file(path))
    throw InputError(input_message(path, 0, "", "cannot open the scene file (not a file)"));
  std::ifstream in(path);
  if (!in) throw InputError(input_message(path, 0, "", "cannot open the scene file"));
  std::stringstream text;
  text << in.rdbuf();
  try {
    return YAML::Load(text.str());
  } catch (const YAML::ParserException& e) {
    throw InputError(
        input_message(path, e.mark.line + 1, "",
                      "YAML syntax error: " + e.msg + tab_hint(text.str(), e.mark.line + 1)));
  }
}

// Remembers where each given key of `m` is, as "BLOCK.KEY".
void note_locs(const YamlMap& m, const std::string& block, const std::vector<std::string>& keys, Scene& scene) {
  for (const std::string& k : keys)
    if (m.has(k)) scene.key_locs[block + "." + k] = m.loc(k);
  scene.key_locs[block] = {m.file(), m.line()};
}

// The restitution error `dt: auto` aims at, kMinAccuracy..kMaxAccuracy (the measured range of
// sim/step_accuracy.cpp); it chooses the step, so a numeric dt conflicts with it.
std::optional<double> read_accuracy(const YamlMap& m, bool numeric_dt) {
  if (!m.has("accuracy")) return std::nullopt;
  const double a = m.quantity("accuracy", Dimension::dimensionless);
  if (!(a >= kMinAccuracy && a <= kMaxAccuracy))
    m.fail("accuracy", "the relative restitution error must be within [1e-5, 0.2], got " + m.scalar("accuracy"));
  if (numeric_dt)
    m.fail("accuracy", "accuracy chooses the step: it needs dt: auto (or no dt), but dt is " + m.scalar("dt"));
  return a;
}

SimulationSettings::BodyOrder read_body_order(const YamlMap& m) {
  if (!m.has("body_order") || m.scalar("body_order") == "space") return SimulationSettings::BodyOrder::space;
  if (m.scalar("body_order") != "input")
    m.fail("body_order", "expected space (bodies stored by cell) or input (as listed), got " + m.scalar("body_order"));
  return SimulationSettings::BodyOrder::input;
}

SimulationSettings read_simulation(const YamlMap& root, Scene& scene) {
  root.require("simulation", "simulation: {duration: \"1 s\", dt: auto}");
  const YamlMap m =
      root.map("simulation", "simulation", {"duration", "dt", "accuracy", "threads", "skin", "skin_max", "seed", "body_order"});
  SimulationSettings s;
  s.duration = check_positive(m, "duration", m.quantity("duration", Dimension::time));
  if (m.has("dt") && m.scalar("dt") != "auto")
    s.dt = check_positive(m, "dt", m.quantity("dt", Dimension::time));
  s.accuracy = read_accuracy(m, s.dt.has_value());
  const long long threads = m.integer("threads", 0, 0);
  if (threads > kMaxThreads)
    m.fail("threads", "at most " + std::to_string(kMaxThreads) + ", got " + m.scalar("threads"));
  s.threads = static_cast<int>(threads);
  if (m.has("skin")) s.skin = check_positive(m, "skin", m.quantity("skin", Dimension::length));
  if (m.has("skin_max")) s.skin_max = check_positive(m, "skin_max", m.quantity("skin_max", Dimension::length));
  if (s.skin && s.skin_max && *s.skin_max < *s.skin)
    m.fail("skin_max", m.scalar("skin_max") + " is below the skin " + m.scalar("skin") + ": a body's skin lies between them");
  s.seed = m.unsigned64("seed", 0);
  s.body_order = read_body_order(m);
  note_locs(m, "simulation", {"duration", "dt", "accuracy", "threads", "skin", "skin_max"}, scene);
  if (s.dt && *s.dt > s.duration)
    m.fail("dt", "the step " + m.scalar("dt") + " is longer than the duration " + m.scalar("duration") +
                     " (the limit): the run would take no step");
  return s;
}

std::vector<std::string> read_shape_files(const YamlMap& root, const std::string& folder) {
  if (!root.has("shapes")) return {};
  const YAML::Node node = root.node("shapes");
  if (node.IsScalar()) return {resolve_input_file(root, "shapes", folder, "shape library")};
  require_sequence(node, root.file(), root.line("shapes"), "shapes", "- shapes/platonic.shp");
  std::vector<std::string> files;
  for (const YAML::Node& item : node) {
    const SourceLoc loc{root.file(), line_of(item, root.line("shapes"))};
    if (!item.IsScalar())
      throw InputError(input_message(loc.file, loc.line, "shapes", "expected a file name"));
    files.push_back(resolve_input_path(item.Scalar(), folder, loc, "shapes", "shape library"));
  }
  return files;
}

OutputSettings read_output(const YamlMap& root, Scene& scene) {
  const std::string& folder = scene.folder;
  const YamlMap m = root.map("output", "output",
                             {"dir", "vtk_every", "csv_every", "checkpoint_every", "contacts", "rounded", "probes"});
  OutputSettings o;
  const fs::path dir(m.text("dir", "out"));
  o.dir = (dir.is_absolute() ? dir : (fs::path(folder) / dir).lexically_normal()).string();
  for (auto [key, field] : {std::pair{"vtk_every", &o.vtk_every},
                            {"csv_every", &o.csv_every},
                            {"checkpoint_every", &o.checkpoint_every}})
    if (m.has(key)) *field = check_positive(m, key, m.quantity(key, Dimension::time));
  o.contacts = m.boolean("contacts", true);
  note_locs(m, "output", {"vtk_every", "csv_every", "checkpoint_every"}, scene);
  o.rounded = m.boolean("rounded", false);
  return o;
}

}  // namespace

Scene load_scene(const std::string& path) {
  const YAML::Node doc = load_yaml(path);
  if (!doc.IsMap())
    throw InputError(input_message(path, line_of(doc, 1), "",
                                   "a scene must be a mapping with the keys simulation, shapes, "
                                   "bodies, drivers, forces and output (see SCENE.md)"));
  Scene scene;
  scene.path = path;
  const fs::path parent = fs::path(path).parent_path();
  scene.folder = parent.empty() ? "." : parent.string();
  const YamlMap root(doc, "scene", path, 1,
                     {"simulation", "shapes", "bodies", "drivers", "forces", "output"});
  scene.simulation = read_simulation(root, scene);
  scene.shape_files = read_shape_files(root, scene.folder);
  if (root.has("bodies")) read_bodies(root.node("bodies"), root.line("bodies"), scene);
  if (!scene.bodies.empty() || !scene.generators.empty()) {
    if (scene.shape_files.empty())
      root.fail(root.has("shapes") ? "shapes" : "bodies",
                "bodies need a shape library: add `shapes: [my_shapes.shp]`");
  }
  if (root.has("drivers")) read_drivers(root.node("drivers"), root.line("drivers"), scene);
  if (root.has("forces")) read_forces(root.node("forces"), root.line("forces"), scene);
  scene.output = read_output(root, scene);
  read_probes(root, scene);  // after drivers, forces and csv_every: it checks against them
  return scene;
}

}  // namespace polydem
