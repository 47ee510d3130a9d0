#include "sim/rank_energy.hpp"

#include <algorithm>
#include <numeric>

#include "contact/pair_loop.hpp"

namespace polydem {

namespace {

bool zero(const EnergyParts& e) { return e.net == 0.0 && e.sliding == 0.0 && e.rolling == 0.0 && e.patch == 0.0; }

// Adds the energies of the pairs this rank answers for and counts them per owned body.
void collect(const PairList& list, const LocalStore& store, bool driver, std::vector<std::uint32_t>& count,
             EnergyShare& share) {
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::uint32_t i = list.pairs[k].i;
    if (store.ghost[i]) continue;
    share.contacts += list.touching[k];
    const std::uint32_t ordinal = count[i]++;
    if (!zero(list.pair_energy[k])) share.pairs.push_back({store.global_id[i], ordinal, driver, list.pair_energy[k]});
  }
}

// The blocks' sums in order, each summed in pair order over the whole one-process list
// (`at`: the pairs' places in it; the pairs left out add exact zeros): O(pairs), no sort.
void add_blocks(const std::vector<PairEnergy>& pairs, const std::vector<std::uint64_t>& at, std::uint64_t n_pairs,
                EnergyParts& total) {
  std::vector<EnergyParts> list(n_pairs);
  for (std::size_t r = 0; r < pairs.size(); ++r) list[at[r]] = pairs[r].e;
  for (std::uint64_t b = 0; b < n_pairs; b += kPairBlock) {
    EnergyParts block;
    for (std::uint64_t k = b; k < std::min<std::uint64_t>(n_pairs, b + kPairBlock); ++k) block += list[k];
    total += block;
  }
}

// Adds each pair's candidate feature pairs to both its bodies (twice to a driver pair's body).
void add_work(const PairList& list, bool driver, std::vector<std::uint32_t>& work) {
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::uint32_t slots = list.slot_begin[k + 1] - list.slot_begin[k];
    work[list.pairs[k].i] += slots;
    work[driver ? list.pairs[k].i : list.pairs[k].j] += slots;
  }
}

}  // namespace

EnergyShare energy_share(const PairList& body_pairs, const PairList& driver_pairs, const LocalStore& store,
                         bool counts) {
  const std::size_t n_local = store.global_id.size();
  std::vector<std::uint32_t> n_body(n_local, 0), n_driver(n_local, 0), work(n_local, 0);
  EnergyShare share;
  collect(body_pairs, store, false, n_body, share);
  collect(driver_pairs, store, true, n_driver, share);
  if (!counts) return share;
  add_work(body_pairs, false, work);
  add_work(driver_pairs, true, work);
  for (std::size_t k = 0; k < n_local; ++k)
    if (!store.ghost[k]) share.counts.push_back({store.global_id[k], n_body[k], n_driver[k], work[k]});
  return share;
}

RankEnergy total_energy(const std::vector<EnergyShare>& shares, std::size_t n_bodies) {
  // Where each body's pairs start in the one-process lists: the counts summed in id order.
  std::vector<std::uint64_t> start_body(n_bodies + 1, 0), start_driver(n_bodies + 1, 0);
  RankEnergy out;
  for (const EnergyShare& s : shares) {
    for (const PairCounts& c : s.counts) {
      start_body[c.id + 1] = c.body;
      start_driver[c.id + 1] = c.driver;
    }
    out.contacts += s.contacts;
  }
  std::partial_sum(start_body.begin(), start_body.end(), start_body.begin());
  std::partial_sum(start_driver.begin(), start_driver.end(), start_driver.begin());
  std::vector<PairEnergy> body, driver;
  std::vector<std::uint64_t> at_body, at_driver;
  for (const EnergyShare& s : shares)
    for (const PairEnergy& p : s.pairs) {
      (p.driver ? driver : body).push_back(p);
      (p.driver ? at_driver : at_body).push_back((p.driver ? start_driver : start_body)[p.i] + p.ordinal);
    }
  add_blocks(body, at_body, start_body.back(), out.energy);
  add_blocks(driver, at_driver, start_driver.back(), out.energy);
  return out;
}

}  // namespace polydem
