// Bad scene files: each InputError names the file, the line and the key, and what to do.
#include <catch2/catch.hpp>
#include <sstream>
#include <vector>

#include "io/scene.hpp"
#include "io_fixture.hpp"

using namespace polydem;
using test::contains;

namespace {

const std::vector<std::string> kBase = {
    "simulation: {duration: 1, dt: \"1 us\", seed: 3}",              // 1
    "shapes: [lib.shp]",                                             // 2
    "forces:",                                                       // 3
    "  - contact_polyhedron:",                                       // 4
    "      config: {kn: 1.0e5, kt: 1.0e5, mu: 0.5, en: 0.5}",        // 5
    "bodies:",                                                       // 6
    "  - shape: cube",                                               // 7
    "    position: [0, 0, 0]",                                       // 8
    "drivers:",                                                      // 9
    "  - wall: {name: floor, point: [0, 0, 0], normal: [0, 0, 1]}",  // 10
};

// The base scene with lines replaced (1-based; a replacement may hold several lines, or
// none); a line past the end is appended (to the drivers).
std::string edited(const std::vector<std::pair<int, std::string>>& edits) {
  std::vector<std::string> lines = kBase;
  for (const auto& [n, text] : edits) {
    if (n > static_cast<int>(lines.size()))
      lines.push_back(text);
    else
      lines[n - 1] = text;
  }
  std::ostringstream out;
  for (const auto& l : lines)
    if (!l.empty()) out << l << "\n";
  return out.str();
}

std::string with_line(int n, const std::string& replacement) { return edited({{n, replacement}}); }

std::string error_of(const std::string& text) {
  test::TempDir dir;
  dir.write("lib.shp", "stub\n");
  dir.write("mesh.stl", "solid s\nendsolid s\n");
  const std::string path = dir.write("scene.yaml", text);
  return test::input_error_of([&] { load_scene(path); });
}

// The error names scene.yaml at `line`, the key, and contains `part`.
void check_error(const std::string& text, int line, const std::string& key,
                 const std::string& part) {
  const std::string msg = error_of(text);
  INFO("message: " << msg);
  CHECK(contains(msg, "scene.yaml:" + std::to_string(line) + ": "));
  CHECK(contains(msg, "key '" + key + "'"));
  CHECK(contains(msg, part));
}

}  // namespace

TEST_CASE("the base scene of these tests is valid", "[scene][errors]") {
  CHECK(error_of(with_line(11, "")) == "");
}

TEST_CASE("unknown keys suggest the nearest valid key", "[scene][errors]") {
  check_error(with_line(11, "  - cylinder: {name: d, center: [0, 0, 0], raduis: 0.1}"), 11,
              "raduis", "unknown key in 'cylinder' (did you mean 'radius'?)");
  check_error(with_line(6, "bodys:"), 6, "bodys", "(did you mean 'bodies'?)");
  check_error(with_line(8, "    postion: [0, 0, 0]"), 8, "postion", "did you mean 'position'?");
  check_error(with_line(5, "      config: {kn: 1.0e5, kt: 1.0e5, mu: 0.5, en: 0.5, damprate: 0.1}"),
              5, "damprate", "did you mean 'damp_rate'?");
  check_error(with_line(4, "  - contact_polyhedra:"), 4, "contact_polyhedra",
              "did you mean 'contact_polyhedron'?");
  check_error(with_line(11, "  - walls: {point: [0, 0, 0], normal: [0, 0, 1]}"), 11, "walls",
              "did you mean 'wall'?");
  // A key nothing resembles gets no misleading hint.
  const std::string msg = error_of(with_line(11, "zzzzzzzz: 1"));
  CHECK((contains(msg, "scene.yaml:11:") && !contains(msg, "did you mean")));
  check_error(with_line(8, "    position: [0, 0, 0]\n    count: 5"), 9, "count",
              "generate: random");
}

TEST_CASE("wrong types and vector lengths", "[scene][errors]") {
  check_error(with_line(1, "simulation: {duration: [1, 2]}"), 1, "duration",
              "expected a number or a quantity string like \"2 ms\"");
  check_error(with_line(8, "    position: [0, 0]"), 8, "position", "list of 3 numbers");
  check_error(with_line(8, "    position: [\"5 s\", 0, 0]"), 8, "position", "expected a length");
  check_error(with_line(8, "    position: 3"), 8, "position", "list of 3 numbers");
  check_error(with_line(1, "simulation: {duration: 1, threads: 1.5}"), 1, "threads",
              "whole number");
  check_error(with_line(1, "simulation: 5"), 1, "simulation", "mapping");
  check_error(edited({{9, "output: {contacts: maybe}"}, {10, ""}}), 9, "contacts", "true or false");
  check_error(edited({{6, "bodies: {shape: cube}"}, {7, ""}, {8, ""}}), 6, "bodies",
              "list of items");
}

