#pragma once
// A distributed run resumed from checkpoint pieces (issue 20): each rank reads a share of the
// pieces (sim/checkpoint_pieces.hpp) and holds their bodies and contacts, its "landed" share,
// until the first step's contact stage cuts the domain and sends them to their owners, point
// to point. No rank lays out the whole state: a rank holds O(its pieces) and, after the
// landing, what a rebuild leaves it (the same owned bodies, ghosts and histories, so the bits).
#include <cstdint>
#include <vector>

#include "contact/exact_sum.hpp"
#include "sim/contact_table.hpp"
#include "sim/domain_cut.hpp"
#include "sim/local_store.hpp"
#include "sim/rank_link.hpp"
#include "sim/rank_migration.hpp"

namespace polydem {

// What a rank read of a checkpoint: the bodies of its pieces (all owned, increasing id, their
// constants from Bodies), the active slots of the pairs whose lower body is among them (body
// and driver pairs, global ids, each pair's pending energy on its first slot) and the pieces'
// ended contacts (J).
struct LandedShare {
  LocalStore store;
  std::vector<TableSlot> body, driver;
  ExactEnergy flushed;
};

// Sends each body of `share` to its owner under `cut` (all its store row) with its driver
// slots (migrate), then each body slot to the owner of its lower body i and to the ranks that
// hold i as a ghost (within `halo` of their box: where the pair's other body may be owned); a
// rank keeps the slots that name a body it owns (a collective). After the ghosts are shared,
// the lists hold what migrate's would for the same bodies and slots.
Handover land_share(const RankLink& link, const DomainCut& cut, double halo, const LandedShare& share);

}  // namespace polydem
