#pragma once
// A distributed step's energy and contact count, the bits of one process: each pair's energy
// is summed into its block of kPairBlock pairs of the one-process list (a pair's place there
// follows from every body's pair count, as the lists are sorted by body) and the blocks in
// order, as ContactEngine::compute does on one process.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "contact/contact_lists.hpp"
#include "sim/local_store.hpp"

namespace polydem {

// An owned body's pairs as body i of the one-process lists, and its measured contact work:
// the candidate feature pairs of every pair it is in (either side; a driver pair's twice, as
// it has one side), the weight of the next cut (sim/domain_cut.hpp).
struct PairCounts {
  std::uint32_t id, body, driver, work;
};

// A pair's energy: the `ordinal`-th pair of body i in the body (driver 0) or driver list.
struct PairEnergy {
  std::uint32_t i, ordinal, driver;
  EnergyParts e;
};

// What a rank sends of the pairs it answers for: its body pairs whose lower body it owns and
// its driver pairs (their body is owned). Pairs of zero energy are left out (they add exact zeros).
struct EnergyShare {
  std::vector<PairCounts> counts;  // per owned body
  std::vector<PairEnergy> pairs;
  std::uint64_t contacts = 0;      // active sub-contacts
};

struct RankEnergy {
  EnergyParts energy;        // J, this step, all ranks' pairs
  std::size_t contacts = 0;  // active sub-contacts, all ranks' pairs
};

// `counts`: with the owned bodies' counts and work (at rebuilds: they hold until the next).
EnergyShare energy_share(const PairList& body_pairs, const PairList& driver_pairs, const LocalStore& store,
                         bool counts);

// The totals from every rank's share, the same on every rank; `n_bodies` in the scene.
RankEnergy total_energy(const std::vector<EnergyShare>& shares, std::size_t n_bodies);

}  // namespace polydem
