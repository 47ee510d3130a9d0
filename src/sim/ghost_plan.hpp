#pragma once
// Who sends which body to whom between two rebuilds of a distributed run: from the cut and
// every body's centre at the rebuild, each rank's owned bodies, its ghosts (bodies within the
// halo of its box, owned elsewhere), and the point-to-point lists that keep them current: the
// owned bodies each other rank holds as ghosts, and the ghosts each other rank owns. Rank p's
// send list to q is, entry for entry, q's receive list from p (both in increasing id), so a
// parcel is bare state in an order both sides know. Boxes of a bisection today; periodic
// images can later be ghosts of the same lists.
#include <cstdint>
#include <vector>

#include "neighbor/body_pair.hpp"
#include "sim/domain_cut.hpp"

namespace polydem {

struct GhostPlan {
  std::vector<std::uint32_t> local;   // owned and ghost bodies, increasing id
  std::vector<std::uint8_t> ghost;    // per local body, 1 for a ghost
  std::vector<std::uint32_t> owned;   // increasing id
  std::vector<std::vector<std::uint32_t>> send;     // per rank: owned bodies it holds as ghosts
  std::vector<std::vector<std::uint32_t>> receive;  // per rank: ghosts it owns
};

// Rank p's plan for the centres `x` cut by `cut` (one part per rank), ghosts within `halo`.
GhostPlan plan_ghosts(const DomainCut& cut, int p, const std::vector<Vec3>& x, double halo);

// The bodies a step's motion parcels need carry, from a rank's lists: a ghost is read only by
// its pairs with owned bodies, and a pair across the cut is listed alike by the owners of both
// its bodies (the same rule on the same state), so what rank q reads of p's bodies between
// rebuilds is p's owned bodies paired with q's ghosts. `pairs`: local rows, one owned at least;
// `owner`: per local row, the rank owning a ghost, -1 for an owned row. Per rank: the owned
// rows paired with its ghosts (`send`) and its ghosts paired with an owned row (`receive`), both
// increasing; a ghost in no pair stays as it was at the rebuild, read by no one until the next.
struct PairedRows {
  std::vector<std::vector<std::uint32_t>> send, receive;
};
PairedRows paired_across(const std::vector<BodyPair>& pairs, const std::vector<int>& owner, int ranks);

}  // namespace polydem
