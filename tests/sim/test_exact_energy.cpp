// The energy ledger (Simulation::close_ledger, contact/exact_sum.hpp) under threads: 800
// spheres on and above a floor, so both the body pairs and the floor's 400 pairs span several
// blocks of the pair loop, give the same ledger bits for 1 and 2 threads and run to run; what
// energy() adds between closes is what a close would add, and reading it changes nothing.
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

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

struct FloorBed {
  Scene scene = base_scene(law(1e5, 0.5, 0.4, 0.8e5), true, Vec3(0, 0, -9.807));
  ShapeLibrary lib = library({sphere_shape(0.005)});
  std::vector<BodySpec> specs;
  FloorBed() {
    std::mt19937_64 rng(5);
    auto u = [&] { return double(rng() >> 11) * 0x1.0p-53 - 0.5; };
    for (int k = 0; k < 800; ++k) {  // 20 x 20, two layers; the lower one 0.1 mm into the floor, sliding
      const Vec3 x(0.0105 * (k % 20), 0.0105 * ((k / 20) % 20), 0.0049 + 0.0105 * (k / 400));
      specs.push_back(body("sphere", x, Vec3(0.3 * u(), 0.3 * u(), -0.2)));
    }
  }
};

Ledger run_floor_bed(int threads) {
  omp_set_num_threads(threads);
  const FloorBed bed;
  Simulation sim(bed.scene, bed.lib, bed.specs);
  for (int s = 0; s < 3 * int(Simulation::kLedgerSteps); ++s) sim.step();  // ends on a close
  omp_set_num_threads(2);
  return {bits(sim.ledger.dissipated), bits(sim.ledger.sliding), bits(sim.ledger.patch_work), state_hash(sim.bodies)};
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

TEST_CASE("energy ledger: energy() between closes adds what a close would, and reading it changes nothing",
          "[energy]") {
  const FloorBed bed;
  Simulation read(bed.scene, bed.lib, bed.specs), left(bed.scene, bed.lib, bed.specs);
  const int steps = int(Simulation::kLedgerSteps) + 50;  // one close, then 50 steps open
  for (int s = 0; s < steps; ++s) {
    read.step();
    left.step();
    (void)read.energy();
  }
  CHECK(state_hash(read.bodies) == state_hash(left.bodies));
  CHECK(bits(read.ledger.dissipated) == bits(left.ledger.dissipated));
  const EnergyRow open = left.energy();
  CHECK(bits(read.energy().dissipated) == bits(open.dissipated));
  CHECK(open.dissipated > left.ledger.dissipated);  // 50 steps of sliding and damping not yet closed
  left.close_ledger();
  CHECK(bits(left.ledger.dissipated) == bits(open.dissipated));
  CHECK(bits(left.ledger.sliding) == bits(open.dissipated_sliding));
  CHECK(bits(left.energy().dissipated) == bits(open.dissipated));  // nothing left open
}
