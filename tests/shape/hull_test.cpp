// Convex hulls: polygon faces, corners only, degenerate sets.
#include "shape/hull.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <set>

#include "polydem/error.hpp"
#include "reference_body.hpp"

using namespace polydem;

namespace {

// Euler V - E + F = 2, each edge once, faces convex and counter-clockwise seen from outside.
void check_polytope(const Shape& s) {
  CHECK(static_cast<int>(s.vertices.size() - s.edges.size() + s.faces.size()) == 2);
  std::set<std::pair<int, int>> unique;
  for (const auto& e : s.edges) unique.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
  CHECK(unique.size() == s.edges.size());
  for (size_t f = 0; f < s.faces.size(); ++f) {
    const auto& p = s.faces[f];
    const Vec3 n = s.face_normals[f];
    CHECK(n.norm() == Approx(1.0));
    for (size_t i = 0; i < p.size(); ++i) {
      const Vec3 a = s.vertices[p[i]], b = s.vertices[p[(i + 1) % p.size()]],
                 c = s.vertices[p[(i + 2) % p.size()]];
      CHECK((b - a).cross(c - b).dot(n) > 0);  // strictly convex, turning left about n
    }
    for (const Vec3& v : s.vertices) CHECK(n.dot(v - s.vertices[p[0]]) < 1e-12);  // outward
  }
}

std::vector<Vec3> cube_with_extras() {
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  p.emplace_back(0.5, 0, 0);      // on an edge
  p.emplace_back(0.5, 0.5, 1);    // in a face
  p.emplace_back(0.3, 0.6, 0.2);  // inside
  p.emplace_back(1, 1, 1);        // duplicate
  return p;
}

std::vector<Vec3> dodecahedron() {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  for (double s1 : {-1.0, 1.0})
    for (double s2 : {-1.0, 1.0}) {
      p.emplace_back(0, s1 / g, s2 * g);
      p.emplace_back(s1 / g, s2 * g, 0);
      p.emplace_back(s1 * g, 0, s2 / g);
    }
  return p;
}

}  // namespace

TEST_CASE("cube hull: extra points dropped, squares merged", "[hull]") {
  const Shape s = build_hull_shape(cube_with_extras(), 0.1, "cube");
  CHECK(s.vertices.size() == 8);
  CHECK(s.edges.size() == 12);
  REQUIRE(s.faces.size() == 6);
  for (const auto& f : s.faces) CHECK(f.size() == 4);
  check_polytope(s);
}

TEST_CASE("dodecahedron: 12 pentagons from rounded coordinates", "[hull]") {
  const Shape s = build_hull_shape(dodecahedron(), 0.1, "dodecahedron");
  CHECK(s.vertices.size() == 20);
  CHECK(s.edges.size() == 30);
  REQUIRE(s.faces.size() == 12);
  for (const auto& f : s.faces) CHECK(f.size() == 5);
  check_polytope(s);
}

TEST_CASE("random rock hull is a valid polytope", "[hull]") {
  const Shape s = build_hull_shape(test::rock_points(3, 60, 1.0, 0.6, 0.4), 0.05, "rock");
  check_polytope(s);
  for (const auto& f : s.faces) CHECK(f.size() == 3);  // random points: no 4 coplanar
}

TEST_CASE("degenerate sets with r > 0: sphere, segment, two-sided plate", "[hull]") {
  const Shape ball = build_hull_shape({Vec3(1, 1, 1), Vec3(1, 1, 1)}, 0.1, "ball");
  CHECK(ball.vertices.size() == 1);
  CHECK(ball.is_sphere());
  const Shape rod = build_hull_shape({Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(0.5, 0.5, 0.5)}, 0.1, "rod");
  CHECK(rod.vertices.size() == 2);
  CHECK(rod.edges.size() == 1);
  CHECK(rod.faces.empty());
  const Shape plate = build_hull_shape(
      {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(0.5, 0, 0), Vec3(0.2, 0.3, 0)}, 0.1,
      "plate");
  CHECK(plate.vertices.size() == 4);
  CHECK(plate.edges.size() == 4);
  REQUIRE(plate.faces.size() == 2);
  CHECK(plate.face_normals[0].dot(plate.face_normals[1]) == Approx(-1.0));
  std::vector<int> reversed(plate.faces[1].rbegin(), plate.faces[1].rend());
  CHECK(reversed == plate.faces[0]);
}

TEST_CASE("bad hull input is an InputError naming the fix", "[hull]") {
  CHECK_THROWS_WITH(
      build_hull_shape({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, 0.0, "flat"),
      Catch::Contains("degenerate hull") && Catch::Contains("give --radius > 0 or more points"));
  CHECK_THROWS_WITH(build_hull_shape({Vec3(0, 0, 0)}, 0.0, "dot"), Catch::Contains("degenerate hull"));
  CHECK_THROWS_WITH(build_hull_shape({Vec3(0, 0, 0)}, -0.1, "dot"), Catch::Contains("must be >= 0"));
  CHECK_THROWS_AS(build_hull_shape({}, 0.1, "none"), InputError);
}

TEST_CASE("hull: points far from the line or plane they would be flattened to are refused", "[hull]") {
  // A unit cube's corners with one moved to 1e9 m: within 1e-9 of the extent of a line, they
  // used to become a 2-vertex segment, silently.
  std::vector<Vec3> points;
  for (int k = 0; k < 7; ++k) points.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  points.emplace_back(1e9, 1e9, 1e9);
  CHECK_THROWS_WITH(build_hull_shape(points, 0.001, "far"),
                    Catch::Contains("off the line") && Catch::Contains("beyond the radius"));
  // Within the radius, the segment holds them all: accepted.
  const Shape rod = build_hull_shape({Vec3(0, 0, 0), Vec3(1e9, 0, 0), Vec3(5e8, 0.5, 0)}, 1.0, "rod");
  CHECK(rod.vertices.size() == 2);
}
