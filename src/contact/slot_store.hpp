#pragma once
// The states of a sparse list's slots (contact_lists.hpp): a slot's history and record exist
// from its first touch after a rebuild, not for every candidate (98% of a cube pile's
// candidates never touch). States are made by the pair loop's threads and never move until
// the next rebuild, which starts a new store with the active slots' states alone.
#include <cstdint>
#include <memory>
#include <vector>

#include "contact/law.hpp"

namespace polydem {

// What an active slot's contact was at the last step: contact output and checkpoints read it,
// and a polyhedron pair hands an ended contact's history to the nearest new one by its point.
struct SlotRecord {
  Vec3 point = Vec3::Zero();  // m, contact point
  Vec3 force = Vec3::Zero();  // N on i
  double fn = 0.0;            // N, normal force
};

// One slot's state in a sparse list: its springs, carried while its key lives, and its record.
struct SlotState {
  ContactHistory history;
  SlotRecord record;
};

// A slot with no state yet (PairList::state_of).
constexpr std::uint32_t kNoState = 0xffffffffu;

// States in chunks that never move once made, so a made state's address holds until reset.
class SlotStore {
 public:
  SlotStore() = default;
  SlotStore(SlotStore&&) = default;
  SlotStore& operator=(SlotStore&&) = default;
  SlotStore(const SlotStore& other) { *this = other; }
  SlotStore& operator=(const SlotStore& other);
  // Room for `capacity` states (a list's slot count: each slot makes one at most), none made.
  void reset(std::size_t capacity);
  // A zeroed state's index; safe from several threads at once.
  std::uint32_t make();
  SlotState& operator[](std::uint32_t g) { return chunks_[g >> kShift][g & kMask]; }
  const SlotState& operator[](std::uint32_t g) const { return chunks_[g >> kShift][g & kMask]; }
  std::size_t size() const { return made_; }

 private:
  static constexpr unsigned kShift = 8;  // 256 states a chunk (35 kB): what a small scene holds at least
  static constexpr std::uint32_t kMask = (1u << kShift) - 1;
  // Sized by reset; a chunk is made with its first state. Pointers, not vectors: one load and a
  // scaled index to reach a state.
  std::vector<std::unique_ptr<SlotState[]>> chunks_;
  std::uint32_t made_ = 0;
};

}  // namespace polydem
