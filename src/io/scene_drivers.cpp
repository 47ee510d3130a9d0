// The `drivers:` list: walls, cylinders, balls, STL meshes and their motions.
#include <algorithm>
#include <map>

#include "io/scene_parts.hpp"
#include "polydem/error.hpp"

namespace polydem {
namespace {

const std::vector<std::string> kDriverKinds = {"wall", "cylinder", "ball", "stl"};

// Servo keys: force (N) or pressure (Pa) with area (m^2, a number); gain (m/(N s), a number;
// default 0.1 / (kn dt)); direction for a ball or a mesh (a wall uses its normal, a cylinder
// its axis).
void read_servo(const YamlMap& m, DriverSpec::Kind kind, Motion& motion) {
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
  const bool own_direction = kind == DriverSpec::Kind::ball || kind == DriverSpec::Kind::stl;
  if (servo && own_direction) {
    m.require("direction", "direction: [0, 0, -1]   # the servo pushes along it");
    motion.direction = m.direction("direction", Vec3::UnitZ());
  } else if (m.has("direction")) {
    m.fail("direction", "a wall's servo pushes along its normal and a cylinder's along its axis: remove it");
  }
}

Motion read_motion(const YamlMap& driver, DriverSpec::Kind kind) {
  Motion motion;
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
  read_servo(m, kind, motion);
  if (m.has("remove_at"))
    motion.remove_at =
        check_positive(m, "remove_at", m.quantity("remove_at", Dimension::time), true);
  motion.start = check_positive(m, "start", m.quantity("start", Dimension::time, 0.0), true);
  motion.stop = m.optional_quantity("stop", Dimension::time);
  if (motion.stop && *motion.stop <= motion.start) m.fail("stop", "must be later than start");
  return motion;
}

void read_wall(const YamlMap& m, DriverSpec& d) {
  d.point = m.vec3("point", Dimension::length);
  m.require("normal", "normal: [0, 0, 1]");
  d.normal = m.direction("normal", Vec3::UnitZ());
  if (m.has("size")) d.size = check_positive(m, "size", m.quantity("size", Dimension::length));
}

void read_cylinder(const YamlMap& m, DriverSpec& d) {
  d.center = m.vec3("center", Dimension::length);
  d.axis = m.direction("axis", Vec3::UnitZ());
  d.radius = check_positive(m, "radius", m.quantity("radius", Dimension::length));
  if (m.has("length"))
    d.length = check_positive(m, "length", m.quantity("length", Dimension::length));
  d.inside = m.boolean("inside", true);
}

void read_ball(const YamlMap& m, DriverSpec& d) {
  d.center = m.vec3("center", Dimension::length);
  d.radius = check_positive(m, "radius", m.quantity("radius", Dimension::length));
}

void read_stl(const YamlMap& m, DriverSpec& d, const std::string& folder) {
  d.file = resolve_input_file(m, "file", folder, "STL file");
  d.file_loc = m.loc("file");
  d.scale = check_positive(m, "scale", m.quantity("scale", Dimension::dimensionless, 1.0));
  d.translation = m.vec3("translation", Dimension::length, Vec3::Zero());
  d.rotation = m.orientation("rotation");
}

std::vector<std::string> keys_of(DriverSpec::Kind kind) {
  switch (kind) {
    case DriverSpec::Kind::wall:
      return {"name", "point", "normal", "size", "motion"};
    case DriverSpec::Kind::cylinder:
      return {"name", "center", "axis", "radius", "length", "inside", "motion"};
    case DriverSpec::Kind::ball:
      return {"name", "center", "radius", "motion"};
    case DriverSpec::Kind::stl:
      return {"name", "file", "scale", "translation", "rotation", "motion"};
  }
  return {};
}

DriverSpec read_driver(const YAML::Node& item, std::size_t index, const Scene& scene, int line) {
  const auto [kind_name, body] = single_entry(item, scene.path, "drivers", kDriverKinds);
  DriverSpec d;
  d.kind = static_cast<DriverSpec::Kind>(
      std::find(kDriverKinds.begin(), kDriverKinds.end(), kind_name) - kDriverKinds.begin());
  const YamlMap m(body, kind_name, scene.path, line_of(item, line), keys_of(d.kind));
  d.name = m.text("name", kind_name + "_" + std::to_string(index + 1));
  switch (d.kind) {
    case DriverSpec::Kind::wall:
      read_wall(m, d);
      break;
    case DriverSpec::Kind::cylinder:
      read_cylinder(m, d);
      break;
    case DriverSpec::Kind::ball:
      read_ball(m, d);
      break;
    case DriverSpec::Kind::stl:
      read_stl(m, d, scene.folder);
      break;
  }
  d.motion = read_motion(m, d.kind);
  d.loc = {scene.path, m.line()};
  return d;
}

}  // namespace

void read_drivers(const YAML::Node& list, int line, Scene& scene) {
  require_sequence(list, scene.path, line, "drivers",
                   "- wall: {point: [0, 0, 0], normal: [0, 0, 1]}");
  std::map<std::string, int> name_lines;
  for (const YAML::Node& item : list) {
    DriverSpec d = read_driver(item, scene.drivers.size(), scene, line);
    const auto [it, fresh] = name_lines.emplace(d.name, d.loc.line);
    if (!fresh)
      throw InputError(input_message(scene.path, d.loc.line, "name",
                                     "driver name '" + d.name + "' is already used at line " +
                                         std::to_string(it->second) + "; names must be unique"));
    scene.drivers.push_back(std::move(d));
  }
}

}  // namespace polydem
