#pragma once
// A distributed run's energy ledger and contact count, the bits of one process: each rank
// flushes the pending energies of the pairs it answers for into an exact sum
// (contact/exact_sum.hpp; ContactEngine::take_energy) and the ranks add their sums as integers
// (one all-reduce of a few kB, at the ledger's closes only), so the total is the one-process
// total for any rank count.
#include <cstdint>
#include <vector>

#include "contact/contact_lists.hpp"
#include "contact/exact_sum.hpp"
#include "sim/local_store.hpp"
#include "sim/rank_link.hpp"

namespace polydem {

// Every rank's `mine` summed, rounded once: the same on every rank (a collective).
EnergyParts sum_over_ranks(const RankLink& link, const ExactEnergy& mine);

// Active sub-contacts this step of the pairs this rank answers for: its body pairs whose lower
// body it owns and its driver pairs (their body is owned).
std::uint64_t owned_contacts(const PairList& body_pairs, const PairList& driver_pairs, const LocalStore& store);

// Each owned body's measured contact work, in local order: the candidate feature pairs of
// every pair it is in (either side; a driver pair's twice, as it has one side, and a pair's
// with a ghost twice, as this rank computes it whole), the weight of the next cut
// (sim/domain_cut.hpp).
std::vector<std::uint32_t> owned_work(const PairList& body_pairs, const PairList& driver_pairs,
                                      const LocalStore& store);

}  // namespace polydem
