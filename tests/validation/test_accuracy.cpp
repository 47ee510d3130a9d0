// The accuracy slice of the work-precision sweep (accuracy_cases.hpp, tools/bench/accuracy) in
// CI: each contact case at dt = 0.1 and 0.3 x the critical step `polydem check` prints (0.1 is
// `dt: auto`), and the observed order of the impacts between 0.1 and 0.05, against bounds set
// from the measured errors (tools/bench/accuracy/README.md) with a margin. The contact dynamics
// are second order in dt (contact/law/second_order.hpp), and the spheres' linear law is stepped
// exactly (contact/law/exact_linear.hpp): with the dashpot on the half-step velocity the
// sphere-wall restitution was 3.0% off at 0.1 and 13.5% at 0.3, order 1.1 (75d955f); with the
// end-of-step dashpot alone 0.19% and 4.1% (b785258).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "accuracy_cases.hpp"

using namespace polydem;
using namespace polydem::validation;
using namespace polydem::validation::accuracy;

namespace {

// Second order at least: the error at each fraction f of {0.3, 0.2, 0.15, 0.1, 0.05} within
// bound (f/0.3)^2. With the exact step the impacts sit far below that line, their error moving
// with the phase of the contact in the steps, so the ratio of two neighbours is no order.
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
    const double at_auto = run(0.1), at_03 = run(0.3);
    std::printf("sphere-wall en %.1f: error %.2e at 0.1, %.2e at 0.3\n", en, at_auto, at_03);
    INFO("en = " << en);
    CHECK(at_auto <= 2e-4);  // measured 0.9-4.4e-5 (exact step: contact/law/exact_linear.hpp)
    CHECK(at_03 <= 5e-3);    // measured 0.5-3.0e-3; the goal is 1e-2
    // en 0.9 levels off at 2.9e-3 between 0.3 and 0.15: its force lets go in the step where the
    // overlap ends, and the kernels no longer see the contact to give the release's last push.
    if (en < 0.9) check_second_order(run, 5e-3);
  }
}

TEST_CASE("accuracy: sphere-sphere restitution, masses 1 : 2.74, at 0.1 and 0.3 x critical", "[validation][second_order]") {
  const double at_auto = sphere_pair_impact(0.1), at_03 = sphere_pair_impact(0.3);
  std::printf("sphere-sphere: error %.2e at 0.1, %.2e at 0.3\n", at_auto, at_03);
  CHECK(at_auto <= 2e-4);  // measured 7.6e-5
  CHECK(at_03 <= 5e-3);    // measured 1.7e-3
  check_second_order(sphere_pair_impact, 5e-3);
}

TEST_CASE("accuracy: oblique impact 45 deg against RK4 at 0.1 and 0.3 x critical", "[validation][second_order]") {
  const double at_auto = oblique_impact(0.1), at_03 = oblique_impact(0.3);
  std::printf("oblique 45 deg: error %.2e at 0.1, %.2e at 0.3\n", at_auto, at_03);
  CHECK(at_auto <= 2e-3);  // measured 1.6e-3 (0.9e-3 before the exact step: its sampled normal force feeds the cap)
  CHECK(at_03 <= 0.01);    // measured 9.2e-3 (1.6e-3 before), the goal
}

TEST_CASE("accuracy: damping_mass: contact, a cube landing on a corner rebounds there at en", "[validation][second_order]") {
  // The pair's dashpot (the default) is tuned to the cube's mass, heavier than the corner's:
  // it rebounds at 0.40 there for en 0.5 (issue 16); this one at en, within the cube row's goals.
  const double at_auto = cube_corner_error(0.1, true), at_03 = cube_corner_error(0.3, true);
  std::printf("cube corner, damping_mass contact: error %.2e at 0.1, %.2e at 0.3\n", at_auto, at_03);
  CHECK(at_auto <= 1e-3);  // measured 2.6e-4
  CHECK(at_03 <= 0.015);
}

TEST_CASE("accuracy: cube corner landing against the rigid-body impulse at 0.1 and 0.3 x critical", "[validation][second_order]") {
  const double at_auto = cube_landing(0.1), at_03 = cube_landing(0.3);
  std::printf("cube corner: error %.2e at 0.1, %.2e at 0.3\n", at_auto, at_03);
  CHECK(at_auto <= 3e-3);
  CHECK(at_03 <= 0.015);
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
