// Friction and rolling through the whole engine: a block on an incline (gravity tilted by
// theta on a floor wall), an oblique sphere impact, rolling resistance.
#include <catch2/catch.hpp>

#include <cmath>

#include "sim_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

constexpr double kG = 9.807;        // m/s^2
constexpr double kSide = 0.009;     // m, core side of the test cube
constexpr double kRound = 0.0005;   // m, its rounding radius

Simulation incline(double theta, double mu) {
  const Vec3 g(kG * std::sin(theta), 0.0, -kG * std::cos(theta));  // the floor tilted by theta
  Scene scene = base_scene(law(1e5, 0.5, mu, 1e5), true, g);
  scene.simulation.dt = 2e-5;  // s: w0 dt = 0.12 on the 2.7 g cube, 0.27 with its rotational mass
  return Simulation(scene, library({cube_shape(kSide, kRound)}),
                    {body("cube", {0, 0, 0.5 * kSide + kRound})});
}

}  // namespace

TEST_CASE("a block on an incline stays put below the friction angle", "[friction]") {
  const double mu = 0.5, theta = 20.0 * kPi / 180.0;  // tan(20 deg) = 0.36 < mu
  Simulation sim = incline(theta, mu);
  run_for(sim, 0.2);
  const double x1 = sim.bodies.position[0].x();
  run_for(sim, 0.3);
  const double x2 = sim.bodies.position[0].x();
  // The tangential springs hold m g sin(theta) with a stretch ~ m g sin(theta) / kt ~ 1e-7 m.
  CHECK(std::abs(x1) < 1e-6);
  CHECK(std::abs(x2 - x1) < 1e-9);   // no creep once settled
  CHECK(sim.bodies.velocity[0].norm() < 1e-6);
}

TEST_CASE("a block on an incline slides at g (sin theta - mu cos theta) above it", "[friction]") {
  const double mu = 0.3, theta = 30.0 * kPi / 180.0;  // tan(30 deg) = 0.58 > mu; tips only above 45 deg
  Simulation sim = incline(theta, mu);
  run_for(sim, 0.05);  // settle the normal contact
  const double v1 = sim.bodies.velocity[0].x(), t1 = sim.time(), x1 = sim.bodies.position[0].x();
  const EnergyRow e1 = sim.energy();
  run_for(sim, 0.1);
  const double a = (sim.bodies.velocity[0].x() - v1) / (sim.time() - t1);
  CHECK(a == Approx(kG * (std::sin(theta) - mu * std::cos(theta))).epsilon(0.01));
  // energy.csv's shares: sliding takes mu m g cos(theta) per metre slid, the settled normal
  // contact's dashpot nothing, and there is no rolling law.
  const EnergyRow e2 = sim.energy();
  const double slid = sim.bodies.position[0].x() - x1;  // m
  const double m = sim.bodies.mass[0];
  CHECK(e2.dissipated_sliding - e1.dissipated_sliding == Approx(mu * m * kG * std::cos(theta) * slid).epsilon(0.01));
  CHECK(std::abs(e2.dissipated_dashpot - e1.dissipated_dashpot) < 1e-3 * (e2.dissipated_sliding - e1.dissipated_sliding));
  CHECK(e2.dissipated_rolling == 0.0);
  CHECK(e2.elastic_parts.normal + e2.elastic_parts.tangential == Approx(e2.elastic).epsilon(1e-12));
}

TEST_CASE("rolling resistance stops a rolling sphere, without it the sphere rolls on", "[rolling]") {
  const double radius = 0.005;
  for (double mur : {0.0, 0.05}) {
    ContactParams p = law(1e5, 0.5, 0.5, 1e5);
    p.kr = mur > 0 ? 1e-2 : 0.0;
    p.mur = mur;
    Scene scene = base_scene(p, true, Vec3(0, 0, -kG));
    BodySpec rolling = body("sphere", {0, 0, radius}, {0.2, 0, 0});
    rolling.angular_velocity = {0, 0.2 / radius, 0};  // rad/s: no slip at the floor, v = w x (R z)
    Simulation sim(scene, library({sphere_shape(radius)}), {rolling});
    run_for(sim, 0.05);  // settle on the floor
    const double v_start = sim.bodies.velocity[0].x();
    const EnergyRow start = sim.energy();
    const double e_start = start.kinetic + start.rotational;
    run_for(sim, 0.7);
    const double x_stopped = sim.bodies.position[0].x();
    run_for(sim, 0.3);
    const EnergyRow end = sim.energy();
    const double e_end = end.kinetic + end.rotational;
    const double by_rolling = end.dissipated_rolling - start.dissipated_rolling;  // J
    if (mur == 0.0) {
      CHECK(v_start > 0.19);
      CHECK(e_end == Approx(e_start).epsilon(1e-3));  // rolling without slip dissipates nothing
      CHECK(by_rolling == 0.0);
    } else {
      // energy.csv's shares: the rolling resistance took what the sphere lost, not sliding
      CHECK(by_rolling + end.elastic_parts.rolling - start.elastic_parts.rolling == Approx(e_start - e_end).epsilon(0.01));
      // The rolling moment mur R fn decelerates rolling at 5/7 mur g: stops within v / (5/7 mur g) = 0.57 s.
      // Afterwards it may rock on the rolling spring, but it no longer travels (0.06 m if it rolled on).
      CHECK(std::abs(sim.bodies.position[0].x() - x_stopped) < 3e-4);
    }
  }
}

TEST_CASE("a sphere launched without spin slides at mu g, then rolls at 5/7 of its speed", "[friction]") {
  // The sphere path's tangential spring slides for ~19 ms: a slip-start push taken on every
  // sliding step (the cap at n misread) would cut the friction (a cube block: 16.2 vs 1.61 m/s^2).
  const double radius = 0.005, mu = 0.3, v0 = 0.2;
  Scene scene = base_scene(law(1e5, 0.5, mu, 1e5), true, Vec3(0, 0, -kG));
  Simulation sim(scene, library({sphere_shape(radius)}), {body("sphere", {0, 0, radius}, {v0, 0, 0})});
  run_for(sim, 0.005);  // the normal contact settles (w0 ~ 8e3 rad/s, en 0.5)
  const double v1 = sim.bodies.velocity[0].x(), t1 = sim.time();
  run_for(sim, 0.01);   // still sliding: it rolls from 2 v0/(7 mu g) = 19.4 ms
  const double a = (sim.bodies.velocity[0].x() - v1) / (sim.time() - t1);
  CHECK(a == Approx(-mu * kG).epsilon(0.01));
  run_for(sim, 0.02);
  // Angular momentum about the contact point: m v0 R = m v R + 2/5 m R^2 (v / R), up to the
  // undamped stuck spring's ringing, mu g / w_t ~ 2e-4 m/s (w_t = sqrt(7 kt / 2 m) ~ 1.6e4 rad/s).
  CHECK(sim.bodies.velocity[0].x() == Approx(5.0 / 7.0 * v0).epsilon(3e-3));
}
