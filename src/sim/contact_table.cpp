#include "sim/contact_table.hpp"

#include <algorithm>


namespace polydem {

std::vector<TableSlot> active_slots(const PairList& list, const LocalStore& store, bool driver) {
  std::vector<TableSlot> out;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const BodyPair p = list.pairs[k];
    if (store.ghost[p.i]) continue;  // the owner of i answers for the pair
    const std::size_t first = out.size();
    for (std::uint32_t s = list.slot_begin[k]; s < list.slot_begin[k + 1]; ++s)
      if (list.active[s])
        out.push_back({store.global_id[p.i], driver ? p.j : store.global_id[p.j], list.features[s],
                       {list.history(s), {}}, list.recording ? list.record(s) : SlotRecord{}});
    if (out.size() > first) out[first].slot.pending = list.open_energy(k);
  }
  return out;
}

PairList table_of(std::vector<TableSlot> slots) {
  // stable: a pair's slots come from one rank, already in key order
  std::stable_sort(slots.begin(), slots.end(), [](const TableSlot& a, const TableSlot& b) {
    return a.i != b.i ? a.i < b.i : a.j < b.j;
  });
  PairList table;
  table.slot_begin.push_back(0);
  for (const TableSlot& t : slots) {
    if (table.pairs.empty() || table.pairs.back().i != t.i || table.pairs.back().j != t.j) {
      table.pairs.push_back({t.i, t.j});
      table.slot_begin.push_back(table.slot_begin.back());
    }
    table.features.push_back(t.key);
    table.slots.push_back(t.slot);
    table.records.push_back(t.record);
    table.active.push_back(1);
    ++table.slot_begin.back();
  }
  table.resize_results();
  for (std::size_t k = 0; k < table.size(); ++k)
    table.touching[k] = std::uint16_t(table.slot_begin[k + 1] - table.slot_begin[k]);
  return table;
}

namespace {

// The index of `g` in `held` (increasing), or -1 when not held.
std::int64_t index_in(const std::vector<std::uint32_t>& held, std::uint32_t g) {
  const auto at = std::lower_bound(held.begin(), held.end(), g);
  return at != held.end() && *at == g ? std::int64_t(at - held.begin()) : -1;
}

}  // namespace

PairList localise(const PairList& table, const std::vector<std::uint32_t>& held, bool driver) {
  PairList mine;
  mine.slot_begin.push_back(0);
  for (std::size_t k = 0; k < table.size(); ++k) {
    const BodyPair p = table.pairs[k];
    const std::int64_t i = index_in(held, p.i), j = driver ? std::int64_t(p.j) : index_in(held, p.j);
    if (i < 0 || j < 0) continue;
    mine.pairs.push_back({std::uint32_t(i), std::uint32_t(j)});  // local order is global order
    for (std::uint32_t s = table.slot_begin[k]; s < table.slot_begin[k + 1]; ++s) {
      mine.features.push_back(table.features[s]);
      mine.slots.push_back(table.slots[s]);
      mine.records.push_back(table.recording ? table.records[s] : SlotRecord{});  // a sphere table between outputs
      mine.active.push_back(1);
    }
    mine.slot_begin.push_back(std::uint32_t(mine.slots.size()));
  }
  mine.resize_results();
  return mine;
}

}  // namespace polydem
