#pragma once
// Numbers a run cannot honour, found before the first step once the time step is known:
// refused with the file, line and key (InputError), or returned as warnings where a user
// may mean them.
#include <optional>
#include <string>
#include <vector>

#include "sim/simulation.hpp"

namespace polydem {

// 2^53: steps a run can count and date exactly (time = step x dt in a double).
constexpr double kMaxSteps = 9007199254740992.0;
// Above this many steps a run draws a warning (a day or more at 1e4 steps/s).
constexpr double kManySteps = 1e9;
// The shortest output interval, in time steps: below it a number is a mistake (a unit?); an
// interval between it and dt writes at every step (the schedule's catch-up loop stays short).
constexpr double kMinIntervalSteps = 1e-3;
// rad, the most a driver may turn in one step: its surface speed must stay meaningful.
constexpr double kMaxTurnPerStep = 1.0;
// The most gravity may move a body from rest in one step (g dt^2), in smallest body radii.
constexpr double kMaxFallPerStep = 1.0;

// `until`: --until (s), else the scene's duration. Throws InputError for a step count beyond
// kMaxSteps, an output interval below kMinIntervalSteps x dt, a driver turning more than
// kMaxTurnPerStep per step, gravity beyond kMaxFallPerStep; returns warning lines (an interval shorter than dt or longer than
// the run, many steps, a skin far beyond the bodies' size).
std::vector<std::string> check_run_limits(const Simulation& sim, std::optional<double> until);

}  // namespace polydem
