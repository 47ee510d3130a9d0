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

// Each owned body's measured contact work, in local order, from the pairs of every list it is
// in (either side; a driver pair's twice, as it has one side, and a pair's with a ghost twice,
// as this rank computes it whole): the weight of the next cut (sim/domain_cut.hpp).
struct OwnedWork {
  std::vector<std::uint32_t> candidates;  // its pairs' candidate feature pairs
  std::vector<std::uint32_t> contacts;    // its pairs' active sub-contacts at the last step
};
OwnedWork owned_work(const PairList& body_pairs, const PairList& driver_pairs, const LocalStore& store);

// The weight of the cut (instructions a step) of an owned body whose passes (kicks and drift,
// integrate.hpp's pass_weights) weigh `passes`, with `candidates` and `contacts` (OwnedWork).
// Fitted by least squares on each rank's counted instructions a step (callgrind, the binary's own
// functions, 2S less S steps) against the sums of these over its owned bodies: the box-fill and
// cubes pours from 0.1 s at -np 2 and 3 cut by the weights before (10 ranks: rms error 4.6%,
// largest 11%, the middle rank of 3; 4.5% on 10 more ranks cut by these). A free cube counts ~580,
// a candidate feature pair ~220 over its two bodies, a touching sub-contact ~940 more;
// pass_weights' counts (one process's pour) are twice what a rank's free bodies of the three
// rotation paths differ by.
struct CutWeight {
  static constexpr std::uint64_t kBodyStep = 446, kHalfCandidate = 108, kHalfContact = 470;
  static std::uint64_t of(float passes, std::uint32_t candidates, std::uint32_t contacts) {
    return std::uint64_t(passes) / 2 + kBodyStep + kHalfCandidate * candidates + kHalfContact * contacts;
  }
};

}  // namespace polydem
