// The contact table of a distributed run (sim/contact_table.hpp): slots that come as a few runs
// in pair order (each rank's, in its list's order) are laid out as a stable sort of all of them
// lays them out, and a rank's share of a table is the one a search of every pair's bodies gives.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "sim/contact_table.hpp"

using namespace polydem;

namespace {

// Pairs (i < j) of `bodies` drawn at random, each with 1-3 slots of keys 0, 1, 2 (key order),
// every slot's history marked with its draw number so a wrong slot shows.
std::vector<std::vector<TableSlot>> random_pairs(std::mt19937_64& rng, std::size_t pairs, std::uint32_t bodies) {
  std::vector<std::vector<TableSlot>> out;
  std::uniform_int_distribution<std::uint32_t> body(0, bodies - 1);
  double mark = 0.0;
  while (out.size() < pairs) {
    const std::uint32_t a = body(rng), b = body(rng);
    if (a == b) continue;
    std::vector<TableSlot>& pair = out.emplace_back();
    for (std::uint16_t key = 0, n = std::uint16_t(1 + rng() % 3); key < n; ++key) {
      TableSlot t{std::min(a, b), std::max(a, b), {PairType::vertex_vertex, key, 0}, {}, {}};
      t.slot.history.ft = Vec3(mark += 1.0, 0, 0);  // N
      pair.push_back(t);
    }
  }
  return out;
}

bool pair_before(const TableSlot& a, const TableSlot& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; }

// The slots of `pairs` split at random into `runs` runs, each sorted by pair (stably: a pair's
// slots stay in key order), a pair's slots in one run.
std::vector<TableSlot> in_runs(std::mt19937_64& rng, const std::vector<std::vector<TableSlot>>& pairs, int runs) {
  std::vector<std::vector<TableSlot>> run(runs);
  for (const std::vector<TableSlot>& p : pairs) {
    std::vector<TableSlot>& to = run[rng() % runs];
    to.insert(to.end(), p.begin(), p.end());
  }
  std::vector<TableSlot> slots;
  for (std::vector<TableSlot>& r : run) {
    std::stable_sort(r.begin(), r.end(), pair_before);
    slots.insert(slots.end(), r.begin(), r.end());
  }
  return slots;
}

// table_of as it was: all slots stably sorted, then laid out pair by pair.
PairList reference_table(std::vector<TableSlot> slots) {
  std::stable_sort(slots.begin(), slots.end(), pair_before);
  PairList table;
  table.slot_begin.push_back(0);
  for (const TableSlot& t : slots) {
    if (table.pairs.empty() || table.pairs.back().i != t.i || table.pairs.back().j != t.j) {
      table.pairs.push_back({t.i, t.j});
      table.slot_begin.push_back(table.slot_begin.back());
    }
    table.features.push_back(t.key);
    table.slots.push_back(t.slot);
    ++table.slot_begin.back();
  }
  return table;
}

void check_same(const PairList& got, const PairList& want) {
  REQUIRE(got.pairs == want.pairs);
  REQUIRE(got.slot_begin == want.slot_begin);
  REQUIRE(got.slots.size() == want.slots.size());
  std::size_t wrong = 0;
  for (std::size_t s = 0; s < got.slots.size(); ++s)
    wrong += got.features[s].a != want.features[s].a || got.slots[s].history.ft != want.slots[s].history.ft;
  CHECK(wrong == 0);
  CHECK(got.active == std::vector<std::uint8_t>(got.slots.size(), 1));
}

}  // namespace

TEST_CASE("a table of slots in sorted runs is laid out as a stable sort of them all", "[checkpoint][mpi]") {
  std::mt19937_64 rng(37);
  for (int runs : {1, 2, 3, 8, 64, 65, 300}) {  // ranks' runs; past 64 runs the table sorts
    for (int draw = 0; draw < 20; ++draw) {
      INFO(runs << " runs, draw " << draw);
      const std::vector<TableSlot> slots = in_runs(rng, random_pairs(rng, 1 + rng() % 400, 60), runs);
      check_same(table_of(slots), reference_table(slots));
    }
  }
  std::vector<TableSlot> shuffled;  // no order at all: pairs' slots apart, keys mixed
  for (const std::vector<TableSlot>& p : random_pairs(rng, 500, 80)) shuffled.insert(shuffled.end(), p.begin(), p.end());
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  check_same(table_of(shuffled), reference_table(shuffled));
}

