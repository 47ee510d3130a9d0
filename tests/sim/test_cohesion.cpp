// Cohesion through the engine: a sphere stuck to the floor by fc stays while the pull is below
// fc and leaves above it (SPEC: fn = fc/dncut dn - fc in the band, -fc at touching).
#include <catch2/catch.hpp>

#include "sim_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

TEST_CASE("a cohesive contact needs fc to pull apart", "[cohesion]") {
  const double radius = 0.005, fc = 0.05, dncut = 1e-4;
  const Shape sphere = sphere_shape(radius);
  const double mass = 2700.0 * sphere.volume;
  for (double pull : {0.8 * fc, 1.2 * fc}) {
    ContactParams p = law(1e5, 0.3);
    p.fc = fc;
    p.dncut = dncut;
    Scene scene = base_scene(p, true, Vec3(0, 0, pull / mass));  // "gravity" pulling the sphere off the floor
    scene.forces.contact.cohesion = true;
    Simulation sim(scene, library({sphere}), {body("sphere", {0, 0, radius})});
    for (int s = 0; s < 20000; ++s) sim.step();
    const double gap = sim.bodies.position[0].z() - radius;
    INFO("pull " << pull << " N, gap " << gap << " m");
    if (pull < fc) {
      CHECK(gap == Approx(-(fc - pull) / 1e5).margin(1e-9));  // equilibrium: kn (-dn) = fc - pull
    } else {
      CHECK(gap > dncut);  // torn off and gone
    }
  }
}
