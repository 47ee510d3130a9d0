// Repeatability: the same run gives the same bits for 1 and 2 threads, run to run, and across
// a checkpoint and resume. Also: the contact set each step equals the brute-force one.
#include <catch2/catch.hpp>

#include <omp.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <tuple>

#include "geometry/shadowing.hpp"
#include "law_cases.hpp"
#include "sim/checkpoint.hpp"
#include "old_formats.hpp"
#include "pile.hpp"
#include "sim_fixtures.hpp"
#include "state_hash.hpp"
#include "../unique_temp_dir.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

std::uint64_t run_pile(int threads, int steps, double damp_tangential = 0.0) {
  omp_set_num_threads(threads);
  Pile p(damp_tangential);
  Simulation sim(p.scene, p.lib, p.specs);
  for (int s = 0; s < steps; ++s) sim.step();
  omp_set_num_threads(2);
  return state_hash(sim.bodies);
}

// Steps with the closing kick left open but every `closed`-th step (then closed), at 2 threads:
// the state and the energies after `steps`, hashed.
std::uint64_t run_open(const Scene& scene, const ShapeLibrary& lib, const std::vector<BodySpec>& specs, int steps,
                       int closed) {
  omp_set_num_threads(2);
  Simulation sim(scene, lib, specs);
  for (int s = 1; s <= steps; ++s) sim.step(s % closed != 0);
  sim.close_step();
  const double energies[] = {sim.energy().kinetic, sim.energy().dissipated, sim.ledger.driver_work};  // J
  return fnv(state_hash(sim.bodies), energies, sizeof(energies));
}

// The same with each open step's next one begun behind its walk (open_steps_follow), at `threads`;
// `ahead` counts the steps that ran it, `turned` those whose walk left a turn (ContactEngine::take_turns).
std::uint64_t run_ahead(const Scene& scene, const ShapeLibrary& lib, const std::vector<BodySpec>& specs, int steps,
                        int threads, int& ahead, int* turned = nullptr) {
  omp_set_num_threads(threads);
  Simulation sim(scene, lib, specs);
  sim.open_steps_follow(true);
  for (int s = 1; s <= steps; ++s) {
    sim.step(s < steps);
    ahead += sim.ran_ahead();
    if (turned) *turned += sim.engine().turns_left();
  }
  omp_set_num_threads(2);
  const double energies[] = {sim.energy().kinetic, sim.energy().dissipated, sim.ledger.driver_work};  // J
  return fnv(state_hash(sim.bodies), energies, sizeof(energies));
}

}  // namespace

TEST_CASE("the next step's joined pass run behind the walk keeps the bits", "[determinism]") {
  const LawCase rolling = kernel_law_cases()[3];
  const ThrownSpheres thrown = thrown_spheres(rolling.config, rolling.exact_step, 7, 0.0102);  // 300 spheres, walls
  const std::uint64_t closed = run_open(thrown.scene, thrown.lib, thrown.specs, 600, 1);
  for (int threads : {1, 2, 3}) {
    int ahead = 0;
    CHECK(run_ahead(thrown.scene, thrown.lib, thrown.specs, 600, threads, ahead) == closed);
    CHECK(ahead == 599);  // every step but the last
  }
}

TEST_CASE("the next step's joined pass and poses run behind a box walk keep the bits", "[determinism]") {
  const Pile cubes(0.0, true, 300);  // 300 cubes thrown at each other and at the walls: a team, rebuilds, turns
  const std::uint64_t closed = run_open(cubes.scene, cubes.lib, cubes.specs, 1500, 1);
  for (int threads : {1, 2, 3}) {
    int ahead = 0, turned = 0;
    CHECK(run_ahead(cubes.scene, cubes.lib, cubes.specs, 1500, threads, ahead, &turned) == closed);
    CHECK(ahead == 1499 - 14);  // every step but the last and those before a ledger closes (Simulation::trails_walk)
    CHECK(turned > 0);  // a walk that left a turn moved no more bodies behind it
  }
}

TEST_CASE("a closing kick joined to the next step's opening pass keeps the bits", "[determinism]") {
  Pile p;  // polyhedra on walls
  const std::uint64_t pile = run_open(p.scene, p.lib, p.specs, 1500, 1);
  CHECK(pile == run_open(p.scene, p.lib, p.specs, 1500, 7));
  CHECK(pile == run_open(p.scene, p.lib, p.specs, 1500, 1500));
  const LawCase rolling = kernel_law_cases()[3];  // rolling and cohesion, the exact step
  const ThrownSpheres thrown = thrown_spheres(rolling.config, rolling.exact_step, 7, 0.0102);  // 300: a team, rebuilds
  const std::uint64_t spheres = run_open(thrown.scene, thrown.lib, thrown.specs, 600, 1);
  CHECK(spheres == run_open(thrown.scene, thrown.lib, thrown.specs, 600, 7));
  CHECK(spheres == run_open(thrown.scene, thrown.lib, thrown.specs, 600, 600));
}

TEST_CASE("final state is bitwise identical for 1 and 2 threads and run to run", "[determinism]") {
  const std::uint64_t one = run_pile(1, 3000), two = run_pile(2, 3000), again = run_pile(2, 3000);
  CHECK(one == two);
  CHECK(two == again);
  const std::uint64_t damped = run_pile(1, 3000, 0.3);
  CHECK(damped == run_pile(2, 3000, 0.3));
  CHECK(damped != one);  // the tangential dashpot acts
}

