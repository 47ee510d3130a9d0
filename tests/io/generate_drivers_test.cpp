// Generators keep the bodies' bounding spheres clear of the drivers present at t = 0 (walls,
// cylinders, balls, STL meshes), say how many fit when the count is too large, and place
// bodies exactly as before when no driver is in the way.
#include <catch2/catch.hpp>
#include <cmath>

#include "io/generate.hpp"
#include "io_fixture.hpp"

using namespace polydem;
using test::contains;

namespace {

constexpr double kR = 0.005;  // m, the one shape's bounding radius: lattice spacing 1 cm

ShapeLibrary library() {
  ShapeLibrary lib;
  lib.shapes = {sphere_shape("ball", kR)};
  return lib;
}

GeneratorSpec generator(GeneratorSpec::Kind kind, int count, const BoxRegion& box) {
  GeneratorSpec g;
  g.kind = kind;
  g.shapes = {{"ball", 1.0}};
  g.count = count;
  g.region = box;
  g.loc = {"scene.yaml", 12};
  g.shapes_loc = {"scene.yaml", 13};
  return g;
}

DriverSettings wall(const Vec3& point, const Vec3& normal) {
  DriverSettings d;
  d.kind = WallSettings{point, normal, std::nullopt};
  return d;
}

DriverSettings cylinder(const Vec3& center, const Vec3& axis, double radius, bool inside) {
  DriverSettings d;
  d.kind = CylinderSettings{center, axis, radius, std::nullopt, inside};
  return d;
}

DriverSettings mesh_driver(const std::string& name, const std::string& file, int line) {
  DriverSettings d;
  d.name = name;
  MeshSettings m;
  m.file = file;
  m.where = input_message("scene.yaml", line, "file", "driver '" + name + "': ");
  d.kind = m;
  return d;
}

Scene scene_with(const GeneratorSpec& g, const std::vector<DriverSettings>& drivers) {
  Scene s;
  s.simulation.seed = 5;
  s.generators = {g};
  s.drivers = drivers;
  return s;
}

// A 20 x 20 x 5 cm box: 20 x 20 x 5 lattice sites at x, y = +-5 mm, +-15 mm, ... +-95 mm.
const BoxRegion kBox{Vec3(-0.1, -0.1, 0.0), Vec3(0.1, 0.1, 0.05)};
// Cut by the wall x = 0 (bodies on x > 0) and by a drum of radius 5 cm about the z axis.
const std::vector<DriverSettings> kCut = {wall(Vec3::Zero(), Vec3::UnitX()),
                                      cylinder(Vec3(0, 0, 0.025), Vec3::UnitZ(), 0.05, true)};

// Sites of kBox whose sphere lies on the wall's side and inside the drum, counted by brute force:
// x = (i + 0.5) 1 cm >= r and x^2 + y^2 <= (5 cm - r)^2, times the 5 layers.
int clear_sites() {
  int n = 0;
  for (int i = -10; i < 10; ++i)
    for (int j = -10; j < 10; ++j) {
      const double x = (i + 0.5) * 0.01, y = (j + 0.5) * 0.01;
      n += x >= kR - 1e-12 && std::hypot(x, y) <= 0.05 - kR + 1e-12;
    }
  return 5 * n;
}

// Distance from p to triangle (a, b, c) by sampling it on a barycentric grid of step 1/n:
// an upper bound within the grid's spacing of the exact distance.
double sampled_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, int n) {
  double best = 1e300;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const Vec3 q = a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n);
      best = std::min(best, (q - p).norm());
    }
  return best;
}

}  // namespace

TEST_CASE("lattice: a region cut by a wall and a drum keeps every body clear of both",
          "[generate]") {
  const ShapeLibrary lib = library();
  const int n = clear_sites();  // 5 layers x 30 = 150 of the 2000 sites
  REQUIRE(n > 100);
  const auto bodies =
      expand_bodies(scene_with(generator(GeneratorSpec::Kind::lattice, n, kBox), kCut), lib);
  REQUIRE(bodies.size() == static_cast<std::size_t>(n));
  double worst = -1.0;  // m, the largest overlap of a bounding sphere with a driver
  for (const BodySpec& b : bodies) {
    worst = std::max(worst, kR - b.position.x());
    worst = std::max(worst, b.position.head<2>().norm() - (0.05 - kR));
  }
  CHECK(worst <= 1e-12);
}

TEST_CASE("lattice: a count above the clear sites says how many fit", "[generate]") {
  const ShapeLibrary lib = library();
  const int n = clear_sites();
  const GeneratorSpec g = generator(GeneratorSpec::Kind::lattice, n + 1, kBox);
  const std::string msg = test::input_error_of([&] { expand_bodies(scene_with(g, kCut), lib); });
  CHECK(contains(msg, "scene.yaml:12:"));
  CHECK(contains(msg, "key 'count'"));
  CHECK(contains(msg, "2000 lattice sites"));
  CHECK(contains(msg, std::to_string(n) + " clear of the drivers)"));  // GCC 12 warns on "(" + string (PR 105329)
  CHECK(contains(msg, "bigger region or a smaller count (at most " + std::to_string(n) + ")"));
}

