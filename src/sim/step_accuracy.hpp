#pragma once
// The restitution error of a single impact against the time step, and the step for a target
// error (simulation: accuracy). The model: the sphere-wall column of tools/bench/accuracy
// (results.csv at e9b1677, en 0.5), the largest error of the contact cases measured there
// from 0.3 x critical down (README, "accuracy:"), interpolated in log-log.

#include <string>

namespace polydem {

// Relative restitution error expected at dt = fraction x critical; slope 2 below the smallest
// measured fraction (the observed order), infinity above the largest.
double expected_restitution_error(double fraction);

// The largest fraction of the critical step (at most kUnsafeFraction) whose expected error is
// within `accuracy`.
double accuracy_fraction(double accuracy);

// "expected restitution error of an impact at this step: 2e-03 (0.1 x critical)" for a step
// dt of a run whose critical step is `critical` (s); "" without a finite critical step.
std::string impact_error_note(double dt, double critical);

}  // namespace polydem
