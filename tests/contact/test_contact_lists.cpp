// A rebuild keeps only the old lists' active slots (active_part) to hand their history over:
// the new lists must come out as they did from the whole old lists.
#include <catch2/catch.hpp>

#include <cstring>

#include "contact/contact_lists.hpp"
#include "contact/list_build.hpp"

using namespace polydem;

namespace {

// A list from per-pair runs of (feature b, active?), each slot's history marked by its index.
PairList make_list(const std::vector<BodyPair>& pairs, const std::vector<std::vector<std::pair<std::uint32_t, bool>>>& runs) {
  PairList list;
  list.pairs = pairs;
  list.slot_begin.push_back(0);
  for (const auto& run : runs) {
    for (const auto& [b, on] : run) {
      list.features.push_back(FeaturePair{PairType{}, 0, b});
      ContactSlot slot;
      slot.history.fd = double(list.slots.size()) + 1.0;  // N, a tag
      list.slots.push_back(slot);
      list.records.push_back(SlotRecord{Vec3::Zero(), Vec3::Zero(), slot.history.fd});  // N, the same tag
      list.active.push_back(on ? 1 : 0);
    }
    list.slot_begin.push_back(std::uint32_t(list.slots.size()));
  }
  list.resize_results();
  return list;
}

// A sparse list with the same layout, no slot touched yet.
PairList make_sparse(const std::vector<BodyPair>& pairs, const std::vector<std::vector<std::uint32_t>>& runs) {
  PairList list;
  list.sparse = true;
  list.pairs = pairs;
  list.slot_begin.push_back(0);
  for (const auto& run : runs) {
    for (std::uint32_t b : run) list.features.push_back(FeaturePair{PairType{}, 0, b});
    list.slot_begin.push_back(std::uint32_t(list.features.size()));
  }
  size_slots(list);
  return list;
}

}  // namespace

TEST_CASE("a sparse list holds states for the carried slots alone, then for each slot at its first touch") {
  const PairList old = make_list({{0, 1}, {1, 2}}, {{{1, true}, {4, false}}, {{3, true}, {5, true}}});
  PairList fresh = make_sparse({{0, 1}, {1, 2}}, {{1, 2, 4, 8}, {3, 5, 7}});
  REQUIRE(fresh.states.size() == 0);
  carry_history(active_part(old), fresh);
  CHECK(fresh.states.size() == 3);  // of 7 slots: the three carried
  CHECK(fresh.history(0).fd == 1.0);  // old slot 0's tag
  CHECK(fresh.history(4).fd == 3.0);
  CHECK(fresh.history(5).fd == 4.0);
  CHECK(fresh.record(5).fn == 4.0);   // its record with it
  CHECK(fresh.state_of[1] == kNoState);
  const SlotState& made = fresh.touch(6);  // a new contact: a zero state
  CHECK(fresh.states.size() == 4);
  CHECK(made.gap == kNoGap);
  CHECK(fresh.record(6).fn == 0.0);
  CHECK(&fresh.touch(6) == &made);  // made once
}

TEST_CASE("a sparse list's states made by several threads at once are distinct and stay put") {
  const std::uint32_t n = 5000;  // slots, over many chunks
  PairList list = make_sparse({{0, 1}}, {std::vector<std::uint32_t>(n, 0)});
  std::vector<const SlotState*> at(n);
#pragma omp parallel for schedule(dynamic, 7)
  for (std::uint32_t s = 0; s < n; ++s) {
    SlotState& state = list.touch(s);
    state.fd = double(s);  // N, a tag
    at[s] = &state;
  }
  CHECK(list.states.size() == n);
  std::size_t wrong = 0;
  for (std::uint32_t s = 0; s < n; ++s) wrong += !(&list.touch(s) == at[s] && list.history(s).fd == double(s));
  CHECK(wrong == 0);
}