TEST_CASE("non-positive sizes, densities, stiffnesses and times", "[scene][errors]") {
  check_error(with_line(8, "    position: [0, 0, 0]\n    density: 0"), 9, "density", "> 0");
  check_error(with_line(8, "    position: [0, 0, 0]\n    density: -2700"), 9, "density", "> 0");
  check_error(with_line(11, "  - ball: {center: [0, 0, 0], radius: 0}"), 11, "radius", "> 0");
  check_error(with_line(5, "      config: {kn: 0, kt: 1.0e5, mu: 0.5, en: 0.5}"), 5, "kn", "> 0");
  check_error(with_line(5, "      config: {kn: 1e5, kt: -1, mu: 0.5, en: 0.5}"), 5, "kt", ">= 0");
  CHECK(error_of(with_line(5, "      config: {kn: 1e5, kt: 0, mu: 0, en: 1}")) == "");
  check_error(with_line(5, "      config: {kn: 1e5, kt: 1e5, mu: -0.1, en: 0.5}"), 5, "mu", ">= 0");
  check_error(with_line(1, "simulation: {duration: 1, dt: 0}"), 1, "dt", "> 0");
  check_error(with_line(1, "simulation: {duration: 1, dt: \"-1 ms\"}"), 1, "dt", "> 0");
  check_error(with_line(1, "simulation: {duration: 0}"), 1, "duration", "> 0");
}

TEST_CASE("simulation skin_max: a length, not below the skin", "[scene][errors]") {
  check_error(with_line(1, "simulation:\n  duration: 1\n  skin: \"1 mm\"\n  skin_max: \"0.5 mm\""), 4, "skin_max",
              "is below the skin");
  check_error(with_line(1, "simulation: {duration: 1, skin_max: \"-1 mm\"}"), 1, "skin_max", "must be > 0");
  check_error(with_line(1, "simulation: {duration: 1, skin_max: \"2 s\"}"), 1, "skin_max", "");  // a time, not a length
  CHECK(error_of(with_line(1, "simulation: {duration: 1, skin: \"1 mm\", skin_max: \"1 mm\"}")) == "");
  CHECK(error_of(with_line(1, "simulation: {duration: 1, skin_max: \"4 mm\"}")) == "");  // the automatic skin: checked by the run
}

TEST_CASE("simulation accuracy: its range, and no numeric dt beside it", "[scene][errors]") {
  check_error(with_line(1, "simulation: {duration: 1, accuracy: 0.3}"), 1, "accuracy", "within [1e-5, 0.2], got 0.3");
  check_error(with_line(1, "simulation: {duration: 1, accuracy: 1e-6}"), 1, "accuracy", "within [1e-5, 0.2]");
  check_error(with_line(1, "simulation: {duration: 1, accuracy: -1e-3}"), 1, "accuracy", "within [1e-5, 0.2]");
  check_error(with_line(1, "simulation: {duration: 1, dt: \"1 us\", accuracy: 1e-3}"), 1, "accuracy",
              "needs dt: auto (or no dt), but dt is 1 us");
  check_error(with_line(1, "simulation:\n  duration: 1\n  dt: 1e-6\n  accuracy: 1e-3"), 4, "accuracy", "needs dt: auto");
  CHECK(error_of(with_line(1, "simulation: {duration: 1, dt: auto, accuracy: 1e-3}")) == "");
  CHECK(error_of(with_line(1, "simulation: {duration: 1, accuracy: 0.2}")) == "");
}

