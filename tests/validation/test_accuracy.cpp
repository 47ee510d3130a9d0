// The accuracy slice of the work-precision sweep (accuracy_cases.hpp, tools/bench/accuracy) in
// CI: each contact case at dt = 0.1 and 0.3 x the critical step `polydem check` prints (0.1 is
// `dt: auto`), and the observed order of the impacts between 0.1 and 0.05, against bounds set
// from the measured errors (tools/bench/accuracy/README.md) with a margin. The contact dynamics
// are second order in dt (contact/law/second_order.hpp): with the dashpot on the half-step
// velocity the sphere-wall restitution was 3.0% off at 0.1 and 13.5% at 0.3, order 1.1 (75d955f).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "accuracy_cases.hpp"
#include "sim/step_accuracy.hpp"

using namespace polydem;
using namespace polydem::validation;
using namespace polydem::validation::accuracy;

namespace {

// -, log2 of the error's ratio when the step is halved from 0.1 to 0.05 x critical.
template <class Run>
double observed_order(const Run& run) {
  return std::log2(run(0.1) / run(0.05));
}

// Second order at least: the error at each fraction f of {0.3, 0.2, 0.15, 0.1, 0.05} within
// bound (f/0.3)^2. The exact step's impacts sit far below that line, their error moving with
// the phase of the contact in the steps, so the ratio of two neighbours is no order.
template <class Run>
void check_second_order(const Run& run, double bound) {
  for (double f : {0.3, 0.2, 0.15, 0.1, 0.05}) {
    INFO("dt = " << f << " x critical");
    CHECK(run(f) <= bound * (f / 0.3) * (f / 0.3));
  }
}

}  // namespace

TEST_CASE("accuracy: sphere-wall restitution at 0.1 and 0.3 x critical, second order, en 0.1 to 0.9", "[validation][second_order]") {
  for (double en : {0.1, 0.5, 0.9}) {
    auto run = [en](double fraction) { return binary_impact(fraction, en); };
    const double at_auto = run(0.1), at_03 = run(0.3), order = observed_order(run);
    std::printf("sphere-wall en %.1f: error %.2e at 0.1, %.2e at 0.3, order %.2f\n", en, at_auto, at_03, order);
    INFO("en = " << en);
    CHECK(at_auto <= 2e-3);
    // The end-of-step dashpot alone (exact_step off: no damped sphere takes it, the default is the
    // exact step below, within the goal of 1%): measured 1.8e-3 to 4.1e-2 at 0.3.
    CHECK(at_03 <= 0.05);
    CHECK(order >= 1.8);
  }
}

TEST_CASE("accuracy: sphere-sphere restitution, masses 1 : 2.74, at 0.1 and 0.3 x critical", "[validation][second_order]") {
  const double at_auto = sphere_pair_impact(0.1), at_03 = sphere_pair_impact(0.3);
  const double order = observed_order([](double f) { return sphere_pair_impact(f); });
  std::printf("sphere-sphere: error %.2e at 0.1, %.2e at 0.3, order %.2f\n", at_auto, at_03, order);
  CHECK(at_auto <= 2e-3);
  CHECK(at_03 <= 0.05);
  CHECK(order >= 1.8);
}

TEST_CASE("accuracy: oblique impact 45 deg, no spike between 0.24 and 0.3 x critical", "[validation][second_order]") {
  // A spring that stuck at its cap (read at n+1) takes the slip push of a kink at the step's
  // start (law.hpp): without it the worst of 16 touch places spiked to 1.34e-2 at 0.26 and
  // 1.38e-2 at 0.273 between neighbours of 7-8e-3. Measured every 1e-4 with it: largest 1.04e-2
  // (0.2541, the normal force's tail at the release); with the sampled force's cap where it
  // slips, 8.59e-3 every 0.001 (0.263). Every 0.001 x critical: 61 x 16 impacts.
  double worst = 0.0, at = 0.0;
  for (int k = 240; k <= 300; ++k) {
    const double e = oblique_impact_worst_phase(k / 1000.0);
    if (e > worst) worst = e, at = k / 1000.0;
  }
  std::printf("oblique 45 deg: largest worst-of-16 error over 0.24-0.3 x critical %.3e at %.3f\n", worst, at);
  CHECK(worst <= 1e-2);
}

