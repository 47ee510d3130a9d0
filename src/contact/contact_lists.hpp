#pragma once
// Verlet lists of interacting pairs and the contact state that persists between steps.
//
// A pair is (body i, partner j): another body (i < j) or a driver. Each pair owns a run of
// slots, one per candidate feature pair found at the last rebuild, sorted by key. A slot
// carries its contact's history (tangential spring, rolling moment) while the key lives, so
// history needs no lookup between rebuilds; rebuilds hand it over by key. A sparse list keeps
// a state for the slots that touched since the rebuild only (slot_store.hpp).
#include <cstdint>
#include <vector>

#include "contact/law.hpp"
#include "contact/slot_store.hpp"
#include "geometry/features.hpp"
#include "neighbor/broad_phase.hpp"
#include "polydem/release.hpp"

namespace polydem {

// A dense list's state of one slot (the sphere fast path's one slot a pair), touched only
// where a contact is (or was) active; the slot's key lives apart in PairList::features, the
// array every step scans. Its last gap is history.gap. A pair's first slot holds the pair's
// pending energy (PairList::open_energy; zero on the others): read with the history where the
// pair touches, not streamed for the pairs that do not (32 bytes a listed pair, issue 19).
// The pending energy first: a contact without rolling touches bytes [0, 81) (ContactHistory's
// mr last), two lines of 64 bytes on a slot that starts a line, where a 112-byte stride spread
// them over 2.25 on average (issue 19; 16 bytes a slot more memory).
struct alignas(64) ContactSlot {
  EnergyParts pending;        // J, on a pair's first slot: its energies since the ledger closed
  ContactHistory history;     // N, N m: springs carried while the key lives
  ContactSlot() = default;
  ContactSlot(const ContactHistory& h, const EnergyParts& e) : pending(e), history(h) {}  // the history first, as it reads
};
static_assert(sizeof(ContactSlot) == 128, "ContactSlot: the history and a pair's pending energy, a line's multiple");

// Packs a contact key of one pair into an integer that orders slots deterministically.
inline std::uint64_t feature_key(FeaturePair f) {
  return (std::uint64_t(f.type) << 48) | (std::uint64_t(f.a) << 32) | std::uint64_t(f.b);
}

// Pairs per block of the pair loop (a thread takes a block at a time; its contacts are counted
// together; the threads' cut of the body pairs falls between blocks): a sphere list's. 64: the
// lanes pair contacts within a block, and a sphere pair is ~87 instructions.
constexpr std::size_t kPairBlock = 64;
// A polyhedron list's (~1,000 instructions a pair): 64 pairs, halved down to 16 while the list
// has fewer than 32 blocks. A pour's ~300 body pairs made 5 blocks of 64, and the walk's cut
// between two left one thread 1.3 times the other's walk; but each block sets its loop up again
// (~200 instructions: the settled cubes' 7,742 pairs in blocks of 16 cost +0.5%). Issue 19.
constexpr std::size_t kSmallestPairBlock = 16;
inline std::size_t polyhedron_pair_block(std::size_t pairs) {
  constexpr std::size_t kFewestBlocks = 32;
  std::size_t block = kPairBlock;
  while (block > kSmallestPairBlock && pairs < kFewestBlocks * block) block /= 2;
  return block;
}

struct PairList {
  std::vector<BodyPair> pairs;             // sorted by (i, j)
  std::size_t block = kPairBlock;          // pairs a block (the loops' unit of work)
  std::vector<std::uint32_t> slot_begin;   // slots of pair k: [slot_begin[k], slot_begin[k+1])
  std::vector<FeaturePair> features;       // per slot: the key (type, feature of i, feature of j); hot
  // Sparse (lists of polyhedra and drivers): a slot's state is states[state_of[s]], made at its
  // first touch since the build (kNoState before), always with its record's point (the hand-over
  // reads it), its force and fn while `recording`. Dense (spheres, and lists read from checkpoints
  // and tables): `slots` and, when `recording`, `records` per slot. Both record only at the steps
  // whose state is written (ContactEngine::record_contacts). Only active slots' state is read.
  bool sparse = false;
  bool rolls = false;  // a sparse list's states keep rolling moments (its law rolls)
  std::vector<std::uint32_t> state_of;
  SlotStore states;
  std::vector<ContactSlot> slots;
  std::vector<SlotRecord> records;
  bool recording = true;
  std::vector<std::uint8_t> active;        // per slot: in contact at the last step (compact: scanned)
  std::vector<float> slot_gap;             // m, per slot: gap when the list was built (lower bound)
  std::vector<double> gap_at_build;        // m, per pair: smallest feature gap when the list was built
  // Per pair, this step: force on i (N), torques on i and on j about their centres (N m).
  std::vector<Vec3> force_i, torque_i, torque_j;
  std::vector<std::uint16_t> touching;     // active sub-contacts of the pair at the last step
  std::vector<std::uint32_t> block_contacts;  // per block, its active sub-contacts this step
  // J, per pair of a sparse list (a dense list's are in its slots): see open_energy.
  std::vector<EnergyParts> pending;
  std::vector<std::uint8_t> block_ended;   // per block: a pair's contact ended this step (its pending is due)
  std::vector<LinearStep> linear_steps;    // per pair: the exact step's k', c' (exact_linear.hpp), set at first use