TEST_CASE("restitution, damping and cohesion parameters", "[scene][errors]") {
  check_error(with_line(5, "      config: {kn: 1e5, kt: 1e5, mu: 0.5, en: 1.5}"), 5, "en",
              "(0, 1]");
  check_error(with_line(5, "      config: {kn: 1e5, kt: 1e5, mu: 0.5, en: 0}"), 5, "en", "(0, 1]");
  check_error(with_line(5, "      config: {kn: 1e5, kt: 1e5, mu: 0.5, en: 0.5, damp_rate: 0.5}"), 5,
              "damp_rate", "not both");
  check_error(with_line(5, "      config: {kn: 1e5, kt: 1e5, mu: 0.5}"), 5, "en", "damp_rate");
  check_error(with_line(5, "      config: {kn: 1e5, kt: 1e5, mu: 0.5, damp_rate: 1}"), 5,
              "damp_rate", "[0, 1)");
  check_error(with_line(5, "      config: {kn: 1e5, kt: 1e5, mu: 0.5, en: 0.5, damp_tangential: 1}"), 5,
              "damp_tangential", "[0, 1)");
  check_error(with_line(5, "      config: {kn: 1e5, kt: 1e5, mu: 0, en: 0.5, damp_tangential: 0.2}"), 5,
              "damp_tangential", "mu > 0");
  check_error(with_line(5, "      config: {kn: 1e5, kt: 1e5, mu: 0.5, en: 0.5, damping_mass: body}"), 5,
              "damping_mass", "pair or contact");
  CHECK(error_of(with_line(5, "      config: {kn: 1e5, kt: 1e5, mu: 0.5, en: 0.5, damping_mass: contact}")) == "");
  check_error(with_line(5, "      config: {kn: 1e5, kt: 1e5, mu: 0.5, en: 0.5, damp_tangental: 0.2}"), 5,
              "damp_tangental", "did you mean 'damp_tangential'?");
  check_error(with_line(5, "      config: {kn: 1e5, kt: 1e5, mu: 0.5, en: 0.5, fc: 0.05}"), 5, "fc",
              "contact_polyhedron_with_cohesion");
  check_error(edited({{4, "  - contact_sphere_with_cohesion:"},
                      {5, "      config: {kn: 1e5, kt: 1e5, mu: 0.5, en: 0.5, fc: 0.05}"}}),
              5, "fc", "dncut > 0");
  CHECK(error_of(edited(
            {{4, "  - contact_sphere_with_cohesion:"},
             {5, "      config: {kn: 1e5, kt: 1e5, mu: 0.5, en: 0.5, fc: 0.05, dncut: 1e-4}"}})) ==
        "");
  check_error(with_line(5,
                        "      config: {kn: 1e5, kt: 1e5, mu: 0.5, en: 0.5}\n"
                        "  - contact_sphere: {config: {kn: 1e5, kt: 1e5, mu: 0.5, en: 0.5}}"),
              6, "contact_sphere", "only one contact operator");
  check_error(with_line(5, "      config_driver: {kn: 1e5, kt: 1e5, mu: 0.5, en: 0.5}"), 4,
              "config", "missing");
}

TEST_CASE("directions: zero is an error, others are normalized", "[scene][errors]") {
  check_error(with_line(10, "  - wall: {name: floor, point: [0, 0, 0], normal: [0, 0, 0]}"), 10,
              "normal", "zero vector");
  check_error(with_line(8, "    position: [0, 0, 0]\n    orientation: {axis: [0, 0, 0], angle: 1}"),
              9, "axis", "zero vector");
  check_error(with_line(8, "    position: [0, 0, 0]\n    orientation: {quaternion: [0, 0, 0, 0]}"),
              9, "quaternion", "must not be zero");
  test::TempDir dir;
  dir.write("lib.shp", "");
  const Scene s = load_scene(
      dir.write("scene.yaml",
                edited({{10, "  - wall: {name: floor, point: [0, 0, 0], normal: [0, 3, 4]}"},
                        {11, "  - cylinder: {center: [0, 0, 0], axis: [0, 0, 2], radius: 1}"}})));
  CHECK((std::get<WallSettings>(s.drivers[0].kind).normal - Vec3(0, 0.6, 0.8)).norm() < 1e-15);
  CHECK((std::get<CylinderSettings>(s.drivers[1].kind).axis - Vec3::UnitZ()).norm() < 1e-15);
  CHECK(s.drivers[1].name == "cylinder_2");
  const Scene q = load_scene(dir.write(
      "q.yaml",
      with_line(8, "    position: [0, 0, 0]\n    orientation: {quaternion: [0, 2, 0, 0]}")));
  CHECK(q.bodies[0].orientation.x() == 1.0);  // (0, 2, 0, 0) / 2: a half turn about x
}

