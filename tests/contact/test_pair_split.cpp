// The body pairs' loop sums each body's terms in the loop (pair_split.hpp) at any team size:
// each body's sum must be, bit for bit, the plain sum of its pairs' terms in pair order, and
// each pair's pending energy its terms added step by step, each block's contact count the plain
// sum of its pairs', and a block flagged where a pair's contact ended.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <numeric>
#include <random>

#include "contact/pair_loop.hpp"

using namespace polydem;

namespace {

// Sorted, distinct pairs i < j; `reach` bounds j - i (a small reach: ids that follow space).
std::vector<BodyPair> random_pairs(std::mt19937_64& rng, std::uint32_t n_bodies, std::size_t n_pairs, std::uint32_t reach) {
  std::vector<BodyPair> pairs;
  std::uniform_int_distribution<std::uint32_t> body(0, n_bodies - 2), step(1, reach);
  for (std::size_t p = 0; p < n_pairs; ++p) {
    const std::uint32_t i = body(rng), j = std::min(n_bodies - 1, i + step(rng));
    pairs.push_back({i, j});
  }
  std::sort(pairs.begin(), pairs.end(), [](BodyPair a, BodyPair b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
  pairs.erase(std::unique(pairs.begin(), pairs.end(), [](BodyPair a, BodyPair b) { return a.i == b.i && a.j == b.j; }),
              pairs.end());
  return pairs;
}

// Each body paired with its next `reach` along a chain whose ids are shuffled: ids at random in
// space, as a random pour's (a body's pairs as i fall with its id).
std::vector<BodyPair> shuffled_chain_pairs(std::mt19937_64& rng, std::uint32_t n_bodies, std::uint32_t reach) {
  std::vector<std::uint32_t> id(n_bodies);
  std::iota(id.begin(), id.end(), 0u);
  std::shuffle(id.begin(), id.end(), rng);
  std::vector<BodyPair> pairs;
  for (std::uint32_t b = 0; b < n_bodies; ++b)
    for (std::uint32_t d = 1; d <= reach && b + d < n_bodies; ++d)
      pairs.push_back({std::min(id[b], id[b + d]), std::max(id[b], id[b + d])});
  std::sort(pairs.begin(), pairs.end(), [](BodyPair a, BodyPair b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
  return pairs;
}

// Terms of mixed magnitudes (N, N m, J): their sums' bits depend on the order of addition.
std::vector<PairTotals> random_terms(std::mt19937_64& rng, std::size_t n) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-8, 8), contacts(0, 2);
  auto value = [&] { return std::ldexp(unit(rng), exponent(rng)); };
  auto vec = [&] { return Vec3(value(), value(), value()); };
  std::vector<PairTotals> terms(n);
  for (PairTotals& t : terms) {
    t.contacts = contacts(rng);
    if (t.contacts == 0) continue;  // out of reach: +0 totals, as the kernels return
    t = {vec(), vec(), vec(), EnergyParts{value(), value(), value(), value()}, t.contacts};
  }
  return terms;
}

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0; }
bool same_bits(const EnergyParts& a, const EnergyParts& b) { return std::memcmp(&a, &b, sizeof(EnergyParts)) == 0; }

// Runs the direct loop on a team of `threads`; counts each pair's kernel calls.
void run_loop(PairList& list, const std::vector<PairTotals>& terms, DirectSums& direct, int threads,
              std::vector<std::atomic<int>>& calls) {
#pragma omp parallel num_threads(threads)
  all_pair_forces(list, [&](std::uint32_t k, PairScratch&) {
    calls[k].fetch_add(1, std::memory_order_relaxed);
    return terms[k];
  }, &direct);
}

void check_sums(std::uint32_t n_bodies, std::uint32_t reach, std::size_t block = kPairBlock) {
  std::mt19937_64 rng(reach);
  PairList list;
  list.pairs = random_pairs(rng, n_bodies, 6 * n_bodies, reach);
  list.sparse = true;  // no slots: the pairs' energies kept per pair
  list.block = block;
  list.resize_results();
  const std::vector<PairTotals> touching = random_terms(rng, list.size());
  std::vector<PairTotals> parting = touching;  // every third pair's contact ends
  for (std::size_t k = 0; k < parting.size(); k += 3) parting[k] = PairTotals{};
  const std::size_t blocks = list.block_contacts.size();
  std::vector<EnergyParts> pending(list.size());      // each pair's terms added step by step
  std::vector<std::uint16_t> was(list.size(), 0);     // contacts at the last step
  DirectSums direct;
  direct.reset(n_bodies);
  direct.cross = CrossWeights{0.7, 0.2};  // the engine's for spheres: the cut made twice
  int step = 0;
  struct Team {
    int threads;
    std::vector<double> shares;  // forced (a cut that followed the threads' pace), or empty: as the loop cuts
  };
  // The team size changes between steps: cut again (a team of 5 leaks in libomp under ASan); then
  // cuts forced far from the even one, as a cut following a slow thread moves.
  const Team teams[] = {{1, {}}, {2, {}}, {3, {}}, {4, {}}, {2, {}}, {2, {0.25, 0.75}}, {2, {0.75, 0.25}}, {3, {0.2, 0.5, 0.3}}};
  for (const auto& [threads, shares] : teams) {
    if (!shares.empty()) {
      direct.shares = shares;
      direct.follow_pace = false;
      direct.split.threads = 0;
    }
    const std::vector<PairTotals>& terms = step++ % 2 ? parting : touching;
    std::vector<BodySum> plain(n_bodies);  // one thread's pair-order sum
    std::vector<std::uint32_t> contacts(blocks, 0);
    std::vector<std::uint8_t> ended(blocks, 0);
    for (std::size_t k = 0; k < list.size(); ++k) {
      const BodyPair p = list.pairs[k];
      plain[p.i].force += terms[k].force_i;
      plain[p.i].torque += terms[k].torque_i;
      plain[p.j].force -= terms[k].force_i;
      plain[p.j].torque += terms[k].torque_j;
      pending[k] += terms[k].energy;
      contacts[k / block] += std::uint32_t(terms[k].contacts);
      ended[k / block] |= was[k] != 0 && terms[k].contacts == 0;
      was[k] = std::uint16_t(terms[k].contacts);
    }
    std::vector<std::atomic<int>> calls(list.size());
    run_loop(list, terms, direct, threads, calls);
    CAPTURE(threads, reach, block, list.size(), direct.split.foreign_side.size());
    int wrong_calls = 0, wrong_sums = 0, wrong_pending = 0, wrong_blocks = 0, ends = 0;
    for (std::size_t k = 0; k < list.size(); ++k) {
      wrong_calls += calls[k] != 1;
      wrong_pending += !same_bits(list.open_energy(k), pending[k]);
    }
    for (std::uint32_t b = 0; b < n_bodies; ++b) {  // the loop's sum, then the late terms (as ForceSums adds them)
      Vec3 force = direct.sums[b].force, torque = direct.sums[b].torque;
      direct.late_terms().add_to(b, force, torque);
      wrong_sums += !same_bits(force, plain[b].force) || !same_bits(torque, plain[b].torque);
    }
    for (std::size_t b = 0; b < blocks; ++b) {
      wrong_blocks += list.block_contacts[b] != contacts[b] || bool(list.block_ended[b]) != bool(ended[b]);
      ends += ended[b];
    }
    CHECK(wrong_calls == 0);
    CHECK(wrong_sums == 0);
    CHECK(wrong_pending == 0);
    CHECK(wrong_blocks == 0);
    CHECK((step % 2 ? ends == 0 : ends > 0));  // contacts end at the parting steps only
    CHECK(direct.split.threads == threads);
    for (int t = 1; t < threads; ++t) CHECK((direct.split.cut[t] % block == 0 || direct.split.cut[t] == list.size()));
    if (!shares.empty() && reach < 100 && list.size() > 8 * kPairBlock)  // the forced cut taken (ids that follow space: pairs weigh alike)
      CHECK(std::abs(double(direct.split.cut[1]) / double(list.size()) - shares[0]) < 0.1);
    if (step % 2) {  // the sums taken and cleared, as a closing pass does (ForceSums): the next loop starts from them
      std::fill(direct.sums.begin(), direct.sums.end(), BodySum{});
      direct.taken();
    }
  }
}

// The split of `pairs` for a team of `threads`, its pair cut's ends checked.
PairSplit split_for(const std::vector<BodyPair>& pairs, std::uint32_t n_bodies, int threads) {
  PairSplit split;
  split_pairs(pairs, {}, {}, n_bodies, threads, split);
  REQUIRE(split.cut.size() == std::size_t(threads) + 1);
  CHECK(split.cut.front() == 0);
  CHECK(split.cut.back() == pairs.size());
  return split;
}

// The chunk of each body's last pair as i; -1 for a body in no pair as i.
std::vector<int> last_chunk_as_i(const std::vector<BodyPair>& pairs, const PairSplit& split, std::uint32_t n_bodies) {
  std::vector<int> last(n_bodies, -1);
  int c = 0;
  for (std::uint32_t k = 0; k < pairs.size(); ++k) {
    while (k >= split.cut[c + 1]) ++c;
    last[pairs[k].i] = c;
  }
  return last;
}

}  // namespace

TEST_CASE("the direct body sums are the pair-order sums at any team size", "[pair_split]") {
  check_sums(2000, 1999);  // ids at random in space: many foreign pairs
  check_sums(2000, 40);    // ids that follow space: few
  check_sums(40, 39);      // one block: the later chunks empty
  check_sums(2000, 1999, kSmallestPairBlock);  // a polyhedron list's smallest blocks
  check_sums(60, 59, kSmallestPairBlock);      // a pour's few pairs: several blocks
}

TEST_CASE("a split cuts at blocks, homes each body in its first pair's chunk and lists its later pairs", "[pair_split]") {
  std::mt19937_64 rng(7);
  const std::uint32_t n_bodies = 3000;
  const std::vector<BodyPair> pairs = random_pairs(rng, n_bodies, 6 * n_bodies, 60);
  for (int threads : {1, 2, 3, 5}) {
    CAPTURE(threads);
    const PairSplit split = split_for(pairs, n_bodies, threads);
    for (int t = 1; t < threads; ++t) CHECK((split.cut[t] % kPairBlock == 0 || split.cut[t] == pairs.size()));
    std::vector<int> home(n_bodies, -1);
    for (int t = 0; t < threads; ++t)
      for (std::uint32_t h = split.home_begin[t]; h < split.home_begin[t + 1]; ++h) {
        CHECK(home[split.homes[h]] == -1);  // one home a body
        home[split.homes[h]] = t;
      }
    // Each body's home is its first pair's chunk; its pairs in later chunks are its late terms, in order.
    std::vector<int> first(n_bodies, -1);
    std::vector<std::vector<std::uint32_t>> later(n_bodies);
    int c = 0;
    for (std::uint32_t k = 0; k < pairs.size(); ++k) {
      while (k >= split.cut[c + 1]) ++c;
      for (std::uint32_t b : {pairs[k].i, pairs[k].j}) {
        if (first[b] < 0) first[b] = c;
        if (c != first[b]) later[b].push_back(k);
      }
    }
    int wrong_home = 0, wrong_late = 0;
    for (std::uint32_t b = 0; b < n_bodies; ++b) {
      wrong_home += home[b] != first[b];
      std::vector<std::uint32_t> listed;
      for (std::uint32_t e = split.late_begin[b]; e < split.late_begin[b + 1]; ++e) {
        const std::uint32_t k = split.foreign[split.late[e] >> 1];
        listed.push_back(k);
        wrong_late += (split.late[e] & 1u) != (pairs[k].j == b);  // the side it is
      }
      wrong_late += listed != later[b];
    }
    CHECK(wrong_home == 0);
    CHECK(wrong_late == 0);
    // Ids that follow space: only a boundary layer of pairs is foreign.
    CHECK(split.foreign_side.size() <= std::size_t(threads - 1) * pairs.size() / 10);
  }
}

TEST_CASE("a split gives the chunk of the touching pairs fewer pairs", "[pair_split]") {
  std::mt19937_64 rng(11);
  const std::uint32_t n_bodies = 3000;
  const std::vector<BodyPair> pairs = random_pairs(rng, n_bodies, 6 * n_bodies, 60);  // ids follow space
  std::vector<std::uint16_t> touching(pairs.size(), 0);
  for (std::size_t k = 0; k < pairs.size() / 4; ++k) touching[k] = 2;  // a pile at the low ids: its pairs cost more
  PairSplit plain, weighed;
  split_pairs(pairs, {}, {}, n_bodies, 2, plain);
  split_pairs(pairs, touching, {}, n_bodies, 2, weighed);
  const double middle = 0.5 * double(pairs.size());
  CHECK(std::abs(double(plain.cut[1]) - middle) <= double(kPairBlock) + 0.05 * middle);  // pairs alike: halves
  CHECK(double(weighed.cut[1]) < 0.75 * middle);  // the pile's chunk ends early
  CHECK(weighed.cut[1] > pairs.size() / 4 / 2);   // yet takes more than the pile's first half
}

TEST_CASE("a split cuts the bodies where it cuts the pairs: each body with the chunk of its last pair as i", "[pair_split]") {
  std::mt19937_64 rng(13);
  const std::uint32_t n_bodies = 3000;
  const std::vector<BodyPair> pairs = random_pairs(rng, n_bodies, 6 * n_bodies, 60);
  for (int threads : {1, 2, 3, 5}) {
    CAPTURE(threads);
    const PairSplit split = split_for(pairs, n_bodies, threads);
    const std::vector<std::uint32_t>& at = split.body_cut;
    REQUIRE(at.size() == std::size_t(threads) + 1);
    CHECK(at.front() == 0);
    CHECK(at.back() == n_bodies);
    for (int t = 0; t < threads; ++t) CHECK(at[t] <= at[t + 1]);
    const std::vector<int> last = last_chunk_as_i(pairs, split, n_bodies);
    int wrong_share = 0;
    for (std::uint32_t b = 0; b < n_bodies; ++b)
      if (last[b] >= 0) wrong_share += b < at[last[b]] || b >= at[last[b] + 1];
    CHECK(wrong_share == 0);
  }
}

TEST_CASE("a split weighs the bodies' other work: heavy bodies at the low ids move the cut down", "[pair_split]") {
  std::mt19937_64 rng(17);
  const std::uint32_t n_bodies = 3000;
  const std::vector<BodyPair> pairs = random_pairs(rng, n_bodies, 6 * n_bodies, 60);  // ~6 pairs a body
  std::vector<float> weight(n_bodies, 1.0f);
  PairSplit light, heavy;
  split_pairs(pairs, {}, weight, n_bodies, 2, light);
  for (std::uint32_t b = 0; b < n_bodies / 4; ++b) weight[b] = 25.0f;  // the first quarter: 4x a body's pairs and pass
  split_pairs(pairs, {}, weight, n_bodies, 2, heavy);
  CHECK(std::abs(double(light.body_cut[1]) - 0.5 * n_bodies) <= 0.05 * n_bodies);  // alike: halves
  // ~5.8 pairs a body: the first quarter weighs ~30.8 a body, the rest ~6.8, half of all ~19,100:
  // reached at body ~620.
  CHECK(std::abs(double(heavy.body_cut[1]) - 620.0) <= 0.03 * n_bodies);
}

TEST_CASE("ids at random in space: the cut halves the pairs, each computed by its chunk's thread", "[pair_split]") {
  std::mt19937_64 rng(19);
  const std::uint32_t n_bodies = 3000;
  PairSplit split;
  const std::vector<BodyPair> pairs = shuffled_chain_pairs(rng, n_bodies, 3);
  split_pairs(pairs, {}, {}, n_bodies, 2, split);
  CHECK(std::abs(double(split.cut[1]) - 0.5 * double(pairs.size())) <= double(kPairBlock));
  // Most pairs are foreign (a body's first pair lies anywhere), each one's late side listed once.
  CHECK(split.foreign_side.size() > pairs.size() / 4);
  CHECK(split.late.size() >= split.foreign_side.size());
}

TEST_CASE("a cut's crossing work moves it: a star's foreign pairs weighed twice end chunk 0 at 5/8", "[pair_split]") {
  // Body 0 paired with every other: the even cut homes body 0 in chunk 0, so every pair of chunk 1
  // is foreign. Each weighed 1 + 1 (a late term 0): the first cut's chunk 0 weighs n/2, its chunk 1
  // n, and the second cut halves 3n/2 where n/2 + 2 (k - n/2) = 3n/4: k = 5n/8.
  const std::uint32_t n_pairs = 64 * kPairBlock, n_bodies = n_pairs + 1;
  std::vector<BodyPair> pairs;
  for (std::uint32_t j = 1; j < n_bodies; ++j) pairs.push_back({0, j});
  PairSplit even, crossed;
  split_pairs(pairs, {}, {}, n_bodies, 2, even);
  split_pairs(pairs, {}, {}, n_bodies, 2, crossed, {}, CrossWeights{1.0, 0.0});
  CHECK(even.cut[1] == n_pairs / 2);
  CHECK(std::abs(double(crossed.cut[1]) - 0.625 * n_pairs) <= double(kPairBlock));
  CHECK(crossed.foreign_side.size() == n_pairs - crossed.cut[1]);  // chunk 1's pairs, of the second cut
}

TEST_CASE("a trailed cut leaves out the passes of the bodies an earlier chunk reads: a chain reaching R ahead", "[pair_split]") {
  // Pairs (b, b + R) for b < 4096, every body's pass weighing 3 pairs. Chunk 0 = pairs [0, c) reads
  // bodies up to c + R, which a trailing pass leaves to the next step: chunk 0 walks and moves
  // c (1 + 3), chunk 1 (4096 - c) + 3 (4096 - c): level at c = 2048. Weighed as untrailed passes
  // chunk 1 also moves the R left: c (1 + 3) = (4096 - c) + 3 (5120 - c), c = 2048 + 3 R / 8 = 2432.
  const std::uint32_t reach = 1024, n_pairs = 64 * kPairBlock, n_bodies = n_pairs + reach;
  std::vector<BodyPair> pairs;
  for (std::uint32_t b = 0; b < n_pairs; ++b) pairs.push_back({b, b + reach});
  const std::vector<float> pass(n_bodies, 3.0f);
  PairSplit untrailed, trailed;
  split_pairs(pairs, {}, pass, n_bodies, 2, untrailed);
  split_pairs(pairs, {}, pass, n_bodies, 2, trailed, {}, CrossWeights{}, kPairBlock, 3.0);
  CHECK(untrailed.cut[1] == 2432);
  CHECK(trailed.cut[1] == 2048);
  CHECK(trailed.body_cut[1] == 2048);
  CHECK(trailed.trail_from[1] == 2048 + reach);
  CHECK(trailed.walk_weight[0] == 8192.0);  // each thread's walk and the passes behind it
  CHECK(trailed.walk_weight[1] == 8192.0);
}

TEST_CASE("a polyhedron list's few hundred pairs cut near halves: its blocks are small", "[pair_split]") {
  // A pour's ~300 body pairs, alike: 64-pair blocks cut them at 128 or 192 (43% or 64%).
  std::mt19937_64 rng(23);
  const std::uint32_t n_bodies = 2000;
  const std::vector<BodyPair> pairs = random_pairs(rng, n_bodies, 300, n_bodies);
  REQUIRE(pairs.size() % kPairBlock > kPairBlock / 4);  // no sphere block boundary near the middle
  const std::size_t block = polyhedron_pair_block(pairs.size());
  CHECK(block == kSmallestPairBlock);
  PairSplit split;
  split_pairs(pairs, {}, {}, n_bodies, 2, split, {}, CrossWeights{}, block);
  CHECK(split.cut[1] % block == 0);
  CHECK(std::abs(double(split.cut[1]) - 0.5 * double(pairs.size())) <= 0.5 * double(block));
  // Many pairs: the sphere lists' blocks (each block sets its loop up again), 32 of them or more.
  CHECK(polyhedron_pair_block(7742) == kPairBlock);  // the settled cubes' list
  CHECK(polyhedron_pair_block(1500) == kPairBlock / 2);
}

// Thread t's bodies under `cut` at `threads`, each body's count of takers (ids: every third body).
struct Taken {
  std::vector<int> taken, owner, taken_ids;
};
Taken take(const std::vector<std::uint32_t>& at, int cut_threads, bool folded, int threads,
           const std::vector<std::size_t>& ids) {
  Taken r{std::vector<int>(1000, 0), std::vector<int>(1000, -1), std::vector<int>(ids.size(), 0)};
#pragma omp parallel num_threads(threads)
  {
    for (const auto [first, last] : team_shares(1000, TeamCut{at.data(), cut_threads, folded}))
      for (std::size_t b = first; b < last; ++b) {
#pragma omp atomic
        ++r.taken[b];
        r.owner[b] = omp_get_thread_num();
      }
    for (const auto [first, last] : team_shares(ids, TeamCut{at.data(), cut_threads, folded}))
      for (std::size_t k = first; k < last; ++k) {
#pragma omp atomic
        ++r.taken_ids[k];
      }
  }
  return r;
}

TEST_CASE("a team's shares of the bodies take each body once, by the cut made for its size", "[pair_split]") {
  const std::vector<std::uint32_t> at = {0, 10, 10, 700, 1000};  // four threads, one with no body
  std::vector<std::size_t> ids;  // every third body
  for (std::size_t b = 0; b < 1000; b += 3) ids.push_back(b);
  for (int threads : {4, 3}) {  // the cut's team, and another (static shares)
    const Taken r = take(at, 4, false, threads, ids);
    CAPTURE(threads);
    CHECK(std::count(r.taken.begin(), r.taken.end(), 1) == 1000);
    CHECK(std::count(r.taken_ids.begin(), r.taken_ids.end(), 1) == long(ids.size()));
    if (threads == 4)
      for (int t = 0; t < 4; ++t)
        for (std::uint32_t b = at[t]; b < at[t + 1]; ++b) CHECK(r.owner[b] == t);
  }
}

TEST_CASE("a folded cut gives thread t pieces t and 2 threads - 1 - t, each body once", "[pair_split]") {
  const std::vector<std::uint32_t> at = {0, 100, 400, 400, 1000};  // two threads: 0 takes [0, 100) and [400, 1000)
  std::vector<std::size_t> ids;
  for (std::size_t b = 0; b < 1000; b += 3) ids.push_back(b);
  for (int threads : {2, 3}) {  // the cut's team, and another (static shares)
    const Taken r = take(at, 2, true, threads, ids);
    CAPTURE(threads);
    CHECK(std::count(r.taken.begin(), r.taken.end(), 1) == 1000);
    CHECK(std::count(r.taken_ids.begin(), r.taken_ids.end(), 1) == long(ids.size()));
    if (threads == 2)
      for (std::uint32_t b = 0; b < 1000; ++b) CHECK(r.owner[b] == (b >= 100 && b < 400 ? 1 : 0));
  }
}

// Walk times (s) of two threads, `steps` each; `outliers` of thread 1's steps 100 times as long.
std::vector<ThreadPace> paces(double t0, double t1, std::uint32_t steps, std::uint32_t outliers = 0) {
  std::vector<ThreadPace> pace(2);
  for (std::uint32_t s = 0; s < steps; ++s) {
    pace[0].took(t0);
    pace[1].took(s < outliers ? 100.0 * t1 : t1);
  }
  return pace;
}

TEST_CASE("a cut follows the threads' pace: the slower thread gets less, half-way, within bounds", "[pair_split]") {
  PairSplit split;
  split.walk_weight = {1000.0, 1000.0};  // an even cut
  // Thread 1 walks its chunk in twice thread 0's time: speeds 2:1, shares 2/3 and 1/3, half-way from even.
  std::vector<double> shares = paced_shares(split, paces(1e-4, 2e-4, 350), {});
  REQUIRE(shares.size() == 2);
  CHECK(shares[0] == Approx(0.5 * (0.5 + 2.0 / 3.0)));
  CHECK(shares[0] + shares[1] == Approx(1.0));
  // The next interval under that cut (weights 7:5; thread 1 still half as fast): on towards 2/3.
  split.walk_weight = {1166.7, 833.3};
  CHECK(paced_shares(split, paces(1e-4, 1.4286e-4, 350), shares)[0] == Approx(0.5 * (shares[0] + 2.0 / 3.0)).epsilon(1e-3));
  // At 2/3 the two walks take the same time: the shares stay.
  split.walk_weight = {1333.3, 666.7};
  CHECK(paced_shares(split, paces(1e-4, 1e-4, 350), {2.0 / 3.0, 1.0 / 3.0})[0] == Approx(2.0 / 3.0).epsilon(1e-3));
  // A thread that lost its core for a tenth of the steps is not slow (the median).
  split.walk_weight = {1000.0, 1000.0};
  CHECK(paced_shares(split, paces(1e-4, 1e-4, 350, 35), {})[0] == Approx(0.5));
  // Too few steps timed: the shares as they were.
  CHECK(paced_shares(split, paces(1e-4, 2e-4, 10), {}).empty());
  // A thread ten times as slow, again and again: no share below half an even one.
  shares.clear();
  for (int rebuild = 0; rebuild < 10; ++rebuild) shares = paced_shares(split, paces(1e-4, 1e-3, 350), shares);
  CHECK(shares[1] == Approx(0.25));
}
