// The `drivers:` list: walls, cylinders, balls, STL meshes and their motions.
#include <algorithm>
#include <cctype>
#include <map>

#include "io/scene_parts.hpp"
#include "polydem/error.hpp"

namespace polydem {
namespace {

// The YAML name of each kind, in the order of KindSettings' alternatives.
const std::vector<std::string> kDriverKinds = {"wall", "cylinder", "ball", "stl"};

// Servo keys: force (N) or pressure (Pa) with area (m^2, a number); gain (m/(N s), a number;
// default 0.1 / (kn dt)); direction for a ball or a mesh (a wall uses its normal, a cylinder
// its axis).
void read_servo(const YamlMap& m, bool own_direction, MotionSettings& motion) {
  if (m.has("force") && m.has("pressure"))
    m.fail("pressure", "give either force or pressure for a servo driver, not both");
  motion.force = m.optional_quantity("force", Dimension::force);
  motion.pressure = m.optional_quantity("pressure", Dimension::pressure);
  const bool servo = motion.force || motion.pressure;
  for (const char* key : {"gain", "area", "direction"})
    if (m.has(key) && !servo) m.fail(key, "only a servo uses it: add force or pressure");
  if (motion.pressure) {
    m.require("area", "area: 0.01   # m^2, pressure x area is the force held");
    motion.area = check_positive(m, "area", m.quantity("area", Dimension::dimensionless));
  }
  if (m.has("gain")) motion.gain = check_positive(m, "gain", m.quantity("gain", Dimension::dimensionless));
  if (servo && own_direction) {
    m.require("direction", "direction: [0, 0, -1]   # the servo pushes along it");
    motion.direction = m.direction("direction", Vec3::UnitZ());
  } else if (m.has("direction")) {
    m.fail("direction", "a wall's servo pushes along its normal and a cylinder's along its axis: remove it");
  }
}

// `own_direction`: the kind has no servo direction of its own (ball, mesh): motion.direction gives it.
MotionSettings read_motion(const YamlMap& driver, bool own_direction) {
  MotionSettings motion;
  if (!driver.has("motion")) return motion;
  const YamlMap m = driver.map("motion", "motion",
                               {"velocity", "rotate", "force", "pressure", "area", "gain", "direction",
                                "remove_at", "start", "stop"});
  motion.velocity = m.vec3("velocity", Dimension::velocity, Vec3::Zero());
  if (m.has("rotate")) {
    const YamlMap r = m.map("rotate", "rotate", {"axis", "center", "omega"});
    r.require("axis", "axis: [0, 1, 0]");
    motion.rotates = true;
    motion.rotation_axis = r.direction("axis", Vec3::UnitZ());
    motion.rotation_center = r.vec3("center", Dimension::length, Vec3::Zero());
    motion.omega = r.quantity("omega", Dimension::angular_velocity);
  }
  read_servo(m, own_direction, motion);
  if (m.has("remove_at"))
    motion.remove_at =
        check_positive(m, "remove_at", m.quantity("remove_at", Dimension::time), true);
  motion.start = check_positive(m, "start", m.quantity("start", Dimension::time, 0.0), true);
  motion.stop = m.optional_quantity("stop", Dimension::time);
  if (motion.stop && *motion.stop <= motion.start) m.fail("stop", "must be later than start");
  return motion;
}

KindSettings read_wall(const YamlMap& m, const Scene&) {
  WallSettings w;
  w.point = m.vec3("point", Dimension::length);
  m.require("normal", "normal: [0, 0, 1]");
  w.normal = m.direction("normal", Vec3::UnitZ());
  if (m.has("size")) w.size = check_positive(m, "size", m.quantity("size", Dimension::length));
  return w;
}

KindSettings read_cylinder(const YamlMap& m, const Scene&) {
  CylinderSettings c;
  c.center = m.vec3("center", Dimension::length);
  c.axis = m.direction("axis", Vec3::UnitZ());
  c.radius = check_positive(m, "radius", m.quantity("radius", Dimension::length));
  if (m.has("length"))
    c.length = check_positive(m, "length", m.quantity("length", Dimension::length));
  c.inside = m.boolean("inside", true);
  return c;
}

KindSettings read_ball(const YamlMap& m, const Scene&) {
  BallSettings b;
  b.center = m.vec3("center", Dimension::length);
  b.radius = check_positive(m, "radius", m.quantity("radius", Dimension::length));
  return b;
}

KindSettings read_stl(const YamlMap& m, const Scene& scene) {
  MeshSettings s;
  s.file = resolve_input_file(m, "file", scene.folder, "STL file");
  s.scale = check_positive(m, "scale", m.quantity("scale", Dimension::dimensionless, 1.0));
  s.translation = m.vec3("translation", Dimension::length, Vec3::Zero());
  s.rotation = m.orientation("rotation");
  return s;
}

// The parser entry of each kind, in the order of kDriverKinds: its keys and its reader.
struct KindEntry {
  std::vector<std::string> keys;
  KindSettings (*read)(const YamlMap&, const Scene&);
  bool own_direction;  // a servo needs motion.direction
};

const KindEntry& kind_entry(std::size_t kind) {
  static const KindEntry entries[] = {
      {{"name", "point", "normal", "size", "motion"}, read_wall, false},
      {{"name", "center", "axis", "radius", "length", "inside", "motion"}, read_cylinder, false},
      {{"name", "center", "radius", "motion"}, read_ball, true},
      {{"name", "file", "scale", "translation", "rotation", "motion"}, read_stl, true},
  };
  return entries[kind];
}

DriverSettings read_driver(const YAML::Node& item, std::size_t index, const Scene& scene, int line) {
  const auto [kind_name, body] = single_entry(item, scene.path, "drivers", kDriverKinds);
  const std::size_t kind = std::find(kDriverKinds.begin(), kDriverKinds.end(), kind_name) - kDriverKinds.begin();
  const KindEntry& entry = kind_entry(kind);
  const YamlMap m(body, kind_name, scene.path, line_of(item, line), entry.keys);
  DriverSettings d;
  d.name = m.text("name", kind_name + "_" + std::to_string(index + 1));
  const bool safe = std::all_of(d.name.begin(), d.name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
  if (d.name.empty() || !safe)  // it names driver_NAME.csv, as probe names do
    m.fail("name", "'" + d.name + "' must be letters, digits, '_' or '-' (it names driver_NAME.csv)");
  d.kind = entry.read(m, scene);
  if (MeshSettings* mesh = std::get_if<MeshSettings>(&d.kind)) {  // its file's errors name the key and the driver
    const SourceLoc at = m.loc("file");
    mesh->where = input_message(at.file, at.line, "file", "driver '" + d.name + "': ");
  }
  d.motion = read_motion(m, entry.own_direction);
  d.loc = {scene.path, m.line()};
  return d;
}

}  // namespace

void read_drivers(const YAML::Node& list, int line, Scene& scene) {
  require_sequence(list, scene.path, line, "drivers",
                   "- wall: {point: [0, 0, 0], normal: [0, 0, 1]}");
  std::map<std::string, int> name_lines;
  for (const YAML::Node& item : list) {
    DriverSettings d = read_driver(item, scene.drivers.size(), scene, line);
    const auto [it, fresh] = name_lines.emplace(d.name, d.loc.line);
    if (!fresh)
      throw InputError(input_message(scene.path, d.loc.line, "name",
                                     "driver name '" + d.name + "' is already used at line " +
                                         std::to_string(it->second) + "; names must be unique"));
    scene.drivers.push_back(std::move(d));
  }
}

}  // namespace polydem
