#include "sim/step_accuracy.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <span>

#include "sim/time_step.hpp"

namespace polydem {

namespace {

struct Point {
  double fraction, error;  // dt / critical, relative restitution error
};

// The default step (end-of-step dashpot): tools/bench/accuracy/results.csv, "binary impact"
// (sphere on a wall, en 0.5, 0.5 m/s), measured at e9b1677; increasing in both columns.
constexpr std::array<Point, 13> kSphereWall = {{{0.002, 3.88329e-07},
                                                {0.005, 2.48912e-06},
                                                {0.01, 1.04713e-05},
                                                {0.02, 4.51413e-05},
                                                {0.03, 0.000109001},
                                                {0.05, 0.000372201},
                                                {0.07, 0.000841735},
                                                {0.1, 0.00194553},
                                                {0.15, 0.00578582},
                                                {0.2, 0.0128749},
                                                {0.3, 0.0411651},
                                                {0.4, 0.061719},
                                                {0.5, 0.144879}}};

// The exact step (the linear law's, contact/law/exact_linear.hpp: spheres, and contacts
// under `damping_mass: contact`): the worst sphere-wall restitution error over en 0.1-0.95 and 16 places of the
// touch in its step (0.5 m/s), the hidden test "[.accuracy_model]" of
// tests/validation/accuracy_sweep.cpp, measured at bb2f584; third order in the step (1.65e-4
// at 0.1, 1.45e-3 at 0.2). Conservative for the spheres' linear law; Hertz and polyhedra,
// stepped by the end-of-step dashpot (second_order.hpp), sit above it (README "Which time step").
constexpr std::array<Point, 18> kExactSphereWall = {{{0.002, 1.27e-09},
                                                {0.005, 1.97e-08},
                                                {0.01, 1.57e-07},
                                                {0.02, 1.28e-06},
                                                {0.03, 4.38e-06},
                                                {0.05, 2.08e-05},
                                                {0.07, 5.76e-05},
                                                {0.1, 0.000165},
                                                {0.12, 0.000281},
                                                {0.14, 0.000463},
                                                {0.15, 0.0006},
                                                {0.16, 0.000672},
                                                {0.18, 0.000978},
                                                {0.2, 0.00145},
                                                {0.25, 0.0029},
                                                {0.3, 0.00492},
                                                {0.4, 0.0137},
                                                {0.5, 2.3}}};

// The log-log line through a and b at x (x and y either fractions or errors).
double log_line(double ax, double ay, double bx, double by, double x) {
  const double t = std::log(x / ax) / std::log(bx / ax);
  return ay * std::pow(by / ay, t);
}

// The model of the exact step or of the default step.
std::span<const Point> sphere_wall(bool exact) {
  if (exact) return kExactSphereWall;
  return kSphereWall;
}

}  // namespace

double expected_restitution_error(double fraction, bool exact) {
  const std::span<const Point> table = sphere_wall(exact);
  const Point& first = table.front();
  if (fraction <= first.fraction) return first.error * (fraction / first.fraction) * (fraction / first.fraction);
  for (std::size_t k = 1; k < table.size(); ++k) {
    const Point &a = table[k - 1], &b = table[k];
    if (fraction <= b.fraction) return log_line(a.fraction, a.error, b.fraction, b.error, fraction);
  }
  return std::numeric_limits<double>::infinity();
}

double accuracy_fraction(double accuracy, bool exact) {
  const std::span<const Point> table = sphere_wall(exact);
  const Point& first = table.front();
  if (accuracy <= first.error) return first.fraction * std::sqrt(accuracy / first.error);
  for (std::size_t k = 1; k < table.size(); ++k) {
    const Point &a = table[k - 1], &b = table[k];
    if (b.fraction > kUnsafeFraction) break;
    if (accuracy <= b.error) return log_line(a.error, a.fraction, b.error, b.fraction, accuracy);
  }
  return kUnsafeFraction;
}

double auto_fraction(bool exact) { return exact ? accuracy_fraction(kAutoAccuracy, true) : kAutoFraction; }

std::string impact_error_note(double dt, double critical, bool exact) {
  if (!std::isfinite(critical) || !(critical > 0.0)) return "";
  const double fraction = dt / critical, error = expected_restitution_error(fraction, exact);
  char line[200];
  if (std::isfinite(error))
    std::snprintf(line, sizeof(line), "expected restitution error of an impact at this step: %.1e (%.3g x critical)",
                  error, fraction);
  else
    std::snprintf(line, sizeof(line), "expected restitution error of an impact at this step: above %.2g (%.3g x "
                  "critical, beyond the largest measured %.2g)", sphere_wall(exact).back().error, fraction,
                  sphere_wall(exact).back().fraction);
  return line;
}

}  // namespace polydem
