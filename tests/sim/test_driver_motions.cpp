// Driver motions and laws not covered elsewhere: walls and outer cylinders at constant
// velocity (the struck sphere leaves at (1 + en) v), start and stop times, servos on a ball and
// on an STL mesh (the pressed sphere's overlaps are F / kn), and config_driver differing from
// config (each overlap follows its own kn).
#include <catch2/catch.hpp>

#include <fstream>

#include "../unique_temp_dir.hpp"
#include "sim_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

constexpr double kRadius = 0.005, kKn = 1e5, kEn = 0.5;  // m, N/m, -

// A free sphere at rest at the origin (no gravity) struck by `driver` moving at 0.5 m/s along
// +x; returned once the contact has ended.
std::unique_ptr<Simulation> strike(DriverSettings driver) {
  Scene scene = base_scene(law(kKn, kEn), false);
  driver.motion.velocity = Vec3(0.5, 0, 0);
  scene.drivers.push_back(driver);
  auto sim = std::make_unique<Simulation>(scene, library({sphere_shape(kRadius)}),
                                          std::vector{body("sphere", Vec3::Zero())});
  REQUIRE(run_through_impact(*sim, 200000));
  return sim;
}

}  // namespace

TEST_CASE("a wall at constant velocity strikes a resting sphere: it leaves at (1 + en) v", "[driver][motion]") {
  DriverSettings wall;
  wall.name = "pusher";
  wall.kind = WallSettings{Vec3(-0.01, 0, 0), Vec3::UnitX()};
  const auto sim = strike(wall);
  CHECK(sim->bodies.velocity[0].x() == Approx((1 + kEn) * 0.5).epsilon(1e-3));
  CHECK(sim->drivers[0].point.x() == Approx(-0.01 + 0.5 * sim->time()).epsilon(1e-12));
  CHECK(sim->drivers[0].point.y() == 0.0);
}

TEST_CASE("an outer cylinder at constant velocity strikes a resting sphere: it leaves at (1 + en) v",
          "[driver][motion][cylinder]") {
  DriverSettings post;
  post.name = "post";
  CylinderSettings c;
  c.center = Vec3(-0.02, 0, 0);
  c.axis = Vec3::UnitZ();
  c.radius = 0.01;
  c.inside = false;
  post.kind = c;
  const auto sim = strike(post);
  CHECK(sim->bodies.velocity[0].x() == Approx((1 + kEn) * 0.5).epsilon(1e-3));
  CHECK(sim->drivers.center(0).x() == Approx(-0.02 + 0.5 * sim->time()).epsilon(1e-12));
}

TEST_CASE("motion start and stop: a wall moves only between them", "[driver][motion]") {
  Scene scene = base_scene(law(kKn, kEn), false);
  DriverSettings wall;
  wall.name = "lift";
  wall.kind = WallSettings{Vec3(0, 0, -0.1), Vec3::UnitZ()};
  wall.motion.velocity = Vec3(0, 0, 0.2);  // m/s
  wall.motion.start = 0.01;                // s
  wall.motion.stop = 0.03;                 // s
  scene.drivers.push_back(wall);
  Simulation sim(scene, library({sphere_shape(kRadius)}), {body("sphere", Vec3::Zero())});
  const double tolerance = 0.2 * sim.dt() * 1.0001;  // m, one step of motion: start and stop fall within a step
  run_for(sim, 0.009);
  CHECK(sim.drivers[0].point.z() == -0.1);
  run_for(sim, 0.011);  // t = 0.02 s, within a step: about 10 ms of motion
  CHECK(std::abs(sim.drivers[0].point.z() - (-0.1 + 0.2 * (sim.time() - 0.01))) <= tolerance);
  run_for(sim, 0.03);  // t = 0.05 s: stopped at 0.03 s
  const double stopped = sim.drivers[0].point.z();
  CHECK(std::abs(stopped - (-0.1 + 0.2 * 0.02)) <= tolerance);
  run_for(sim, 0.01);
  CHECK(sim.drivers[0].point.z() == stopped);
  CHECK(sim.drivers[0].velocity.norm() == 0.0);
}

