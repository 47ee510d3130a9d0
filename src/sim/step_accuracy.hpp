#pragma once
// The restitution error of a single impact against the time step, and the step for a target
// error (simulation: accuracy). The model: the sphere-wall columns of tools/bench/accuracy,
// interpolated in log-log: for the end-of-step dashpot at e9b1677 (en 0.5); for the linear
// law's exact step (spheres, read there by `accuracy` and `dt: auto`), the worst of en 0.1-0.95 and
// of the touch's place in its step (README).

#include <string>

namespace polydem {

// Relative restitution error expected at dt = fraction x critical; slope 2 below the smallest
// measured fraction (the observed order), infinity above the largest.
double expected_restitution_error(double fraction, bool exact = false);

// The restitution error `dt: auto` keeps where every contact takes the exact step (spheres
// under a damped linear law): 0.1%, 0.18 x critical by the exact step's model (0.1 x before
// issue 16's last step; dense beds checked there: README "dt: auto").
constexpr double kAutoAccuracy = 1e-3;

// The fraction of the critical step `dt: auto` takes: accuracy_fraction(kAutoAccuracy, true) where
// every contact takes the exact step, else kAutoFraction (sim/time_step.hpp).
double auto_fraction(bool exact);

// The largest fraction of the critical step (at most kUnsafeFraction) whose expected error is
// within `accuracy`, by the exact step's model or the default step's.
double accuracy_fraction(double accuracy, bool exact);

// "expected restitution error of an impact at this step: 2e-03 (0.1 x critical)" for a step
// dt of a run whose critical step is `critical` (s), with the exact step or not; "" without a
// finite critical step.
std::string impact_error_note(double dt, double critical, bool exact = false);

}  // namespace polydem
