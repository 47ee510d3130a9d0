// Drivers beyond the fixed wall: the inside of a cylinder, a rotating drum, a ball, a gate
// removed at a given time, and a clear error for what the engine does not simulate yet.
#include <catch2/catch.hpp>

#include <cmath>

#include "polydem/error.hpp"
#include "sim_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

constexpr double kG = 9.807, kRadius = 0.005, kKn = 1e5;

DriverSettings drum(double radius, double omega) {
  DriverSettings d;
  d.name = "drum";
  CylinderSettings c;
  c.axis = Vec3::UnitX();
  c.radius = radius;
  d.kind = c;
  if (omega != 0.0) {
    d.motion.rotates = true;
    d.motion.rotation_axis = Vec3::UnitX();
    d.motion.omega = omega;
  }
  return d;
}

}  // namespace

TEST_CASE("a sphere rests inside a cylinder with the overlap it has on a plane", "[driver]") {
  Scene scene = base_scene(law(kKn, 0.3, 0.5, kKn), false, Vec3(0, 0, -kG));
  scene.drivers.push_back(drum(0.05, 0.0));
  const ShapeLibrary lib = library({sphere_shape(kRadius)});
  Simulation sim(scene, lib, {body("sphere", {0, 0, -0.05 + kRadius})});
  run_for(sim, 0.1);
  const double mass = sim.bodies.mass[0];
  const double overlap = sim.bodies.position[0].norm() + kRadius - 0.05;  // m, beyond the cylinder surface
  CHECK(overlap == Approx(mass * kG / kKn).epsilon(1e-3));                 // kn overlap = m g, as on a wall
  CHECK(std::abs(sim.bodies.position[0].y()) < 1e-9);                    // at the bottom
  CHECK(sim.drivers[0].force.z() == Approx(-mass * kG).epsilon(1e-3));   // the drum carries the weight
}

TEST_CASE("a rotating drum moves the contact at the wall's velocity", "[driver]") {
  const double omega = 1.0, radius = 0.05;  // rad/s, m: the wall moves at 0.05 m/s
  Scene scene = base_scene(law(kKn, 0.3, 0.5, kKn), false, Vec3(0, 0, -kG));
  scene.drivers.push_back(drum(radius, omega));
  Simulation sim(scene, library({sphere_shape(kRadius)}), {body("sphere", {0, 0, -radius + kRadius})});
  run_for(sim, 0.05);
  // Rolling without slip on the drum: the sphere's point at the wall moves with the wall, up
  // to the undamped tangential spring's oscillation (a few % of the wall speed here).
  const Vec3 x = sim.bodies.position[0];
  const Vec3 outward = Vec3(0, x.y(), x.z()).normalized();
  const Vec3 contact = Vec3(x.x(), 0, 0) + radius * outward;
  const Vec3 sphere_point = sim.bodies.velocity[0] + sim.bodies.angular_velocity[0].cross(contact - x);
  const Vec3 wall = Vec3(omega, 0, 0).cross(contact);
  INFO("sphere point " << sphere_point.transpose() << ", wall " << wall.transpose());
  CHECK((sphere_point - wall).norm() < 0.05 * wall.norm());
  CHECK(sim.bodies.velocity[0].y() > 0.0);  // dragged the way the wall moves (+y at the bottom for +x spin)
}

TEST_CASE("a sphere dropped on a ball driver rebounds with en", "[driver][impact]") {
  for (double en : {0.3, 0.7}) {
    Scene scene = base_scene(law(kKn, en), false);
    DriverSettings ball;
    ball.name = "ball";
    ball.kind = BallSettings{Vec3::Zero(), 0.02};
    scene.drivers.push_back(ball);
    const ShapeLibrary lib = library({sphere_shape(kRadius)});
    scene.simulation.dt = kPi * std::sqrt(2700.0 * lib.shapes[0].volume / kKn) / 400.0;
    Simulation sim(scene, lib, {body("sphere", {0, 0, 0.02 + kRadius + 1e-5}, {0, 0, -1.0})});
    bool touched = false;
    for (int s = 0; s < 20000 && !(touched && sim.engine().stats().contacts == 0); ++s) {
      sim.step();
      touched = touched || sim.engine().stats().contacts > 0;
    }
    CHECK(sim.bodies.velocity[0].z() == Approx(en).epsilon(0.005));  // m_eff = m: same law as a wall
  }
}

TEST_CASE("a gate removed at its time lets the body fall", "[driver]") {
  Scene scene = base_scene(law(kKn, 0.3), true, Vec3(0, 0, -kG));
  scene.drivers[0].motion.remove_at = 0.02;
  Simulation sim(scene, library({sphere_shape(kRadius)}), {body("sphere", {0, 0, kRadius})});
  run_for(sim, 0.019);
  CHECK(std::abs(sim.bodies.velocity[0].z()) < 1e-3);  // held up by the gate
  run_for(sim, 0.031);
  CHECK(sim.bodies.velocity[0].z() == Approx(-kG * (sim.time() - 0.02)).epsilon(0.02));  // free fall since 0.02 s
}

TEST_CASE("a moving ball driver finds and strikes a body it started far from", "[driver][impact]") {
  const double en = 0.5, speed = 1.0;  // m/s, the impactor's speed
  Scene scene = base_scene(law(kKn, en), false);
  DriverSettings ball;
  ball.name = "impactor";
  ball.kind = BallSettings{{0, 0, 0.05}, 0.02};  // 25 mm above the sphere's top: far beyond the skin
  ball.motion.velocity = {0, 0, -speed};
  scene.drivers.push_back(ball);
  const ShapeLibrary lib = library({sphere_shape(kRadius)});
  scene.simulation.dt = kPi * std::sqrt(2700.0 * lib.shapes[0].volume / kKn) / 400.0;
  Simulation sim(scene, lib, {body("sphere", {0, 0, 0})});
  run_for(sim, 0.035);  // contact at ~25 ms, over by ~26 ms
  // An infinitely heavy impactor: the body leaves at -(1 + e) times its speed.
  CHECK(sim.bodies.velocity[0].z() == Approx(-(1.0 + en) * speed).epsilon(0.005));
}
