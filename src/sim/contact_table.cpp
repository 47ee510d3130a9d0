#include "sim/contact_table.hpp"

#include <algorithm>
#include <numeric>
#include <optional>


namespace polydem {

void append_pair_slots(const PairList& list, std::size_t k, const std::vector<std::uint32_t>& ids, bool driver,
                       std::vector<TableSlot>& out) {
  const BodyPair p = list.pairs[k];
  const std::size_t first = out.size();
  for (std::uint32_t s = list.slot_begin[k]; s < list.slot_begin[k + 1]; ++s)
    if (list.active[s])
      out.push_back({ids[p.i], driver ? p.j : ids[p.j], list.features[s], {list.history(s), {}},
                     list.record(s)});
  if (out.size() > first) out[first].slot.pending = list.open_energy(k);
}

std::vector<TableSlot> active_slots(const PairList& list, const LocalStore& store, bool driver) {
  std::vector<TableSlot> out;
  for (std::size_t k = 0; k < list.size(); ++k)
    if (!store.ghost[list.pairs[k].i]) append_pair_slots(list, k, store.global_id, driver, out);  // the owner of i answers
  return out;
}

std::vector<std::uint32_t> rows_now(const std::vector<std::uint32_t>& was, const std::vector<std::uint32_t>& now) {
  std::vector<std::uint32_t> row(was.size(), kNotHeld);
  for (std::size_t a = 0, b = 0; a < was.size() && b < now.size();) {
    if (was[a] < now[b]) ++a;
    else if (now[b] < was[a]) ++b;
    else row[a++] = std::uint32_t(b++);
  }
  return row;
}

namespace {

bool pair_before(const TableSlot& a, const TableSlot& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; }

// The slots' places in pair order, stable (a pair's slots come from one rank, in key order).
// The slots come as a few runs already in order (each rank's in its list's order: migrate's,
// gather_table's), merged as indices so no 200-byte slot moves; more runs: sorted.
std::vector<std::uint32_t> pair_order(const std::vector<TableSlot>& slots) {
  constexpr std::size_t kMaxRuns = 64;
  std::vector<std::uint32_t> order(slots.size());
  std::iota(order.begin(), order.end(), 0u);
  const auto before = [&](std::uint32_t a, std::uint32_t b) { return pair_before(slots[a], slots[b]); };
  std::vector<std::size_t> ends;
  for (std::size_t k = 1; k < slots.size() && ends.size() <= kMaxRuns; ++k)
    if (pair_before(slots[k], slots[k - 1])) ends.push_back(k);
  if (ends.size() > kMaxRuns) {
    std::stable_sort(order.begin(), order.end(), before);
    return order;
  }
  ends.push_back(slots.size());
  for (std::size_t r = 0; r + 1 < ends.size(); ++r)  // the sorted prefix and the next run
    std::inplace_merge(order.begin(), order.begin() + std::ptrdiff_t(ends[r]), order.begin() + std::ptrdiff_t(ends[r + 1]),
                       before);
  return order;
}

}  // namespace

PairList table_of(const std::vector<TableSlot>& slots) {
  PairList table;
  table.slot_begin.push_back(0);
  table.features.reserve(slots.size());
  table.slots.reserve(slots.size());
  table.records.reserve(slots.size());
  table.active.assign(slots.size(), 1);
  for (std::uint32_t at : pair_order(slots)) {
    const TableSlot& t = slots[at];
    if (table.pairs.empty() || table.pairs.back().i != t.i || table.pairs.back().j != t.j) {
      table.pairs.push_back({t.i, t.j});
      table.slot_begin.push_back(table.slot_begin.back());
    }
    table.features.push_back(t.key);
    table.slots.push_back(t.slot);
    table.records.push_back(t.record);
    ++table.slot_begin.back();
  }
  table.resize_results();
  for (std::size_t k = 0; k < table.size(); ++k)
    table.touching[k] = std::uint16_t(table.slot_begin[k + 1] - table.slot_begin[k]);
  return table;
}

namespace {

// Pair (i, j) of global ids in this rank's rows (places in the cursor's `held`), or none where it
// does not hold both (a driver's j is the driver's index). Pairs come in increasing i.
std::optional<BodyPair> held_pair(RowCursor& rows, std::uint32_t i, std::uint32_t j, bool driver) {
  const std::vector<std::uint32_t>& held = rows.ids;
  const std::size_t li = rows.at(i);
  if (li >= held.size() || held[li] != i) return std::nullopt;
  if (driver) return BodyPair{std::uint32_t(li), j};
  const std::size_t lj = rows.after(li, j);  // a body pair's j above its i
  if (lj >= held.size() || held[lj] != j) return std::nullopt;
  return BodyPair{std::uint32_t(li), std::uint32_t(lj)};  // local order is global order
}

PairList reserved(std::size_t slots) {
  PairList mine;
  mine.slot_begin.push_back(0);
  mine.features.reserve(slots);
  mine.slots.reserve(slots);
  mine.records.reserve(slots);
  return mine;
}

void finish(PairList& mine) {
  mine.active.assign(mine.slots.size(), 1);
  mine.resize_results();
}

}  // namespace

PairList localise(const PairList& table, const std::vector<std::uint32_t>& held, bool driver) {
  PairList mine = reserved(table.slots.size());
  RowCursor rows{held};  // a table's i do not decrease
  for (std::size_t k = 0; k < table.size(); ++k) {
    const std::optional<BodyPair> p = held_pair(rows, table.pairs[k].i, table.pairs[k].j, driver);
    if (!p) continue;
    mine.pairs.push_back(*p);
    for (std::uint32_t s = table.slot_begin[k]; s < table.slot_begin[k + 1]; ++s) {
      mine.features.push_back(table.features[s]);
      mine.slots.push_back(table.slots[s]);
      mine.records.push_back(table.recording ? table.records[s] : SlotRecord{});  // a sphere table between outputs
    }
    mine.slot_begin.push_back(std::uint32_t(mine.slots.size()));
  }
  finish(mine);
  return mine;
}

PairList local_table(const std::vector<TableSlot>& slots, const std::vector<std::uint32_t>& held, bool driver) {
  PairList mine = reserved(slots.size());
  RowCursor rows{held};  // the pairs' i do not decrease
  bool kept = false;     // the current pair's bodies are held
  const TableSlot* last = nullptr;
  for (std::uint32_t at : pair_order(slots)) {
    const TableSlot& t = slots[at];
    if (!last || last->i != t.i || last->j != t.j) {  // a new pair
      if (kept) mine.slot_begin.push_back(std::uint32_t(mine.slots.size()));
      const std::optional<BodyPair> p = held_pair(rows, t.i, t.j, driver);
      if ((kept = p.has_value())) mine.pairs.push_back(*p);
    }
    last = &t;
    if (!kept) continue;
    mine.features.push_back(t.key);
    mine.slots.push_back(t.slot);
    mine.records.push_back(t.record);
  }
  if (kept) mine.slot_begin.push_back(std::uint32_t(mine.slots.size()));
  finish(mine);
  return mine;
}

namespace {

// Pair k of `from` with its slots appended to `to`.
void append_pair(const PairList& from, std::size_t k, PairList& to) {
  to.pairs.push_back(from.pairs[k]);
  for (std::uint32_t s = from.slot_begin[k]; s < from.slot_begin[k + 1]; ++s) {
    to.features.push_back(from.features[s]);
    to.slots.push_back(from.slots[s]);
    to.records.push_back(from.records[s]);
  }
  to.slot_begin.push_back(std::uint32_t(to.slots.size()));
}

bool pair_before(BodyPair a, BodyPair b) { return a.i != b.i ? a.i < b.i : a.j < b.j; }

}  // namespace

PairList kept_table(const PairList& list, const std::vector<std::uint32_t>& row_now,
                    const std::vector<std::uint8_t>& ghost, bool driver, const PairList& landed) {
  PairList mine = reserved(list.slot_count() + landed.slot_count());
  std::size_t next = 0;  // the first landed pair not yet placed
  for (std::size_t k = 0; k < list.size(); ++k) {
    const BodyPair p = list.pairs[k];
    const std::uint32_t i = row_now[p.i], j = driver ? p.j : row_now[p.j];
    if (i == kNotHeld || j == kNotHeld || (ghost[i] && (driver || ghost[j]))) continue;  // not listed here again
    while (next < landed.size() && pair_before(landed.pairs[next], {i, j})) append_pair(landed, next++, mine);
    bool first = true;  // the pair's pending energy goes on its first active slot (active_slots')
    for (std::uint32_t s = list.slot_begin[k]; s < list.slot_begin[k + 1]; ++s) {
      if (!list.active[s]) continue;
      mine.features.push_back(list.features[s]);
      mine.slots.emplace_back(list.history(s), first ? list.open_energy(k) : EnergyParts{});
      mine.records.push_back(list.record(s));
      first = false;
    }
    if (first) continue;  // no active slot: nothing to hand over
    mine.pairs.push_back({i, j});
    mine.slot_begin.push_back(std::uint32_t(mine.slots.size()));
  }
  while (next < landed.size()) append_pair(landed, next++, mine);
  finish(mine);
  return mine;
}

}  // namespace polydem