TEST_CASE("missing files, duplicate names, missing blocks", "[scene][errors]") {
  check_error(with_line(2, "shapes: [nothere.shp]"), 2, "shapes", "cannot open shape library");
  check_error(with_line(11, "  - stl: {file: nothere.stl}"), 11, "file", "cannot open STL file");
  CHECK(error_of(with_line(11, "  - stl: {file: mesh.stl}")) == "");
  check_error(with_line(11, "  - wall: {name: floor, point: [0, 0, 1], normal: [0, 0, -1]}"), 11,
              "name", "already used at line 10");
  check_error(with_line(1, "output: {dir: o}"), 1, "simulation", "missing");
  check_error(with_line(1, "simulation: {dt: auto}"), 1, "duration", "missing");
  check_error(with_line(2, "outputs: {}"), 2, "outputs", "did you mean 'output'");
  check_error(with_line(2, ""), 5, "bodies", "shape library");  // lines move up by one
}

TEST_CASE("the file itself: missing, not a mapping, YAML syntax error", "[scene][errors]") {
  test::TempDir dir;
  const std::string missing = (dir.path / "none.yaml").string();
  const std::string msg = test::input_error_of([&] { load_scene(missing); });
  CHECK((contains(msg, "none.yaml") && contains(msg, "cannot open")));
  const std::string list = dir.write("list.yaml", "- a\n- b\n");
  CHECK(contains(test::input_error_of([&] { load_scene(list); }), "must be a mapping"));
  const std::string syntax = error_of(with_line(8, "    position: [0, 0, 0"));
  CHECK(contains(syntax, "YAML syntax error"));
  CHECK(contains(syntax, "scene.yaml:"));
  const std::string tab = error_of(with_line(8, "\tposition: [0, 0, 0]"));
  CHECK((contains(tab, "scene.yaml:8:") && contains(tab, "tabs")));
}

TEST_CASE("generator blocks: kind, mix fractions, region, scale", "[scene][errors]") {
  // The generator starts at line 9, after the explicit body.
  const std::string body = "    position: [0, 0, 0]\n";
  const std::string gen =
      body + "  - generate: random\n    shapes: {cube: 0.5, tetra: 0.5}\n    count: 10\n";
  const std::string box = "    region: {box: {min: [0, 0, 0], max: [1, 1, 1]}}\n";
  check_error(with_line(8, gen + box + "    scale: {min: 1.2, max: 0.8}"), 13, "max", ">= min");
  check_error(with_line(8, body + "  - generate: randon\n    shapes: cube\n    count: 1\n" + box),
              9, "generate", "did you mean 'random'?");
  check_error(
      with_line(
          8, body + "  - generate: random\n    shapes: {cube: 0.5, tetra: 0.4}\n    count: 10\n" +
                 box),
      10, "shapes", "sum to");
  check_error(with_line(8, gen + "    region: {box: {min: [0, 0, 0], max: [1, 0, 1]}}"), 12, "max",
              "must exceed");
  check_error(
      with_line(8, gen + "    region: {cylinder: {center: [0, 0, 0], axis: [0, 0, 0], radius: 1, "
                         "length: 1}}"),
      12, "axis", "zero vector");
  check_error(
      with_line(8, gen + "    region: {box: {min: [0, 0, 0], max: [1, 1, 1]}, cylinder: {}}"), 12,
      "region", "exactly one");
  check_error(with_line(8, gen), 9, "region", "missing");
  check_error(with_line(8, body + "  - generate: lattice\n    shapes: cube\n    count: 0\n" + box),
              11, "count", "at least 1");
  test::TempDir dir;
  dir.write("lib.shp", "");
  const Scene s =
      load_scene(dir.write("g.yaml", with_line(8, gen + box + "    orientation: fixed")));
  CHECK_FALSE(s.generators[0].random_orientation);
  CHECK(s.generators[0].scale_min == 1.0);
  CHECK(s.generators[0].loc.line == 9);
}

// The law's ranges are checked here, once: prepare_law trusts them.
TEST_CASE("contact law: ranges and pairings are refused at their key", "[scene][errors]") {
  check_error(with_line(5, "      config: {kn: 1e5, kt: 0, mu: 0.5, en: 0.5}"), 5, "kt", "mu > 0 needs kt > 0");
  check_error(with_line(5, "      config: {kn: 1e5, kt: 1e5, mu: 0.5, en: 0.5, mur: 0.1}"), 5, "kr", "kr > 0");
  check_error(with_line(5, "      config: {kn: -1, kt: 1e5, mu: 0.5, en: 0.5}"), 5, "kn", "");
  check_error(with_line(5, "      config: {kn: 1e5, kt: 1e5, mu: 0.5, en: 1.5}"), 5, "en", "(0, 1]");
}