TEST_CASE("accuracy: oblique impact 45 deg against RK4 at 0.1 and 0.3 x critical", "[validation][second_order]") {
  const double at_auto = oblique_impact(0.1), at_03 = oblique_impact(0.3);
  const double worst_auto = oblique_impact_worst_phase(0.1), worst_03 = oblique_impact_worst_phase(0.3);
  std::printf("oblique 45 deg: error %.2e at 0.1, %.2e at 0.3; worst of 16 touch places %.2e and %.2e\n", at_auto,
              at_03, worst_auto, worst_03);
  // The sphere takes the exact normal step (the default), its Coulomb cap the force at n+1
  // where it slips, and its tangential spring starts at the touch inside the step where the
  // overlap starts (law.hpp). The tangential force kinks where the spring starts and where it
  // starts to slip: the steps there take the kink's push (tangential_spring.hpp); where it slips
  // the kicks take the sampled force's cap, and it starts at the exact onset's arc touch. Measured
  // 7.7e-6 and 7.04e-3 at one place, at the worst of 16 touch places 7.29e-4 and 6.42e-3 (9.28e-4
  // and 7.65e-3 before those two, fb926d1; 1.37e-3 and 9.24e-3 without the pushes). The goals:
  // 0.2% at 0.1, 1% at 0.3.
  CHECK(at_auto <= 2e-3);
  CHECK(at_03 <= 1e-2);
  CHECK(worst_auto <= 2e-3);
  CHECK(worst_03 <= 1e-2);
  // Order at the worst touch place between 0.1 and 0.05: measured 2.19 (1.60e-4 at 0.05; 2.32 at
  // fb926d1, 4.7e-5 at 0.025 then). Without the pushes 1.50 (1.37e-3, 4.87e-4): the kinks' errors, up to kt vt dt^2/8
  // of impulse each with the kink's place in its step, added or cancelled by the place.
  const double worst_005 = oblique_impact_worst_phase(0.05), order = std::log2(worst_auto / worst_005);
  std::printf("oblique 45 deg: worst of 16 touch places %.2e at 0.05, order %.2f from 0.1\n", worst_005, order);
  CHECK(order >= 1.8);
}

TEST_CASE("accuracy: oblique impact 45 deg with damp_tangential against RK4, second order", "[validation][second_order]") {
  // The tangential dashpot (ratio 0.3) takes its share of the cap first; where the spring slips the
  // kicks take the sampled force's cap for spring and dashpot together, and a spring that stuck
  // at n takes the slip push with the cap at n less the dashpot's share then (law.hpp); a spring
  // the dashpot held at zero loads from where its share stopped taking the whole cap
  // (share_opened_time). Worst of 16 touch places, measured: 4.59e-4 at 0.1, 1.15e-4 at 0.05
  // (order 2.0), 5.53e-3 at 0.3, 4.20e-6 at 0.01, 1.10e-6 at 0.005 (order 1.93). Before
  // share_opened_time the spring loaded from the step's start, an O(dt) excess its stick kept:
  // 4.31e-4, 9.21e-5 (2.23), 1.60e-5 at 0.01, 8.36e-6 at 0.005 (order 0.94), hidden above 1e-4.
  const double at_auto = oblique_impact_worst_phase(0.1, 16, 0.3), at_005 = oblique_impact_worst_phase(0.05, 16, 0.3);
  const double at_03 = oblique_impact_worst_phase(0.3, 16, 0.3), order = std::log2(at_auto / at_005);
  const double at_001 = oblique_impact_worst_phase(0.01, 16, 0.3), at_0005 = oblique_impact_worst_phase(0.005, 16, 0.3);
  const double order_fine = std::log2(at_001 / at_0005);
  std::printf("oblique 45 deg, damp_tangential 0.3: worst of 16 touch places %.2e at 0.1, %.2e at 0.05 (order %.2f), %.2e at 0.3, "
              "%.2e at 0.01, %.2e at 0.005 (order %.2f)\n", at_auto, at_005, order, at_03, at_001, at_0005, order_fine);
  CHECK(at_auto <= 6e-4);
  CHECK(order >= 1.8);
  CHECK(at_03 <= 1e-2);  // the goal
  CHECK(order_fine >= 1.8);
}

