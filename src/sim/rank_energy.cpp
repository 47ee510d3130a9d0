#include "sim/rank_energy.hpp"

namespace polydem {

namespace {

// Adds the energies and sub-contacts of the pairs of `list` whose lower body this rank owns.
void collect(const PairList& list, const LocalStore& store, ExactEnergy& energy, std::uint64_t& contacts) {
  for (std::size_t k = 0; k < list.size(); ++k) {
    if (store.ghost[list.pairs[k].i]) continue;
    contacts += list.touching[k];
    energy.add(list.pair_energy[k]);
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

RankEnergy total_energy(const RankLink& link, const PairList& body_pairs, const PairList& driver_pairs,
                        const LocalStore& store) {
  ExactEnergy mine;  // J
  std::uint64_t contacts = 0;
  collect(body_pairs, store, mine, contacts);
  collect(driver_pairs, store, mine, contacts);
  std::vector<std::uint64_t> words = mine.words();
  words.push_back(contacts);
  words = link.sum(words);  // integers: exact in any order
  const std::uint64_t total_contacts = words.back();
  words.pop_back();
  return {ExactEnergy::from_words(words, std::uint64_t(link.ranks())).value(), std::size_t(total_contacts)};
}

std::vector<std::uint32_t> owned_work(const PairList& body_pairs, const PairList& driver_pairs,
                                      const LocalStore& store) {
  std::vector<std::uint32_t> work(store.global_id.size(), 0), owned;
  add_work(body_pairs, false, work);
  add_work(driver_pairs, true, work);
  for (std::size_t k = 0; k < work.size(); ++k)
    if (!store.ghost[k]) owned.push_back(work[k]);
  return owned;
}

}  // namespace polydem
