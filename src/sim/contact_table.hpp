#pragma once
// The contact histories of a distributed run in global ids: the active slots every rank
// answers for (its body pairs whose lower body it owns, its driver pairs), gathered into one
// table laid out as read_active lays out a checkpoint's (pairs sorted, active slots only). The
// table is what checkpoints and output read on rank 0 and what each rank takes its share of
// at a rebuild, so contacts migrate with their bodies.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "contact/contact_lists.hpp"
#include "sim/local_store.hpp"

namespace polydem {

// One active slot with its pair in global ids (j: a body, or a driver index); on a pair's
// first slot, slot.pending holds the pair's pending energy (J, PairList::open_energy; zero on
// the others): it moves with the history.
struct TableSlot {
  std::uint32_t i, j;
  FeaturePair key;
  ContactSlot slot;
  SlotRecord record;
};

// The row of id g in increasing global ids `ids` (a store's, a rank's held bodies): at() searches
// on from the row it found last (ids asked in increasing order, as a table's i: one search over
// `ids` in all; a smaller one searches all), after(row, g) from a row below g's (a pair's j above its i).
struct RowCursor {
  const std::vector<std::uint32_t>& ids;
  std::size_t last = 0;
  std::size_t at(std::uint32_t g) {
    if (last > 0 && ids[last - 1] >= g) last = 0;  // out of order: search all
    return last = after(last, g);
  }
  // lower_bound's answer, galloping from `row` (a pair's bodies are near in id: the body order is
  // spatial), so a search costs the log of the distance, not of the store.
  std::size_t after(std::size_t row, std::uint32_t g) const {
    const std::size_t n = ids.size();
    std::size_t lo = row, step = 1;  // every id in [row, lo) is below g
    while (lo < n && ids[lo] < g) {
      const std::size_t hi = std::min(n, lo + step);
      if (hi == n || ids[hi] >= g)  // g's place in (lo, hi]
        return std::size_t(std::lower_bound(ids.begin() + std::ptrdiff_t(lo + 1), ids.begin() + std::ptrdiff_t(hi), g) -
                           ids.begin());
      lo = hi;
      step *= 2;
    }
    return lo;
  }
};

// The active slots of `list` (local indices of `store`) this rank answers for.
std::vector<TableSlot> active_slots(const PairList& list, const LocalStore& store, bool driver);
// Appends pair k's active slots of `list` (ids: the local rows' global ids) to `out`, the
// pair's pending energy on its first active slot (active_slots' record of one pair).
void append_pair_slots(const PairList& list, std::size_t k, const std::vector<std::uint32_t>& ids, bool driver,
                       std::vector<TableSlot>& out);

// A row of the store before a rebuild that the new store does not hold (rows_now).
constexpr std::uint32_t kNotHeld = ~std::uint32_t(0);
// Each row of a store of global ids `was` (increasing) in one of ids `now` (increasing), or kNotHeld.
std::vector<std::uint32_t> rows_now(const std::vector<std::uint32_t>& was, const std::vector<std::uint32_t>& now);

// A rank's staying pairs at a rebuild, without the table's round trip: the pairs of `list` (its
// lists, rows of the store before) with an active slot whose bodies `row_now` finds both in the
// new store, one of them owned there (`ghost`: the new store's flags; a driver pair: its body
// owned), relabelled and laid out as local_table lays out their active_slots, merged in pair
// order with the pairs that came (`landed`, local_table's; no pair in both). A pair across the
// cut is computed on both sides alike, so the copy here is the answering rank's, bit for bit.
PairList kept_table(const PairList& list, const std::vector<std::uint32_t>& row_now,
                    const std::vector<std::uint8_t>& ghost, bool driver, const PairList& landed);

// The table of all ranks' slots: pairs in increasing (i, j), each pair's slots from one rank in key order.
PairList table_of(const std::vector<TableSlot>& slots);

// The table's pairs between local bodies (`held`: their global ids, increasing; a body's local
// index is its place there), in local indices: the histories a rebuild on this rank hands over.
PairList localise(const PairList& table, const std::vector<std::uint32_t>& held, bool driver);

// localise(table_of(slots), held, driver) in one pass, each slot copied once (a rank's rebuild:
// the slots it was handed straight into its local rows).
PairList local_table(const std::vector<TableSlot>& slots, const std::vector<std::uint32_t>& held, bool driver);

}  // namespace polydem
