// Rockable .shp reading and writing.
#include "shape/shp_io.hpp"

#include <catch2/catch.hpp>
#include <sstream>

#include "polydem/error.hpp"
#include "polydem/shape_library.hpp"
#include "shape/hull.hpp"
#include "temp_file.hpp"

using namespace polydem;

namespace {

// A block as Rockable's Shape::write prints it (its Monte-Carlo mass properties, its
// quaternion "s vx vy vz"), plus comment lines as Rockable's kwParser skips them.
const char* kRockableCube = R"(# library written by Rockable
<
name Cube
radius 0.1
preCompDone y
volume 2.0
I/m 0.26 0.27 0.28
obb.extent 0.6 0.6 0.6
obb.center 0 0 0
obb.e1 1 0 0
obb.e2 0 1 0
obb.e3 0 0 1
OBBtreeLevel 1
position 1 2 3
orientation 1 0 0 0
MCnstep 10000
fibObbOption 0
nv 8
-0.5 -0.5 -0.5
0.5 -0.5 -0.5
0.5 0.5 -0.5
-0.5 0.5 -0.5
-0.5 -0.5 0.5
0.5 -0.5 0.5
0.5 0.5 0.5
-0.5 0.5 0.5
ne 12
0 1
1 2
2 3
3 0
4 5
5 6
6 7
7 4
0 4
1 5
2 6
3 7
nf 6
4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 1 2 6 5
4 2 3 7 6
4 3 0 4 7
>
// a second shape, properties to compute
<
name Ball
radius 0.25
preCompDone n
nv 1
0 0 0
ne 0
nf 0
>
)";

std::string message_of(const std::string& text) {
  std::istringstream in(text);
  try {
    read_shp(in, "lib.shp");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("a Rockable library loads: precomputed values kept, others computed", "[shp]") {
  std::istringstream in(kRockableCube);
  const std::vector<Shape> shapes = read_shp(in, "lib.shp");
  REQUIRE(shapes.size() == 2);
  const Shape& cube = shapes[0];
  CHECK(cube.name == "Cube");
  CHECK(cube.vertices.size() == 8);
  CHECK(cube.edges.size() == 12);
  CHECK(cube.faces.size() == 6);
  CHECK(cube.volume == 2.0);  // preCompDone y: the file's values, vertices as they are
  CHECK(cube.inertia_per_mass == Vec3(0.26, 0.27, 0.28));
  CHECK(cube.vertices[6] == Vec3(0.5, 0.5, 0.5));
  CHECK(cube.input_center == Vec3(1, 2, 3));
  CHECK(cube.bounding_radius == Approx(std::sqrt(0.75) + 0.1));
  for (size_t f = 0; f < cube.faces.size(); ++f)  // outward normals of the axis-aligned cube
    CHECK(cube.face_normals[f].dot(cube.vertices[cube.faces[f][0]]) == Approx(0.5));
  const Shape& ball = shapes[1];
  CHECK(ball.volume == Approx(4.0 / 3.0 * kPi * std::pow(0.25, 3)));
  CHECK(ball.inertia_per_mass.x() == Approx(0.4 * 0.25 * 0.25));
}

TEST_CASE("write then read gives back the same shapes, bit for bit", "[shp]") {
  std::vector<Shape> shapes;
  shapes.push_back(build_hull_shape(
      {Vec3(0, 0, 0), Vec3(1, 0.1, 0), Vec3(0.2, 1, 0.1), Vec3(0.3, 0.2, 0.9), Vec3(0.9, 0.8, 0.7)}, 0.05,
      "rock"));
  shapes.push_back(build_hull_shape({Vec3(0, 0, 0), Vec3(0, 0, 2)}, 0.3, "rod"));
  const std::string path = test::temp_path("round_trip.shp");
  write_shp_file(path, shapes);
  const std::vector<Shape> back = read_shape_file(path);
  REQUIRE(back.size() == 2);
  for (size_t i = 0; i < 2; ++i) {
    CHECK(back[i].name == shapes[i].name);
    CHECK(back[i].radius == shapes[i].radius);
    CHECK(back[i].volume == shapes[i].volume);
    CHECK(back[i].inertia_per_mass == shapes[i].inertia_per_mass);
    CHECK(back[i].vertices == shapes[i].vertices);
    CHECK(back[i].edges == shapes[i].edges);
    CHECK(back[i].faces == shapes[i].faces);
    CHECK(back[i].input_center == shapes[i].input_center);
    CHECK(back[i].input_rotation.coeffs() == shapes[i].input_rotation.coeffs());
    CHECK(back[i].bounding_radius == shapes[i].bounding_radius);
  }
}

TEST_CASE("bad .shp input names file, line and key", "[shp]") {
  CHECK_THAT(message_of("<\nname a\nradius x\n>\n"),
             Catch::Contains("lib.shp:3: key 'radius': 'x' is not a number"));
  CHECK_THAT(message_of("<\nname a\nradius 0.1\nnv 1\n0 0 0\n"),
             Catch::Contains("a shape block ends with '>'"));
  CHECK_THAT(message_of("<\nname a\nradius 0.1\n<\nname b\n>\n"),
             Catch::Contains("lib.shp:4: '<' inside the shape block opened at line 1"));
  CHECK_THAT(message_of("<\nname a\nradius -0.1\nnv 1\n0 0 0\n>"),
             Catch::Contains("lib.shp:1: key 'radius'"));
  CHECK_THAT(message_of("<\nname a\nradius 0.1\nnv 2\n0 0 0\n1 0 0\nne 1\n0 2\n>"),
             Catch::Contains("vertex index 2 out of range"));
}

TEST_CASE("unknown .shp keys are skipped with a warning naming file, line and key, as Rockable does", "[shp]") {
  std::istringstream in("<\nname a\nradus 0.1 0.2\nradius 0.1\nnv 1\n0 0 0\n>\n");
  std::vector<std::string> warnings;
  const std::vector<Shape> shapes = read_shp(in, "lib.shp", &warnings);
  REQUIRE(shapes.size() == 1);
  CHECK(shapes[0].radius == 0.1);
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0] == "lib.shp:3: key 'radus': unknown key in a shape block, ignored (did you mean 'radius'?)");
}

