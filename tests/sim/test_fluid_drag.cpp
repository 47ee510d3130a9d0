// Drag operators of a whole Simulation against the closed forms of the quadratic laws, and
// the energy they take out (EnergyLedger::external_work).
#include <catch2/catch.hpp>

#include <cmath>
#include <omp.h>

#include "sim_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

const double kR = 0.005;  // m, sphere radius

Scene drag_scene(double dt, std::optional<Vec3> gravity) {
  Scene s = base_scene(law(1.0e4, 0.5), false, gravity);
  s.simulation.dt = dt;
  return s;
}

// A uniform analytic fluid flowing at U on a grid around the origin.
ForceSettings::FluidField uniform_fluid(const Vec3& U) {
  ForceSettings::FluidField f;
  f.grid_min = Vec3(-0.5, -0.5, -0.5);
  f.grid_max = Vec3(2.0, 0.5, 0.5);
  f.cells = Eigen::Vector3i(5, 2, 2);
  f.velocity = U;
  return f;
}

}  // namespace

TEST_CASE("Quadratic drag: free fall reaches sqrt(m g / (mu cx)) along v_t tanh(g t / v_t)", "[sim][fluid]") {
  // m dv/dt = -m g + mu cx v^2 (falling, v > 0 downwards): v(t) = v_t tanh(g t / v_t).
  Scene s = drag_scene(1.0e-4, Vec3(0, 0, -9.807));
  s.forces.quadratic = ForceSettings::Quadratic{0.38, 0.01};
  Simulation sim(s, library({sphere_shape(kR)}), {body("sphere", Vec3::Zero())});
  const double m = sim.bodies.mass[0], g = 9.807, vt = std::sqrt(m * g / (0.01 * 0.38));
  const double tau = vt / g;  // 0.19 s
  while (sim.time() < tau - 1e-9) sim.step();
  // the drag sees the half-step velocity: a lag of dt/2, relative error ~ dt / tau = 5e-4
  CHECK(-sim.bodies.velocity[0].z() == Approx(vt * std::tanh(1.0)).epsilon(1e-3));
  while (sim.time() < 10 * tau) sim.step();
  CHECK(-sim.bodies.velocity[0].z() == Approx(vt).epsilon(1e-6));  // tanh(10) = 1 - 4e-9
  const EnergyRow e = sim.energy();  // gravity work = kinetic energy + the drag's loss
  CHECK(sim.ledger.external_work < 0.0);
  CHECK(std::abs(e.gravity_work + sim.ledger.external_work - e.kinetic) < 1e-3 * e.gravity_work);
}

TEST_CASE("Fluid friction: a body released in a uniform flow relaxes as U / (1 + k U t)", "[sim][fluid]") {
  // m dv/dt = cx pi r^2 (U - v)^2: w = U - v obeys dw/dt = -k w^2, k = cx pi r^2 / m, so
  // w(t) = U / (1 + k U t) and x(t) = U t - ln(1 + k U t) / k.
  for (bool trilinear : {false, true}) {
    Scene s = drag_scene(1.0e-4, std::nullopt);
    s.forces.fluid = uniform_fluid(Vec3(0.5, 0, 0));
    s.forces.fluid->trilinear = trilinear;
    s.forces.fluid_friction = ForceSettings::FluidFriction{"", 100.0};
    Simulation sim(s, library({sphere_shape(kR)}), {body("sphere", Vec3::Zero())});
    const double k = 100.0 * kPi * kR * kR / sim.bodies.mass[0], U = 0.5;  // 1 / (k U) = 0.36 s
    for (double t_check : {0.1, 0.4, 1.0}) {
      while (sim.time() < t_check - 1e-9) sim.step();
      const double t = sim.time();
      CHECK(U - sim.bodies.velocity[0].x() == Approx(U / (1 + k * U * t)).epsilon(1e-3));
      CHECK(sim.bodies.position[0].x() == Approx(U * t - std::log(1 + k * U * t) / k).epsilon(1e-3));
    }
    CHECK(sim.bodies.velocity[0].tail<2>().norm() == 0.0);
    CHECK(sim.ledger.external_work > 0.0);  // the flow drives the body
  }
}

TEST_CASE("Bodies outside the fluid grid feel no grid force and are counted", "[sim][fluid]") {
  Scene s = drag_scene(1.0e-4, std::nullopt);
  s.forces.fluid = uniform_fluid(Vec3(0.5, 0, 0));
  s.forces.fluid_friction = ForceSettings::FluidFriction{"", 100.0};
  Simulation sim(s, library({sphere_shape(kR)}), {body("sphere", Vec3(-1, 0, 0)), body("sphere", Vec3::Zero())});
  for (int k = 0; k < 10; ++k) sim.step();
  REQUIRE(sim.external());
  CHECK(sim.external()->outside() == 1);
  CHECK(sim.bodies.velocity[0].norm() == 0.0);
  CHECK(sim.bodies.velocity[1].x() > 0.0);
}

TEST_CASE("A scene without drag or fluid operators builds no external forces", "[sim][fluid]") {
  Simulation sim(drag_scene(1.0e-4, Vec3(0, 0, -9.807)), library({sphere_shape(kR)}), {body("sphere", Vec3::Zero())});
  CHECK(sim.external() == nullptr);
}

TEST_CASE("Fluid forces give the same bits for 1 and 2 threads", "[sim][fluid]") {
  // 400 spheres (above the parallel threshold) half in, half out of a vortex, with friction,
  // buoyancy and the void fraction: per-body forces, the work summed in body order.
  auto run = [](int threads) {
    omp_set_num_threads(threads);
    Scene s = drag_scene(1.0e-4, Vec3(0, 0, -9.807));
    ForceSettings::FluidField f = uniform_fluid(Vec3::Zero());
    f.grid_min = Vec3(-0.1, -0.1, -0.1);
    f.grid_max = Vec3(0.1, 0.1, 0.1);
    f.cells = Eigen::Vector3i(7, 7, 7);
    f.velocity_gradient << 0, -3, 0, 3, 0, 0, 0, 0, 0;  // solid-body rotation at 3 rad/s about z
    f.trilinear = true;
    f.rho = 1000.0;
    s.forces.fluid = f;
    s.forces.fluid_friction = ForceSettings::FluidFriction{"", 50.0};
    s.forces.archimedes = true;
    s.forces.void_fraction = ForceSettings::VoidFraction{0.2, 4};
    std::vector<BodySpec> bodies;
    for (int k = 0; k < 400; ++k)
      bodies.push_back(body("sphere", Vec3(-0.19 + 0.019 * (k % 20), -0.095 + 0.01 * (k / 20), 0.003 * (k % 7))));
    Simulation sim(s, library({sphere_shape(0.002)}), bodies);
    for (int k = 0; k < 10; ++k) sim.step();
    omp_set_num_threads(2);
    return std::pair{sim.bodies.position, sim.ledger.external_work};
  };
  const auto one = run(1), two = run(2);
  CHECK(one.first == two.first);
  CHECK(one.second == two.second);
  CHECK(one.second != 0.0);
}