TEST_CASE("random: bodies stay clear of a wall, a post and a ball", "[generate]") {
  const ShapeLibrary lib = library();
  const CylinderSettings post{Vec3(0.05, 0, 0.025), Vec3(0, 1, 1).normalized(), 0.02, 0.04, false};
  const BallSettings ball{Vec3(-0.05, 0.03, 0.02), 0.03};
  const WallSettings tilted{Vec3(0, 0, 0.01), Vec3(0.3, 0.2, 1).normalized(), std::nullopt};
  const std::vector<DriverSettings> drivers{{"", post, {}, {}}, {"", ball, {}, {}}, {"", tilted, {}, {}}};
  const auto bodies = expand_bodies(scene_with(generator(GeneratorSpec::Kind::random, 400, kBox), drivers), lib);
  REQUIRE(bodies.size() == 400u);
  double worst = -1.0;
  for (const BodySpec& b : bodies) {
    const Vec3 rel = b.position - post.center;
    const double along = std::clamp(rel.dot(post.axis), -0.02, 0.02);
    worst = std::max(worst, 0.02 + kR - (rel - along * post.axis).norm());
    worst = std::max(worst, 0.03 + kR - (b.position - ball.center).norm());
    worst = std::max(worst, kR - (b.position - tilted.point).dot(tilted.normal));
  }
  CHECK(worst <= 0.0);
}

TEST_CASE("random and lattice: drivers out of the way change no body", "[generate]") {
  const ShapeLibrary lib = library();
  // Touching the region's faces from outside, and a drum around it: nothing is in the way.
  const std::vector<DriverSettings> around = {
      wall(Vec3(0, 0, 0), Vec3::UnitZ()),
      cylinder(Vec3(0, 0, 0), Vec3::UnitZ(), 0.1 * std::sqrt(2.0), true)};
  for (auto kind : {GeneratorSpec::Kind::random, GeneratorSpec::Kind::lattice}) {
    const GeneratorSpec g = generator(kind, 800, kBox);
    const auto free = expand_bodies(scene_with(g, {}), lib);
    const auto held = expand_bodies(scene_with(g, around), lib);
    REQUIRE(free.size() == held.size());
    bool same = true;
    for (std::size_t i = 0; i < free.size(); ++i)
      same = same && free[i].position == held[i].position &&
             free[i].orientation.coeffs() == held[i].orientation.coeffs();
    CHECK(same);
  }
}

TEST_CASE("random: bodies stay clear of an STL mesh, and a region it fills says how many fit",
          "[generate]") {
  const ShapeLibrary lib = library();
  const test::TempDir dir;
  // A tetrahedron in mm (scale 0.001), placed by a rotation and a translation.
  const std::array<Vec3, 4> v = {Vec3(0, 0, 0), Vec3(80, 0, 0), Vec3(0, 80, 0), Vec3(0, 0, 60)};
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::string stl = "solid t\n";
  for (const auto& f : faces) {
    stl += "facet normal 0 0 0\nouter loop\n";
    for (int k : f)
      stl += "vertex " + std::to_string(v[k].x()) + " " + std::to_string(v[k].y()) + " " +
             std::to_string(v[k].z()) + "\n";
    stl += "endloop\nendfacet\n";
  }
  DriverSettings tet = mesh_driver("tet", dir.write("tet.stl", stl + "endsolid t\n"), 0);
  MeshSettings& mesh = std::get<MeshSettings>(tet.kind);
  mesh.scale = 0.001;
  mesh.rotation = Quat(Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()));
  mesh.translation = Vec3(-0.03, -0.02, 0.0);
  const auto bodies =
      expand_bodies(scene_with(generator(GeneratorSpec::Kind::random, 500, kBox), {tet}), lib);
  REQUIRE(bodies.size() == 500u);
  double nearest = 1e300;  // m, the smallest sampled centre-triangle distance
  std::array<Vec3, 4> w;
  for (int k = 0; k < 4; ++k) w[k] = mesh.translation + mesh.rotation * (0.001 * v[k]);
  for (const BodySpec& b : bodies)
    for (const auto& f : faces)
      nearest = std::min(nearest, sampled_distance(b.position, w[f[0]], w[f[1]], w[f[2]], 200));
  // Sampling only overestimates (by < 0.4 mm, the grid step): a clear body passes, an overlap
  // deeper than 0.4 mm fails.
  CHECK(nearest >= kR);
  CHECK(nearest < kR + 0.002);  // and bodies do come close: the mesh is in the region

  // A slab around the face z = 0: every centre is within 1 mm of it, so no body fits.
  const BoxRegion slab{Vec3(0.01, 0.01, -0.006), Vec3(0.03, 0.03, 0.006)};
  mesh.rotation = Quat::Identity();
  mesh.translation = Vec3::Zero();
  const std::string msg = test::input_error_of([&] {
    expand_bodies(scene_with(generator(GeneratorSpec::Kind::random, 5, slab), {tet}), lib);
  });
  CHECK(contains(msg, "scene.yaml:12: key 'count': placed 0 of 5 bodies"));
  CHECK(contains(msg, "or a driver"));
  CHECK(contains(msg, "bigger region or a smaller count"));
}

TEST_CASE("generators: a missing STL names the driver's file key", "[generate]") {
  const ShapeLibrary lib = library();
  const DriverSettings mesh = mesh_driver("plate", "/nonexistent/plate.stl", 30);
  const std::string msg = test::input_error_of([&] {
    expand_bodies(scene_with(generator(GeneratorSpec::Kind::lattice, 5, kBox), {mesh}), lib);
  });
  CHECK(contains(msg, "scene.yaml:30: key 'file': driver 'plate'"));
  CHECK(contains(msg, "plate.stl"));
}