namespace {

std::string fixture(const std::string& name) { return std::string(POLYDEM_SOURCE_DIR) + "/tests/shape/fixtures/" + name; }

const Shape& named(const std::vector<Shape>& shapes, const std::string& name) {
  for (const Shape& s : shapes)
    if (s.name == name) return s;
  FAIL("no shape " << name);
  return shapes[0];
}

}  // namespace

TEST_CASE("exaDEM shapes: the alpha3 cross with 'na 0', a cluster, a duplicated edge", "[shp]") {
  std::vector<std::string> warnings;
  const std::vector<Shape> shapes = read_shp_file(fixture("exadem.shp"), &warnings);
  REQUIRE(shapes.size() == 3);
  const Shape& alpha3 = named(shapes, "alpha3");
  CHECK(alpha3.vertices.size() == 6);
  CHECK(alpha3.edges.size() == 3);
  CHECK(alpha3.faces.empty());
  CHECK_FALSE(alpha3.convex);
  CHECK(alpha3.volume == 0.523598775598299);  // preCompDone y: taken as given, as exaDEM wrote it
  CHECK(alpha3.inertia_per_mass == Vec3(0.13266, 0.13266, 0.13266));
  const Shape& cross = named(shapes, "cross");
  CHECK(cross.edges.size() == 3);  // "3 2" repeats "2 3": merged
  CHECK_FALSE(cross.convex);
  CHECK(cross.mass_error > 0.0);
  CHECK(cross.mass_error < 1e-4);
  const Shape& aggregate = named(shapes, "aggregate");
  CHECK(aggregate.edges.empty());
  CHECK_FALSE(aggregate.convex);
  REQUIRE(warnings.size() == 1);
  CHECK_THAT(warnings[0], Catch::Contains("exadem.shp:43: key 'ne': shape 'cross': edge 3 2 is listed twice, merged"));
}

TEST_CASE("Rockable shapes: Rice polylines and an isSurface plate", "[shp]") {
  std::vector<std::string> warnings;
  const std::vector<Shape> shapes = read_shp_file(fixture("rockable.shp"), &warnings);
  REQUIRE(shapes.size() == 3);
  const Shape& rice = named(shapes, "Rice");
  CHECK(rice.vertices.size() == 3);
  CHECK(rice.edges.size() == 2);
  CHECK_FALSE(rice.convex);
  // Straight: a capsule of core length 0.6 and radius 0.05 (the middle vertex adds nothing).
  const Shape& straight = named(shapes, "RiceStraight");
  const double r = 0.05, L = 0.6;
  CHECK(straight.volume == Approx(kPi * r * r * L + 4.0 / 3.0 * kPi * r * r * r).epsilon(straight.mass_error));
  const Shape& plate = named(shapes, "plate");
  CHECK(plate.surface);
  CHECK_FALSE(plate.convex);
  CHECK(plate.faces.size() == 6);
  CHECK(plate.edges.size() == 12);  // 6 spokes and 6 rim edges, from the faces
  REQUIRE(warnings.size() == 1);
  CHECK_THAT(warnings[0], Catch::Contains("rockable.shp:48: key 'futureKey': unknown key"));
}

TEST_CASE("every non-convex kind round-trips through the writer with its mass properties", "[shp]") {
  for (const char* file : {"exadem.shp", "rockable.shp"}) {
    std::vector<std::string> warnings;
    const std::vector<Shape> shapes = read_shp_file(fixture(file), &warnings);
    const std::string path = test::temp_path(std::string("round_") + file);
    write_shp_file(path, shapes);
    const std::vector<Shape> back = read_shp_file(path, &warnings);
    REQUIRE(back.size() == shapes.size());
    for (size_t i = 0; i < shapes.size(); ++i) {
      INFO(shapes[i].name);
      CHECK(back[i].volume == shapes[i].volume);
      CHECK(back[i].inertia_per_mass == shapes[i].inertia_per_mass);
      CHECK(back[i].vertices == shapes[i].vertices);
      CHECK(back[i].edges == shapes[i].edges);
      CHECK(back[i].faces == shapes[i].faces);
      CHECK(back[i].convex == shapes[i].convex);
      CHECK(back[i].surface == shapes[i].surface);
    }
  }
}

TEST_CASE("library: missing file, unknown type and duplicate names are InputErrors", "[shp]") {
  CHECK_THROWS_WITH(read_shape_file("/nonexistent/lib.shp"), Catch::Contains("cannot open"));
  const std::string other = test::write_temp("lib.txt", "x");
  CHECK_THROWS_WITH(read_shape_file(other), Catch::Contains("use .shp or .yaml"));
  const std::string a = test::write_temp("a.shp", "<\nname ball\nradius 0.1\nnv 1\n0 0 0\n>\n");
  const std::string b = test::write_temp("b.shp", "<\nname ball\nradius 0.2\nnv 1\n0 0 0\n>\n");
  CHECK(load_shape_library({a}).find("ball") == 0);
  CHECK_THROWS_WITH(load_shape_library({a, b}), Catch::Contains("shape 'ball' is already defined in " + a));
}
