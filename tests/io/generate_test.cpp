// Body generators: counts, no overlap (brute force), inside the region, reproducibility,
// mix fractions and orientation statistics.
#include "io/generate.hpp"

#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>

#include "io_fixture.hpp"

using namespace polydem;
using test::contains;

namespace {


ShapeLibrary library() {
  ShapeLibrary lib;
  lib.shapes = {sphere_shape("small", 0.005), sphere_shape("large", 0.01)};
  return lib;
}

GeneratorSpec generator(int count, std::variant<BoxRegion, CylinderRegion> region) {
  GeneratorSpec g;
  g.shapes = {{"small", 0.7}, {"large", 0.3}};
  g.count = count;
  g.region = region;
  g.scale_min = 0.8;
  g.scale_max = 1.2;
  g.loc = {"scene.yaml", 17};
  g.shapes_loc = {"scene.yaml", 18};
  return g;
}

Scene scene_with(const GeneratorSpec& g, std::uint64_t seed = 42) {
  Scene s;
  s.simulation.seed = seed;
  s.generators = {g};
  return s;
}

double radius_of(const BodySpec& b, const ShapeLibrary& lib) {
  return lib.shapes[lib.find(b.shape)].bounding_radius * b.scale;
}

// Brute force over all pairs: the largest overlap of bounding spheres (<= 0 when none).
double max_overlap(const std::vector<BodySpec>& bodies, const ShapeLibrary& lib) {
  double worst = -1.0;
  for (std::size_t i = 0; i < bodies.size(); ++i)
    for (std::size_t j = i + 1; j < bodies.size(); ++j)
      worst = std::max(worst, radius_of(bodies[i], lib) + radius_of(bodies[j], lib) -
                                  (bodies[i].position - bodies[j].position).norm());
  return worst;
}

bool inside_box(const BodySpec& b, double r, const BoxRegion& box) {
  return ((b.position.array() - r) >= box.min.array()).all() &&
         ((b.position.array() + r) <= box.max.array()).all();
}

bool inside_cylinder(const BodySpec& b, double r, const CylinderRegion& c) {
  const Vec3 d = b.position - c.center;
  const double along = d.dot(c.axis);
  const double radial = (d - along * c.axis).norm();
  return along >= r - 1e-12 && along <= c.length - r + 1e-12 && radial <= c.radius - r + 1e-12;
}

const BoxRegion kBox{Vec3(-0.1, -0.1, 0.0), Vec3(0.1, 0.1, 0.3)};

}  // namespace

TEST_CASE("random: count placed, no overlap, all inside a box", "[generate]") {
  const ShapeLibrary lib = library();
  const auto bodies = expand_bodies(scene_with(generator(2000, kBox)), lib);
  REQUIRE(bodies.size() == 2000);
  CHECK(max_overlap(bodies, lib) <= 0.0);
  int outside = 0;
  for (const auto& b : bodies) outside += !inside_box(b, radius_of(b, lib), kBox);
  CHECK(outside == 0);
  for (const auto& b : bodies) {
    CHECK((b.scale >= 0.8 && b.scale < 1.2));
    CHECK(std::abs(b.orientation.norm() - 1.0) < 1e-12);
  }
}

TEST_CASE("random: a cylinder with a tilted axis", "[generate]") {
  const ShapeLibrary lib = library();
  CylinderRegion c;
  c.center = Vec3(0.3, -0.2, 0.1);
  c.axis = Vec3(1, 2, 2).normalized();
  c.radius = 0.1;
  c.length = 0.25;  // 1200 bodies fill about 25% of it
  const auto bodies = expand_bodies(scene_with(generator(1200, c)), lib);
  REQUIRE(bodies.size() == 1200);
  CHECK(max_overlap(bodies, lib) <= 0.0);
  int outside = 0;
  Vec3 mean = Vec3::Zero();
  for (const auto& b : bodies) {
    outside += !inside_cylinder(b, radius_of(b, lib), c);
    mean += b.position / bodies.size();
  }
  CHECK(outside == 0);
  // The bodies fill the whole cylinder: their mean sits near its centre (within 1 cm).
  CHECK((mean - (c.center + 0.5 * c.length * c.axis)).norm() < 0.01);
}