  std::size_t size() const { return pairs.size(); }
  std::size_t blocks() const { return (pairs.size() + block - 1) / block; }
  std::size_t slot_count() const { return features.size(); }
  // Slot s's state; a sparse list's is made here at the slot's first touch (from the one
  // thread that steps its pair).
  SlotState& touch(std::uint32_t s) {
    std::uint32_t& g = state_of[s];
    if (g == kNoState) g = states.make();
    return states[g];
  }
  // Slot s's history (an active slot's, in a sparse list), and its setter (made on first use).
  ContactHistory history(std::uint32_t s) const {
    if (!sparse) return slots[s].history;
    const std::uint32_t g = state_of[s];
    return states[g].history(states.rolls() ? states.moment(g) : Vec3::Zero());
  }
  void set_history(std::uint32_t s, const ContactHistory& h) {
    if (!sparse) {
      slots[s].history = h;
      return;
    }
    touch(s).keep(h);
    if (states.rolls()) states.moment(state_of[s]) = h.mr;
  }
  // J, pair k's energies summed in step order since the ledger last closed or its contact began
  // (ContactEngine::flush_ended): the same bits whatever thread or rank steps the pair and
  // whenever the lists rebuild (carried with the history; zero while not touching). A dense
  // list keeps it on the pair's first slot; a pair with no slot has none (has_slots).
  bool has_slots(std::size_t k) const { return slot_begin[k] != slot_begin[k + 1]; }
  EnergyParts& open_energy(std::size_t k) { return sparse ? pending[k] : slots[slot_begin[k]].pending; }
  const EnergyParts& open_energy(std::size_t k) const { return sparse ? pending[k] : slots[slot_begin[k]].pending; }
  // Pair k's pending energy, or none (+0) for a pair without a slot.
  EnergyParts open_energy_or_zero(std::size_t k) const {
    if (sparse) return k < pending.size() ? pending[k] : EnergyParts{};
    return has_slots(k) ? slots[slot_begin[k]].pending : EnergyParts{};
  }
  // Slot s's record (an active slot's; force and fn +0 while not recording), and its setter (a
  // sparse list keeps the point always, a dense one all only while recording).
  SlotRecord record(std::uint32_t s) const {
    if (!sparse) return recording ? records.at(s) : SlotRecord{};
    const std::uint32_t g = state_of[s];
    if (!recording) return SlotRecord{states[g].point, Vec3::Zero(), 0.0};
    return SlotRecord{states[g].point, states.force(g).force, states.force(g).fn};
  }
  void set_record(std::uint32_t s, const SlotRecord& r) {
    if (!sparse) {
      if (recording) records.at(s) = r;
      return;
    }
    touch(s).point = r.point;
    if (recording) states.force(state_of[s]) = SlotForce{r.force, r.fn};
  }
  void set_recording(bool on) {
    recording = on;
    if (sparse) states.set_records(on);  // 32 bytes a state freed between output steps
    else if (on) records.resize(slots.size());
    else release(records);  // freed: a sphere's 56 bytes a slot between output steps
  }
  // pair_steps false: no linear_steps (a kernel that keeps one k', c' for all pairs).
  void resize_results(bool pair_steps = true) {
    force_i.assign(pairs.size(), Vec3::Zero());
    torque_i.assign(pairs.size(), Vec3::Zero());
    torque_j.assign(pairs.size(), Vec3::Zero());
    touching.assign(pairs.size(), 0);
    linear_steps.assign(pair_steps ? pairs.size() : 0, LinearStep{});
    // Sized here, with the list: the pair loop then needs no `omp single` (a barrier) each step.
    pending.assign(sparse ? pairs.size() : 0, EnergyParts{});
    block_contacts.assign(blocks(), 0);
    block_ended.assign(block_contacts.size(), 0);
  }
};

// Per body b of `n_bodies`, its pairs [begin[b], begin[b + 1]) in `pairs` sorted by body i (a
// driver list): the fixed order of each body's driver terms, whatever the thread count.
std::vector<std::uint32_t> pairs_by_body(const std::vector<BodyPair>& pairs, std::size_t n_bodies);

// The pairs of `list` with an active slot, and those slots alone, with the pairs' pending
// energies: all carry_history reads of an old list, held instead of it while the new one is
// built (a rebuild's memory peak).
PairList active_part(const PairList& list);

// Copies the history of every active slot of `old_list` into the slot with the same pair
// and key in `fresh` (both sorted) and counts it in the pair's `touching`, and the pair's pending
// energy with it. Keys absent from `fresh` end their contact. Returns the old pairs whose
// pending energy found no touching pair in `fresh` (the caller's to count).
std::vector<std::uint32_t> carry_history(const PairList& old_list, PairList& fresh);

}  // namespace polydem
