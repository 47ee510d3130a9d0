// The `forces:` list: gravity, the contact operator, drag, and the fluid operators (exaDEM
// and CFDEM names).
#include <cmath>
#include <map>
#include <optional>

#include "field/fluid_grid.hpp"  // kMaxGridCells
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
                                              "sphere_fluid_friction",
                                              "fluid_field",
                                              "pressure_force",
                                              "viscous_force",
                                              "archimedes_force",
                                              "void_fraction"};
const std::vector<std::string> kConfigKeys = {"model", "E",  "poisson",   "kn",
                                              "kt",    "kr", "mur",       "mu",
                                              "en",    "damp_rate",       "damp_tangential",
                                              "fc",    "dncut",           "damping_mass"};

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

void read_tangential_damping(const YamlMap& m, ContactParams& p) {
  if (!m.has("damp_tangential")) return;
  p.damp_tangential = m.quantity("damp_tangential", Dimension::dimensionless);
  if (!(p.damp_tangential >= 0.0 && p.damp_tangential < 1.0))
    m.fail("damp_tangential", "must be in [0, 1), got " + m.scalar("damp_tangential"));
  if (p.damp_tangential > 0.0 && p.hertz)
    m.fail("damp_tangential", "is not available with model: hertz yet (its tangential stiffness varies)");
  if (p.damp_tangential > 0.0 && !(p.mu > 0.0 && p.kt > 0.0))
    m.fail("damp_tangential", "needs friction to act on (mu > 0 and kt > 0)");
}

