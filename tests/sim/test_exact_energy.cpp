// The energy ledger's exact sums (contact/exact_sum.hpp) under threads: 800 spheres on and
// above a floor, so both the body pairs and the floor's 400 pairs span several blocks of the
// pair loop, give the same ledger bits for 1 and 2 threads and run to run (each thread's sum
// is merged before the sums are read).
#include <catch2/catch.hpp>

#include <omp.h>

#include <bit>
#include <random>

#include "sim_fixtures.hpp"
#include "state_hash.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

struct Ledger {
  std::uint64_t dissipated, sliding, patch, state;
  bool operator==(const Ledger&) const = default;
};

Ledger run_floor_bed(int threads) {
  omp_set_num_threads(threads);
  Scene scene = base_scene(law(1e5, 0.5, 0.4, 0.8e5), true, Vec3(0, 0, -9.807));
  ShapeLibrary lib = library({sphere_shape(0.005)});
  std::vector<BodySpec> specs;
  std::mt19937_64 rng(5);
  auto u = [&] { return double(rng() >> 11) * 0x1.0p-53 - 0.5; };
  for (int k = 0; k < 800; ++k) {  // 20 x 20, two layers; the lower one 0.1 mm into the floor, sliding
    const Vec3 x(0.0105 * (k % 20), 0.0105 * ((k / 20) % 20), 0.0049 + 0.0105 * (k / 400));
    specs.push_back(body("sphere", x, Vec3(0.3 * u(), 0.3 * u(), -0.2)));
  }
  Simulation sim(scene, lib, specs);
  for (int s = 0; s < 300; ++s) sim.step();
  omp_set_num_threads(2);
  return {std::bit_cast<std::uint64_t>(sim.ledger.dissipated), std::bit_cast<std::uint64_t>(sim.ledger.sliding),
          std::bit_cast<std::uint64_t>(sim.ledger.patch_work), state_hash(sim.bodies)};
}

}  // namespace

TEST_CASE("energy ledger: the same bits for 1 and 2 threads with several blocks of body and floor pairs",
          "[determinism][energy]") {
  const Ledger one = run_floor_bed(1), two = run_floor_bed(2);
  CHECK(one == two);
  CHECK(two == run_floor_bed(2));
  CHECK(std::bit_cast<double>(one.dissipated) > 0.0);  // the contacts dissipate
  CHECK(std::bit_cast<double>(one.sliding) > 0.0);     // and slide
}
