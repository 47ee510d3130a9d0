#pragma once
// A distributed step's energy and contact count, the bits of one process: each pair's energy
// is summed into its block of kPairBlock pairs of the one-process list (a pair's place there
// follows from every body's pair count, as the lists are sorted by body) and the blocks in
// order, as ContactEngine::compute does on one process.
#include <cstddef>

#include "contact/contact_lists.hpp"
#include "sim/local_store.hpp"
#include "sim/rank_link.hpp"

namespace polydem {

struct RankEnergy {
  EnergyParts energy;        // J, this step, all ranks' pairs
  std::size_t contacts = 0;  // active sub-contacts, all ranks' pairs
};

// A collective: every rank gets the totals. The pairs a rank answers for are its body pairs
// whose lower body it owns and its driver pairs (their body is owned); `n_bodies` in the scene.
RankEnergy sum_rank_energy(const RankLink& link, const PairList& body_pairs, const PairList& driver_pairs,
                           const LocalStore& store, std::size_t n_bodies);

}  // namespace polydem