// Hertz with Tsuji's dashpot: each step's force the hat average over [n-1, n+1] of the force
// along the motion (normal_hertz.hpp: hat_spring, hat_dashpot, hat_curvature, released_force
// past the clamp), the dashpot's velocity at n to O(dt^3), the onset step on the impact's arc
// (its chord: hertz_arc.hpp). Measured at the worst of 16 touch places (error at 0.1, at 0.3,
// order between 0.1 and 0.05; before, d322b70's cell averages and point samples): en 0.1
// 2.56e-4, 3.94e-3, 2.53 (1.09e-3, 9.06e-3, 1.99); en 0.3 2.02e-4, 3.78e-3, 2.52 (2.17e-4,
// 2.25e-3, 2.54); en 0.5 1.24e-4, 2.15e-3, 2.69 (3.30e-4, 1.71e-3, 1.71); en 0.7 5.32e-5,
// 6.82e-4, 2.75 (3.91e-4, 1.87e-3, 1.71); en 0.9 4.04e-6, 5.80e-3, 2.32 (2.54e-4, 5.44e-3, 1.59).
TEST_CASE("accuracy: Hertz sphere-wall restitution wherever in the step it touches, at 0.1 and 0.3 x critical", "[validation][second_order]") {
  for (double en : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    auto run = [en](double fraction) { return hertz_impact(fraction, en); };
    const double at_auto = run(0.1), at_03 = run(0.3), order = observed_order(run);
    std::printf("Hertz en %.1f, worst touch place: error %.2e at 0.1, %.2e at 0.3, order %.2f\n", en, at_auto, at_03, order);
    INFO("en = " << en);
    CHECK(at_auto <= 5e-4);  // the goal: 2e-3
    CHECK(at_03 <= 1e-2);    // the goal
    CHECK(order >= 2.2);     // the goal: 1.8
  }
}

// No floor: en 0.5 falls on at order 2.5 below 0.05 x critical (measured 1.92e-5 at 0.05, 3.21e-6
// at 0.025, 5.1e-7 at 0.0125; d322b70: 1.01e-4, 2.75e-5, 7.4e-6).
TEST_CASE("accuracy: Hertz en 0.5 keeps its order below 0.05 x critical", "[validation][second_order]") {
  const double at_005 = hertz_impact(0.05, 0.5), at_0025 = hertz_impact(0.025, 0.5);
  std::printf("Hertz en 0.5, worst touch place: %.2e at 0.05, %.2e at 0.025, order %.2f\n", at_005, at_0025,
              std::log2(at_005 / at_0025));
  CHECK(at_0025 <= 1e-5);
  CHECK(std::log2(at_005 / at_0025) >= 2.2);
}

TEST_CASE("accuracy: a cohesive sphere-wall impact is second order", "[validation][second_order]") {
  // Cohesion's force is continuous (-fc inside, a ramp to 0 over dncut): its kinks at the band's
  // ends cost O(dt^2) each. Worst of 16 touch places against the converged rebound (0.414 for en 0.5).
  const double at_01 = cohesive_impact_worst_phase(0.1), at_00125 = cohesive_impact_worst_phase(0.0125);
  const double order = std::log2(at_01 / at_00125) / 3.0;
  std::printf("cohesive sphere-wall: worst of 16 touch places %.2e at 0.1, %.2e at 0.0125, order %.2f\n", at_01, at_00125, order);
  CHECK(at_01 <= 4e-3);  // measured 2.55e-3
  CHECK(order >= 1.8);   // measured 2.02
}

TEST_CASE("accuracy: damping_mass: contact, a cube landing on a corner rebounds there at en", "[validation][second_order]") {
  // The pair's dashpot (the default) is tuned to the cube's mass, heavier than the corner's:
  // it rebounds at 0.40 there for en 0.5 (issue 16); this one at en, within the cube row's goals.
  const double at_auto = cube_corner_error(0.1, true), at_03 = cube_corner_error(0.3, true);
  std::printf("cube corner, damping_mass contact: error %.2e at 0.1, %.2e at 0.3\n", at_auto, at_03);
  // Stepped exactly (the default with damping_mass: contact): measured 3.4e-4 and 5.0e-4 (the
  // end-of-step dashpot: 2.6e-4 and 1.1e-2).
  CHECK(at_auto <= 1e-3);
  CHECK(at_03 <= 2e-3);
}

TEST_CASE("accuracy: cube corner landing against the rigid body with the contact law, at 0.1 and 0.3 x critical", "[validation][second_order]") {
  const auto run = [](double fraction) { return cube_corner_error(fraction, false, true); };
  const double at_auto = run(0.1), at_03 = run(0.3), order = observed_order(run);
  std::printf("cube corner vs RK4: error %.2e at 0.1, %.2e at 0.3, order %.2f\n", at_auto, at_03, order);
  CHECK(at_auto <= 3e-3);  // measured 1.94e-3
  CHECK(at_03 <= 0.015);   // measured 1.26e-2
  // Measured 1.89 (5.21e-4 at 0.05, 1.33e-4 at 0.025). Against the rigid-body impulse
  // (cube_landing) it was 1.21: that answer ignores the turn during the contact, 5.6e-4 of the
  // rebound, a floor the error meets below 0.1.
  CHECK(order >= 1.8);
}