TEST_CASE("contact law: model hertz takes E and poisson, with units and ranges", "[scene][errors][hertz]") {
  CHECK(error_of(with_line(5, "      config: {model: hertz, E: \"70 GPa\", poisson: 0.3, mu: 0.5, en: 0.5}")) == "");
  check_error(with_line(5, "      config: {model: hertz, E: \"70 GPa\", poisson: 0.7, mu: 0.5, en: 0.5}"), 5,
              "poisson", "[0, 0.5]");
  check_error(with_line(5, "      config: {model: hertz, E: \"70 GPa\", poisson: -0.1, mu: 0.5, en: 0.5}"), 5,
              "poisson", "[0, 0.5]");
  check_error(with_line(5, "      config: {model: hertz, E: \"70 m\", poisson: 0.3, mu: 0.5, en: 0.5}"), 5, "E",
              "pressure");
  check_error(with_line(5, "      config: {model: hertz, poisson: 0.3, mu: 0.5, en: 0.5}"), 5, "E", "missing");
  check_error(with_line(5, "      config: {model: hertz, E: 7e10, kn: 1e5, poisson: 0.3, mu: 0.5, en: 0.5}"), 5, "kn",
              "E and poisson");
  check_error(with_line(5, "      config: {kn: 1e5, kt: 1e5, poisson: 0.3, mu: 0.5, en: 0.5}"), 5, "poisson",
              "model: hertz");
  check_error(with_line(5, "      config: {model: hooke, kn: 1e5, kt: 1e5, mu: 0.5, en: 0.5}"), 5, "model",
              "linear or hertz");
  check_error(with_line(5,
                        "      config: {kn: 1e5, kt: 1e5, mu: 0.5, en: 0.5}\n"
                        "      config_driver: {model: hertz, E: 2e11, poisson: 0.3, mu: 0.5, en: 0.5}"),
              6, "config_driver", "give config model: hertz too");
}

TEST_CASE("YAML's .nan and .inf, and numbers beyond double (1e400, 1e308 km), are refused at their line",
          "[scene][errors]") {
  for (const std::string v : {".nan", ".NaN", ".inf", "-.inf", "+.inf", "\"nan N/m\"", "\"inf N/m\""}) {
    INFO(v);
    check_error(with_line(5, "      config: {kn: " + v + ", kt: 1.0e5, mu: 0.5, en: 0.5}"), 5, "kn",
                "expected a number");
    check_error(with_line(8, "    position: [0, " + v + ", 0]"), 8, "position", "expected a number");
  }
  for (const std::string v : {"1e400", "-1e400", "1e-400", "\"1e400 N/m\""}) {
    INFO(v);
    check_error(with_line(5, "      config: {kn: " + v + ", kt: 1.0e5, mu: 0.5, en: 0.5}"), 5, "kn", "out of range");
  }
  // Finite as written, infinite in SI units: the unit's factor overflows.
  check_error(with_line(8, "    position: [0, \"1e308 km\", 0]"), 8, "position", "out of range in SI units");
  check_error(with_line(1, "simulation: {duration: \"1e307 min\", dt: \"1 us\", seed: 3}"), 1, "duration",
              "out of range in SI units");
}

TEST_CASE("a wall's drawing size and the rounded output are read with units, and a bad size names its key",
          "[scene][errors]") {
  test::TempDir dir;
  dir.write("lib.shp", "stub\n");
  const Scene scene = load_scene(dir.write("scene.yaml", edited({{10, "  - wall: {point: [0, 0, 0], normal: [0, 0, 1], "
                                                                        "size: \"20 cm\"}"},
                                                                    {11, "output: {rounded: true}"}})));
  REQUIRE(scene.drivers.size() == 1);
  CHECK(std::get<WallSettings>(scene.drivers[0].kind).size == Approx(0.2).epsilon(1e-15));
  CHECK(scene.output.rounded);
  CHECK_FALSE(load_scene(dir.write("plain.yaml", with_line(11, ""))).output.rounded);
  check_error(with_line(10, "  - wall: {point: [0, 0, 0], normal: [0, 0, 1], size: -1}"), 10, "size", "must be > 0");
  check_error(with_line(11, "output: {rounde: true}"), 11, "rounde", "did you mean 'rounded'?");
}
