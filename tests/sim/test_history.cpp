// Contact history hand-over (SPEC "Contact geometry"): a key that lives keeps its springs; a
// vertex sliding from a face onto an edge changes key, and the new contact inherits the
// spring of the nearest contact of the same pair that just ended instead of starting at zero.
#include <catch2/catch.hpp>

#include "contact/pair_kernel.hpp"

using namespace polydem;

namespace {

PairList one_pair_list(std::vector<FeaturePair> keys) {
  PairList list;
  list.pairs = {{0, 1}};
  list.slot_begin = {0, std::uint32_t(keys.size())};
  list.features = keys;
  list.slots.resize(keys.size());
  list.records.resize(keys.size());
  list.active.assign(keys.size(), 0);
  list.resize_results();
  return list;
}

FoundContact found(std::uint32_t slot, Vec3 point) {
  return {slot, ContactPoint{Vec3::UnitZ(), point, -1e-6}};
}

}  // namespace

TEST_CASE("a vertex sliding from a face onto an edge keeps its tangential spring", "[history]") {
  PairList list = one_pair_list({{PairType::vertex_edge, 0, 3}, {PairType::vertex_face, 0, 1}});
  ContactSlot& face = list.slots[1];
  list.active[1] = 1;
  list.records[1].point = {0.01, 0, 0};
  face.history.ft = {0.2, -0.1, 0};
  face.history.mr = {0, 0, 1e-4};
  std::vector<std::uint8_t> scratch;
  hand_over_history(list, 0, 2, 1, {found(0, {0.0101, 0, 0})}, scratch);  // now on the edge
  CHECK(list.active[0]);
  CHECK(list.slots[0].history.ft == Vec3(0.2, -0.1, 0));
  CHECK(list.slots[0].history.mr == Vec3(0, 0, 1e-4));
  CHECK_FALSE(list.active[1]);
  CHECK(list.slots[1].history.ft == Vec3::Zero());
}

TEST_CASE("a living key keeps its history and a fresh contact starts from zero", "[history]") {
  PairList list = one_pair_list({{PairType::vertex_face, 0, 1}, {PairType::vertex_face, 1, 1}});
  list.active[0] = 1;
  list.slots[0].history.ft = {0.3, 0, 0};
  std::vector<std::uint8_t> scratch;
  hand_over_history(list, 0, 2, 1, {found(0, {0, 0, 0}), found(1, {0.01, 0, 0})}, scratch);
  CHECK(list.slots[0].history.ft == Vec3(0.3, 0, 0));  // same key: kept
  CHECK(list.slots[1].history.ft == Vec3::Zero());      // nothing ended: starts from zero
  hand_over_history(list, 0, 2, 2, {}, scratch);           // separation resets everything
  CHECK_FALSE(list.active[0]);
  CHECK(list.slots[0].history.ft == Vec3::Zero());
}

TEST_CASE("each ended contact hands its history over once, to the nearest new one", "[history]") {
  PairList list = one_pair_list({{PairType::vertex_face, 0, 1}, {PairType::vertex_edge, 0, 2},
                                 {PairType::vertex_edge, 1, 2}});
  list.active[0] = 1;
  list.records[0].point = {0, 0, 0};
  list.slots[0].history.ft = {1, 0, 0};
  std::vector<std::uint8_t> scratch;
  hand_over_history(list, 0, 3, 1, {found(1, {0.05, 0, 0}), found(2, {0.001, 0, 0})}, scratch);
  CHECK(list.slots[2].history.ft == Vec3(1, 0, 0));  // nearest
  CHECK(list.slots[1].history.ft == Vec3::Zero());
}
