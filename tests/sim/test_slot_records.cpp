// A sphere list keeps its contacts' points and forces (PairList::records) only for the steps
// whose state is written: the checkpoint after such a step is the one of a run that kept them
// at every step, byte for byte, and between those steps the list holds none.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include "sim/checkpoint.hpp"
#include "sim/contact_table.hpp"
#include "sim_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

// 64 spheres touching in a 4 x 4 x 4 lattice on the floor, shaken by random velocities:
// contacts begin and end and the lists are rebuilt while they do.
struct SphereThrow {
  Scene scene = base_scene(law(1e5, 0.5, 0.4, 1e5), true, Vec3(0, 0, -9.807));
  ShapeLibrary lib = library({sphere_shape(0.005)});
  std::vector<BodySpec> specs;
  SphereThrow() {
    std::mt19937_64 rng(11);
    auto u = [&] { return double(rng() >> 11) * 0x1.0p-53 - 0.5; };
    for (int k = 0; k < 64; ++k)
      specs.push_back(body("sphere", Vec3(0.01 * (k % 4), 0.01 * ((k / 4) % 4), 0.005 + 0.01 * (k / 16)),
                           0.1 * Vec3(u(), u(), u())));
  }
};

std::string checkpoint_bytes(Simulation& sim, const std::string& path) {
  write_checkpoint(path, sim, OutputProgress{});
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("a sphere list records its contacts only for the steps whose state is written", "[checkpoint][memory]") {
  const SphereThrow t;
  const std::string path =
      (std::filesystem::temp_directory_path() / ("polydem_test_records_" + std::to_string(::getpid()) + ".bin")).string();
  constexpr int kSteps = 1000;
  Simulation always(t.scene, t.lib, t.specs), at_end(t.scene, t.lib, t.specs);
  for (int s = 0; s < kSteps; ++s) always.step();
  at_end.engine().record_contacts(false);
  for (int s = 0; s + 1 < kSteps; ++s) {
    at_end.step();
    REQUIRE(at_end.engine().body_pairs().records.capacity() == 0);  // nothing held between written steps
    REQUIRE(!at_end.engine().driver_pairs().states.records());  // drivers keep their points alone (the hand-over's)
  }
  at_end.engine().record_contacts(true);
  at_end.step();
  INFO("t = " << always.time() << " rebuilds " << always.engine().stats().rebuilds);
  REQUIRE(always.engine().stats().rebuilds > 2);
  REQUIRE(always.engine().stats().contacts > 10);
  const PairList& list = at_end.engine().body_pairs();
  REQUIRE(list.records.size() == list.slots.size());
  const std::string recorded_always = checkpoint_bytes(always, path);
  CHECK(checkpoint_bytes(at_end, path) == recorded_always);
  std::filesystem::remove(path);
}

TEST_CASE("a contact table without records still hands its histories to a rank", "[checkpoint][memory]") {
  // A distributed sphere run between outputs: the table read from a checkpoint had its records
  // freed by record_contacts(false) before the forced rebuild localises it.
  PairList table;
  table.pairs = {{0, 2}, {1, 2}};
  table.slot_begin = {0, 1, 2};
  table.features = {{PairType::vertex_vertex, 0, 0}, {PairType::vertex_vertex, 0, 0}};
  table.slots.resize(2);
  table.slots[0].history.ft = Vec3(1, 0, 0);  // N
  table.slots[1].history.ft = Vec3(0, 2, 0);
  table.active = {1, 1};
  table.resize_results();
  table.set_recording(false);
  const PairList mine = localise(table, {1, 2}, false);  // body 0 elsewhere: one pair is local
  REQUIRE(mine.size() == 1);
  CHECK((mine.pairs[0].i == 0 && mine.pairs[0].j == 1));
  CHECK(mine.slots[0].history.ft == Vec3(0, 2, 0));
  CHECK(mine.records.size() == mine.slots.size());
}
