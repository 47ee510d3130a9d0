// The step for a target restitution error (simulation: accuracy, sim/step_accuracy.cpp): the
// model reproduces the sphere-wall errors measured in tools/bench/accuracy/results.csv, grows
// with the step, and inverts; `dt: auto` without it takes kAutoAccuracy's step where every
// contact takes the exact step, by the Hertz rows for spheres under Hertz, by the cube landings
// for polyhedra, else kAutoFraction.
#include <catch2/catch.hpp>

#include <cmath>

#include "io/scene_settings.hpp"
#include "sim/step_accuracy.hpp"
#include "sim/time_step.hpp"

using namespace polydem;

namespace {
const ImpactModel kExact{.exact = true};
}  // namespace

TEST_CASE("step accuracy: the model passes through the measured sphere-wall errors", "[step_accuracy]") {
  // tools/bench/accuracy/results.csv, binary impact at e9b1677.
  CHECK(expected_restitution_error(0.1) == Approx(0.00194553).epsilon(1e-9));
  CHECK(expected_restitution_error(0.2) == Approx(0.0128749).epsilon(1e-9));
  CHECK(expected_restitution_error(0.3) == Approx(0.0411651).epsilon(1e-9));
  CHECK(expected_restitution_error(0.01) == Approx(1.04713e-05).epsilon(1e-9));
  // Between two points, the log-log line: 0.07 -> 0.1 has slope log(1.9455e-3/8.4174e-4)/log(1/0.7).
  const double slope = std::log(0.00194553 / 0.000841735) / std::log(0.1 / 0.07);
  CHECK(expected_restitution_error(0.085) == Approx(0.000841735 * std::pow(0.085 / 0.07, slope)).epsilon(1e-9));
  // Below the smallest measured fraction, second order; above the largest, unknown.
  CHECK(expected_restitution_error(0.001) == Approx(3.88329e-07 / 4).epsilon(1e-9));
  CHECK(std::isinf(expected_restitution_error(0.6)));
}

TEST_CASE("step accuracy: with the exact step, the worst sphere-wall errors of en 0.1-0.95 and the touch's phase", "[step_accuracy]") {
  // tests/validation/accuracy_sweep.cpp "[.accuracy_model]": the exact step's worst error.
  CHECK(expected_restitution_error(0.1, kExact) == Approx(1.65e-04).epsilon(1e-9));
  CHECK(expected_restitution_error(0.3, kExact) == Approx(4.92e-03).epsilon(1e-9));
  CHECK(expected_restitution_error(0.001, kExact) == Approx(1.27e-09 / 4).epsilon(1e-9));
  CHECK(impact_error_note(1e-6, 1e-5, kExact) == "expected restitution error of an impact at this step: 1.7e-04 (0.1 x critical; exact-step sphere-wall impacts)");
}

TEST_CASE("step accuracy: dt: auto keeps 1e-3 where every contact takes the exact step, 0.1 x critical for other spheres", "[step_accuracy]") {
  const double f = auto_fraction({.exact = true});
  CHECK(expected_restitution_error(f, kExact) == Approx(kAutoAccuracy).epsilon(1e-9));
  CHECK(f == Approx(0.18 * std::pow(0.2 / 0.18, std::log(1e-3 / 0.000978) / std::log(0.00145 / 0.000978))).epsilon(1e-9));
  CHECK(auto_fraction({}) == kAutoFraction);
}

TEST_CASE("step accuracy: dt: auto keeps 1e-3 by the cube landings for polyhedra", "[step_accuracy]") {
  const ImpactModel cubes{.polyhedra = true};
  const double f = auto_fraction(cubes);
  CHECK(expected_restitution_error(f, cubes) == Approx(kAutoAccuracy).epsilon(1e-9));
  CHECK(f == Approx(0.0654).margin(0.0005));  // acc19's kCubes: 1e-3 between 0.065 and 0.07
  // Hertz's rows (0.167) and friction's (left out) do not move it.
  CHECK(auto_fraction({.polyhedra = true, .hertz = true}) == f);
  CHECK(auto_fraction({.polyhedra = true, .friction = true}) == f);
}

// damping_mass: contact (kCubesContactMass): the tilted cube binds, 1e-3 between 0.115 and 0.12.
TEST_CASE("step accuracy: dt: auto keeps 1e-3 by the contact-mass cube landings under damping_mass: contact", "[step_accuracy]") {
  const ImpactModel contact{.polyhedra = true, .contact_mass = true}, pair{.polyhedra = true};
  const double f = auto_fraction(contact);
  CHECK(expected_restitution_error(f, contact) == Approx(kAutoAccuracy).epsilon(1e-9));
  CHECK(f > 0.115);
  CHECK(f < 0.12);
  CHECK(auto_fraction({.polyhedra = true, .contact_mass = true, .friction = true}) == f);
  CHECK(auto_fraction(pair) == Approx(0.0654).margin(0.0005));  // the pair's mass: unchanged
  // Spheres do not read it: the flag only picks the polyhedra's table.
  CHECK(auto_fraction({.exact = true, .contact_mass = true}) == auto_fraction(kExact));
  // A scene mixing both masses keeps the pair's table: the larger at every step.
  for (double g = 1e-3; g <= 0.5; g *= 1.05) {
    INFO("dt = " << g << " x critical");
    CHECK(expected_restitution_error(g, pair) > expected_restitution_error(g, contact));
  }
  CHECK(impact_error_note(f, 1.0, contact) ==
        "expected restitution error of an impact at this step: 1.0e-03 (0.117 x critical; cube landings, contact mass)");
}

