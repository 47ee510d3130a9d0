// Faces in contact (SPEC): a face landing flat acts as one contact whatever its vertex count,
// so the restitution is the one asked for and the resting overlap is m g / kn.
#include <catch2/catch.hpp>

#include <cmath>

#include "sim_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

constexpr double kG = 9.807;

// Drops a prism flat on the floor at v0 and returns the rebound restitution of its centre.
double flat_restitution(const Shape& prism, double en, double v0) {
  Scene scene = base_scene(law(1e5, en), true);
  scene.simulation.dt = kPi * std::sqrt(2700.0 * prism.volume / 1e5) / 400.0;  // resolve the impact: test the patch, not dt
  const double half_height = prism.vertices[0].z() < 0 ? -prism.vertices[0].z() : prism.vertices[0].z();
  Simulation sim(scene, library({prism}), {body(prism.name.c_str(), {0, 0, half_height + prism.radius + 1e-5}, {0, 0, -v0})});
  if (!run_through_impact(sim, 100000) || sim.engine().stats().contacts) return -1.0;  // never touched, or still touching
  return sim.bodies.velocity[0].z() / v0;
}

// Rests a prism on the floor under gravity and returns its settled overlap.
double resting_overlap(const Shape& prism, double density) {
  Scene scene = base_scene(law(1e5, 0.3), true, Vec3(0, 0, -kG));
  double half_height = 0.0;
  for (const Vec3& v : prism.vertices) half_height = std::max(half_height, -v.z());
  BodySpec b = body(prism.name.c_str(), {0, 0, half_height + prism.radius});
  b.density = density;
  scene.simulation.dt = kPi * std::sqrt(density * prism.volume / 1e5) / 50.0;  // 50 steps per contact time
  Simulation sim(scene, library({prism}), {b});
  for (int s = 0; s < 5000; ++s) sim.step();  // 100 contact times: the resting oscillation has died out
  return half_height + prism.radius - sim.bodies.position[0].z();
}

}  // namespace

TEST_CASE("a cube dropped flat rebounds with the restitution asked for", "[patch]") {
  const Shape cube = cube_shape(0.009, 0.0005);
  for (double en : {0.3, 0.5, 0.8}) {
    const double e = flat_restitution(cube, en, 1.0);
    INFO("en " << en << " measured " << e << " (per-vertex damping would give 0.34 for 0.5)");
    CHECK(e == Approx(en).epsilon(0.01));
  }
}

TEST_CASE("square and octagonal prisms of equal mass land and rest alike", "[patch]") {
  const Shape square = prism_shape(4, 0.006, 0.008, 0.0005, "square");
  const Shape octagon = prism_shape(8, 0.006, 0.008, 0.0005, "octagon");
  const double rho_square = 2700.0, rho_octagon = rho_square * square.volume / octagon.volume;  // equal masses
  const double mass = rho_square * square.volume;
  const double d_square = resting_overlap(square, rho_square), d_octagon = resting_overlap(octagon, rho_octagon);
  INFO("overlaps " << d_square << " " << d_octagon << " expected m g / kn = " << mass * kG / 1e5);
  CHECK(d_square == Approx(mass * kG / 1e5).epsilon(0.01));
  CHECK(d_octagon == Approx(mass * kG / 1e5).epsilon(0.01));
  CHECK(flat_restitution(square, 0.5, 1.0) == Approx(flat_restitution(octagon, 0.5, 1.0)).epsilon(0.01));
}
