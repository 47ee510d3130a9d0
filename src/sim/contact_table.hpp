#pragma once
// The contact histories of a distributed run in global ids: the active slots every rank
// answers for (its body pairs whose lower body it owns, its driver pairs), gathered into one
// table laid out as read_active lays out a checkpoint's (pairs sorted, active slots only). The
// table is what checkpoints and output read on rank 0 and what each rank takes its share of
// at a rebuild, so contacts migrate with their bodies.
#include <cstdint>
#include <vector>

#include "contact/contact_lists.hpp"
#include "sim/local_store.hpp"

namespace polydem {

// One active slot with its pair in global ids (j: a body, or a driver index); on a pair's
// first slot, slot.pending holds the pair's pending energy (J, PairList::open_energy; zero on
// the others): it moves with the history.
struct TableSlot {
  std::uint32_t i, j;
  FeaturePair key;
  ContactSlot slot;
  SlotRecord record;
};

// The active slots of `list` (local indices of `store`) this rank answers for.
std::vector<TableSlot> active_slots(const PairList& list, const LocalStore& store, bool driver);

// The table of all ranks' slots: pairs in increasing (i, j), each pair's slots from one rank in key order.
PairList table_of(const std::vector<TableSlot>& slots);

// The table's pairs between local bodies (`held`: their global ids, increasing; a body's local
// index is its place there), in local indices: the histories a rebuild on this rank hands over.
PairList localise(const PairList& table, const std::vector<std::uint32_t>& held, bool driver);

}  // namespace polydem
