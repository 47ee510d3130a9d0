#pragma once
// The error of a single impact against the time step, and the step for a target error
// (simulation: accuracy): the measured errors of tools/bench/accuracy's cases that bound a
// scene's impacts (ImpactModel), interpolated in log-log (README "`dt: auto` by accuracy").

#include <string>

namespace polydem {

// Which measured cases bound a scene's impacts: their errors' largest at each step. Spheres
// neither exact nor Hertz take the end-of-step dashpot's sphere-wall rows.
struct ImpactModel {
  bool exact = false;      // every contact takes the linear law's exact step: its sphere-wall rows
  bool polyhedra = false;  // a body is not a sphere: the cube landings (flat, tilted, corner)
  // Every law the polyhedra's contacts take steps its dashpot exactly on the contact point's
  // mass (damping_mass: contact, linear, damped): the cube landings under it. A scene mixing
  // both dashpot masses keeps the pair's-mass landings, the larger at every step.
  bool contact_mass = false;
  bool hertz = false;      // a law is Hertz: its sphere-wall rows (en 0.1-0.9)
  bool friction = false;   // a law has mu > 0 and kt > 0: the oblique impact's rows
};

// Relative error expected of an impact at dt = fraction x critical under `model`; slope 2
// below the smallest measured fraction (the observed order), infinity above the largest.
double expected_restitution_error(double fraction, ImpactModel model = {});

// The restitution error `dt: auto` keeps where every contact takes the exact step (spheres
// under a damped linear law): 0.1%, 0.18 x critical by the exact step's sphere-wall rows alone
// (0.1 x before issue 16's last step; dense beds checked there: README "dt: auto").
constexpr double kAutoAccuracy = 1e-3;

// The fraction of the critical step `dt: auto` takes: kAutoAccuracy's by the exact step's
// sphere-wall rows where every contact takes the exact step (0.181), by the Hertz rows for
// spheres under a Hertz law (0.167), by the cube landings where a body is a polyhedron (0.0654,
// 0.1 before session 27; 0.117 under damping_mass: contact), else kAutoFraction
// (sim/time_step.hpp). The oblique impact's rows are left out of all three, as friction's error
// is the tangential spring's.
double auto_fraction(ImpactModel model);

// The largest fraction of the critical step (at most kUnsafeFraction) whose expected error
// under `model` is within `accuracy`.
double accuracy_fraction(double accuracy, ImpactModel model);

// "expected restitution error of an impact at this step: 2e-03 (0.1 x critical)" for a step
// dt of a run whose critical step is `critical` (s) under `model`; "" without a finite
// critical step.
std::string impact_error_note(double dt, double critical, ImpactModel model = {});

}  // namespace polydem