TEST_CASE("step accuracy: dt: auto keeps 1e-3 by the Hertz rows for spheres under Hertz", "[step_accuracy]") {
  const ImpactModel hertz{.hertz = true};
  const double f = auto_fraction(hertz);
  CHECK(expected_restitution_error(f, hertz) == Approx(kAutoAccuracy).epsilon(1e-9));
  CHECK(f == Approx(0.167).margin(0.001));  // acc16's kHertz: 1e-3 between 0.165 and 0.17
  CHECK(auto_fraction({.hertz = true, .friction = true}) == f);
}

TEST_CASE("step accuracy: error grows with the step and the fraction inverts it", "[step_accuracy]") {
  double previous = 0.0;
  for (double f = 1e-3; f <= 0.5; f *= 1.05) {
    const double e = expected_restitution_error(f, kExact);
    CHECK(e > previous);
    CHECK(expected_restitution_error(f) > 0.0);
    previous = e;
  }
  double previous_fraction = 0.0;
  for (double a = kMinAccuracy; a <= kMaxAccuracy; a *= 1.1) {
    const double f = accuracy_fraction(a, kExact);
    INFO("accuracy " << a << ", fraction " << f);
    CHECK(f >= previous_fraction);
    CHECK(f <= kUnsafeFraction);
    CHECK(expected_restitution_error(f, kExact) <= a * (1 + 1e-12));
    if (f < kUnsafeFraction) CHECK(expected_restitution_error(f, kExact) == Approx(a).epsilon(1e-9));
    previous_fraction = f;
  }
  CHECK(accuracy_fraction(1.65e-04, kExact) == Approx(0.1).epsilon(1e-9));
  CHECK(accuracy_fraction(0.1, kExact) == kUnsafeFraction);  // beyond 0.3 x critical: capped
}

// Polyhedra (the pair's mass) take the end-of-step dashpot: `accuracy` must step them by the
// cube landings' model, not by the spheres' exact step.
TEST_CASE("step accuracy: without the exact step, accuracy inverts the scene's model", "[step_accuracy]") {
  const double f = accuracy_fraction(1e-3, {});
  CHECK(f > 0.05);
  CHECK(f < 0.1);
  CHECK(expected_restitution_error(f) == Approx(1e-3).epsilon(1e-9));
  CHECK(accuracy_fraction(1e-3, kExact) > 0.18);  // the exact step allows 2.5 times more
  const ImpactModel cubes{.polyhedra = true};
  CHECK(accuracy_fraction(1e-3, cubes) < f);  // the cube corner is further off than a sphere
}

TEST_CASE("step accuracy: a scene's model is the largest of its cases' and inverts", "[step_accuracy]") {
  const ImpactModel models[] = {kExact, {.exact = true, .friction = true}, {.polyhedra = true},
                                {.polyhedra = true, .friction = true}, {.polyhedra = true, .contact_mass = true},
                                {.polyhedra = true, .contact_mass = true, .friction = true}, {.hertz = true},
                                {.friction = true}};
  for (const ImpactModel& m : models) {
    ImpactModel without_friction = m;
    without_friction.friction = false;
    double previous = 0.0;
    for (double f = 1e-3; f <= 0.5; f *= 1.05) {  // at least each of its parts, never falling
      const double e = expected_restitution_error(f, m);
      CHECK(e >= expected_restitution_error(f, without_friction) * (1 - 1e-12));  // up to round-off
      CHECK(e >= previous);
      previous = e;
    }
    double previous_fraction = 0.0;
    for (double a = kMinAccuracy; a <= kMaxAccuracy; a *= 1.1) {
      const double f = accuracy_fraction(a, m);
      INFO("accuracy " << a << ", fraction " << f);
      CHECK(f >= previous_fraction);
      CHECK(expected_restitution_error(f, m) <= a * (1 + 1e-12));
      if (f < kUnsafeFraction) CHECK(expected_restitution_error(f, m) == Approx(a).epsilon(1e-9));
      previous_fraction = f;
    }
  }
  // Friction adds the oblique impact: above the frictionless spheres at dt: auto.
  CHECK(expected_restitution_error(auto_fraction({.exact = true}), {.exact = true, .friction = true}) > kAutoAccuracy);
}

TEST_CASE("step accuracy: the note names the error, rounded up, and the fraction", "[step_accuracy]") {
  CHECK(impact_error_note(1e-6, 1e-5) == "expected restitution error of an impact at this step: 2.0e-03 (0.1 x critical; end-of-step sphere-wall impact)");
  CHECK(impact_error_note(accuracy_fraction(1e-3, {}), 1.0).find(": 1.0e-03 (") != std::string::npos);
  CHECK(impact_error_note(6e-6, 1e-5).find("above 0.14 (0.6 x critical") != std::string::npos);
  CHECK(impact_error_note(1e-6, INFINITY).empty());
}
