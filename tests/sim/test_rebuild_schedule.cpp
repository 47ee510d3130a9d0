// The rebuild trigger's pair test (RebuildTrigger::pair_exceeded) keeps the lists while one body
// alone moved past skin/2, and no contact is missed: the same bits as a rebuild every step; with
// per-body skins (skin_max) too.
#include <catch2/catch.hpp>

#include <omp.h>

#include <algorithm>

#include "law_cases.hpp"
#include "neighbor/rebuild_trigger.hpp"
#include "pile.hpp"
#include "sim_fixtures.hpp"
#include "state_hash.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

struct Schedule {
  std::uint64_t hash = 0;        // the state and energies after the steps
  std::size_t rebuilds = 0;
  std::size_t kept_past_half = 0;  // steps kept while some body had moved more than skin/2 from the build
  double first_skin = 0.0, largest_skin = 0.0;  // m, the largest body skin after the first step, and in all
};

// m, the largest of the engine's body skins (0 when it keeps none: the scene's skin each).
double largest(const std::vector<double>& skins) {
  return skins.empty() ? 0.0 : *std::max_element(skins.begin(), skins.end());
}

// `steps` steps at 2 threads, the lists rebuilt at every step (`every_step`) or as the trigger asks.
Schedule run(const Scene& scene, const ShapeLibrary& lib, const std::vector<BodySpec>& specs, int steps,
             bool every_step) {
  omp_set_num_threads(2);
  Simulation sim(scene, lib, specs);
  RebuildTrigger half;  // the skin/2 test of centres alone, marked where the engine rebuilt
  const double skin = sim.engine().skin();  // m
  const std::vector<double> centres(sim.bodies.size(), 0.0);
  Schedule out;
  for (int s = 0; s < steps; ++s) {
    if (every_step) sim.engine().force_rebuild();
    const std::size_t before = sim.engine().stats().rebuilds;
    sim.step();
    if (s == 0) out.first_skin = largest(sim.engine().body_skins());
    out.largest_skin = std::max(out.largest_skin, largest(sim.engine().body_skins()));
    if (sim.engine().stats().rebuilds != before)
      half.mark_built(sim.bodies.position, sim.bodies.orientation);
    else if (half.needs_rebuild(sim.bodies.position, sim.bodies.orientation, centres, skin))
      ++out.kept_past_half;
  }
  const double energies[] = {sim.energy().kinetic, sim.energy().dissipated, sim.ledger.driver_work};  // J
  out.hash = fnv(state_hash(sim.bodies), energies, sizeof(energies));
  out.rebuilds = sim.engine().stats().rebuilds;
  return out;
}

// The scene with every body on its skin (skin_max = skin: the per-body skins off).
Scene uniform_skin(const Scene& scene, const ShapeLibrary& lib, const std::vector<BodySpec>& specs) {
  Scene uniform = scene;
  uniform.simulation.skin_max = Simulation(scene, lib, specs).engine().skin();  // m, the scene's (auto)
  return uniform;
}

void check_schedule(const Scene& given, const ShapeLibrary& lib, const std::vector<BodySpec>& specs, int steps) {
  const Scene scene = uniform_skin(given, lib, specs);
  const Schedule trigger = run(scene, lib, specs, steps, false), every = run(scene, lib, specs, steps, true);
  INFO("rebuilds " << trigger.rebuilds << " of " << steps << " steps; kept past skin/2 " << trigger.kept_past_half);
  CHECK(trigger.hash == every.hash);  // no contact missed, none found late
  CHECK(every.rebuilds >= std::size_t(steps));
  CHECK(trigger.rebuilds < std::size_t(steps) / 5);
  CHECK(trigger.kept_past_half > 0);  // the pair test at work
}

