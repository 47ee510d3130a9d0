#include "sim/rank_energy.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>

#include "contact/pair_loop.hpp"

namespace polydem {

namespace {

// An owned body's pairs as body i of the one-process lists.
struct PairCounts {
  std::uint32_t id, body, driver;
};

// A pair's energy: the `ordinal`-th pair of body i in the body (driver 0) or driver list.
struct PairEnergy {
  std::uint32_t i, ordinal, driver;
  EnergyParts e;
};

bool zero(const EnergyParts& e) { return e.net == 0.0 && e.sliding == 0.0 && e.rolling == 0.0 && e.patch == 0.0; }

// Appends the energies of the pairs this rank answers for, counts them per owned body and
// returns the sub-contacts they hold.
std::size_t collect(const PairList& list, const LocalStore& store, bool driver, std::vector<std::uint32_t>& count,
                    std::vector<char>& bytes) {
  std::size_t contacts = 0;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::uint32_t i = list.pairs[k].i;
    if (store.ghost[i]) continue;
    contacts += list.touching[k];
    const std::uint32_t ordinal = count[i]++;
    if (!zero(list.pair_energy[k])) append_record(bytes, PairEnergy{store.global_id[i], ordinal, driver, list.pair_energy[k]});
  }
  return contacts;
}

// The blocks' sums in order, each summed in pair order (`at`: the pairs' places in the list).
void add_blocks(const std::vector<PairEnergy>& pairs, const std::vector<std::uint64_t>& at, EnergyParts& total) {
  std::vector<std::size_t> order(pairs.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return at[a] < at[b]; });
  EnergyParts block;
  std::uint64_t current = 0;
  bool open = false;
  for (std::size_t r : order) {
    const std::uint64_t b = at[r] / kPairBlock;
    if (open && b != current) {
      total += block;
      block = EnergyParts{};
    }
    current = b;
    open = true;
    block += pairs[r].e;
  }
  if (open) total += block;
}

}  // namespace

RankEnergy sum_rank_energy(const RankLink& link, const PairList& body_pairs, const PairList& driver_pairs,
                           const LocalStore& store, std::size_t n_bodies) {
  const std::size_t n_local = store.global_id.size();
  std::vector<std::uint32_t> n_body(n_local, 0), n_driver(n_local, 0);
  std::vector<char> energy_bytes, count_bytes;
  std::uint64_t contacts = collect(body_pairs, store, false, n_body, energy_bytes);
  contacts += collect(driver_pairs, store, true, n_driver, energy_bytes);
  for (std::size_t k = 0; k < n_local; ++k)
    if (!store.ghost[k]) append_record(count_bytes, PairCounts{store.global_id[k], n_body[k], n_driver[k]});
  // Where each body's pairs start in the one-process lists: the counts summed in id order.
  std::vector<std::uint64_t> start_body(n_bodies + 1, 0), start_driver(n_bodies + 1, 0);
  for (const PairCounts& c : records_of<PairCounts>(link.all_gather(count_bytes))) {
    start_body[c.id + 1] = c.body;
    start_driver[c.id + 1] = c.driver;
  }
  std::partial_sum(start_body.begin(), start_body.end(), start_body.begin());
  std::partial_sum(start_driver.begin(), start_driver.end(), start_driver.begin());
  const std::vector<PairEnergy> all = records_of<PairEnergy>(link.all_gather(energy_bytes));
  std::vector<PairEnergy> body, driver;
  std::vector<std::uint64_t> at_body, at_driver;
  for (const PairEnergy& p : all) {
    (p.driver ? driver : body).push_back(p);
    (p.driver ? at_driver : at_body).push_back((p.driver ? start_driver : start_body)[p.i] + p.ordinal);
  }
  RankEnergy out;
  add_blocks(body, at_body, out.energy);
  add_blocks(driver, at_driver, out.energy);
  std::vector<char> mine;
  append_record(mine, contacts);
  for (std::uint64_t c : records_of<std::uint64_t>(link.all_gather(mine))) out.contacts += c;
  return out;
}

}  // namespace polydem
