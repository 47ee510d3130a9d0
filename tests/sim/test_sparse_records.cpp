// A sparse list's state (SlotState, 80 bytes) keeps the springs and the contact point; the rolling
// moment lives beside it where the law rolls, and the record's force and fn only while the steps'
// contacts are recorded. The split must be invisible: a run that records only its last step ends
// in the checkpoint of one that records every step, and the moments ride through steps, rebuilds
// and the hand-over between a pair's slots.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include "contact/list_build.hpp"
#include "contact/pair_kernel.hpp"
#include "sim/checkpoint.hpp"
#include "pile.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

// The determinism tests' 150 cubes and spheres thrown into a walled box (pile.hpp), with a
// rolling law: contacts roll, begin and end, and the lists are rebuilt while they do.
struct RollingPile : Pile {
  RollingPile() {
    for (ContactParams* p : {&scene.forces.contact.config, &scene.forces.contact.config_driver}) {
      p->kr = 1e-4;  // N m/rad
      p->mur = 0.05;
    }
  }
};

std::string checkpoint_bytes(Simulation& sim, const std::string& path) {
  write_checkpoint(path, sim, OutputProgress{});
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// N m, the largest rolling moment of `list`'s active slots.
double largest_moment(const PairList& list) {
  double m = 0.0;
  for (std::uint32_t s = 0; s < list.slot_count(); ++s)
    if (list.active[s]) m = std::max(m, list.history(s).mr.norm());
  return m;
}

// A sparse rolling list of one pair and `n` slots, recording or not.
PairList sparse_pair(std::uint32_t n, bool recording) {
  PairList list;
  list.sparse = true;
  list.rolls = true;
  list.recording = recording;
  list.pairs = {{0, 1}};
  list.slot_begin = {0, n};
  for (std::uint32_t b = 0; b < n; ++b) list.features.push_back(FeaturePair{PairType{}, 0, b});
  size_slots(list);
  list.resize_results();
  return list;
}

ContactHistory rolling_history(double tag) {
  ContactHistory h;
  h.ft = Vec3(tag, 0, 0);     // N
  h.gap = -1e-6;              // m
  h.mr = Vec3(0, 0, tag);     // N m
  h.rolling_slipping = true;
  return h;
}

}  // namespace

TEST_CASE("a list of polyhedra records its forces only at the steps whose state is written", "[checkpoint][memory]") {
  const RollingPile t;
  const std::string path =
      (std::filesystem::temp_directory_path() / ("polydem_test_sparse_" + std::to_string(::getpid()) + ".bin")).string();
  constexpr int kSteps = 1500;
  Simulation always(t.scene, t.lib, t.specs), at_end(t.scene, t.lib, t.specs);
  for (int s = 0; s < kSteps; ++s) always.step();
  at_end.engine().record_contacts(false);
  for (int s = 0; s + 1 < kSteps; ++s) {
    at_end.step();
    REQUIRE(!at_end.engine().body_pairs().states.records());  // no force kept between written steps
    REQUIRE(!at_end.engine().driver_pairs().states.records());
  }
  at_end.engine().record_contacts(true);
  at_end.step();
  const PairList& list = at_end.engine().body_pairs();
  INFO("t = " << always.time() << " rebuilds " << always.engine().stats().rebuilds);
  REQUIRE(list.sparse);
  REQUIRE(list.states.rolls());
  REQUIRE(always.engine().stats().rebuilds > 2);
  REQUIRE(always.engine().stats().contacts > 5);
  CHECK(largest_moment(list) > 0.0);  // moments kept from step to step (each starts at 0)
  CHECK(largest_moment(at_end.engine().driver_pairs()) > 0.0);
  double fn = 0.0;  // N, the recorded normal forces at the written step
  for (std::uint32_t s = 0; s < list.slot_count(); ++s)
    if (list.active[s]) fn += list.record(s).fn;
  CHECK(fn > 0.0);
  // The records' points, forces and fn and the moments are all in the checkpoint.
  const std::string recorded_always = checkpoint_bytes(always, path);
  CHECK(checkpoint_bytes(at_end, path) == recorded_always);
  std::filesystem::remove(path);
}

TEST_CASE("a sparse list's rolling moment and point ride with its springs through a rebuild") {
  PairList old = sparse_pair(3, false);
  old.set_history(1, rolling_history(2.0));
  old.set_record(1, SlotRecord{Vec3(1, 2, 3), Vec3(4, 5, 6), 7.0});
  old.active[1] = 1;
  old.touching[0] = 1;
  CHECK(old.record(1).point == Vec3(1, 2, 3));
  CHECK(old.record(1).fn == 0.0);  // not recording: the point alone kept
  PairList fresh = sparse_pair(2, true);
  carry_history(active_part(old), fresh);
  REQUIRE(fresh.active[1]);
  const ContactHistory h = fresh.history(1);
  CHECK(h.mr == Vec3(0, 0, 2.0));
  CHECK(h.ft == Vec3(2.0, 0, 0));
  CHECK(h.rolling_slipping);
  CHECK(fresh.record(1).point == Vec3(1, 2, 3));
  fresh.set_record(1, SlotRecord{Vec3(1, 2, 3), Vec3(4, 5, 6), 7.0});
  CHECK(fresh.record(1).force == Vec3(4, 5, 6));  // recording: force and fn kept too
  CHECK(fresh.record(1).fn == 7.0);
}

TEST_CASE("a sparse list hands an ended contact's rolling moment to the nearest new one") {
  PairList list = sparse_pair(3, false);
  list.set_history(0, rolling_history(3.0));  // ended this step, at (0, 0, 0)
  list.set_record(0, SlotRecord{});
  list.active[0] = 1;
  std::vector<FoundContact> found(1);
  found[0].slot = 2;  // starts now, near slot 0's point
  found[0].geometry.point = Vec3(1e-6, 0, 0);
  std::vector<std::uint8_t> now_on;
  hand_over_history(list, 0, 3, 1, found, now_on);
  CHECK(list.history(2).mr == Vec3(0, 0, 3.0));
  CHECK(list.history(2).ft == Vec3(3.0, 0, 0));
  CHECK(list.history(0).mr == Vec3::Zero());  // given once
}