TEST_CASE("a rank's share of a table holds the pairs of its bodies, in its local indices", "[checkpoint][mpi]") {
  std::mt19937_64 rng(38);
  for (int draw = 0; draw < 40; ++draw) {
    const PairList table = table_of(in_runs(rng, random_pairs(rng, 300, 50), 2));
    std::vector<std::uint32_t> held;  // a rank's bodies, increasing: about half of them
    for (std::uint32_t b = 0; b < 50; ++b)
      if (rng() % 2) held.push_back(b);
    for (bool driver : {false, true}) {
      INFO("draw " << draw << (driver ? ", driver pairs" : ", body pairs"));
      const PairList mine = localise(table, held, driver);
      std::size_t at = 0, k = 0;  // mine's pairs, in order, are the table's whose bodies are held
      for (std::size_t t = 0; t < table.size(); ++t) {
        const auto i = std::find(held.begin(), held.end(), table.pairs[t].i);
        const auto j = std::find(held.begin(), held.end(), table.pairs[t].j);
        if (i == held.end() || (!driver && j == held.end())) continue;
        REQUIRE(k < mine.size());
        CHECK(mine.pairs[k].i == std::uint32_t(i - held.begin()));
        CHECK(mine.pairs[k].j == (driver ? table.pairs[t].j : std::uint32_t(j - held.begin())));
        for (std::uint32_t s = table.slot_begin[t]; s < table.slot_begin[t + 1]; ++s, ++at)
          CHECK(mine.slots[at].history.ft == table.slots[s].history.ft);
        ++k;
      }
      CHECK(k == mine.size());
      CHECK(at == mine.slots.size());
      CHECK(mine.active == std::vector<std::uint8_t>(mine.slots.size(), 1));
    }
  }
}

TEST_CASE("a rank's share laid out in one pass is the share of the table", "[checkpoint][mpi]") {
  std::mt19937_64 rng(39);
  for (int draw = 0; draw < 40; ++draw) {
    const std::vector<TableSlot> slots = in_runs(rng, random_pairs(rng, 300, 50), 1 + int(rng() % 3));
    std::vector<std::uint32_t> held;  // a rank's bodies, increasing: about half of them
    for (std::uint32_t b = 0; b < 50; ++b)
      if (rng() % 2) held.push_back(b);
    for (bool driver : {false, true}) {
      INFO("draw " << draw << (driver ? ", driver pairs" : ", body pairs"));
      const PairList want = localise(table_of(slots), held, driver);
      const PairList got = local_table(slots, held, driver);
      CHECK(got.pairs.size() > 0);
      check_same(got, want);
      CHECK(got.records.size() == got.slots.size());
    }
  }
}

TEST_CASE("a row cursor's galloping search finds lower_bound's row from any start", "[checkpoint][mpi]") {
  std::mt19937_64 rng(40);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<std::uint32_t> ids(std::size_t(rng() % 200));  // increasing global ids with gaps
    std::uint32_t id = 0;
    for (std::uint32_t& g : ids) g = id += 1 + std::uint32_t(rng() % 3);
    RowCursor rows{ids};
    for (int ask = 0; ask < 50; ++ask) {
      const std::size_t row = ids.empty() ? 0 : std::size_t(rng() % (ids.size() + 1));
      const std::uint32_t g = std::uint32_t(rng() % (id + 3));
      const auto from = ids.begin() + std::ptrdiff_t(row);
      INFO("trial " << trial << ", row " << row << ", id " << g);
      CHECK(rows.after(row, g) == std::size_t(std::lower_bound(from, ids.end(), g) - ids.begin()));
      CHECK(rows.at(g) == std::size_t(std::lower_bound(ids.begin(), ids.end(), g) - ids.begin()));
    }
  }
}