// damping_mass: pair (the default: the pair's m_i m_j/(m_i + m_j)) or contact (the contact
// point's effective mass, contact/contact_mass.hpp).
void read_damping_mass(const YamlMap& m, ContactParams& p) {
  if (!m.has("damping_mass")) return;
  const std::string mass = m.scalar("damping_mass");
  if (mass != "pair" && mass != "contact") m.fail("damping_mass", "must be pair or contact, got '" + mass + "'");
  p.damping_contact_mass = mass == "contact";
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

// model: hertz reads the material's E and poisson (normal_hertz.hpp); linear, the default, kn and kt.
void read_stiffness(const YamlMap& m, ContactParams& p) {
  const std::string model = m.has("model") ? m.scalar("model") : "linear";
  if (model != "linear" && model != "hertz") m.fail("model", "must be linear or hertz, got '" + model + "'");
  p.hertz = model == "hertz";
  if (!p.hertz) {
    for (const char* key : {"E", "poisson"})
      if (m.has(key)) m.fail(key, "is a Hertz parameter: add model: hertz, or give kn and kt");
    p.kn = check_positive(m, "kn", m.quantity("kn", Dimension::stiffness));
    p.kt = check_positive(m, "kt", m.quantity("kt", Dimension::stiffness), true);
    return;
  }
  for (const char* key : {"kn", "kt"})
    if (m.has(key)) m.fail(key, "model: hertz takes the material's E and poisson, not kn and kt");
  m.require("E", "E: \"70 GPa\"");
  p.young = check_positive(m, "E", m.quantity("E", Dimension::pressure));
  m.require("poisson", "poisson: 0.3");
  p.poisson = m.quantity("poisson", Dimension::dimensionless);
  if (!(p.poisson >= 0.0 && p.poisson <= 0.5)) m.fail("poisson", "must be in [0, 0.5], got " + m.scalar("poisson"));
}

ContactParams read_params(const YamlMap& op_map, const std::string& key, const std::string& op,
                          bool cohesion) {
  const YamlMap m = op_map.map(key, key, kConfigKeys);
  ContactParams p;
  read_stiffness(m, p);
  p.kr = check_positive(m, "kr", m.quantity("kr", Dimension::rolling_stiffness, 0.0), true);
  p.mur = check_positive(m, "mur", m.quantity("mur", Dimension::dimensionless, 0.0), true);
  if (p.mur > 0.0 && p.kr == 0.0) m.fail("kr", "mur > 0 needs a rolling stiffness kr > 0 (N m/rad)");
  if (!m.has("mu")) m.fail("mu", "missing in '" + key + "' (give mu: 0 for frictionless contacts)");
  p.mu = check_positive(m, "mu", m.quantity("mu", Dimension::dimensionless), true);
  if (p.mu > 0.0 && p.kt == 0.0 && !p.hertz)
    m.fail("kt", "mu > 0 needs kt > 0, or friction is lost (kt = kn is common)");
  read_damping(m, p);
  read_tangential_damping(m, p);
  read_damping_mass(m, p);
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
      c.has_config_driver ? read_params(m, "config_driver", base, c.cohesion) : c.config;  // later stages read config_driver
  if (c.config_driver.hertz && !c.config.hertz)
    m.fail("config_driver", "model: hertz pairs the driver's E and poisson with the particles': give config "
                            "model: hertz too");
  c.loc = {m.file(), m.line()};
  return c;
}

Mat3 cross_matrix(const Vec3& w) {  // cross_matrix(w) x = w x x
  Mat3 m;
  m << 0.0, -w.z(), w.y(), w.z(), 0.0, -w.x(), -w.y(), w.x(), 0.0;
  return m;
}

void read_grid(const YamlMap& f, ForceSettings::FluidField& fl) {
  const YamlMap g = f.map("grid", "grid", {"min", "max", "cells"});
  fl.grid_min = g.vec3("min", Dimension::length);
  fl.grid_max = g.vec3("max", Dimension::length);
  g.require("cells", "cells: [10, 10, 40]");
  const YAML::Node c = g.node("cells");
  if (!c.IsSequence() || c.size() != 3) g.fail("cells", "expected 3 whole numbers like [10, 10, 40]");
  for (int a = 0; a < 3; ++a) {
    int n = 0;
    try { n = c[a].as<int>(); } catch (const YAML::Exception&) { n = 0; }
    if (n < 1) g.fail("cells", "expected 3 whole numbers >= 1 like [10, 10, 40]");
    fl.cells[a] = n;
    if (!(fl.grid_max[a] > fl.grid_min[a]))
      g.fail("max", "the grid spacing must be positive: max must exceed min on every axis");
  }
  const double total = double(fl.cells[0]) * double(fl.cells[1]) * double(fl.cells[2]);
  if (total > kMaxGridCells)
    g.fail("cells", std::to_string(fl.cells[0]) + " x " + std::to_string(fl.cells[1]) + " x " +
                        std::to_string(fl.cells[2]) + " cells is more than the limit of " +
                        std::to_string(std::int64_t(kMaxGridCells)) + " (about 100 bytes a cell)");
}

void read_velocity(const YamlMap& f, ForceSettings::FluidField& fl) {
  if (!f.has("velocity")) return;
  if (f.node("velocity").IsSequence()) {
    fl.velocity = f.vec3("velocity", Dimension::velocity);
    return;
  }
  const YamlMap v = f.map("velocity", "velocity", {"uniform", "shear", "vortex"});
  if (v.has("uniform") + v.has("shear") + v.has("vortex") != 1)
    f.fail("velocity", "give one of [ux, uy, uz], {uniform: [...]}, {shear: {...}} or {vortex: {...}}");
  fl.velocity = v.vec3("uniform", Dimension::velocity, Vec3::Zero());
  if (v.has("shear")) {  // U = rate (normal . (x - reference)) direction
    const YamlMap s = v.map("shear", "shear", {"rate", "direction", "normal"});
    const Vec3 d = s.direction("direction", Vec3::UnitX()), n = s.direction("normal", Vec3::UnitZ());
    if (std::abs(d.dot(n)) > 1e-9) s.fail("normal", "must be perpendicular to the shear direction");
    fl.velocity_gradient = s.quantity("rate", Dimension::angular_velocity) * d * n.transpose();
  } else if (v.has("vortex")) {  // solid-body rotation about the axis through `reference`
    const YamlMap s = v.map("vortex", "vortex", {"axis", "omega"});
    fl.velocity_gradient = cross_matrix(s.quantity("omega", Dimension::angular_velocity) *
                                        s.direction("axis", Vec3::UnitZ()));
  }
}

// The `fluid_field` operator; a hydrostatic pressure uses the scene's gravity.
ForceSettings::FluidField read_fluid(const YamlMap& f, const std::string& folder, const Vec3& gravity) {
  ForceSettings::FluidField fl;
  fl.loc = {f.file(), f.line()};
  if (f.has("file") == f.has("grid"))
    f.fail(f.has("file") ? "grid" : "file", "give either file: flow.vti or an analytic grid: {min, max, cells}");
  if (f.has("rho")) fl.rho = check_positive(f, "rho", f.quantity("rho", Dimension::density));
  if (f.has("nu")) fl.nu = check_positive(f, "nu", f.quantity("nu", Dimension::dimensionless), true);
  const std::string sampling = f.text("sampling", "cell");
  if (sampling != "cell" && sampling != "trilinear")
    f.fail("sampling", "expected cell or trilinear, got " + sampling);
  fl.trilinear = sampling == "trilinear";
  if (f.has("file")) {
    for (const char* key : {"velocity", "pressure", "reference"})
      if (f.has(key)) f.fail(key, "the file gives the fluid; analytic fields need grid: {min, max, cells}");
    fl.file = resolve_input_file(f, "file", folder, "fluid field");
    fl.file_loc = f.loc("file");
    return fl;
  }
  read_grid(f, fl);
  read_velocity(f, fl);
  fl.reference = f.vec3("reference", Dimension::length, Vec3::Zero());
  if (f.has("pressure") && f.node("pressure").IsMap()) {
    const YamlMap p = f.map("pressure", "pressure", {"hydrostatic"});
    const YamlMap h = p.map("hydrostatic", "hydrostatic", {"p0"});
    if (!p.has("hydrostatic")) f.fail("pressure", "expected a pressure or {hydrostatic: {p0: 0}}");
    if (!fl.rho) f.fail("rho", "missing: a hydrostatic pressure needs the fluid density (e.g. rho: 1000)");
    fl.pressure = h.quantity("p0", Dimension::pressure, 0.0);
    fl.pressure_gradient = *fl.rho * gravity;  // grad p = rho g
  } else {
    fl.pressure = f.quantity("pressure", Dimension::pressure, 0.0);
  }
  return fl;
}

ForceSettings::CfdForce read_cfd_force(const YamlMap& m) {
  return {check_positive(m, "C_added_mass", m.quantity("C_added_mass", Dimension::dimensionless, 0.0), true)};
}

void read_force(const std::string& name, const YamlMap& m, const std::string& folder,
                ForceSettings& f) {
  if (name == "gravity_force") {
    f.gravity = m.vec3("gravity", Dimension::acceleration, Vec3(0.0, 0.0, -9.807));
    f.gravity_loc = m.has("gravity") ? m.loc("gravity") : SourceLoc{m.file(), m.line()};
  } else if (name == "quadratic_force") {
    ForceSettings::Quadratic q;
    q.cx = check_positive(m, "cx", m.quantity("cx", Dimension::dimensionless, q.cx), true);
    q.mu = check_positive(m, "mu", m.quantity("mu", Dimension::dimensionless, q.mu), true);
    f.quadratic = q;
  } else if (name == "sphere_fluid_friction") {
    ForceSettings::FluidFriction ff;
    if (m.has("field")) ff.field = resolve_input_file(m, "field", folder, "fluid field");
    ff.cx = check_positive(m, "cx", m.quantity("cx", Dimension::dimensionless, ff.cx), true);
    f.fluid_friction = ff;
    if (m.has("field")) {  // the fluid given here, values taken in the particle's cell
      f.fluid = ForceSettings::FluidField{};  // not emplace(): clang sees no default constructor (CWG 1397)
      f.fluid->file = ff.field;
      f.fluid->loc = f.fluid->file_loc = m.loc("field");
      f.fluid->file_key = "field";
    }
  } else if (name == "pressure_force") {
    f.pressure_force = read_cfd_force(m);
  } else if (name == "viscous_force") {
    f.viscous_force = read_cfd_force(m);
  } else if (name == "archimedes_force") {
    f.archimedes = true;
  } else if (name == "void_fraction") {
    ForceSettings::VoidFraction v;
    v.alpha_min = m.quantity("alpha_min", Dimension::dimensionless, v.alpha_min);
    if (!(v.alpha_min >= 0.0 && v.alpha_min < 1.0)) m.fail("alpha_min", "must be in [0, 1), got " + m.scalar("alpha_min"));
    v.samples = int(m.integer("samples", v.samples, 1));
    if (v.samples > 64) m.fail("samples", "at most 64 lattice points per axis (64^3 per body), got " + m.scalar("samples"));
    f.void_fraction = v;
  } else {
    f.contact = read_contact(m, name);
  }
}

std::vector<std::string> keys_of(const std::string& name) {
  if (name == "gravity_force") return {"gravity"};
  if (name == "quadratic_force") return {"cx", "mu"};
  if (name == "sphere_fluid_friction") return {"field", "cx"};
  if (name == "fluid_field") return {"file", "grid", "velocity", "reference", "pressure", "rho", "nu", "sampling"};
  if (name == "pressure_force" || name == "viscous_force") return {"C_added_mass"};
  if (name == "archimedes_force") return {};
  if (name == "void_fraction") return {"alpha_min", "samples"};
  return {"config", "config_driver"};
}

// Every fluid operator needs a fluid; the analytic one needs the constants they read.
void check_fluid(const Scene& scene, const std::map<std::string, int>& seen) {
  const ForceSettings& f = scene.forces;
  for (const char* op : {"sphere_fluid_friction", "pressure_force", "viscous_force", "archimedes_force", "void_fraction"}) {
    if (!seen.count(op)) continue;
    if (!f.fluid)
      throw InputError(input_message(scene.path, seen.at(op), op,
                                     "needs a fluid: add - fluid_field: {file: flow.vti} (or an analytic grid)"));
    const bool needs_rho = std::string(op) == "archimedes_force" || std::string(op) == "viscous_force";
    const bool needs_nu = std::string(op) == "viscous_force";
    if (f.fluid->file.empty() && ((needs_rho && !f.fluid->rho) || (needs_nu && !f.fluid->nu)))
      throw InputError(input_message(scene.path, f.fluid->loc.line, needs_rho && !f.fluid->rho ? "rho" : "nu",
                                     std::string("missing in fluid_field: ") + op +
                                         " needs it (e.g. rho: 1000, nu: 1.0e-6)"));
  }
  if (f.archimedes && !f.gravity)
    throw InputError(input_message(scene.path, seen.at("archimedes_force"), "archimedes_force",
                                   "buoyancy opposes gravity: add - gravity_force: {gravity: [0, 0, -9.807]}"));
}

}  // namespace

void read_forces(const YAML::Node& list, int line, Scene& scene) {
  require_sequence(list, scene.path, line, "forces", "- gravity_force: {gravity: [0, 0, -9.807]}");
  std::map<std::string, int> seen;  // operator (all contact operators as one) -> line
  std::optional<YamlMap> fluid;     // read last: a hydrostatic pressure needs the gravity
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
    if (name == "fluid_field") fluid = m;
    else read_force(name, m, scene.folder, scene.forces);
  }
  if (fluid) {
    if (scene.forces.fluid)
      fluid->fail("file", "the fluid is already given by sphere_fluid_friction's field (line " +
                              std::to_string(scene.forces.fluid->loc.line) + "); give it in one place");
    scene.forces.fluid = read_fluid(*fluid, scene.folder,
                                    scene.forces.gravity.value_or(Vec3(0.0, 0.0, -9.807)));
  }
  check_fluid(scene, seen);
}

}  // namespace polydem