TEST_CASE("random: same seed gives the same bodies, another seed other bodies", "[generate]") {
  const ShapeLibrary lib = library();
  const GeneratorSpec g = generator(500, kBox);
  const auto a = expand_bodies(scene_with(g, 7), lib);
  const auto b = expand_bodies(scene_with(g, 7), lib);
  const auto c = expand_bodies(scene_with(g, 8), lib);
  REQUIRE((a.size() == b.size() && a.size() == c.size()));
  int same = 0, differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    same += a[i].position == b[i].position &&
            a[i].orientation.coeffs() == b[i].orientation.coeffs() && a[i].scale == b[i].scale &&
            a[i].shape == b[i].shape;
    differ += a[i].position != c[i].position;
  }
  CHECK(same == static_cast<int>(a.size()));
  CHECK(differ == static_cast<int>(a.size()));
  // Two generators in one scene draw from different streams.
  Scene two = scene_with(g, 7);
  two.generators.push_back(g);
  const auto both = expand_bodies(two, lib);
  REQUIRE(both.size() == 1000);
  CHECK(both[0].position == a[0].position);
  CHECK(both[500].position != a[0].position);
}

TEST_CASE("random: mix fractions of 5000 bodies and uniform orientations", "[generate]") {
  const ShapeLibrary lib = library();
  GeneratorSpec g = generator(5000, BoxRegion{Vec3(0, 0, 0), Vec3(0.4, 0.4, 0.4)});
  const auto bodies = expand_bodies(scene_with(g), lib);
  REQUIRE(bodies.size() == 5000);
  std::map<std::string, int> counts;
  double mean_z = 0.0, mean_z2 = 0.0;
  for (const auto& b : bodies) {
    ++counts[b.shape];
    const double z = (b.orientation * Vec3::UnitZ()).z();
    mean_z += z / 5000.0;
    mean_z2 += z * z / 5000.0;
  }
  // Binomial: sigma = sqrt(n p (1 - p)) = 32 bodies for p = 0.7; allow 4 sigma.
  const double sigma = std::sqrt(5000 * 0.7 * 0.3);
  CHECK(std::abs(counts["small"] - 3500) <= 4 * sigma);
  CHECK(counts["small"] + counts["large"] == 5000);
  // A uniform rotation maps e_z to a uniform point on the sphere: <z> = 0 (sd 1/sqrt(3n)),
  // <z^2> = 1/3 (sd sqrt(4/45 / n)).
  CHECK(std::abs(mean_z) < 4.0 / std::sqrt(3.0 * 5000));
  CHECK(std::abs(mean_z2 - 1.0 / 3.0) < 4.0 * std::sqrt(4.0 / 45.0 / 5000));
}

TEST_CASE("random: 50,000 bodies place with no overlap", "[generate]") {
  ShapeLibrary lib;
  lib.shapes = {sphere_shape("grain", 0.001)};
  GeneratorSpec g = generator(50000, BoxRegion{Vec3(0, 0, 0), Vec3(0.1, 0.1, 0.1)});
  g.shapes = {{"grain", 1.0}};
  // 50,000 spheres of radius 0.8-1.2 mm fill 22% of the 1 L box, under the jamming limit.
  const auto bodies = expand_bodies(scene_with(g), lib);
  REQUIRE(bodies.size() == 50000);
  // Overlap check by hashing centres into 2.4 mm cells (the largest diameter) and testing
  // each pair of bodies in neighbouring cells.
  std::map<std::array<long, 3>, std::vector<std::size_t>> cells;
  const auto cell_of = [](const Vec3& p) {
    return std::array<long, 3>{std::lround(std::floor(p.x() / 0.0024)),
                               std::lround(std::floor(p.y() / 0.0024)),
                               std::lround(std::floor(p.z() / 0.0024))};
  };
  for (std::size_t i = 0; i < bodies.size(); ++i) cells[cell_of(bodies[i].position)].push_back(i);
  int overlaps = 0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const auto c = cell_of(bodies[i].position);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto it = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == cells.end()) continue;
          for (std::size_t j : it->second)
            overlaps += j > i && (bodies[i].position - bodies[j].position).norm() <
                                     radius_of(bodies[i], lib) + radius_of(bodies[j], lib);
        }
  }
  CHECK(overlaps == 0);
}

TEST_CASE("random: an impossible count names the generator line", "[generate]") {
  const ShapeLibrary lib = library();
  GeneratorSpec g = generator(3000, BoxRegion{Vec3(0, 0, 0), Vec3(0.1, 0.1, 0.1)});
  const std::string msg = test::input_error_of([&] { expand_bodies(scene_with(g), lib); });
  CHECK(contains(msg, "scene.yaml:17:"));
  CHECK(contains(msg, "key 'count'"));
  CHECK(contains(msg, "placed"));
  CHECK(contains(msg, "bigger region or a smaller count"));
  g.region = BoxRegion{Vec3(0, 0, 0), Vec3(0.01, 0.1, 0.1)};  // narrower than a large body
  CHECK(contains(test::input_error_of([&] { expand_bodies(scene_with(g), lib); }), "does not fit"));
}

