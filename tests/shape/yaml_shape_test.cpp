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
  const std::string flat =
      test::write_temp("flat.yaml", "- name: a\n  radius: 0.1\n  vertices: [[0,0,0],[1,0,0],[0,1,0]]\n");
  CHECK_THROWS_WITH(read_shape_file(flat), Catch::Contains("flat.yaml:3") && Catch::Contains("'points'"));
}
