#include "shape/yaml_shape.hpp"

#include <yaml-cpp/yaml.h>

#include "polydem/error.hpp"
#include "shape/hull.hpp"
#include "shape/length_text.hpp"
#include "shape/mass.hpp"
#include "shape/suggest.hpp"

namespace polydem {
namespace {

const std::vector<std::string> kYamlKeys = {"name",     "radius",      "vertices", "faces",
                                            "edges",    "points",      "volume",   "inertia_per_mass",
                                            "position", "orientation", "convex",   "surface"};

int line_of(const YAML::Node& node) { return node.Mark().line >= 0 ? node.Mark().line + 1 : 0; }

class ShapeEntry {
 public:
  ShapeEntry(const YAML::Node& node, std::string file) : node_(node), file_(std::move(file)) {
    if (!node.IsMap()) fail(node, "", "each shape is a mapping with name, radius, vertices or points");
    for (const auto& kv : node) {
      const std::string key = kv.first.as<std::string>();
      bool known = false;
      for (const auto& k : kYamlKeys) known = known || k == key;
      if (!known) fail(kv.first, key, "unknown key in a shape" + did_you_mean(key, kYamlKeys));
    }
  }

  bool has(const std::string& key) const { return static_cast<bool>(node_[key]); }

  [[noreturn]] void fail(const YAML::Node& at, const std::string& key, const std::string& what) const {
    throw InputError(input_message(file_, line_of(at), key, what));
  }

  std::string text(const std::string& key) const {
    const YAML::Node n = node_[key];
    if (!n || !n.IsScalar()) fail(node_, key, "missing (a shape needs a " + key + ")");
    return n.Scalar();
  }

  double number(const YAML::Node& n, const std::string& key) const {
    try {
      return n.as<double>();
    } catch (const YAML::Exception&) {
      fail(n, key, "'" + (n.IsScalar() ? n.Scalar() : std::string("...")) + "' is not a number");
    }
  }

  double length(const std::string& key) const {
    const auto value = parse_length(text(key));
    if (!value) fail(node_[key], key, "'" + text(key) + "' is not a length (write 0.0005 or \"0.5 mm\")");
    return *value;
  }

  std::vector<double> numbers(const YAML::Node& n, const std::string& key, size_t size) const {
    if (!n.IsSequence() || n.size() != size)
      fail(n, key, "expected a list of " + std::to_string(size) + " numbers");
    std::vector<double> out;
    for (const auto& x : n) out.push_back(number(x, key));
    return out;
  }

  Vec3 vec3(const YAML::Node& n, const std::string& key) const {
    const auto v = numbers(n, key, 3);
    return Vec3(v[0], v[1], v[2]);
  }

  std::vector<Vec3> points(const std::string& key) const {
    const YAML::Node n = node_[key];
    if (!n.IsSequence() || n.size() == 0) fail(n, key, "expected a list of [x, y, z] points");
    std::vector<Vec3> out;
    for (const auto& p : n) out.push_back(vec3(p, key));
    return out;
  }

  std::vector<std::vector<int>> index_lists(const std::string& key) const {
    const YAML::Node n = node_[key];
    if (!n.IsSequence()) fail(n, key, "expected a list of vertex index lists");
    std::vector<std::vector<int>> out;
    for (const auto& list : n) {
      if (!list.IsSequence()) fail(list, key, "expected a list of vertex indices like [0, 1, 2]");
      std::vector<int> ids;
      for (const auto& i : list) ids.push_back(static_cast<int>(number(i, key)));
      out.push_back(ids);
    }
    return out;
  }

  bool flag(const std::string& key) const {
    const YAML::Node n = node_[key];
    if (n.IsScalar() && (n.Scalar() == "true" || n.Scalar() == "false")) return n.Scalar() == "true";
    fail(n, key, "expected true or false");
  }

  const YAML::Node& node() const { return node_; }

 private:
  YAML::Node node_;
  std::string file_;
};

void read_topology(const ShapeEntry& e, Shape& s) {
  s.vertices = e.points("vertices");
  if (e.has("faces")) s.faces = e.index_lists("faces");
  if (e.has("edges"))
    for (const auto& pair : e.index_lists("edges")) {
      if (pair.size() != 2) e.fail(e.node()["edges"], "edges", "each edge is a pair [i, j]");
      s.edges.push_back({pair[0], pair[1]});
    }
  // Two vertices and no `edges` key: a segment (write `edges: []` for two separate spheres).
  if (s.vertices.size() == 2 && s.faces.empty() && !e.has("edges")) s.edges.push_back({0, 1});
  if (e.has("surface")) s.surface = e.flag("surface");
}

// `convex: false` turns the convex fast paths off for a convex core; `convex: true` on a core
// that is not convex is an error (the fast paths would be wrong).
void apply_convex_key(const ShapeEntry& e, Shape& s) {
  if (!e.has("convex")) return;
  const bool wanted = e.flag("convex");
  if (wanted && !s.convex)
    e.fail(e.node()["convex"], "convex",
           "shape '" + s.name + "' is not convex (its faces do not close a convex polyhedron); leave the key out");
  s.convex = wanted;
}

void read_precomputed(const ShapeEntry& e, Shape& s) {
  s.volume = e.number(e.node()["volume"], "volume");
  s.inertia_per_mass = e.vec3(e.node()["inertia_per_mass"], "inertia_per_mass");
  if (e.has("position")) s.input_center = e.vec3(e.node()["position"], "position");
  if (e.has("orientation")) {
    const auto q = e.numbers(e.node()["orientation"], "orientation", 4);
    s.input_rotation = Quat(q[0], q[1], q[2], q[3]).normalized();
  }
  if (!(s.volume > 0.0)) e.fail(e.node()["volume"], "volume", "must be > 0 (m^3)");
}

Shape read_entry(const ShapeEntry& e, const std::string& file) {
  const std::string name = e.text("name");
  const double radius = e.length("radius");
  if (!(radius > 0.0)) e.fail(e.node()["radius"], "radius", "must be > 0 (the Minkowski radius)");
  if (e.has("points") == e.has("vertices"))
    e.fail(e.node(), "", "shape '" + name + "': give exactly one of 'vertices' or 'points'");
  try {
    if (e.has("points")) return build_hull_shape(e.points("points"), radius, name);
    Shape s;
    s.name = name;
    s.radius = radius;
    read_topology(e, s);
    if (e.has("volume") && e.has("inertia_per_mass")) {
      read_precomputed(e, s);
      compute_derived_geometry(s);
    } else {
      compute_mass_properties(s);
    }
    apply_convex_key(e, s);
    return s;
  } catch (const InputError& error) {
    const std::string what = error.what();
    if (what.rfind("shape '", 0) != 0) throw;  // already located
    throw InputError(input_message(file, line_of(e.node()), "", what));
  }
}

}  // namespace

std::vector<Shape> read_yaml_shapes(const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw InputError(input_message(path, 0, "", "cannot open the shape file"));
  } catch (const YAML::ParserException& e) {
    throw InputError(input_message(path, e.mark.line + 1, "", "YAML syntax: " + e.msg));
  }
  if (!root.IsSequence())
    throw InputError(
        input_message(path, line_of(root), "", "a YAML shape file is a list of shapes ('- name: ...')"));
  std::vector<Shape> shapes;
  try {
    for (const auto& node : root) shapes.push_back(read_entry(ShapeEntry(node, path), path));
  } catch (const YAML::Exception& e) {  // a value of the wrong kind, e.g. a list as a key
    throw InputError(input_message(path, e.mark.line + 1, "", e.msg));
  }
  return shapes;
}

}  // namespace polydem