TEST_CASE("accuracy: dt: auto on spheres, the exact step's step for 1e-3, rebounds within it wherever it touches", "[validation][step_accuracy]") {
  // Every contact takes the exact step: auto is 0.181 x critical (0.1 before), the model's step
  // for kAutoAccuracy; measured at the worst of 16 touch phases 4.7e-4 (en 0.1) to 1.08e-3 (en
  // 0.5): the model's 16 phases, placed otherwise, miss the worst by up to ~10%, so within 1.2 x.
  for (double en : {0.1, 0.5, 0.9, 0.95}) {
    const double error = binary_impact_at_auto_worst_phase(en);
    std::printf("sphere-wall en %.2f at dt: auto, worst touch phase: error %.2e\n", en, error);
    INFO("en = " << en);
    CHECK(error <= 1.2 * kAutoAccuracy);
  }
}

TEST_CASE("accuracy: a sphere on a wall at dt: auto with accuracy rebounds within that error", "[validation][step_accuracy]") {
  // simulation: accuracy picks the step from the sphere-wall errors measured at en 0.5
  // (sim/step_accuracy.cpp): within the target there; at en 0.1 and 0.9, and between the
  // measured steps, the error moves with the phase of the contact in the steps (measured up to
  // 1.4 x the target: en 0.9 at 1e-3), so within 1.5 x.
  for (double en : {0.1, 0.5, 0.9})
    for (double target : {1e-2, 1e-3, 1e-4}) {
      const double error = binary_impact_at_accuracy(target, en);
      std::printf("sphere-wall en %.1f, accuracy %.0e: error %.2e\n", en, target, error);
      INFO("en = " << en << ", accuracy = " << target);
      CHECK(error <= (en == 0.5 && target >= 1e-3 ? 1.0 : 1.5) * target);
    }
}

// Hertz under simulation: accuracy takes its step from kHertz (sim/step_accuracy.cpp, the hat
// average's errors): 0.16 x critical for 1e-3 and 0.06 for 1e-4 (d322b70's table: 0.091, 0.030),
// the cap 0.3 for 1e-2 (6.9e-3 there); the error at the worst of 16 touch places within the target.
TEST_CASE("accuracy: a Hertz sphere on a wall with accuracy rebounds within it, at a larger step than before", "[validation][step_accuracy]") {
  const struct {
    double target, old_fraction;
  } cases[] = {{1e-2, 0.3}, {1e-3, 0.0907}, {1e-4, 0.0302}};
  for (const auto& [target, old_fraction] : cases)
    for (double en : {0.1, 0.5, 0.9}) {
      const StepError at = hertz_impact_at_accuracy(target, en);
      std::printf("Hertz en %.1f, accuracy %.0e: %.3g x critical (was %.3g), worst touch place %.2e\n", en, target,
                  at.fraction, old_fraction, at.error);
      INFO("en = " << en << ", accuracy = " << target);
      CHECK(at.error <= target);
      CHECK(at.fraction >= std::min(1.7 * old_fraction, 0.3) - 1e-9);
    }
}

// With the linear law's exact step (contact/law/exact_linear.hpp, what simulation: accuracy
// turns on): the goal of 1% at 0.3 x critical for the spheres, 0.2% at 0.1.
TEST_CASE("accuracy: exact step, sphere-wall restitution at 0.1 and 0.3 x critical, en 0.1 to 0.9", "[validation][second_order]") {
  for (double en : {0.1, 0.5, 0.9}) {
    auto run = [en](double fraction) { return binary_impact(fraction, en, true); };
    const double at_auto = run(0.1), at_03 = run(0.3);
    std::printf("exact step, sphere-wall en %.1f: error %.2e at 0.1, %.2e at 0.3\n", en, at_auto, at_03);
    INFO("en = " << en);
    CHECK(at_auto <= 2e-4);  // measured 0.9-4.4e-5
    CHECK(at_03 <= 5e-3);    // measured 0.5-3.0e-3
    check_second_order(run, 5e-3);
  }
}

// A bed's impacts touch anywhere in a step: the worst of 16 touch phases. With high en the
// force lets go in the step where the overlap ends, where the kernels no longer see the contact;
// its last push is given a step early (exact_linear.hpp): without it en 0.9 was 1.3e-3 off at
// 0.1 and 3.5e-2 at 0.3, en 0.95 3.2e-3 and 4.0e-2.
TEST_CASE("accuracy: exact step, sphere-wall restitution wherever in the step it touches, en 0.1 to 0.95", "[validation][second_order]") {
  for (double en : {0.1, 0.5, 0.9, 0.95}) {
    const double at_auto = binary_impact_worst_phase(0.1, en), at_03 = binary_impact_worst_phase(0.3, en);
    std::printf("exact step, sphere-wall en %.2f, worst touch phase: error %.2e at 0.1, %.2e at 0.3\n", en, at_auto, at_03);
    INFO("en = " << en);
    CHECK(at_auto <= 3e-4);  // measured 0.6-1.7e-4
    CHECK(at_03 <= 7e-3);    // measured 2.1-4.7e-3
  }
}