TEST_CASE("a resumed checkpoint continues bit for bit", "[checkpoint]") {
  const UniqueTempDir dir("checkpoint");
  const std::string path = (dir.path / "state.bin").string();
  Pile p;
  Simulation first(p.scene, p.lib, p.specs);
  for (int s = 0; s < 1500; ++s) first.step();
  write_checkpoint(path, first, OutputProgress{});
  first.engine().force_rebuild();  // as the runner does at every checkpoint
  for (int s = 0; s < 1500; ++s) first.step();

  Simulation resumed(p.scene, p.lib, p.specs);
  OutputProgress progress;
  read_checkpoint(path, resumed, progress);
  CHECK(resumed.step_index() == 1500);
  for (int s = 0; s < 1500; ++s) resumed.step();
  CHECK(state_hash(first.bodies) == state_hash(resumed.bodies));
}

TEST_CASE("a format-04 checkpoint (no dissipation shares) still resumes bit for bit", "[checkpoint]") {
  const UniqueTempDir dir("checkpoint04");
  const std::string path05 = (dir.path / "state06.bin").string(), path04 = (dir.path / "state04.bin").string();
  Pile p;
  Simulation first(p.scene, p.lib, p.specs);
  for (int s = 0; s < 1500; ++s) first.step();
  write_checkpoint(path05, first, OutputProgress{});
  // Format 04: magic "PDCKPT04", the payload of format 05 (old_formats.hpp) and the ledger
  // without its three shares (the last 24 of its 72 bytes).
  std::ifstream in(path05, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  bytes = "PDCKPT04" + as_format05(bytes).substr(8);
  const std::size_t shares = 8 + 8 + 8 + sizeof(EnergyLedger) - 3 * sizeof(double);  // magic, step, dt, ledger prefix
  bytes.erase(shares, 3 * sizeof(double));
  std::ofstream(path04, std::ios::binary) << bytes;
  first.engine().force_rebuild();
  for (int s = 0; s < 1500; ++s) first.step();

  Simulation resumed(p.scene, p.lib, p.specs);
  OutputProgress progress;
  read_checkpoint(path04, resumed, progress);
  CHECK(resumed.ledger.sliding == 0.0);  // unknown before the resume: counted as dashpot
  for (int s = 0; s < 1500; ++s) resumed.step();
  CHECK(state_hash(first.bodies) == state_hash(resumed.bodies));
  CHECK(resumed.energy().dissipated == first.energy().dissipated);
  CHECK(resumed.ledger.sliding < first.ledger.sliding);  // only what slid after the resume
}

TEST_CASE("the contact set each step equals the brute-force set", "[verlet]") {
  Pile p;
  Simulation sim(p.scene, p.lib, p.specs);
  using Key = std::tuple<std::uint32_t, std::uint32_t, int, int, int>;
  std::size_t compared = 0, steps_with_contacts = 0;
  for (int s = 0; s < 3000; ++s) {
    sim.step();
    if (s % 10) continue;
    std::set<Key> engine, brute;
    const PairList& list = sim.engine().body_pairs();
    for (std::size_t k = 0; k < list.size(); ++k)
      for (std::uint32_t q = list.slot_begin[k]; q < list.slot_begin[k + 1]; ++q)
        if (list.active[q])
          engine.insert({list.pairs[k].i, list.pairs[k].j, int(list.features[q].type), list.features[q].a,
                         list.features[q].b});
    const Bodies& b = sim.bodies;
    std::vector<std::vector<Vec3>> verts(b.size());
    std::vector<PosedBody> posed(b.size());
    for (std::size_t i = 0; i < b.size(); ++i) {
      const Shape& sh = sim.shapes()[b.shape[i]];
      verts[i].resize(sh.vertices.size());
      pose_vertices(sh, b.scale[i], b.position[i], b.orientation[i], verts[i].data());
      posed[i] = PosedBody{&sh, verts[i].data(), b.orientation[i].toRotationMatrix(), b.position[i], sh.radius * b.scale[i],
                            b.scale[i]};
    }
    for (std::uint32_t i = 0; i < b.size(); ++i)
      for (std::uint32_t j = i + 1; j < b.size(); ++j) {
        const double reach = sim.shapes()[b.shape[i]].bounding_radius + sim.shapes()[b.shape[j]].bounding_radius;
        if ((b.position[i] - b.position[j]).norm() >= reach) continue;  // bounding spheres apart: no contact possible
        // Every feature pair, less the duplicates a vertex-face contact shadows (SPEC boundary rule).
        const auto all = brute_force_contacts(posed[i], posed[j]);
        std::vector<std::uint8_t> drop(all.size());
        mark_shadowed(all.size(), [&](std::size_t k) { return all[k].first; }, [&](std::size_t k) { return all[k].second.gap; },
                      posed[i].radius + posed[j].radius, drop.data());
        for (std::size_t k = 0; k < all.size(); ++k)
          if (!drop[k]) brute.insert({i, j, int(all[k].first.type), all[k].first.a, all[k].first.b});
      }
    REQUIRE(engine == brute);
    compared += brute.size();
    steps_with_contacts += !brute.empty();
  }
  INFO("contacts compared " << compared);
  CHECK(compared > 500);  // the pile really is dense (~1000 contacts over the checks)
  CHECK(steps_with_contacts > 100);
}