// Per-body skins up to `factor` times the scene's: the bits of a rebuild every step at the scene's
// skin, with fewer rebuilds than the scene's skin alone. Returns the per-body run's schedule.
Schedule check_own_skins(const Scene& scene, const ShapeLibrary& lib, const std::vector<BodySpec>& specs, int steps,
                         double factor) {
  const Scene uniform = uniform_skin(scene, lib, specs);
  const double skin = *uniform.simulation.skin_max;  // m, the scene's (auto)
  Scene own = scene;
  own.simulation.skin_max = factor * skin;
  const Schedule skins = run(own, lib, specs, steps, false), fixed = run(uniform, lib, specs, steps, false),
                 every = run(uniform, lib, specs, steps, true);
  INFO("rebuilds " << skins.rebuilds << " against " << fixed.rebuilds << " at the scene's skin, of " << steps << " steps");
  CHECK(skins.hash == every.hash);  // no contact missed, none found late
  CHECK(fixed.largest_skin == 0.0);  // skin_max = skin: no body skins
  CHECK(skins.largest_skin > skin);
  CHECK(skins.largest_skin <= factor * skin);
  CHECK(skins.rebuilds < fixed.rebuilds);
  return skins;
}

}  // namespace

TEST_CASE("per-body skins give the bits of a rebuild every step: a spinning pile", "[rebuild]") {
  Pile p;  // cubes and spheres thrown into each other, spinning: skins up to 4 x the scene's
  check_own_skins(p.scene, p.lib, p.specs, 1500, 4.0);
}

TEST_CASE("per-body skins give the bits of a rebuild every step: bodies at rest that start to fall", "[rebuild]") {
  Pile p;
  for (BodySpec& b : p.specs) b.velocity = b.angular_velocity = Vec3::Zero();
  p.scene.forces.gravity = Vec3(0, 0, -500.0);  // m/s^2: from rest to ~1 m/s within the run's steps
  const Schedule s = check_own_skins(p.scene, p.lib, p.specs, 1500, 4.0);
  CHECK(s.first_skin == 0.0);  // at rest at the first build: the scene's skin each (none kept); they sped up past it
}

TEST_CASE("the pair trigger gives the bits of a rebuild every step: polyhedra and spheres", "[rebuild]") {
  Pile p;  // cubes and spheres thrown into each other, spinning
  check_schedule(p.scene, p.lib, p.specs, 1500);
}

TEST_CASE("the pair trigger gives the bits of a rebuild every step: spheres' points", "[rebuild]") {
  const LawCase rolling = kernel_law_cases()[3];  // rolling and cohesion: a band beyond touching
  const ThrownSpheres thrown = thrown_spheres(rolling.config, rolling.exact_step, 7, 0.0102);
  check_schedule(thrown.scene, thrown.lib, thrown.specs, 600);
}

TEST_CASE("a skin_max below the automatic skin is refused, naming the key", "[rebuild][errors]") {
  Pile p;  // no skin given: 10% of the smallest bounding radius
  const double skin = Simulation(p.scene, p.lib, p.specs).engine().skin();  // m
  p.scene.simulation.skin_max = 0.5 * skin;
  CHECK_THROWS_AS(Simulation(p.scene, p.lib, p.specs), InputError);
  CHECK_THROWS_WITH(Simulation(p.scene, p.lib, p.specs), Catch::Contains("skin_max") && Catch::Contains("automatic skin"));
  p.scene.simulation.skin_max = skin;  // equal: allowed (no body gets more)
  CHECK_NOTHROW(Simulation(p.scene, p.lib, p.specs));
}

TEST_CASE("per-body skins are on by default, up to 4 times the scene's skin", "[rebuild]") {
  Pile p;  // spinning cubes and spheres: some body fast enough for a skin of its own
  const double skin = *uniform_skin(p.scene, p.lib, p.specs).simulation.skin_max;  // m
  const Schedule s = run(p.scene, p.lib, p.specs, 300, false);
  CHECK(s.largest_skin > skin);
  CHECK(s.largest_skin <= 4.0 * skin);
}