TEST_CASE("accuracy: exact step, sphere-sphere restitution, masses 1 : 2.74, at 0.1 and 0.3 x critical", "[validation][second_order]") {
  auto run = [](double fraction) { return sphere_pair_impact(fraction, true); };
  const double at_auto = run(0.1), at_03 = run(0.3);
  std::printf("exact step, sphere-sphere: error %.2e at 0.1, %.2e at 0.3\n", at_auto, at_03);
  CHECK(at_auto <= 2e-4);  // measured 7.6e-5
  CHECK(at_03 <= 5e-3);    // measured 1.7e-3
  check_second_order(run, 5e-3);
}

TEST_CASE("accuracy: rolling resistance, a spinning sphere's landing against RK4, second order", "[validation][second_order]") {
  // The rolling spring is loaded from the touch where it starts, and its kinks (where it starts,
  // where one that stuck starts to slip) take their pushes as the tangential spring's (law.hpp);
  // it starts at the exact onset's arc touch, and where it slips the kicks take the sampled
  // force's cap. Worst of 16 touch places, measured: 2.82e-4 at 0.1, 6.03e-5 at 0.05 (order
  // 2.22), 3.72e-3 at 0.3; from the straight line's touch and with the cap at n+1 (fb926d1)
  // 1.65e-3, 3.66e-4, 3.95e-2; loaded over the whole step (372a7f8) 5.88e-2, 2.97e-2 (order 0.99), 0.136.
  const double at_auto = rolling_impact_worst_phase(0.1), at_005 = rolling_impact_worst_phase(0.05);
  const double at_03 = rolling_impact_worst_phase(0.3), order = std::log2(at_auto / at_005);
  std::printf("rolling: worst of 16 touch places %.2e at 0.1, %.2e at 0.05 (order %.2f), %.2e at 0.3\n", at_auto, at_005,
              order, at_03);
  CHECK(at_auto <= 5e-4);
  CHECK(order >= 1.8);
  CHECK(at_03 <= 1e-2);  // the goal
}

TEST_CASE("accuracy: a spinning sphere landing with friction and damp_tangential and rolling resistance against RK4", "[validation][second_order]") {
  // Tangential spring, its dashpot and the rolling spring together, each slipping and sticking
  // (accuracy_cases.hpp). Worst of 16 touch places, measured: 2.95e-4 at 0.1, 5.65e-5 at 0.05
  // (order 2.38), 3.36e-3 at 0.3; 1.85e-5 at 0.025 and 6.5e-6 at 0.0125 (at one touch place 4.5e-6
  // at both: the floor the oblique impact with the dashpot shows). At 82b9e28: 3.52e-4 at 0.1,
  // 8.08e-5 at 0.05 (order 2.12), 3.38e-3 at 0.3.
  const double at_auto = rolling_friction_impact_worst_phase(0.1), at_005 = rolling_friction_impact_worst_phase(0.05);
  const double at_03 = rolling_friction_impact_worst_phase(0.3), order = std::log2(at_auto / at_005);
  std::printf("rolling with friction and damp_tangential: worst of 16 touch places %.2e at 0.1, %.2e at 0.05 (order %.2f), %.2e at 0.3\n",
              at_auto, at_005, order, at_03);
  CHECK(at_auto <= 5e-4);
  CHECK(order >= 1.8);
  CHECK(at_03 <= 1e-2);  // the goal
}

TEST_CASE("accuracy: the free top's flip period at 0.1 of 2/w is no worse than before, second order", "[validation][second_order]") {
  // No contact: issue 16's "unchanged or better" row. The step is a fraction of 2/w (w = 10
  // rad/s). The reference curve (tools/bench/accuracy/reference.csv, 75d955f) has 1.98e-3 at
  // 0.1 and 5.0e-4 at 0.05; measured the same at 82b9e28 (order 1.99).
  const double at_auto = free_top(0.1), at_005 = free_top(0.05), order = std::log2(at_auto / at_005);
  std::printf("free top: flip period error %.3e at 0.1, %.3e at 0.05, order %.2f\n", at_auto, at_005, order);
  CHECK(at_auto <= 1.99e-3);
  CHECK(order >= 1.8);
}
