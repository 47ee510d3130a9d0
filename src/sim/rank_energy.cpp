#include "sim/rank_energy.hpp"

namespace polydem {

namespace {

std::uint64_t count_owned(const PairList& list, const LocalStore& store) {
  std::uint64_t contacts = 0;
  for (std::size_t k = 0; k < list.size(); ++k)
    if (!store.ghost[list.pairs[k].i]) contacts += list.touching[k];
  return contacts;
}

// Adds each pair's candidate feature pairs and active sub-contacts to both its bodies: twice
// to a driver pair's body, and to the owned body of a pair with a ghost (both ranks compute that
// pair whole).
void add_work(const PairList& list, bool driver, const std::vector<std::uint8_t>& ghost, OwnedWork& work) {
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::uint32_t slots = list.slot_begin[k + 1] - list.slot_begin[k], touching = list.touching[k];
    const std::uint32_t a = list.pairs[k].i, b = driver ? a : list.pairs[k].j;
    for (const std::uint32_t side : {ghost[a] ? b : a, ghost[b] ? a : b}) {
      work.candidates[side] += slots;
      work.contacts[side] += touching;
    }
  }
}

}  // namespace

EnergyParts sum_over_ranks(const RankLink& link, const ExactEnergy& mine) {
  const std::vector<std::uint64_t> words = link.sum(mine.words());  // integers: exact in any order
  return ExactEnergy::from_words(words, std::uint64_t(link.ranks())).value();
}

std::uint64_t owned_contacts(const PairList& body_pairs, const PairList& driver_pairs, const LocalStore& store) {
  return count_owned(body_pairs, store) + count_owned(driver_pairs, store);
}

OwnedWork owned_work(const PairList& body_pairs, const PairList& driver_pairs, const LocalStore& store) {
  const std::size_t n = store.global_id.size();
  OwnedWork work{std::vector<std::uint32_t>(n, 0), std::vector<std::uint32_t>(n, 0)};
  add_work(body_pairs, false, store.ghost, work);
  add_work(driver_pairs, true, store.ghost, work);
  OwnedWork owned;
  for (std::size_t k = 0; k < n; ++k) {
    if (store.ghost[k]) continue;
    owned.candidates.push_back(work.candidates[k]);
    owned.contacts.push_back(work.contacts[k]);
  }
  return owned;
}

}  // namespace polydem
