#pragma once
// A distributed step's energy and contact count, the bits of one process: each rank sums the
// energies of the pairs it answers for exactly (contact/exact_sum.hpp) and the ranks add their
// sums as integers (one all-reduce of a few kB a step, whatever the pair count), so the total
// is the one-process total for any rank count.
#include <cstdint>
#include <vector>

#include "contact/contact_lists.hpp"
#include "sim/local_store.hpp"
#include "sim/rank_link.hpp"

namespace polydem {

struct RankEnergy {
  EnergyParts energy;        // J, this step, all ranks' pairs
  std::size_t contacts = 0;  // active sub-contacts, all ranks' pairs
};

// This rank's pairs' energy and contacts, every rank's summed (a collective): its body pairs
// whose lower body it owns and its driver pairs (their body is owned).
RankEnergy total_energy(const RankLink& link, const PairList& body_pairs, const PairList& driver_pairs,
                        const LocalStore& store);

// Each owned body's measured contact work, in local order: the candidate feature pairs of
// every pair it is in (either side; a driver pair's twice, as it has one side), the weight of
// the next cut (sim/domain_cut.hpp).
std::vector<std::uint32_t> owned_work(const PairList& body_pairs, const PairList& driver_pairs,
                                      const LocalStore& store);

}  // namespace polydem
