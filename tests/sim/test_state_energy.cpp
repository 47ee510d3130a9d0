// A CSV row's body energies summed on a team (StateEnergy::add_bodies, issue 19): each thread
// sums its share of the bodies apart and the shares join, so the words (exact sums) must be the
// serial loop's at any team size, every body counted once.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <omp.h>

#include "sim/state_energy.hpp"

using namespace polydem;

namespace {

// n bodies with values of mixed magnitudes (their double sums' bits depend on the order).
Bodies random_bodies(std::size_t n) {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-12, 12);
  auto value = [&] { return std::ldexp(unit(rng), exponent(rng)); };
  auto vec = [&] { return Vec3(value(), value(), value()); };
  Bodies b;
  b.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    b.position[k] = vec();
    b.velocity[k] = vec();
    b.angular_momentum[k] = vec();
    b.mass[k] = std::abs(value()) + 1e-3;
    b.inertia[k] = vec().cwiseAbs() + Vec3::Constant(1e-3);
  }
  return b;
}

}  // namespace

TEST_CASE("the bodies' energies summed on a team are the serial sums at any team size", "[state_energy]") {
  const std::size_t n = 3 * kParallelMinItems + 7;  // a team's loop, shares of unequal size
  const Bodies bodies = random_bodies(n);
  StateEnergy serial;
  for (std::size_t b = 0; b < n; ++b) serial.add_body(bodies, b);
  const int team_size = omp_get_max_threads();  // restored after: the next tests' teams
  for (int threads : {1, 2, 3, 4}) {
    CAPTURE(threads);
    omp_set_num_threads(threads);
    StateEnergy team;
    team.add_bodies(bodies, n);
    CHECK(team.words() == serial.words());
    StateEnergy twice = serial;  // a body counted twice (or a share dropped) changes the words
    twice.add_body(bodies, n - 1);
    CHECK(team.words() != twice.words());
  }
  omp_set_num_threads(team_size);
  StateEnergy few;  // below a team's size: this thread alone
  few.add_bodies(bodies, 3);
  StateEnergy three;
  for (std::size_t b = 0; b < 3; ++b) three.add_body(bodies, b);
  CHECK(few.words() == three.words());
}
