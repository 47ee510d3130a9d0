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
#include "sim/rank_link.hpp"

namespace polydem {

// What a rank holds after the migration: its bodies and the histories of their pairs.
struct Handover {
  std::vector<std::uint32_t> owned;              // increasing id
  PairList body_table, driver_table;             // global ids, as table_of lays them out
};

// Sends each of `owned` (increasing id, current in `bodies`) whose centre `cut` gives to
// another rank to it, and each active slot (`body`: the pairs whose lower body this rank owns,
// partners current in `bodies`; `driver`: its driver pairs) to the new owners of its bodies;
// writes the bodies that came into `bodies` (a collective).
Handover migrate(const RankLink& link, const DomainCut& cut, const std::vector<std::uint32_t>& owned,
                 const std::vector<TableSlot>& body, const std::vector<TableSlot>& driver, Bodies& bodies);

// The plan of this rank's `owned` bodies (current in `bodies`): each goes, with its id and
// ghost state, to the ranks whose box lies within `halo` of it; the ghosts that come are
// written into `bodies` (a collective). The same plan as plan_ghosts on every body's centre.
GhostPlan share_ghosts(const RankLink& link, const DomainCut& cut, std::vector<std::uint32_t> owned, double halo,
                       Bodies& bodies);

// The least of the ranks' `mine` that are not -1 (ids of failing bodies), or -1 (a collective).
long least_over_ranks(const RankLink& link, long mine);

}  // namespace polydem
