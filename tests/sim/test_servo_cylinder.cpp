// Servo drivers (a wall holding a force or a pressure, across a checkpoint) and the outer
// surface of a cylinder (infinite, and a finite one with rounded ends).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "sim/checkpoint.hpp"
#include "sim_fixtures.hpp"
#include "../unique_temp_dir.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

constexpr double kG = 9.807, kRadius = 0.005, kKn = 1e5;

// A sphere on the floor under a servo lid (normal -z) that starts 1 mm above it.
Scene lid_scene(std::optional<double> force, std::optional<double> pressure) {
  Scene scene = base_scene(law(kKn, 0.3, 0.5, kKn), true, Vec3(0, 0, -kG));
  DriverSettings lid;
  lid.name = "lid";
  lid.kind = WallSettings{{0, 0, 2 * kRadius + 0.001}, -Vec3::UnitZ(), std::nullopt};
  lid.motion.force = force;
  lid.motion.pressure = pressure;
  if (pressure) lid.motion.area = 0.01;
  scene.drivers.push_back(lid);
  return scene;
}

DriverSettings outer_cylinder(const Vec3& axis, double radius, std::optional<double> length) {
  DriverSettings d;
  d.name = "post";
  d.kind = CylinderSettings{Vec3::Zero(), axis, radius, length, false};
  return d;
}

}  // namespace

TEST_CASE("a servo wall settles at the requested force", "[driver][servo]") {
  const double target = 0.5;  // N, 36 x the sphere's weight
  for (bool by_pressure : {false, true}) {
    Simulation sim(lid_scene(by_pressure ? std::nullopt : std::optional(target),
                             by_pressure ? std::optional(target / 0.01) : std::nullopt),
                   library({sphere_shape(kRadius)}), {body("sphere", {0, 0, kRadius})});
    CHECK(sim.drivers.servo_target(1) == Approx(target));
    // The servo closes and settles in a number of steps (its gain is 0.1 / (kn dt)): 0.1 s at
    // dt: auto (0.181 x critical for a sphere) is 1.1 x the steps of 0.05 s at 0.1 x (before).
    run_for(sim, 0.1);
    const double push = -sim.drivers[1].force.dot(sim.drivers.servo_direction(1));  // N, lid on the sphere
    const double weight = sim.bodies.mass[0] * kG;
    CHECK(push == Approx(target).epsilon(1e-4));
    CHECK(-sim.drivers[0].force.z() == Approx(target + weight).epsilon(1e-4));  // the floor carries both
    CHECK(std::abs(sim.drivers[1].velocity.z()) < 1e-6);                        // at rest
    const double squeeze = 2 * kRadius - (sim.drivers[1].point.z() - sim.drivers[0].point.z());  // m, both overlaps
    CHECK(squeeze == Approx((2 * target + weight) / kKn).epsilon(1e-3));        // kn x1 = F, kn x2 = F + m g
  }
}

TEST_CASE("a servo with neither a contact law nor a gain stops with a clear error", "[driver][servo][errors]") {
  Scene scene = lid_scene(1.0, std::nullopt);
  scene.forces.contact.present = false;  // no kn to choose the default gain from
  scene.simulation.dt = 1e-5;
  scene.drivers[1].loc = {"scene.yaml", 9};
  Simulation sim(scene, library({sphere_shape(kRadius)}), {body("sphere", {0, 0, kRadius})});
  CHECK_THROWS_WITH(sim.step(), Catch::StartsWith("scene.yaml:9: key 'gain': driver 'lid'"));
}

TEST_CASE("a servo wall resumed from a checkpoint continues bit for bit", "[driver][servo][checkpoint]") {
  const UniqueTempDir dir("servo_checkpoint");
  const std::string path = (dir.path / "state.bin").string();
  const Scene scene = lid_scene(0.5, std::nullopt);
  const ShapeLibrary lib = library({sphere_shape(kRadius)});
  Simulation first(scene, lib, {body("sphere", {0, 0, kRadius})});
  for (int s = 0; s < 3000; ++s) first.step();  // the lid is moving and pressing
  write_checkpoint(path, first, OutputProgress{});
  first.engine().force_rebuild();  // as the runner does at every checkpoint
  for (int s = 0; s < 3000; ++s) first.step();
  Simulation resumed(scene, lib, {body("sphere", {0, 0, kRadius})});
  OutputProgress progress;
  read_checkpoint(path, resumed, progress);
  for (int s = 0; s < 3000; ++s) resumed.step();
  CHECK(std::memcmp(first.bodies.position[0].data(), resumed.bodies.position[0].data(), sizeof(Vec3)) == 0);
  CHECK(std::memcmp(first.drivers[1].point.data(), resumed.drivers[1].point.data(), sizeof(Vec3)) == 0);
  CHECK(std::memcmp(first.drivers[1].velocity.data(), resumed.drivers[1].velocity.data(), sizeof(Vec3)) == 0);
}

TEST_CASE("a sphere rests on the outside of a cylinder with overlap m g / kn", "[driver][cylinder]") {
  const double radius = 0.02;  // m
  struct Case { const char* what; DriverSettings post; Vec3 start; };
  const Case cases[] = {
      {"horizontal, infinite", outer_cylinder(Vec3::UnitX(), radius, std::nullopt), {0.3, 0, radius + kRadius}},
      {"vertical, on its rounded end", outer_cylinder(Vec3::UnitZ(), radius, 0.04), {0, 0, 0.02 + radius + kRadius}},
      {"tilted, finite", outer_cylinder(Vec3(1, 0.3, 0), radius, 0.1), {0, 0, radius + kRadius}}};
  for (const Case& c : cases) {
    Scene scene = base_scene(law(kKn, 0.3, 0.5, kKn), false, Vec3(0, 0, -kG));
    scene.drivers.push_back(c.post);
    Simulation sim(scene, library({sphere_shape(kRadius)}), {body("sphere", c.start)});
    run_for(sim, 0.1);
    const double weight = sim.bodies.mass[0] * kG;
    INFO(c.what << ": at " << sim.bodies.position[0].transpose());
    CHECK(c.start.z() - sim.bodies.position[0].z() == Approx(weight / kKn).epsilon(1e-3));  // on top: kn x = m g
    CHECK((sim.bodies.position[0] - (c.start - Vec3(0, 0, c.start.z() - sim.bodies.position[0].z()))).norm() < 1e-9);
    CHECK(sim.drivers[0].force.z() == Approx(-weight).epsilon(1e-3));
  }
}
