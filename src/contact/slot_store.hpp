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

// One slot's state in a sparse list, what the pair loop reads and writes each step: the springs
// of ContactHistory (its fields by their names: the lanes take either) but the rolling moment, and
// the record's point, which the hand-over reads. 80 bytes, 4 states in 5 lines, walked as one
// stream; the rolling moment and the record's force and fn live apart (SlotStore), read only
// where the law rolls and written only at the steps whose contacts are read (issue 19: 136 B).
struct SlotState {
  Vec3 ft = Vec3::Zero();  // N, tangential spring force
  double fd = 0.0;         // N, dashpot force at the last step
  double gap = kNoGap;     // m, at the last step
  double weight = 1.0;     // -, patch share
  bool slipping = false;   // the tangential spring was capped
  bool rolling_slipping = false;  // the rolling spring was capped
  Vec3 point = Vec3::Zero();  // m, the contact point at the last step (SlotRecord::point)

  // The law's history, with the rolling moment `mr` (N m) kept apart.
  ContactHistory history(const Vec3& mr = Vec3::Zero()) const {
    return ContactHistory{ft, fd, gap, weight, slipping, rolling_slipping, mr};
  }
  // Takes h's springs but its rolling moment (the caller's to keep).
  void keep(const ContactHistory& h) {
    ft = h.ft;
    fd = h.fd;
    gap = h.gap;
    weight = h.weight;
    slipping = h.slipping;
    rolling_slipping = h.rolling_slipping;
  }
};
static_assert(sizeof(SlotState) == 80, "SlotState: the springs and the point, 4 states in 5 lines");

// The record's force and fn of a state, kept only while contacts are recorded.
struct SlotForce {
  Vec3 force = Vec3::Zero();  // N on i
  double fn = 0.0;            // N
};

// A slot with no state yet (PairList::state_of).
constexpr std::uint32_t kNoState = 0xffffffffu;

// States in chunks that never move once made, so a made state's address holds until reset;
// beside each chunk, the states' rolling moments (a store that rolls) and record forces (while
// recording), at the same index.
class SlotStore {
 public:
  SlotStore() = default;
  SlotStore(SlotStore&&) = default;
  SlotStore& operator=(SlotStore&&) = default;
  SlotStore(const SlotStore& other) { *this = other; }
  SlotStore& operator=(const SlotStore& other);
  // Room for `capacity` states (a list's slot count: each slot makes one at most), none made;
  // `rolls`: each keeps a rolling moment; `records`: each keeps its record's force.
  void reset(std::size_t capacity, bool rolls, bool records);
  // Keeps the record forces from now on (zero until written), or frees them.
  void set_records(bool on);
  // A zeroed state's index; safe from several threads at once.
  std::uint32_t make();
  SlotState& operator[](std::uint32_t g) { return chunks_[g >> kShift][g & kMask]; }
  const SlotState& operator[](std::uint32_t g) const { return chunks_[g >> kShift][g & kMask]; }
  bool rolls() const { return rolls_; }
  bool records() const { return records_; }
  Vec3& moment(std::uint32_t g) { return moments_[g >> kShift][g & kMask]; }  // N m; a store that rolls
  const Vec3& moment(std::uint32_t g) const { return moments_[g >> kShift][g & kMask]; }
  SlotForce& force(std::uint32_t g) { return forces_[g >> kShift][g & kMask]; }  // while recording
  const SlotForce& force(std::uint32_t g) const { return forces_[g >> kShift][g & kMask]; }
  std::size_t size() const { return made_; }

 private:
  static constexpr unsigned kShift = 8;  // 256 states a chunk (20 kB): what a small scene holds at least
  static constexpr std::uint32_t kMask = (1u << kShift) - 1;
  static constexpr std::size_t kChunk = std::size_t(kMask) + 1;
  // Sized by reset; a chunk is made with its first state. Pointers, not vectors: one load and a
  // scaled index to reach a state.
  std::vector<std::unique_ptr<SlotState[]>> chunks_;
  std::vector<std::unique_ptr<Vec3[]>> moments_;       // empty unless rolls_
  std::vector<std::unique_ptr<SlotForce[]>> forces_;   // empty unless records_
  std::uint32_t made_ = 0;
  bool rolls_ = false, records_ = false;
};

}  // namespace polydem
