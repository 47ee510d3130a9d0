// The shape library shipped in shapes/: it loads, and its sizes are the documented ones.
#include <catch2/catch.hpp>

#include "polydem/shape_library.hpp"

using namespace polydem;

TEST_CASE("shipped library loads with unique names and documented sizes", "[library]") {
  const std::string dir = std::string(POLYDEM_SOURCE_DIR) + "/shapes/";
  const ShapeLibrary lib = load_shape_library({dir + "platonic.shp", dir + "boxes.shp", dir + "rocks.shp"});
  CHECK(lib.shapes.size() == 11);
  for (const char* name : {"sphere", "tetrahedron", "cube", "octahedron", "dodecahedron", "icosahedron",
                           "box_elongated", "box_flat", "rock1", "rock2", "rock3"})
    CHECK(lib.find(name) >= 0);
  const Shape& sphere = lib.shapes[lib.find("sphere")];
  CHECK(sphere.radius == Approx(0.005));
  // Benchmark cube: core side a = 9 mm, r = 0.5 mm. Steiner: a^3 + 6 a^2 r + 3 pi a r^2 + 4/3 pi r^3.
  const Shape& cube = lib.shapes[lib.find("cube")];
  const double a = 0.009, r = 0.0005;
  CHECK(cube.radius == Approx(r).epsilon(1e-15));
  CHECK(cube.volume ==
        Approx(a * a * a + 6 * a * a * r + 3 * kPi * a * r * r + 4.0 / 3.0 * kPi * r * r * r).epsilon(1e-13));
  for (const Vec3& v : cube.vertices) CHECK(v.cwiseAbs().maxCoeff() <= a / 2 * (1 + 1e-12));
  for (const Shape& s : lib.shapes) {
    CHECK(s.radius == Approx(s.name == "sphere" ? 0.005 : 0.0005));
    CHECK(2 * s.bounding_radius <= 0.0175);  // about 1 cm across (the cube's diagonal 1.66 cm)
    CHECK(2 * s.bounding_radius >= 0.0095);
  }
}