namespace {

// A sphere on the floor (no gravity) pressed from above by `press`, a servo of force F along -z.
// At rest both overlaps are F / kn of config_driver: the sphere's centre is r - F / kn.
void check_servo_presses(DriverSettings press, double kn_driver) {
  const double force = 2.0;  // N
  Scene scene = base_scene(law(kKn, kEn), true);
  scene.forces.contact.config_driver.kn = kn_driver;
  press.motion.force = force;
  press.motion.direction = -Vec3::UnitZ();
  scene.drivers.push_back(press);
  Simulation sim(scene, library({sphere_shape(kRadius)}), {body("sphere", Vec3(0, 0, kRadius))});
  run_for(sim, 0.1);
  const double overlap = force / kn_driver;  // m
  CHECK(kRadius - sim.bodies.position[0].z() == Approx(overlap).epsilon(1e-4));
  CHECK(sim.drivers[1].force.z() == Approx(force).epsilon(1e-4));   // the sphere pushes the servo up
  CHECK(-sim.drivers[0].force.z() == Approx(force).epsilon(1e-4));  // and the floor down
  CHECK(sim.drivers[1].velocity.norm() < 1e-6);                     // m/s, at rest
}

}  // namespace

TEST_CASE("a ball servo presses a sphere on the floor with its force", "[driver][servo][ball]") {
  DriverSettings ball;
  ball.name = "press";
  BallSettings b;
  b.radius = 0.02;
  b.center = Vec3(0, 0, 2 * kRadius + 0.02);  // touching the sphere
  ball.kind = b;
  check_servo_presses(ball, 4 * kKn);
}

TEST_CASE("an STL mesh servo presses a sphere on the floor with its force", "[driver][servo][stl]") {
  const UniqueTempDir dir("mesh_servo");
  const std::string file = (dir.path / "plate.stl").string();
  // A 4 cm square plate at z = 0 of its own frame, placed touching the sphere's top.
  std::ofstream(file) << "solid p\n"
                         "facet normal 0 0 -1\nouter loop\nvertex -0.02 -0.02 0\nvertex 0.02 0.02 0\n"
                         "vertex 0.02 -0.02 0\nendloop\nendfacet\n"
                         "facet normal 0 0 -1\nouter loop\nvertex -0.02 -0.02 0\nvertex -0.02 0.02 0\n"
                         "vertex 0.02 0.02 0\nendloop\nendfacet\nendsolid p\n";
  DriverSettings plate;
  plate.name = "press";
  MeshSettings m;
  m.file = file;
  m.translation = Vec3(0, 0, 2 * kRadius);
  plate.kind = m;
  check_servo_presses(plate, 4 * kKn);
}

TEST_CASE("config_driver differing from config: the floor overlap follows its kn, the pair's follows config's",
          "[driver][law]") {
  const double g = 9.807, kn_driver = 4 * kKn;  // m/s^2, N/m
  Scene scene = base_scene(law(kKn, kEn), true, Vec3(0, 0, -g));
  scene.forces.contact.config_driver.kn = kn_driver;
  Simulation sim(scene, library({sphere_shape(kRadius)}),
                 {body("sphere", Vec3(0, 0, kRadius)), body("sphere", Vec3(0, 0, 3 * kRadius))});
  run_for(sim, 0.3);
  const double weight = sim.bodies.mass[0] * g;  // N, each sphere
  const double floor_overlap = kRadius - sim.bodies.position[0].z();
  const double pair_overlap = 2 * kRadius - (sim.bodies.position[1].z() - sim.bodies.position[0].z());
  CHECK(floor_overlap == Approx(2 * weight / kn_driver).epsilon(1e-4));
  CHECK(pair_overlap == Approx(weight / kKn).epsilon(1e-4));
}
