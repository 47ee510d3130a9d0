// polydem's YAML shape format and the length strings it accepts.
#include <catch2/catch.hpp>

#include "polydem/error.hpp"
#include "polydem/shape_library.hpp"
#include "shape/length_text.hpp"
#include "temp_file.hpp"

using namespace polydem;

TEST_CASE("lengths: plain metres or m, cm, mm", "[yaml]") {
  CHECK(*parse_length("0.0005") == 0.0005);
  CHECK(*parse_length("0.5 mm") == Approx(0.0005));
  CHECK(*parse_length("0.05cm") == Approx(0.0005));
  CHECK(*parse_length("5e-4 m") == 0.0005);
  CHECK_FALSE(parse_length("0.5 in"));
  CHECK_FALSE(parse_length("mm"));
}

TEST_CASE("YAML shapes: points hulled, vertices with faces, precomputed values kept", "[yaml]") {
  const std::string path = test::write_temp("lib.yaml", R"(
- name: tetra
  radius: 1 mm
  points: [[0, 0, 0], [0.01, 0, 0], [0, 0.01, 0], [0, 0, 0.01]]
- name: tetra_faces
  radius: 0.001
  vertices: [[0, 0, 0], [0.01, 0, 0], [0, 0.01, 0], [0, 0, 0.01]]
  faces: [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
- name: ball
  radius: 0.002
  vertices: [[0, 0, 0]]
  volume: 3.0e-8
  inertia_per_mass: [1.0e-6, 1.0e-6, 1.0e-6]
)");
  const ShapeLibrary lib = load_shape_library({path});
  REQUIRE(lib.shapes.size() == 3);
  const Shape& a = lib.shapes[0];
  const Shape& b = lib.shapes[1];
  CHECK(a.faces.size() == 4);
  CHECK(b.edges.size() == 6);
  CHECK(b.volume == Approx(a.volume).epsilon(1e-12));
  CHECK((b.inertia_per_mass - a.inertia_per_mass).norm() < 1e-12 * a.inertia_per_mass.norm());
  CHECK(lib.shapes[2].volume == 3.0e-8);  // given, not recomputed
}

TEST_CASE("YAML shape errors: line, key and suggestion", "[yaml]") {
  const std::string typo =
      test::write_temp("typo.yaml", "- name: a\n  radius: 0.001\n  vertice: [[0, 0, 0]]\n");
  CHECK_THROWS_WITH(read_shape_file(typo), Catch::Contains("typo.yaml:3: key 'vertice'") &&
                                               Catch::Contains("did you mean 'vertices'?"));
  const std::string unit =
      test::write_temp("unit.yaml", "- name: a\n  radius: 1 inch\n  points: [[0, 0, 0]]\n");
  CHECK_THROWS_WITH(read_shape_file(unit), Catch::Contains("unit.yaml:2: key 'radius'"));
  const std::string wrong = test::write_temp(
      "wrong.yaml", "- name: v\n  radius: 0.1\n  vertices: [[0,0,0],[1,0,0],[1,1,0]]\n"
                    "  edges: [[0, 1], [1, 2]]\n  convex: true\n");
  CHECK_THROWS_WITH(read_shape_file(wrong), Catch::Contains("wrong.yaml:5: key 'convex'") &&
                                                Catch::Contains("shape 'v' is not convex"));
}

TEST_CASE("YAML non-convex kinds: cluster, polyline, open surface, convex: false", "[yaml]") {
  const std::string path = test::write_temp("kinds.yaml", R"(
- name: cluster
  radius: 0.1
  vertices: [[0, 0, 0], [0.3, 0, 0], [0, 0.3, 0]]
- name: pair
  radius: 0.1
  vertices: [[0, 0, 0], [0.3, 0, 0]]
  edges: []
- name: rod
  radius: 0.1
  vertices: [[0, 0, 0], [0.3, 0, 0]]
- name: vee
  radius: 0.05
  vertices: [[-0.3, 0, 0], [0, 0.2, 0], [0.3, 0, 0]]
  edges: [[0, 1], [1, 2]]
- name: sheet
  radius: 0.01
  vertices: [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 0.4]]
  faces: [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]
  surface: true
- name: slow_cube
  radius: 0.01
  vertices: [[0,0,0],[1,0,0],[0,1,0],[1,1,0],[0,0,1],[1,0,1],[0,1,1],[1,1,1]]
  faces: [[0,2,3,1],[4,5,7,6],[0,1,5,4],[2,6,7,3],[0,4,6,2],[1,3,7,5]]
  convex: false
)");
  const std::vector<Shape> shapes = read_shape_file(path);
  REQUIRE(shapes.size() == 6);
  CHECK(shapes[0].edges.empty());
  CHECK_FALSE(shapes[0].convex);
  CHECK(shapes[0].mass_error == 0.0);  // balls apart: closed form
  CHECK(shapes[1].edges.empty());
  CHECK_FALSE(shapes[1].convex);
  CHECK(shapes[2].edges.size() == 1);  // two vertices without `edges`: a segment
  CHECK(shapes[2].convex);
  CHECK_FALSE(shapes[3].convex);
  CHECK(shapes[4].surface);
  CHECK_FALSE(shapes[4].convex);
  CHECK(shapes[4].edges.size() == 8);
  CHECK_FALSE(shapes[5].convex);
  CHECK(shapes[5].mass_error == 0.0);  // a convex core keeps its closed forms
}