TEST_CASE("lattice: spacing, order, inside, too many", "[generate]") {
  const ShapeLibrary lib = library();
  GeneratorSpec g = generator(100, BoxRegion{Vec3(0, 0, 0), Vec3(0.1, 0.1, 0.2)});
  g.kind = GeneratorSpec::Kind::lattice;
  const auto bodies = expand_bodies(scene_with(g), lib);
  REQUIRE(bodies.size() == 100);
  const double spacing = 2 * 0.01 * 1.2;  // largest bounding diameter: large x scale_max
  // floor(0.1 / 0.024) = 4 sites per row: x runs fastest, then y, then z.
  CHECK(bodies[1].position.x() - bodies[0].position.x() == Approx(spacing));
  CHECK(bodies[4].position.y() - bodies[0].position.y() == Approx(spacing));
  CHECK(bodies[16].position.z() - bodies[0].position.z() == Approx(spacing));
  CHECK(max_overlap(bodies, lib) <= 1e-12);
  int outside = 0;
  for (const auto& b : bodies)
    outside += !inside_box(b, spacing / 2, std::get<BoxRegion>(g.region));
  CHECK(outside == 0);
  g.count = 4 * 4 * 8 + 1;  // floor(0.2 / 0.024) = 8 layers
  const std::string msg = test::input_error_of([&] { expand_bodies(scene_with(g), lib); });
  CHECK((contains(msg, "scene.yaml:17:") && contains(msg, "128 lattice sites")));
}

TEST_CASE("lattice: a tilted cylinder", "[generate]") {
  const ShapeLibrary lib = library();
  CylinderRegion c;
  c.axis = Vec3(0, 1, 1).normalized();
  c.radius = 0.06;
  c.length = 0.1;
  GeneratorSpec g = generator(40, c);
  g.kind = GeneratorSpec::Kind::lattice;
  const auto bodies = expand_bodies(scene_with(g), lib);
  REQUIRE(bodies.size() == 40);
  CHECK(max_overlap(bodies, lib) <= 1e-12);
  int outside = 0;
  for (const auto& b : bodies) outside += !inside_cylinder(b, 0.012, c);
  CHECK(outside == 0);
}

TEST_CASE("unknown shape names suggest the nearest known one", "[generate]") {
  const ShapeLibrary lib = library();
  Scene s;
  BodySpec b;
  b.shape = "smal";
  b.loc = {"scene.yaml", 9};
  s.bodies = {b};
  std::string msg = test::input_error_of([&] { expand_bodies(s, lib); });
  CHECK((contains(msg, "scene.yaml:9:") && contains(msg, "key 'shape'") &&
         contains(msg, "did you mean 'small'?")));
  GeneratorSpec g = generator(10, kBox);
  g.shapes = {{"small", 0.5}, {"larje", 0.5}};
  g.shapes_loc = {"scene.yaml", 19};  // the `shapes:` line of the generator
  msg = test::input_error_of([&] { expand_bodies(scene_with(g), lib); });
  CHECK((contains(msg, "scene.yaml:19:") && contains(msg, "'larje'") &&
         contains(msg, "did you mean 'large'?")));
  // Explicit bodies come first, then generated ones, in file order.
  s.bodies[0].shape = "large";
  s.generators = {generator(5, kBox)};
  const auto all = expand_bodies(s, lib);
  REQUIRE(all.size() == 6);
  CHECK(all[0].loc.line == 9);
  CHECK(all[5].loc.line == 17);
}

TEST_CASE("contact_sphere rejects a polyhedral shape", "[generate]") {
  ShapeLibrary lib = library();
  Shape cube = sphere_shape("cube", 0.001);
  cube.vertices = {Vec3(1, 1, 1), Vec3(-1, -1, -1)};  // any shape with more than one vertex
  lib.shapes.push_back(cube);
  Scene s = scene_with(generator(10, kBox));
  s.forces.contact.present = s.forces.contact.sphere = true;
  CHECK(test::input_error_of([&] { expand_bodies(s, lib); }).empty());
  s.generators[0].shapes = {{"small", 0.5}, {"cube", 0.5}};
  const std::string msg = test::input_error_of([&] { expand_bodies(s, lib); });
  CHECK((contains(msg, "scene.yaml:18:") && contains(msg, "not a sphere") &&
         contains(msg, "contact_polyhedron")));
}