TEST_CASE("active_part keeps the active slots with their pairs, keys and state, in order") {
  const PairList old = make_list({{0, 1}, {0, 2}, {1, 2}}, {{{1, true}, {4, false}}, {{2, false}}, {{3, false}, {5, true}, {6, true}}});
  const PairList kept = active_part(old);
  REQUIRE(kept.pairs.size() == 2);  // (0, 2) had no active slot
  CHECK((kept.pairs[0].i == 0 && kept.pairs[0].j == 1));
  CHECK((kept.pairs[1].i == 1 && kept.pairs[1].j == 2));
  REQUIRE(kept.slot_begin == std::vector<std::uint32_t>{0, 1, 3});
  CHECK(kept.features[0].b == 1);
  CHECK(kept.features[1].b == 5);
  CHECK(kept.features[2].b == 6);
  CHECK(kept.slots[0].history.fd == 1.0);  // old slot 0
  CHECK(kept.slots[2].history.fd == 6.0);  // old slot 5
  CHECK(kept.records[2].fn == 6.0);  // its record with it
  CHECK(kept.active == std::vector<std::uint8_t>{1, 1, 1});
}

TEST_CASE("carry_history from the active part gives the new list the whole old list gives") {
  const PairList old = make_list({{0, 1}, {0, 2}, {1, 2}, {2, 3}},
                                 {{{1, true}, {4, false}}, {{2, true}}, {{3, false}, {5, true}, {6, true}}, {{7, false}}});
  // The new list: (0, 2) left range, (1, 3) came in, key 5 of (1, 2) is gone, key 9 new.
  const PairList fresh = make_list({{0, 1}, {1, 2}, {1, 3}, {2, 3}}, {{{1, false}, {4, false}}, {{3, false}, {6, false}, {9, false}}, {{2, false}}, {{7, false}}});
  PairList from_whole = fresh, from_part = fresh;
  carry_history(old, from_whole);
  carry_history(active_part(old), from_part);
  CHECK(from_part.active == from_whole.active);
  CHECK(from_part.touching == from_whole.touching);
  for (std::size_t s = 0; s < fresh.slots.size(); ++s) {
    CHECK(from_part.slots[s].history.fd == from_whole.slots[s].history.fd);
    CHECK(from_part.records[s].fn == from_whole.records[s].fn);
  }
  CHECK(from_whole.active == std::vector<std::uint8_t>{1, 0, 0, 1, 0, 0, 0});  // keys 1 and 6 carried
  CHECK(from_whole.touching == std::vector<std::uint16_t>{1, 1, 0, 0});
}

// A pair's pending energy is the ledger's open sum of its contact: it moves with the history
// wherever the pair still touches, and the pairs whose sum found no touching pair are named
// (the engine adds those to the exact sum at once).
TEST_CASE("carry_history moves a touching pair's pending energy with its history") {
  PairList old = make_list({{0, 1}, {0, 2}, {1, 2}}, {{{1, true}}, {{2, true}}, {{3, true}, {5, true}}});
  for (std::size_t k = 0; k < old.size(); ++k) old.open_energy(k) = EnergyParts{0.1 * double(k + 1), 0.01, 0.0, 0.0};  // J
  // The new list: (0, 2) left range, (1, 2) kept key 5 only, (0, 1) lost its key.
  PairList fresh = make_list({{0, 1}, {1, 2}, {1, 3}}, {{{4, false}}, {{5, false}}, {{2, false}}});
  const std::vector<std::uint32_t> left = carry_history(active_part(old), fresh);
  CHECK(left == std::vector<std::uint32_t>{0, 1});  // (0, 1) touches no more, (0, 2) is gone
  CHECK(fresh.open_energy(0).net == 0.0);
  CHECK(fresh.open_energy(1).net == old.open_energy(2).net);
  CHECK(fresh.open_energy(1).sliding == old.open_energy(2).sliding);
  CHECK(fresh.open_energy(2).net == 0.0);
}

TEST_CASE("a sphere slot starts a cache line, so a contact without rolling reads two lines of it") {
  constexpr std::uintptr_t kLine = 64;  // bytes
  PairList list = make_list({{0, 1}, {0, 2}, {1, 2}}, {{{0, true}}, {{0, false}}, {{0, true}}});
  for (const ContactSlot& slot : list.slots) CHECK(reinterpret_cast<std::uintptr_t>(&slot) % kLine == 0);
  // The bytes a steady contact touches: the pending energy, then the history up to its slipping flag.
  const ContactSlot& slot = list.slots[0];
  const auto begin = reinterpret_cast<std::uintptr_t>(&slot);
  const auto end = reinterpret_cast<std::uintptr_t>(&slot.history.slipping) + 1;
  CHECK(reinterpret_cast<std::uintptr_t>(&slot.pending) == begin);
  CHECK((end - 1) / kLine - begin / kLine + 1 == 2);
}
