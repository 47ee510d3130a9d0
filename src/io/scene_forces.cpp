// The `forces:` list: gravity, the contact operator and the drag forces (exaDEM names).
#include <map>

#include "io/scene_parts.hpp"
#include "polydem/error.hpp"

namespace polydem {
namespace {

const std::vector<std::string> kForceNames = {"gravity_force",
                                              "contact_sphere",
                                              "contact_polyhedron",
                                              "contact_sphere_with_cohesion",
                                              "contact_polyhedron_with_cohesion",
                                              "quadratic_force",
                                              "sphere_fluid_friction"};
const std::vector<std::string> kConfigKeys = {"kn", "kt",        "kr", "mur",  "mu",
                                              "en", "damp_rate", "fc", "dncut"};

void read_damping(const YamlMap& m, ContactParams& p) {
  if (m.has("en") == m.has("damp_rate"))
    m.fail(m.has("en") ? "damp_rate" : "en",
           m.has("en") ? "give either en (restitution) or damp_rate (damping ratio), not both"
                       : "missing: give en (restitution in (0, 1]) or damp_rate (in [0, 1))");
  if (m.has("en")) {
    p.en = m.quantity("en", Dimension::dimensionless);
    if (!(p.en > 0.0 && p.en <= 1.0)) m.fail("en", "must be in (0, 1], got " + m.scalar("en"));
  } else {
    p.damp_rate = m.quantity("damp_rate", Dimension::dimensionless);
    if (!(p.damp_rate >= 0.0 && p.damp_rate < 1.0))
      m.fail("damp_rate", "must be in [0, 1), got " + m.scalar("damp_rate"));
  }
}

void read_cohesion(const YamlMap& m, ContactParams& p, const std::string& op, bool cohesion) {
  p.fc = check_positive(m, "fc", m.quantity("fc", Dimension::force, 0.0), true);
  p.dncut = check_positive(m, "dncut", m.quantity("dncut", Dimension::length, 0.0), true);
  if (!cohesion && (p.fc > 0.0 || p.dncut > 0.0))
    m.fail(p.fc > 0.0 ? "fc" : "dncut",
           "cohesion needs the operator " + op + "_with_cohesion instead of " + op);
  if (cohesion) m.require("fc", "fc: 0.05");
  if (p.fc > 0.0 && !(p.dncut > 0.0))
    m.fail(m.has("dncut") ? "dncut" : "fc",
           "fc > 0 needs a cohesion band dncut > 0 (e.g. dncut: \"0.1 mm\")");
}

ContactParams read_params(const YamlMap& op_map, const std::string& key, const std::string& op,
                          bool cohesion) {
  const YamlMap m = op_map.map(key, key, kConfigKeys);
  ContactParams p;
  p.kn = check_positive(m, "kn", m.quantity("kn", Dimension::stiffness));
  p.kt = check_positive(m, "kt", m.quantity("kt", Dimension::stiffness), true);
  p.kr = check_positive(m, "kr", m.quantity("kr", Dimension::rolling_stiffness, 0.0), true);
  p.mur = check_positive(m, "mur", m.quantity("mur", Dimension::dimensionless, 0.0), true);
  if (!m.has("mu")) m.fail("mu", "missing in '" + key + "' (give mu: 0 for frictionless contacts)");
  p.mu = check_positive(m, "mu", m.quantity("mu", Dimension::dimensionless), true);
  read_damping(m, p);
  read_cohesion(m, p, op, cohesion);
  return p;
}

ContactOperator read_contact(const YamlMap& m, const std::string& name) {
  ContactOperator c;
  c.present = true;
  c.sphere = name.rfind("contact_sphere", 0) == 0;
  c.cohesion = name.size() > 14 && name.compare(name.size() - 14, 14, "_with_cohesion") == 0;
  const std::string base = c.cohesion ? name.substr(0, name.size() - 14) : name;
  m.require("config", "config: {kn: 1.0e5, kt: 1.0e5, mu: 0.5, en: 0.5}");
  c.config = read_params(m, "config", base, c.cohesion);
  c.has_config_driver = m.has("config_driver");
  c.config_driver =
      c.has_config_driver ? read_params(m, "config_driver", base, c.cohesion) : c.config;
  c.loc = {m.file(), m.line()};
  return c;
}

void read_force(const std::string& name, const YamlMap& m, const std::string& folder,
                ForceSettings& f) {
  if (name == "gravity_force") {
    f.gravity = m.vec3("gravity", Dimension::acceleration, Vec3(0.0, 0.0, -9.807));
  } else if (name == "quadratic_force") {
    ForceSettings::Quadratic q;
    q.cx = check_positive(m, "cx", m.quantity("cx", Dimension::dimensionless, q.cx), true);
    q.mu = check_positive(m, "mu", m.quantity("mu", Dimension::dimensionless, q.mu), true);
    f.quadratic = q;
  } else if (name == "sphere_fluid_friction") {
    ForceSettings::FluidFriction ff;
    ff.field = resolve_input_file(m, "field", folder, "fluid field");
    ff.cx = check_positive(m, "cx", m.quantity("cx", Dimension::dimensionless, ff.cx), true);
    f.fluid_friction = ff;
  } else {
    f.contact = read_contact(m, name);
  }
}

std::vector<std::string> keys_of(const std::string& name) {
  if (name == "gravity_force") return {"gravity"};
  if (name == "quadratic_force") return {"cx", "mu"};
  if (name == "sphere_fluid_friction") return {"field", "cx"};
  return {"config", "config_driver"};
}

}  // namespace

void read_forces(const YAML::Node& list, int line, Scene& scene) {
  require_sequence(list, scene.path, line, "forces", "- gravity_force: {gravity: [0, 0, -9.807]}");
  std::map<std::string, int> seen;  // operator (all contact operators as one) -> line
  for (const YAML::Node& item : list) {
    const auto [name, body] = single_entry(item, scene.path, "forces", kForceNames);
    const YamlMap m(body, name, scene.path, line_of(item, line), keys_of(name));
    const std::string kind = name.rfind("contact_", 0) == 0 ? "contact" : name;
    const auto [it, fresh] = seen.emplace(kind, m.line());
    if (!fresh)
      throw InputError(input_message(
          scene.path, m.line(), name,
          (kind == "contact" ? "only one contact operator may be given" : "given twice") +
              std::string(" (the first is at line ") + std::to_string(it->second) + ")"));
    read_force(name, m, scene.folder, scene.forces);
  }
}

}  // namespace polydem
