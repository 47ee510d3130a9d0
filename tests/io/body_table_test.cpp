// `- file: bodies.csv`: a table reads to the same bodies as the YAML list it stands for, and
// each bad cell is an InputError naming the table's file, row and column.
#include <catch2/catch.hpp>

#include "io/scene.hpp"
#include "io_fixture.hpp"

using namespace polydem;
using test::contains;

namespace {

const std::string kHead =
    "simulation: {duration: 1, dt: \"1 us\", seed: 3}\n"
    "shapes: [lib.shp]\n"
    "forces:\n"
    "  - contact_polyhedron:\n"
    "      config: {kn: 1.0e5, kt: 1.0e5, mu: 0.5, en: 0.5}\n"
    "bodies:\n";

Scene scene_with(const std::string& bodies, const std::string& table) {
  test::TempDir dir;
  dir.write("lib.shp", "stub\n");
  dir.write("data/bodies.csv", table);
  return load_scene(dir.write("scene.yaml", kHead + bodies));
}

std::string error_of(const std::string& table, const std::string& entry = "  - file: data/bodies.csv\n") {
  return test::input_error_of([&] { scene_with(entry, table); });
}

// The error names bodies.csv at `row` (1-based line of the file), the column, and `part`.
void check_error(const std::string& table, int row, const std::string& column, const std::string& part) {
  const std::string msg = error_of(table);
  INFO("message: " << msg);
  CHECK(contains(msg, "bodies.csv:" + std::to_string(row) + ": "));
  CHECK(contains(msg, "key '" + column + "'"));
  CHECK(contains(msg, part));
}

}  // namespace

TEST_CASE("body table: rows read to the bodies the YAML list gives", "[io][body_table]") {
  const std::string yaml =
      "  - {shape: cube, position: [0.1, -2.5e-3, 3], velocity: [1, 0, -0.25],\n"
      "     angular_velocity: [0, 7, 0], density: 1500, scale: 1.5, group: 2,\n"
      "     orientation: {quaternion: [1, 1, 0, 0]}}\n"
      "  - {shape: tetra, position: [0, 0, 0.012345678901234567], density: 2700}\n";
  const std::string table =
      "# two bodies, the second with the entry's defaults\n"
      "shape, x, y, z, qw, qx, qy, qz, vx, vy, vz, wx, wy, wz, density, scale, group\n"
      "cube, 0.1, -2.5e-3, 3, 1, 1, 0, 0, 1, 0, -0.25, 0, 7, 0, 1500, 1.5, 2\n"
      "\n"
      "tetra, 0, 0, 0.012345678901234567, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2700, 1, 0\n";
  const Scene a = scene_with(yaml, "");
  const Scene b = scene_with("  - file: data/bodies.csv\n", table);
  REQUIRE(a.bodies.size() == 2);
  REQUIRE(b.bodies.size() == 2);
  for (std::size_t i = 0; i < 2; ++i) {
    const BodySpec &y = a.bodies[i], &t = b.bodies[i];
    CHECK(t.shape == y.shape);
    CHECK(t.position == y.position);  // the same digits parse to the same doubles
    CHECK(t.orientation.coeffs() == y.orientation.coeffs());
    CHECK(t.velocity == y.velocity);
    CHECK(t.angular_velocity == y.angular_velocity);
    CHECK(t.density == y.density);
    CHECK(t.scale == y.scale);
    CHECK(t.group == y.group);
  }
  CHECK(contains(b.bodies[1].loc.file, "bodies.csv"));
  CHECK(b.bodies[1].loc.line == 5);
  CHECK(b.bodies[0].orientation.norm() == Approx(1.0).epsilon(1e-15));
}

TEST_CASE("body table: absent columns take the entry's values and the defaults", "[io][body_table]") {
  const Scene s = scene_with("  - {file: data/bodies.csv, density: 1000, group: 4}\n  - {shape: cube, position: [0, 0, 1]}\n",
                             "shape,x,y,z\nsphere,1,2,3\n");
  REQUIRE(s.bodies.size() == 2);
  CHECK(s.bodies[0].position == Vec3(1, 2, 3));
  CHECK(s.bodies[0].density == 1000.0);
  CHECK(s.bodies[0].group == 4);
  CHECK(s.bodies[0].scale == 1.0);
  CHECK(s.bodies[0].orientation.coeffs() == Quat::Identity().coeffs());
  CHECK(s.bodies[0].velocity == Vec3::Zero());
  CHECK(s.bodies[1].shape == "cube");  // the list goes on after the table, in order
}

TEST_CASE("body table: bad tables name the file, row and column", "[io][body_table]") {
  check_error("shape, x, y, zz\n", 1, "zz", "did you mean 'z'");
  check_error("shape, x, y\n", 1, "z", "missing column");
  check_error("x, y, z\n", 1, "shape", "missing column");
  check_error("shape, x, y, z, x\n", 1, "x", "column given twice");
  check_error("shape, x, y, z, qw, qx\n", 1, "qy", "missing column");
  check_error("shape, x, y, z\n# comment\ncube, 0, 0\n", 3, "row", "has 3 cells, the header 4");
  check_error("shape, x, y, z\ncube, 0, 1.5.2, 0\n", 2, "y", "expected a finite number");
  check_error("shape, x, y, z\ncube, 0, inf, 0\n", 2, "y", "expected a finite number");
  check_error("shape, x, y, z\ncube, 0, 0, 5 mm\n", 2, "z", "SI units");
  check_error("shape, x, y, z, density\ncube, 0, 0, 0, -2700\n", 2, "density", "must be > 0");
  check_error("shape, x, y, z, group\ncube, 0, 0, 0, 1.5\n", 2, "group", "integer");
  check_error("shape, x, y, z, qw, qx, qy, qz\ncube, 0, 0, 0, 0, 0, 0, 0\n", 2, "qw", "must not be zero");
  check_error("shape, x, y, z\n, 0, 0, 0\n", 2, "shape", "empty shape name");
}

TEST_CASE("body table: the entry's own errors name the scene", "[io][body_table]") {
  const std::string missing = error_of("", "  - file: nowhere.csv\n");
  CHECK(contains(missing, "scene.yaml:7: "));
  CHECK(contains(missing, "cannot open body table"));
  const std::string empty = error_of("# only a comment\n");
  CHECK(contains(empty, "scene.yaml:7: "));
  CHECK(contains(empty, "no header row"));
  const std::string stray = error_of("shape,x,y,z\n", "  - file: data/bodies.csv\n    position: [0, 0, 0]\n");
  CHECK(contains(stray, "key 'position'"));
}
