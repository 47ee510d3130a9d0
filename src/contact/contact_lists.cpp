#include "contact/contact_lists.hpp"

namespace polydem {

std::vector<std::uint32_t> pairs_by_body(const std::vector<BodyPair>& pairs, std::size_t n_bodies) {
  std::vector<std::uint32_t> begin(n_bodies + 1, 0);
  for (const BodyPair& p : pairs) ++begin[p.i + 1];
  for (std::size_t b = 0; b < n_bodies; ++b) begin[b + 1] += begin[b];
  return begin;
}

namespace {
bool pair_less(const BodyPair& a, const BodyPair& b) {
  return a.i != b.i ? a.i < b.i : a.j < b.j;
}
}  // namespace

PairList active_part(const PairList& list) {
  PairList kept;
  std::size_t n_slots = 0, n_pairs = 0;  // sized exactly: this copy is held at a rebuild's peak
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::size_t before = n_slots;
    for (std::uint32_t s = list.slot_begin[k]; s < list.slot_begin[k + 1]; ++s) n_slots += list.active[s];
    n_pairs += n_slots > before;
  }
  kept.pairs.reserve(n_pairs);
  kept.slot_begin.reserve(n_pairs + 1);
  kept.features.reserve(n_slots);
  kept.slots.reserve(n_slots);
  // A sparse list's points always: the hand-over reads them (force and fn +0 while not recording).
  kept.recording = list.recording || list.sparse;
  if (kept.recording) kept.records.reserve(n_slots);
  kept.slot_begin.push_back(0);
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::size_t before = kept.slots.size();
    for (std::uint32_t s = list.slot_begin[k]; s < list.slot_begin[k + 1]; ++s) {
      if (!list.active[s]) continue;
      kept.features.push_back(list.features[s]);
      kept.slots.push_back(ContactSlot{list.history(s), {}});
      if (kept.recording) kept.records.push_back(list.record(s));
    }
    if (kept.slots.size() == before) continue;
    kept.pairs.push_back(list.pairs[k]);
    kept.slots[before].pending = list.open_energy_or_zero(k);  // dense: on the pair's first slot
    kept.slot_begin.push_back(std::uint32_t(kept.slots.size()));
  }
  kept.active.assign(kept.slots.size(), 1);
  return kept;
}

std::vector<std::uint32_t> carry_history(const PairList& old_list, PairList& fresh) {
  std::vector<std::uint32_t> uncarried;
  const bool has_pending = !old_list.sparse || !old_list.pending.empty();
  std::size_t k_new = 0;
  for (std::size_t k_old = 0; k_old < old_list.size(); ++k_old) {
    const BodyPair& p = old_list.pairs[k_old];
    while (k_new < fresh.size() && pair_less(fresh.pairs[k_new], p)) ++k_new;
    if (k_new == fresh.size() || pair_less(p, fresh.pairs[k_new])) {  // pair dropped out of range
      if (has_pending) uncarried.push_back(std::uint32_t(k_old));
      continue;
    }
    std::uint32_t s_new = fresh.slot_begin[k_new];
    const std::uint32_t s_new_end = fresh.slot_begin[k_new + 1];
    for (std::uint32_t s = old_list.slot_begin[k_old]; s < old_list.slot_begin[k_old + 1]; ++s) {
      if (!old_list.active[s]) continue;
      const std::uint64_t key = feature_key(old_list.features[s]);
      while (s_new < s_new_end && feature_key(fresh.features[s_new]) < key) ++s_new;
      if (s_new < s_new_end && feature_key(fresh.features[s_new]) == key) {
        fresh.set_history(s_new, old_list.history(s));  // a sparse list's states made here in slot order
        fresh.set_record(s_new, old_list.record(s));
        fresh.active[s_new] = 1;
        ++fresh.touching[k_new];
      }
    }
    if (!has_pending) continue;
    if (fresh.touching[k_new]) fresh.open_energy(k_new) = old_list.open_energy(k_old);
    else uncarried.push_back(std::uint32_t(k_old));
  }
  return uncarried;
}

}  // namespace polydem
