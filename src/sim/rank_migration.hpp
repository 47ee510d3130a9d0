#pragma once
// A rebuild of a distributed run, point to point (issue 20): each rank sends the owned bodies
// whose centre left its box to their new owners, with the histories of their pairs, then
// each owned body to the ranks within the halo of it, as a ghost with its id. No rank reads
// another's bodies but these: the bytes are O(movers + surface), and the parcels' sizes go
// first, all to all (RankLink::deliver). The result is the one the gather of every body gave:
// the same owned bodies, ghosts and histories on each rank, so the same bits.
#include <cstdint>
#include <vector>

#include "polydem/bodies.hpp"
#include "sim/contact_table.hpp"
#include "sim/domain_cut.hpp"
#include "sim/ghost_plan.hpp"
#include "sim/local_store.hpp"
#include "sim/rank_link.hpp"

namespace polydem {

// What a rank holds after the migration: its bodies and the histories of their pairs.
struct Handover {
  LocalStore owned;                   // the owned bodies kept and landed, increasing id, no ghost
  std::vector<TableSlot> body_slots, driver_slots;  // global ids, a pair's slots from one rank (local_table)
};

// Sends each owned body of `store` (its ghosts current too) whose centre `cut` gives to
// another rank to it, with all the store holds of it, and each active slot (`body`: the pairs
// whose lower body this rank owns; `driver`: its driver pairs) to the new owners of its
// bodies (a collective).
Handover migrate(const RankLink& link, const DomainCut& cut, const LocalStore& store,
                 const std::vector<TableSlot>& body, const std::vector<TableSlot>& driver);

// The same from this rank's lists (local rows of `store`), without the table's round trip: a
// pair goes only to the new owners of its bodies that did not hold it (`was_owner`: each
// row's owner before, this rank for its owned rows; a listed ghost's is set), the others
// keeping their own copy (kept_table); Handover's slots are the ones that came (a collective).
Handover migrate_lists(const RankLink& link, const DomainCut& cut, const LocalStore& store, const PairList& body,
                       const PairList& driver, const std::vector<int>& was_owner);

// The plan of this rank's bodies in `store` (owned alone, increasing id): each goes, with its
// id, ghost state and constants, to the ranks whose box lies within `halo` of it; the ghosts
// that come join `store`, in id order (a collective). The same plan as plan_ghosts on every
// body's centre.
GhostPlan share_ghosts(const RankLink& link, const DomainCut& cut, double halo, LocalStore& store);

// The least of the ranks' `mine` that are not -1 (ids of failing bodies), or -1 (a collective).
long least_over_ranks(const RankLink& link, long mine);

}  // namespace polydem
