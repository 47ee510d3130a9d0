// REPRODUCER, hidden from the suite (tag [.]): run with tests_validation "[.reproducer]".
// The critical step (src/sim/time_step.cpp) takes the lightest contact-point mass along the
// normal, 1/m + (v x n)^T I^-1 (v x n) at each vertex v; it leaves out the tangential spring
// acting on the rotation through the lever to the contact point (the rounding radius), where a
// sphere offers 1/m_t = 1/m + R^2/I = 3.5/m per body (m/7 for a pair): the tangential mode of a
// sphere pair is unstable above 2 sqrt(m/(7 kt)), 0.66 x the printed step when kt = kn.
// Expected once fixed: this passes at any dt below the printed critical step.
// tools/stress measured: 8 spheres in a box gain energy at 0.9 x the printed step.
#include <catch2/catch.hpp>

#include "validation.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

// J, largest mechanical energy above the work of gravity for a stack of two spheres on the
// floor, the top one given a tiny spin, at dt = fraction x the printed critical step.
double energy_created(double kt, double fraction) {
  const double radius = 0.005;
  Scene scene = base_scene(law(1e5, 0.5, kt > 0 ? 1.0 : 0.0, kt), true, Vec3(0, 0, -9.807));  // mu 1: sticks
  const ShapeLibrary lib = library({sphere_shape(radius)});
  BodySpec top = body("sphere", {0, 0, 3 * radius});
  top.angular_velocity = {0, 1e-3, 0};  // rad/s: a tiny tangential disturbance of the stack
  const std::vector<BodySpec> specs = {body("sphere", {0, 0, radius}), top};
  scene.simulation.dt = fraction * Simulation(scene, lib, specs).time_step().critical;
  Simulation sim(scene, lib, specs);
  double worst = 0.0;
  for (int s = 0; s < 20000; ++s) {
    sim.step();
    const EnergyRow e = sim.energy();
    worst = std::max(worst, e.kinetic + e.rotational + e.elastic - e.gravity_work);
  }
  return worst;
}

}  // namespace

TEST_CASE("reproducer: sphere stack in sticking contact gains energy below the printed critical step", "[.reproducer]") {
  const double scale = 2700.0 * 4.0 / 3.0 * kPi * 0.005 * 0.005 * 0.005 * 9.807 * 0.005;  // J, m g R
  const double without_kt = energy_created(0.0, 0.9), with_kt = energy_created(1e5, 0.9);
  // Measured: 1.3e-9 J without the tangential spring, 2.5e-6 J (3.6% of m g R) with kt = kn.
  INFO("energy created at 0.9 x critical: kt = 0: " << without_kt << " J, kt = kn: " << with_kt << " J; m g R = " << scale);
  CHECK(without_kt < 1e-3 * scale);  // the normal contact alone is stable there
  CHECK(with_kt < 1e-3 * scale);     // fails today: the tangential mode is left out of the estimate
}
