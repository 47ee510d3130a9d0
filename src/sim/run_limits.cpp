#include "sim/run_limits.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "polydem/error.hpp"

namespace polydem {

namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.3g", v);
  return buf;
}

SourceLoc loc_of(const Scene& scene, const std::string& key) {
  const auto it = scene.key_locs.find(key);
  return it != scene.key_locs.end() ? it->second : SourceLoc{scene.path, 0};
}

[[noreturn]] void refuse(const SourceLoc& loc, const std::string& key, const std::string& message) {
  throw InputError(input_message(loc.file, loc.line, key, message));
}

// Refuses a step count beyond kMaxSteps, naming what set it: --until, dt or the stiffness.
void check_step_count(const Simulation& sim, std::optional<double> until, std::vector<std::string>& warnings) {
  const Scene& scene = sim.scene();
  const double end = until ? *until : scene.simulation.duration, dt = sim.dt();
  const double steps = end / dt;
  const std::string count = num(steps) + " steps of dt = " + num(dt) + " s for " + num(end) + " s";
  if (steps <= kManySteps) return;
  if (steps <= kMaxSteps) {
    warnings.push_back("warning: " + count + ": the run will take very long (check dt, kn and the duration)");
    return;
  }
  const std::string limit = ", beyond the " + num(kMaxSteps) + " steps a run can count (the limit)";
  if (until) throw InputError("--until " + num(*until) + " s asks for " + count + limit);
  if (scene.simulation.dt) refuse(loc_of(scene, "simulation.dt"), "dt", count + limit);
  const ContactOperator& c = scene.forces.contact;
  refuse(c.loc, "kn", "kn = " + num(c.config.kn) + " N/m sets dt: auto to " + num(dt) + " s: " + num(steps) +
                          " steps for " + num(end) + " s" + limit + "; lower kn or give dt");
}

void check_schedules(const Simulation& sim, std::optional<double> until, std::vector<std::string>& warnings) {
  const Scene& scene = sim.scene();
  const OutputSettings& o = scene.output;
  const double end = until ? *until : scene.simulation.duration, dt = sim.dt();
  for (auto [key, every] : {std::pair{"vtk_every", o.vtk_every}, {"csv_every", o.csv_every},
                            {"checkpoint_every", o.checkpoint_every}}) {
    if (!every) continue;
    const SourceLoc loc = loc_of(scene, std::string("output.") + key);
    if (!(*every >= kMinIntervalSteps * dt))
      refuse(loc, key, num(*every) + " s is below " + num(kMinIntervalSteps) + " x the time step dt = " + num(dt) +
                           " s (the limit; an interval below dt writes at every step)");
    if (*every < dt)
      warnings.push_back("warning: " + input_message(loc.file, loc.line, key, num(*every) +
                         " s is shorter than the time step dt = " + num(dt) + " s: written at every step"));
    if (*every > end)
      warnings.push_back("warning: " + input_message(loc.file, loc.line, key, num(*every) +
                                       " s is longer than the run (" + num(end) + " s): written at the start only"));
  }
}

void check_driver_motions(const Simulation& sim) {
  for (std::size_t j = 0; j < sim.drivers.size(); ++j) {
    const DriverSettings& d = sim.scene().drivers[j];
    const double turn = std::abs(d.motion.omega) * sim.dt();  // rad per step
    if (d.motion.rotates && !(turn <= kMaxTurnPerStep))
      refuse(d.loc, "omega", "driver '" + d.name + "' turns " + num(turn) + " rad in one step of dt = " +
                                 num(sim.dt()) + " s; the limit is " + num(kMaxTurnPerStep) + " rad per step");
  }
}

// Gravity that moves a body by its own size in one step from rest: no contact can catch it
// (an exponent typed wrong; 1e300 m/s^2 turned the state non-finite in two steps).
void check_gravity(const Simulation& sim) {
  const FieldSettings& f = sim.scene().forces;
  if (!f.gravity || sim.bodies.size() == 0) return;
  double r_min = std::numeric_limits<double>::infinity();  // m, the smallest bounding radius
  for (std::size_t b = 0; b < sim.bodies.size(); ++b)
    r_min = std::min(r_min, sim.shapes()[sim.bodies.shape[b]].bounding_radius * sim.bodies.scale[b]);
  const double g = f.gravity->stableNorm(), fall = g * sim.dt() * sim.dt();  // m/s^2 (norm() overflows at 1e300), m per step
  if (!(fall <= kMaxFallPerStep * r_min))
    refuse(f.gravity_loc, "gravity", num(g) + " m/s^2 moves a body " + num(fall) + " m in one step of dt = " +
                                         num(sim.dt()) + " s, more than " + num(kMaxFallPerStep) +
                                         " x the smallest body radius " + num(r_min) + " m (the limit)");
}

// A skin far beyond the bodies: every neighbour list reaches that far (memory and time grow
// with its cube).
void check_skin(const Simulation& sim, std::vector<std::string>& warnings) {
  const Scene& scene = sim.scene();
  if (!scene.simulation.skin || sim.bodies.size() == 0) return;
  double r_max = 0.0;  // m, the largest bounding radius
  for (std::size_t b = 0; b < sim.bodies.size(); ++b)
    r_max = std::max(r_max, sim.shapes()[sim.bodies.shape[b]].bounding_radius * sim.bodies.scale[b]);
  const double skin = *scene.simulation.skin;
  if (skin > 10.0 * r_max) {
    const SourceLoc loc = loc_of(scene, "simulation.skin");
    warnings.push_back("warning: " + input_message(loc.file, loc.line, "skin", num(skin) + " m is " +
        num(skin / r_max) + " x the largest body radius " + num(r_max) + " m: the neighbour lists reach that far "
        "(memory and time grow with its cube); the default is 0.1 x the smallest radius"));
  }
}

}  // namespace

std::vector<std::string> check_run_limits(const Simulation& sim, std::optional<double> until) {
  std::vector<std::string> warnings;
  check_step_count(sim, until, warnings);
  check_schedules(sim, until, warnings);
  check_driver_motions(sim);
  check_gravity(sim);
  check_skin(sim, warnings);
  return warnings;
}

}  // namespace polydem
