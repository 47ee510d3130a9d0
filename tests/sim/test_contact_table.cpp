// The contact table of a distributed run (sim/contact_table.hpp): slots that come as a few runs
// in pair order (each rank's, in its list's order) are laid out as a stable sort of all of them
// lays them out, and a rank's share of a table is the one a search of every pair's bodies gives.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
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

namespace {

template <class T>
bool same_bytes(const T& a, const T& b) { return std::memcmp(&a, &b, sizeof(T)) == 0; }

// Field by field (their padding aside), each double's bits.
bool same_slot(const ContactSlot& a, const ContactSlot& b) {
  const ContactHistory &x = a.history, &y = b.history;
  return same_bytes(x.ft, y.ft) && same_bytes(x.fd, y.fd) && same_bytes(x.gap, y.gap) && same_bytes(x.weight, y.weight) &&
         x.slipping == y.slipping && x.rolling_slipping == y.rolling_slipping && same_bytes(x.mr, y.mr) &&
         same_bytes(a.pending, b.pending);  // EnergyParts: 4 doubles, no padding
}

// Slot by slot, bit for bit: the keys, the histories with their pending energies, the records.
void check_bits(const PairList& got, const PairList& want) {
  REQUIRE(got.pairs == want.pairs);
  REQUIRE(got.slot_begin == want.slot_begin);
  REQUIRE(got.slots.size() == want.slots.size());
  REQUIRE(got.records.size() == want.records.size());
  std::size_t wrong = 0;
  for (std::size_t s = 0; s < got.slots.size(); ++s) {
    const FeaturePair &a = got.features[s], &b = want.features[s];
    const SlotRecord &r = got.records[s], &q = want.records[s];
    wrong += a.type != b.type || a.a != b.a || a.b != b.b || !same_slot(got.slots[s], want.slots[s]) ||
             !same_bytes(r.point, q.point) || !same_bytes(r.force, q.force) || !same_bytes(r.fn, q.fn);
  }
  CHECK(wrong == 0);
  CHECK(got.active == want.active);
}

// A rank's dense list over a store of `ids`: pairs (i < j) of local rows, 1-3 slots each, some
// inactive (a pair's first slot too: its pending energy, kept on that slot, then moves to the
// first active one), each history, pending energy and record marked with its draw number.
PairList random_list(std::mt19937_64& rng, std::size_t rows, std::size_t pairs) {
  std::vector<BodyPair> drawn;
  while (drawn.size() < pairs) {
    const auto a = std::uint32_t(rng() % rows), b = std::uint32_t(rng() % rows);
    if (a != b) drawn.push_back({std::min(a, b), std::max(a, b)});
  }
  std::sort(drawn.begin(), drawn.end(), [](BodyPair x, BodyPair y) { return x.i != y.i ? x.i < y.i : x.j < y.j; });
  drawn.erase(std::unique(drawn.begin(), drawn.end(), [](BodyPair x, BodyPair y) { return x.i == y.i && x.j == y.j; }),
              drawn.end());
  PairList list;
  list.slot_begin.push_back(0);
  double mark = 0.0;
  for (const BodyPair p : drawn) {
    list.pairs.push_back(p);
    for (std::uint16_t key = 0, n = std::uint16_t(1 + rng() % 3); key < n; ++key) {
      list.features.push_back({PairType::vertex_vertex, key, 0});
      ContactSlot slot;
      slot.history.ft = Vec3(mark += 1.0, 0, 0);  // N
      if (key == 0) slot.pending.net = mark;  // J, the pair's on its first slot
      list.slots.push_back(slot);
      list.records.push_back({Vec3(0, mark, 0), Vec3(0, 0, mark), mark});
      list.active.push_back(std::uint8_t(rng() % 3 != 0));
    }
    list.slot_begin.push_back(std::uint32_t(list.slots.size()));
  }
  list.resize_results();
  return list;
}

}  // namespace

TEST_CASE("rows_now finds each row of a store in the next one, or none", "[checkpoint][mpi]") {
  const std::vector<std::uint32_t> was{2, 3, 5, 8, 13}, now{1, 3, 4, 8, 9, 13, 20};
  CHECK(rows_now(was, now) == std::vector<std::uint32_t>{kNotHeld, 1, kNotHeld, 3, 5});
}

TEST_CASE("a rank's kept pairs with the landed ones are the table the round trip gave", "[checkpoint][mpi]") {
  // The round trip: every active slot of the old list as a table slot (append_pair_slots), with
  // the landed ones, laid out over the new store (local_table), keeping the pairs with a body
  // owned there; without it: the kept pairs relabelled and merged with the landed ones (kept_table).
  std::mt19937_64 rng(41);
  for (int draw = 0; draw < 60; ++draw) {
    INFO("draw " << draw);
    std::vector<std::uint32_t> was, now;  // the stores' global ids: half the old rows stay
    for (std::uint32_t g = 0; g < 120; ++g) {
      if (rng() % 3 != 0) was.push_back(g);
      if (rng() % 2) now.push_back(g);
    }
    std::vector<std::uint8_t> ghost(now.size());
    for (std::uint8_t& f : ghost) f = std::uint8_t(rng() % 2);
    const PairList list = random_list(rng, was.size(), 200);
    const auto held = [&](std::uint32_t g) { return std::binary_search(was.begin(), was.end(), g); };
    const std::vector<std::vector<TableSlot>> drawn = random_pairs(rng, 40, 120);
    for (bool driver : {false, true}) {
      INFO((driver ? "driver pairs" : "body pairs"));
      std::vector<TableSlot> landed;  // pairs the old store did not hold (a driver pair: its body)
      for (const std::vector<TableSlot>& pair : drawn)
        if (!held(pair[0].i) || (!driver && !held(pair[0].j))) landed.insert(landed.end(), pair.begin(), pair.end());
      std::vector<TableSlot> round_trip;
      for (std::size_t k = 0; k < list.size(); ++k) append_pair_slots(list, k, was, driver, round_trip);
      const auto owned = [&](std::uint32_t g) {
        const auto at = std::lower_bound(now.begin(), now.end(), g);
        return at != now.end() && *at == g && !ghost[std::size_t(at - now.begin())];
      };
      std::erase_if(round_trip, [&](const TableSlot& t) { return !owned(t.i) && (driver || !owned(t.j)); });
      const std::size_t kept = round_trip.size();
      round_trip.insert(round_trip.end(), landed.begin(), landed.end());
      const PairList want = local_table(round_trip, now, driver);
      const PairList got = kept_table(list, rows_now(was, now), ghost, driver, local_table(landed, now, driver));
      CHECK(kept > 0);
      check_bits(got, want);
    }
  }
}
