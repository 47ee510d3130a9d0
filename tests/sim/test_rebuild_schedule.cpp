// The rebuild trigger's pair test (RebuildTrigger::pair_exceeded) keeps the lists while one body
// alone moved past skin/2, and no contact is missed: the same bits as a rebuild every step.
#include <catch2/catch.hpp>

#include <omp.h>

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
};

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

void check_schedule(const Scene& scene, const ShapeLibrary& lib, const std::vector<BodySpec>& specs, int steps) {
  const Schedule trigger = run(scene, lib, specs, steps, false), every = run(scene, lib, specs, steps, true);
  INFO("rebuilds " << trigger.rebuilds << " of " << steps << " steps; kept past skin/2 " << trigger.kept_past_half);
  CHECK(trigger.hash == every.hash);  // no contact missed, none found late
  CHECK(every.rebuilds >= std::size_t(steps));
  CHECK(trigger.rebuilds < std::size_t(steps) / 5);
  CHECK(trigger.kept_past_half > 0);  // the pair test at work
}

}  // namespace

TEST_CASE("the pair trigger gives the bits of a rebuild every step: polyhedra and spheres", "[rebuild]") {
  Pile p;  // cubes and spheres thrown into each other, spinning
  check_schedule(p.scene, p.lib, p.specs, 1500);
}

TEST_CASE("the pair trigger gives the bits of a rebuild every step: spheres' points", "[rebuild]") {
  const LawCase rolling = kernel_law_cases()[3];  // rolling and cohesion: a band beyond touching
  const ThrownSpheres thrown = thrown_spheres(rolling.config, rolling.exact_step, 7, 0.0102);
  check_schedule(thrown.scene, thrown.lib, thrown.specs, 600);
}
