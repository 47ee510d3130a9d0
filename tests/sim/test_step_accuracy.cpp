// The step for a target restitution error (simulation: accuracy, sim/step_accuracy.cpp): the
// model reproduces the sphere-wall errors measured in tools/bench/accuracy/results.csv, grows
// with the step, and inverts; `dt: auto` without it keeps kAutoFraction.
#include <catch2/catch.hpp>

#include <cmath>

#include "io/scene_settings.hpp"
#include "sim/step_accuracy.hpp"
#include "sim/time_step.hpp"

using namespace polydem;

TEST_CASE("step accuracy: the model passes through the measured sphere-wall errors", "[step_accuracy]") {
  // tools/bench/accuracy/results.csv, binary impact, worst of en 0.1, 0.5, 0.9 at 89039a5.
  CHECK(expected_restitution_error(0.1) == Approx(4.9e-05).epsilon(1e-9));
  CHECK(expected_restitution_error(0.2) == Approx(2.9e-03).epsilon(1e-9));
  CHECK(expected_restitution_error(0.3) == Approx(2.99e-03).epsilon(1e-9));
  CHECK(expected_restitution_error(0.01) == Approx(1.33e-07).epsilon(1e-9));
  // Between two points, the log-log line: 0.1 -> 0.15 has slope log(2.88e-3/4.9e-5)/log(1.5).
  const double slope = std::log(2.88e-03 / 4.9e-05) / std::log(0.15 / 0.1);
  CHECK(expected_restitution_error(0.12) == Approx(4.9e-05 * std::pow(0.12 / 0.1, slope)).epsilon(1e-9));
  // Below the smallest measured fraction, second order; above the largest, unknown.
  CHECK(expected_restitution_error(0.001) == Approx(3.0e-10 / 4).epsilon(1e-9));
  CHECK(std::isinf(expected_restitution_error(0.6)));
}

TEST_CASE("step accuracy: error grows with the step and the fraction inverts it", "[step_accuracy]") {
  double previous = 0.0;
  for (double f = 1e-3; f <= 0.5; f *= 1.05) {
    const double e = expected_restitution_error(f);
    CHECK(e > previous);
    previous = e;
  }
  double previous_fraction = 0.0;
  for (double a = kMinAccuracy; a <= kMaxAccuracy; a *= 1.1) {
    const double f = accuracy_fraction(a);
    INFO("accuracy " << a << ", fraction " << f);
    CHECK(f >= previous_fraction);
    CHECK(f <= kUnsafeFraction);
    CHECK(expected_restitution_error(f) <= a * (1 + 1e-12));
    if (f < kUnsafeFraction) CHECK(expected_restitution_error(f) == Approx(a).epsilon(1e-9));
    previous_fraction = f;
  }
  CHECK(accuracy_fraction(4.9e-05) == Approx(0.1).epsilon(1e-9));
  CHECK(accuracy_fraction(0.1) == kUnsafeFraction);  // beyond 0.3 x critical: capped
}

TEST_CASE("step accuracy: the note names the error and the fraction", "[step_accuracy]") {
  CHECK(impact_error_note(1e-6, 1e-5) == "expected restitution error of an impact at this step: 4.9e-05 (0.1 x critical)");
  CHECK(impact_error_note(6e-6, 1e-5).find("above 2.3 (0.6 x critical") != std::string::npos);
  CHECK(impact_error_note(1e-6, INFINITY).empty());
}
