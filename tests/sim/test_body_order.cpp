// Bodies stored in space order (sim/body_order.hpp): the order sorts by cell, the run keeps the
// user ids beside its arrays, and a checkpoint carries the order so a resume continues in it.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include "polydem/error.hpp"
#include "sim/body_order.hpp"
#include "sim/checkpoint.hpp"
#include "old_formats.hpp"
#include "sim_fixtures.hpp"
#include "state_hash.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

// 60 spheres of two sizes poured at random over a floor: the pour's ids follow no space order.
struct Pour {
  Scene scene = base_scene(law(1e4, 0.5, 0.4, 1e4), true, Vec3(0, 0, -9.807));
  ShapeLibrary lib = library({sphere_shape(0.004, "small"), sphere_shape(0.006, "large")});
  std::vector<BodySpec> specs;
  Pour() {
    std::mt19937_64 rng(7);
    auto u = [&] { return double(rng() >> 11) * 0x1.0p-53; };
    for (int k = 0; k < 60; ++k)
      specs.push_back(body(k % 3 ? "small" : "large", Vec3(0.05 * u(), 0.05 * u(), 0.007 + 0.05 * u())));
  }
};

std::array<double, 3> cell_of(const Vec3& x, const Vec3& low, double size) {
  const Vec3 c = (x - low) / size;
  return {std::floor(c.z()), std::floor(c.y()), std::floor(c.x())};
}

std::string temp_path(const char* name) {
  return (std::filesystem::temp_directory_path() / (std::string(name) + std::to_string(::getpid()))).string();
}

}  // namespace

TEST_CASE("the space order sorts the bodies by cell (z, y, x) of the largest diameter, then by id", "[order]") {
  const Pour p;
  const std::vector<std::uint32_t> order = spatial_order(p.specs, p.lib);
  REQUIRE(is_order_of(order, p.specs.size()));
  CHECK(order != identity_order(p.specs.size()));
  Vec3 low = p.specs[0].position;
  for (const BodySpec& s : p.specs) low = low.cwiseMin(s.position);
  for (std::size_t k = 1; k < order.size(); ++k) {
    const auto a = cell_of(p.specs[order[k - 1]].position, low, 0.012);  // m, the large spheres' diameter
    const auto b = cell_of(p.specs[order[k]].position, low, 0.012);
    INFO("place " << k);
    CHECK((a < b || (a == b && order[k - 1] < order[k])));
  }
  CHECK(spatial_order(p.specs, p.lib) == order);  // no state: the same order each time
}

TEST_CASE("in_order puts specs[order[k]] at k, in place, over cycles of any length and fixed points", "[order]") {
  const std::vector<std::uint32_t> order{3, 1, 0, 5, 2, 4, 6, 9, 7, 8};  // cycles (0 3 5 4 2), (7 9 8); 1, 6 stay
  std::vector<BodySpec> specs;
  for (int k = 0; k < 10; ++k) {
    specs.push_back(body("s", Vec3(k, 0, 0)));
    specs.back().shape = "a shape name past the short-string buffer " + std::to_string(k);  // moved, not copied
  }
  const std::vector<BodySpec> sorted = in_order(specs, order);
  REQUIRE(sorted.size() == order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    CHECK(sorted[k].shape == specs[order[k]].shape);
    CHECK(sorted[k].position.x() == double(order[k]));
  }
}

TEST_CASE("a run in space order holds the input run's bodies under their ids, and resumes in its order", "[order]") {
  Pour p;
  Pour in_input;
  in_input.scene.simulation.body_order = SimulationSettings::BodyOrder::input;
  Simulation space(p.scene, p.lib, p.specs), input(in_input.scene, in_input.lib, in_input.specs);
  REQUIRE(space.bodies.id == spatial_order(p.specs, p.lib));
  REQUIRE(input.bodies.id == identity_order(p.specs.size()));
  run_for(space, 0.3);  // s: fallen, bounced and settling
  run_for(input, 0.3);
  REQUIRE(space.engine().stats().contacts > 10);
  double apart = 0.0, speed = 0.0;  // m and m/s, largest over the bodies
  for (std::size_t b = 0; b < space.bodies.size(); ++b) {
    const std::size_t id = space.bodies.id[b];
    CHECK(space.bodies.mass[b] == input.bodies.mass[id]);
    apart = std::max(apart, (space.bodies.position[b] - input.bodies.position[id]).norm());
    speed = std::max(speed, (space.bodies.velocity[b] - input.bodies.velocity[id]).norm());
  }
  std::printf("space against input order after 0.3 s: %.3g m, %.3g m/s apart\n", apart, speed);
  CHECK(apart < 1e-9 * 0.05);  // m: 1e-9 of the pour's height

  const std::string path = temp_path("polydem_test_order_");
  write_checkpoint(path, space, OutputProgress{});
  const std::vector<std::uint32_t> stored = checkpoint_body_order(path, p.specs.size());
  CHECK(stored == space.bodies.id);
  OutputProgress progress;
  Simulation wrong(in_input.scene, in_input.lib, in_input.specs);  // built in another order: refused
  CHECK_THROWS_WITH(read_checkpoint(path, wrong, progress), Catch::Contains("body order"));
  Simulation resumed(in_input.scene, in_input.lib, in_input.specs, nullptr, stored);
  read_checkpoint(path, resumed, progress);
  space.engine().force_rebuild();  // as the runner does at every checkpoint
  for (int s = 0; s < 500; ++s) space.step(), resumed.step();
  CHECK(state_hash(resumed.bodies) == state_hash(space.bodies));
  std::filesystem::remove(path);
}

TEST_CASE("a checkpoint of the scene's order, or older than orders, resumes in the scene's order", "[order]") {
  Pour p;
  p.scene.simulation.body_order = SimulationSettings::BodyOrder::input;
  Simulation sim(p.scene, p.lib, p.specs);
  for (int s = 0; s < 100; ++s) sim.step();
  const std::string path = temp_path("polydem_test_order_input_");
  write_checkpoint(path, sim, OutputProgress{});
  CHECK(checkpoint_body_order(path, p.specs.size()) == identity_order(p.specs.size()));
  std::ifstream in(path, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::ofstream(path, std::ios::binary) << as_format05(bytes);
  CHECK(checkpoint_body_order(path, p.specs.size()) == identity_order(p.specs.size()));
  std::filesystem::remove(path);
}
