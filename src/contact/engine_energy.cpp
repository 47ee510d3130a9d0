// ContactEngine's share of the energy ledger: the pairs' pending energies flushed into the
// exact sum of ended contacts, and the elastic energy stored in the active slots.
#include <algorithm>
#include <utility>

#include "contact/contact_engine.hpp"

namespace polydem {

// Each pair's pending energy enters the exact sum whole (in no set order: the sum is exact), so
// a flush splits no pair's step-ordered sum but where every run splits it (at its contact's
// end, at the ledger's closes).
static void add_pending(const PairList& list, const std::vector<std::uint8_t>* ghost, ExactEnergy& sum) {
  for (std::size_t k = 0; k < list.size(); ++k)
    if (!ghost || !(*ghost)[list.pairs[k].i]) sum.add(list.open_energy_or_zero(k));
}

void ContactEngine::flush_pair(PairList& list, std::size_t k, const std::vector<std::uint8_t>* ghost) {
  if (!list.sparse && !list.has_slots(k)) return;  // no slot: no energy (its first slot is the next pair's)
  if (!ghost || !(*ghost)[list.pairs[k].i]) flushed_.add(list.open_energy(k));
  list.open_energy(k) = EnergyParts{};
}

void ContactEngine::flush_pairs(PairList& list, const std::vector<std::uint32_t>& pairs,
                                const std::vector<std::uint8_t>* ghost) {
  for (std::uint32_t k : pairs) flush_pair(list, k, ghost);
}

// Serial, after the pair loops: only the blocks the loop flagged are scanned (a few a step).
void ContactEngine::flush_ended(const std::vector<std::uint8_t>* ghost) {
  for (PairList* list : {&body_list_, &driver_list_})
    for (std::size_t b = 0; b < list->block_ended.size(); ++b) {
      if (!list->block_ended[b]) continue;
      for (std::size_t k = b * list->block; k < std::min(list->size(), (b + 1) * list->block); ++k)
        if (!list->touching[k]) flush_pair(*list, k, ghost);
    }
}

void ContactEngine::flush_idle(PairList& list, const std::vector<std::uint8_t>* ghost) {
  for (std::size_t k = 0; k < list.size(); ++k) {
    bool active = false;
    for (std::uint32_t s = list.slot_begin[k]; s < list.slot_begin[k + 1]; ++s) active |= list.active[s] != 0;
    if (!active) flush_pair(list, k, ghost);
  }
}

void ContactEngine::flush_energy(const std::vector<std::uint8_t>* ghost) {
  for (PairList* list : {&body_list_, &driver_list_}) {
    add_pending(*list, ghost, flushed_);
    std::fill(list->pending.begin(), list->pending.end(), EnergyParts{});
    for (ContactSlot& slot : list->slots) slot.pending = EnergyParts{};
  }
}

ExactEnergy ContactEngine::take_energy(const std::vector<std::uint8_t>* ghost) {
  flush_energy(ghost);
  return std::exchange(flushed_, ExactEnergy{});
}

ExactEnergy ContactEngine::open_energy(const std::vector<std::uint8_t>* ghost) const {
  ExactEnergy sum = flushed_;
  for (const PairList* list : {&body_list_, &driver_list_}) add_pending(*list, ghost, sum);
  return sum;
}

// Adds the active slots of the pairs whose lower body is not a ghost (exactly: any order).
// r_star(k): m, pair k's curvature radius (Hertz).
template <class RStar>
static void add_stored_energy(const PairList& list, const LawParams& law, const RStar& r_star_of,
                              const std::vector<std::uint8_t>* ghost, ExactStored& total) {
  for (std::size_t k = 0; k < list.size(); ++k) {
    if (ghost && (*ghost)[list.pairs[k].i]) continue;
    const double r_star = law.normal == NormalModel::hertz ? r_star_of(list.pairs[k]) : 0.0;  // m
    for (std::uint32_t s = list.slot_begin[k]; s < list.slot_begin[k + 1]; ++s)
      if (list.active[s]) total.add(stored_parts(law, list.history(s), r_star));
  }
}

ExactStored ContactEngine::elastic(const Drivers& drivers, const std::vector<std::uint8_t>* ghost) const {
  ExactStored total;  // J
  add_stored_energy(body_list_, settings_.particle, [&](BodyPair p) {
    return radius_[p.i] * radius_[p.j] / (radius_[p.i] + radius_[p.j]);
  }, ghost, total);
  add_stored_energy(driver_list_, settings_.driver, [&](BodyPair p) {
    return drivers.r_star(p.j, radius_[p.i]);
  }, ghost, total);
  return total;
}

}  // namespace polydem
