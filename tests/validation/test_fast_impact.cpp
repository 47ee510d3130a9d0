// Impacts too fast for the contact law (src/sim/time_step.cpp): a sphere of radius R = 5 mm
// and mass m hitting a wall at v overlaps at most v sqrt(m/kn) (undamped bound); the start-up
// warning fires above kOverlapFraction R sqrt(kn/m) = 21 m/s for kn = 1e5 N/m, and the
// run-time watch when an active contact is deeper than kOverlapFraction R.
#include <catch2/catch.hpp>

#include "contact/contact_lists.hpp"
#include "validation.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

constexpr double kRadius = 0.005, kKn = 1e5;  // m, N/m

Simulation sphere_on_wall(double speed) {
  return Simulation(base_scene(law(kKn, 0.5), true), library({sphere_shape(kRadius)}),
                    {body("sphere", {0, 0, kRadius + 1e-4}, {0, 0, -speed})});
}

// The watch's first warning over the impact, checked every 10 steps like an output row.
std::string watched(double speed) {
  Simulation sim = sphere_on_wall(speed);
  OverlapWatch watch(sim.bodies, sim.shapes());
  std::string first;
  for (int s = 0; s < 400 && first.empty(); ++s) {
    sim.step();
    if (s % 10 == 0)
      first = watch.check(sim.engine().body_pairs(), sim.engine().driver_pairs(), sim.drivers, kKn, kKn, sim.time());
  }
  return first;
}

}  // namespace

TEST_CASE("inscribed radius: the rounding plus the nearest face plane", "[fast_impact]") {
  CHECK(inscribed_radius(sphere_shape(kRadius), 1.0) == Approx(kRadius));
  CHECK(inscribed_radius(cube_shape(0.01, 0.001), 2.0) == Approx(2.0 * (0.005 + 0.001)));  // half side + r, scaled
}

TEST_CASE("fast impact: the start-up warning fires above 0.5 R sqrt(kn/m), not below", "[fast_impact]") {
  const double m = 2700.0 * 4.0 / 3.0 * kPi * kRadius * kRadius * kRadius;  // kg
  const double limit = kOverlapFraction * kRadius * std::sqrt(kKn / m);    // m/s, 21
  for (double speed : {0.9 * limit, 1.1 * limit}) {
    const Simulation sim = sphere_on_wall(speed);
    const std::string w = fast_impact_warning(sim.bodies, sim.shapes(), sim.drivers, kKn, kKn, sim.dt());
    INFO(speed << " m/s against " << limit << " m/s: '" << w << "'");
    CHECK(w.empty() == (speed < limit));
  }
  // Two spheres approaching each other at 15 m/s each close at 30 m/s > 21 m/s.
  const Simulation pair(base_scene(law(kKn, 0.5), false), library({sphere_shape(kRadius)}),
                        {body("sphere", {0, 0, 0}, {15, 0, 0}), body("sphere", {0.02, 0, 0}, {-15, 0, 0})});
  const std::string w = fast_impact_warning(pair.bodies, pair.shapes(), pair.drivers, kKn, kKn, pair.dt());
  CHECK(w.find("may hit another body at 30 m/s") != std::string::npos);
}

TEST_CASE("fast impact: the run-time watch reports an overlap deeper than half the radius once", "[fast_impact]") {
  const std::string fast = watched(100.0), slow = watched(1.0);  // overlap ~8.5 mm, ~0.09 mm
  INFO("100 m/s: '" << fast << "'");
  CHECK(fast.find("between body 0 and driver 'floor' exceeds 0.5 x the inscribed radius 5 mm") != std::string::npos);
  CHECK(slow.empty());
}
