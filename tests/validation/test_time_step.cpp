// The critical step (src/sim/time_step.cpp) against the measured stability limit of a stack of
// two spheres in sticking contact (tools/stress: 8 spheres in a box gained energy at 0.9 x
// the step printed before the tangential mode was counted).
// Tangential mode of a sphere: a force t at the contact point, R from the centre, meets
// 1/m_t = 1/m + R^2/I = 1/m + 1/(0.4 m) = 3.5/m; a pair (m/7) with the undamped spring kt is
// velocity Verlet stable below 2 sqrt(m/(7 kt)). Normal mode: the pair m/2 with the dashpot,
// 2 sqrt(m/(2 kn)) (sqrt(1 + a^2) - a) (law.hpp). With kt = kn and en = 0.5 (a = 0.245):
// 0.756 vs 1.10 sqrt(m/kn): the tangential spring sets the step, 0.69 x the normal one.
#include <catch2/catch.hpp>

#include "validation.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

constexpr double kRadius = 0.005, kKn = 1e5;  // m, N/m

Scene stack_scene(double kt) {
  return base_scene(law(kKn, 0.5, kt > 0 ? 1.0 : 0.0, kt), true, Vec3(0, 0, -9.807));  // mu 1: sticks
}

std::vector<BodySpec> stack_bodies() {
  BodySpec top = body("sphere", {0, 0, 3 * kRadius});
  top.angular_velocity = {0, 1e-3, 0};  // rad/s: a tiny tangential disturbance of the stack
  return {body("sphere", {0, 0, kRadius}), top};
}

TimeStepEstimate estimate(double kt) {
  return Simulation(stack_scene(kt), library({sphere_shape(kRadius)}), stack_bodies()).time_step();
}

// J, largest mechanical energy above the work of gravity for the stack on the floor over
// 20000 steps (~100 tangential periods) at the step dt.
double energy_created(double kt, double dt) {
  Scene scene = stack_scene(kt);
  scene.simulation.dt = dt;
  Simulation sim(scene, library({sphere_shape(kRadius)}), stack_bodies());
  double worst = 0.0;
  for (int s = 0; s < 20000; ++s) {
    sim.step();
    const EnergyRow e = sim.energy();
    worst = std::max(worst, e.kinetic + e.rotational + e.elastic - e.gravity_work);
  }
  return worst;
}

}  // namespace

TEST_CASE("critical step of spheres: the tangential mode 2 sqrt(m/(7 kt)) sets it when kt = kn", "[time_step]") {
  const double m = 2700.0 * 4.0 / 3.0 * kPi * kRadius * kRadius * kRadius;  // kg
  const LawParams p = prepare_law(law(kKn, 0.5, 1.0, kKn));
  const TimeStepEstimate with_kt = estimate(kKn), without_kt = estimate(0.0);
  CHECK(with_kt.mode == StepMode::kTangential);
  CHECK(with_kt.m_tangential == Approx(m / 3.5).epsilon(1e-6));
  CHECK(with_kt.critical == Approx(2.0 * std::sqrt(m / (7.0 * kKn))).epsilon(1e-6));
  // kt = 0 (no friction): the normal damped limit on m/2, the estimate before the tangential mode.
  CHECK(without_kt.mode == StepMode::kNormal);
  CHECK(without_kt.critical == Approx(critical_time_step(kKn, 0.5 * m, p.alpha_n)).epsilon(1e-6));
  CHECK(with_kt.critical < 0.7 * without_kt.critical);  // 0.69 with the exact damping ratio of en = 0.5
}

TEST_CASE("critical step of spheres: a sticking stack is stable at 0.95 x it and gains energy at the old estimate", "[time_step]") {
  const double m = 2700.0 * 4.0 / 3.0 * kPi * kRadius * kRadius * kRadius;  // kg
  const double mgr = m * 9.807 * kRadius;                                    // J
  const double critical = estimate(kKn).critical, normal_only = estimate(0.0).critical;
  const double stable = energy_created(kKn, 0.95 * critical);
  const double old_estimate = energy_created(kKn, 0.9 * normal_only);  // 1.36 x the new critical step
  const double no_kt = energy_created(0.0, 0.9 * normal_only);
  std::printf("sphere stack, energy created / m g R: kt = kn at 0.95 x critical %.2e, at 0.9 x the normal-mode step "
              "%.2e; kt = 0 at 0.9 x it %.2e\n", stable / mgr, old_estimate / mgr, no_kt / mgr);
  CHECK(stable < 1e-3 * mgr);
  CHECK(no_kt < 1e-3 * mgr);       // the normal mode alone is stable at 0.9 x its own limit
  // The tangential mode is real: it gains energy beyond its limit (3.0e-3 m g R with the exact
  // normal step the spheres take by default, contact/law/exact_linear.hpp; stable: 0).
  CHECK(old_estimate > 1e-3 * mgr);
}

TEST_CASE("critical step: a stiff rolling spring sets it at 2 sqrt(I/(2 kr)) for a sphere pair", "[time_step]") {
  const double m = 2700.0 * 4.0 / 3.0 * kPi * kRadius * kRadius * kRadius, inertia = 0.4 * m * kRadius * kRadius;
  ContactParams c = law(kKn, 0.5, 0.5, kKn);
  c.kr = 1e3 * kKn * kRadius * kRadius;  // N m/rad, far stiffer than the contact's kn R^2
  c.mur = 0.1;
  Scene scene = base_scene(c, false);
  const TimeStepEstimate e = Simulation(scene, library({sphere_shape(kRadius)}), stack_bodies()).time_step();
  CHECK(e.mode == StepMode::kRolling);
  CHECK(e.critical == Approx(2.0 * std::sqrt(0.5 * inertia / c.kr)).epsilon(1e-6));
}
