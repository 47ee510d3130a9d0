// A rebuild lays its candidates out block by block (contact/list_build.hpp): the list must be
// the one a pair-by-pair build gives (pairs with candidates, runs in key order, the gaps at the
// build), whatever the thread count, also when the pairs' searches are remembered between
// rebuilds (contact/candidate_memory.hpp); and sizing the results after carry_history keeps
// the contact counts it carried.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <utility>
#include <omp.h>

#include "../geometry/test_shapes.hpp"
#include "contact/candidate_memory.hpp"
#include "contact/list_build.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

// Bodies of every kind, in random poses in a box where a third of the pairs are near.
std::vector<Posed> random_bodies(const std::vector<Shape>& shapes, std::size_t n) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 3.0);
  std::vector<Posed> bodies;
  for (std::size_t b = 0; b < n; ++b)
    bodies.emplace_back(shapes[b % shapes.size()], 1.0, Vec3(u(rng), u(rng), u(rng)), random_rotation(rng));
  return bodies;
}

// The list built pair by pair: what the blocks must join into.
PairList reference(const std::vector<BodyPair>& near, const std::vector<PosedBody>& posed, double range) {
  PairList list;
  list.slot_begin.push_back(0);
  for (const BodyPair& p : near) {
    std::vector<FeaturePair> found;
    std::vector<double> d2;  // m^2
    const double smallest = candidate_features(posed[p.i], posed[p.j], range, found, &d2);
    if (found.empty()) continue;
    std::vector<std::uint32_t> order(found.size());  // by key, sorted here (not by sorted_by_key)
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t x, std::uint32_t y) { return feature_key(found[x]) < feature_key(found[y]); });
    for (std::uint32_t c : order) {
      list.features.push_back(found[c]);
      list.slot_gap.push_back(gap_below(d2[c], posed[p.i].radius + posed[p.j].radius));
    }
    list.pairs.push_back(p);
    list.gap_at_build.push_back(smallest);
    list.slot_begin.push_back(std::uint32_t(list.features.size()));
  }
  return list;
}

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

std::vector<std::uint64_t> keys(const std::vector<FeaturePair>& features) {  // FeaturePair has padding
  std::vector<std::uint64_t> out;
  for (const FeaturePair& f : features) out.push_back(feature_key(f));
  return out;
}

// Bounding spheres within range: some pairs have no candidate.
std::vector<BodyPair> near_pairs(const std::vector<PosedBody>& posed, double range) {
  std::vector<BodyPair> near;
  for (std::uint32_t i = 0; i < posed.size(); ++i)
    for (std::uint32_t j = i + 1; j < posed.size(); ++j)
      if ((posed[i].position - posed[j].position).norm() <
          posed[i].shape->bounding_radius + posed[j].shape->bounding_radius + range)
        near.push_back({i, j});
  return near;
}

// The same candidates, slots and gaps, byte for byte.
void check_same_list(const PairList& got, const PairList& want) {
  CHECK(same_bytes(got.pairs, want.pairs));
  CHECK(same_bytes(got.slot_begin, want.slot_begin));
  CHECK(keys(got.features) == keys(want.features));
  CHECK(same_bytes(got.slot_gap, want.slot_gap));
  CHECK(same_bytes(got.gap_at_build, want.gap_at_build));
}

// m, the farthest core vertex from the centre (CandidateMemory's motion bound reads it).
double core_reach(const Posed& b) {
  double r = 0.0;
  for (const Vec3& v : b.shape->vertices) r = std::max(r, b.scale * v.norm());
  return r;
}

}  // namespace

TEST_CASE("body candidates joined from blocks equal the pair-by-pair list at 1 to 4 threads") {
  const std::vector<Shape> shapes = {make_sphere(0.3), make_cube(0.5, 0.05), make_octahedron(0.6, 0.04),
                                     make_hex_prism(0.5, 0.3, 0.05), make_tetrahedron(0.4, 0.05)};
  const std::vector<Posed> bodies = random_bodies(shapes, 60);
  std::vector<PosedBody> posed;
  for (const Posed& b : bodies) posed.push_back(b.body());
  const double range = 0.05;  // m
  const std::vector<BodyPair> near = near_pairs(posed, range);
  REQUIRE(near.size() > 4 * kCandidateBlock);  // several blocks, in parallel
  const PairList want = reference(near, posed, range);
  REQUIRE(want.size() < near.size());          // pairs without candidates are dropped
  REQUIRE(want.features.size() > want.size());  // runs of several candidates
  const int threads_before = omp_get_max_threads();
  for (int threads : {1, 2, 3, 4}) {
    omp_set_num_threads(threads);
    PairList got;
    body_candidates(near, [&](std::uint32_t b) -> const PosedBody& { return posed[b]; }, range, got);
    check_same_list(got, want);
  }
  omp_set_num_threads(threads_before);
}

TEST_CASE("remembered searches give the list a new search gives, rebuild after rebuild, at 1 to 4 threads") {
  const std::vector<Shape> shapes = {make_sphere(0.3), make_cube(0.5, 0.05), make_octahedron(0.6, 0.04),
                                     make_hex_prism(0.5, 0.3, 0.05), make_tetrahedron(0.4, 0.05)};
  const double range = 0.05, extra = 0.05;  // m
  const int threads_before = omp_get_max_threads();
  // Each block matches its pairs to the kept searches on its own; the list and the searches are
  // laid out on two threads at once and copied on the team.
  std::vector<std::size_t> recalled_at_one;  // per rebuild, at 1 thread: every team keeps the same searches
  for (int threads : {1, 2, 3, 4}) {
    omp_set_num_threads(threads);
    std::vector<std::size_t> recalled_each;
    std::vector<Posed> bodies = random_bodies(shapes, 60);
    std::vector<double> reach;  // m
    for (const Posed& b : bodies) reach.push_back(core_reach(b));
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    CandidateMemory memory(extra);
    std::size_t recalled = 0, searched_again = 0;
    for (int rebuild = 0; rebuild < 8; ++rebuild) {
      std::vector<PosedBody> posed;
      std::vector<Vec3> x;
      std::vector<Quat> q;
      for (const Posed& b : bodies) {
        posed.push_back(b.body());
        x.push_back(b.position);
        q.push_back(b.q);
      }
      const std::vector<BodyPair> near = near_pairs(posed, range);
      const PairList want = reference(near, posed, range);
      PairList got;
      memory.find(near, posed, {x.data(), q.data(), reach.data()}, range, got);
      check_same_list(got, want);
      recalled_each.push_back(memory.recalled());
      if (rebuild > 0) {
        recalled += memory.recalled();
        searched_again += memory.searched();
      }
      // Most bodies creep (their pairs' motion crosses `extra` after a few rebuilds); every
      // seventh jumps; every fifth turns by up to 0.05 rad about a random axis.
      for (std::size_t b = 0; b < bodies.size(); ++b) {
        const double step = b % 7 == 0 ? 0.3 : 0.006;  // m
        Quat turn = Quat::Identity();
        if (b % 5 == 0) turn = Quat(Eigen::AngleAxisd(0.05 * u(rng), random_unit(rng)));
        bodies[b] = Posed(*bodies[b].shape, bodies[b].scale, bodies[b].position + step * Vec3(u(rng), u(rng), u(rng)),
                          turn * bodies[b].q);
      }
    }
    CHECK(recalled > 0);        // searches kept
    CHECK(searched_again > 0);  // and made anew
    if (threads == 1) recalled_at_one = recalled_each;
    CHECK(recalled_each == recalled_at_one);
  }
  omp_set_num_threads(threads_before);
}

TEST_CASE("remembered searches relabelled to a rank's next bodies give the list a new search gives") {
  const std::vector<Shape> shapes = {make_cube(0.5, 0.05), make_octahedron(0.6, 0.04), make_tetrahedron(0.4, 0.05)};
  const double range = 0.05, extra = 0.05;  // m
  std::vector<Posed> all = random_bodies(shapes, 60);  // indexed by global id
  // A rank's local bodies before and after a migration: increasing ids, some left, some new.
  std::vector<std::uint32_t> was, now;
  for (std::uint32_t g = 0; g < all.size(); ++g) {
    if (g % 4 != 3) was.push_back(g);
    if (g % 5 != 4) now.push_back(g);
  }
  const auto search = [&](CandidateMemory& memory, const std::vector<std::uint32_t>& ids) {
    std::vector<PosedBody> posed;
    std::vector<Vec3> x;
    std::vector<Quat> q;
    std::vector<double> reach;  // m
    for (std::uint32_t g : ids) {
      posed.push_back(all[g].body());
      x.push_back(all[g].position);
      q.push_back(all[g].q);
      reach.push_back(core_reach(all[g]));
    }
    const std::vector<BodyPair> near = near_pairs(posed, range);
    const PairList want = reference(near, posed, range);
    PairList got;
    memory.find(near, posed, {x.data(), q.data(), reach.data()}, range, got);
    check_same_list(got, want);
    return near;
  };
  CandidateMemory memory(extra);
  search(memory, was);
  for (Posed& b : all) b = Posed(*b.shape, b.scale, b.position + Vec3(0.004, -0.003, 0.002), b.q);  // all moved alike
  memory.relabel(was, now);
  const std::vector<BodyPair> near = search(memory, now);
  // No pair moved relative to itself: every pair of two bodies local before kept its search.
  const auto was_local = [&](std::uint32_t k) { return std::binary_search(was.begin(), was.end(), now[k]); };
  const auto both = std::count_if(near.begin(), near.end(), [&](BodyPair p) { return was_local(p.i) && was_local(p.j); });
  CHECK(both > 0);
  CHECK(memory.recalled() == std::size_t(both));
  CHECK(memory.searched() == near.size() - std::size_t(both));  // the new bodies' pairs
}

TEST_CASE("a driver pair's candidates sorted in place are the pair's features in key order") {
  const std::vector<Shape> shapes = {make_cube(0.5, 0.05), make_octahedron(0.6, 0.04), make_tetrahedron(0.4, 0.05)};
  const std::vector<Posed> bodies = random_bodies(shapes, 30);
  std::vector<PosedBody> posed;
  for (const Posed& b : bodies) posed.push_back(b.body());
  std::mt19937_64 rng(11);
  std::size_t unsorted = 0;  // runs shuffled out of key order (a driver's search gives any order)
  for (const BodyPair& p : near_pairs(posed, 0.3)) {
    std::vector<FeaturePair> found;
    candidate_features(posed[p.i], posed[p.j], 0.3, found);
    std::shuffle(found.begin(), found.end(), rng);
    std::vector<std::uint64_t> want = keys(found);
    unsorted += !std::is_sorted(want.begin(), want.end());
    std::sort(want.begin(), want.end());
    sort_by_key(found);
    CHECK(keys(found) == want);
  }
  CHECK(unsorted > 10);
}

TEST_CASE("a gap rounded to a float is the float std::nextafter gives below it, on both sides of 0") {
  // gap_below steps the float's bits itself: it must be the nearest float <= the gap, as before.
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<std::pair<double, double>> cases{// m^2 core distance^2, m radii
                                               {0.0, 1e-46}, {0.0, 0.0}, {1e-90, 0.0}, {1e-6, 1e-3}, {1e-8, 1e-3},
                                               {1.0 / 3.0, 0.5}, {0.01, 0.2}, {2.0, 0.0}};
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 2e-3);
  for (int k = 0; k < 1000; ++k) cases.emplace_back(u(rng) * u(rng), u(rng));
  for (const auto& [d2, radii] : cases) {
    const double exact = std::sqrt(d2) - radii;  // m, the gap as gap_below makes it
    const float f = static_cast<float>(exact);
    const float want = static_cast<double>(f) > exact ? std::nextafter(f, -inf) : f;
    const float got = gap_below(d2, radii);
    CHECK(std::memcmp(&got, &want, sizeof got) == 0);
    CHECK(static_cast<double>(got) <= exact);
  }
}

TEST_CASE("a list's results sized after carry_history keep the contact counts it carried") {
  PairList old;
  old.pairs = {{0, 1}, {1, 2}};
  old.slot_begin = {0, 2, 3};
  old.features = {FeaturePair{PairType::vertex_face, 0, 1}, FeaturePair{PairType::edge_edge, 1, 2},
                  FeaturePair{PairType::vertex_vertex, 0, 0}};
  size_slots(old);
  old.active = {1, 1, 1};
  PairList fresh = old;  // the same keys: every history carried
  fresh.active.assign(3, 0);
  size_slots(fresh);
  carry_history(old, fresh);
  size_results(fresh);
  CHECK(fresh.touching == std::vector<std::uint16_t>{2, 1});
  CHECK(fresh.force_i.size() == 2);
  CHECK(fresh.linear_steps.size() == 2);
  CHECK(fresh.block_contacts.size() == 1);
  CHECK(fresh.pending.empty());  // a dense list keeps its pairs' energies on their first slots
}

// `v = {}` keeps a vector's buffer: what a rebuild frees must give its memory back.
TEST_CASE("a list's results, gaps and records are freed, not only emptied, before a rebuild copies its active part") {
  PairList list;
  list.pairs = {{0, 1}, {1, 2}, {2, 3}};
  list.slot_begin = {0, 1, 2, 3};
  list.features.assign(3, FeaturePair{PairType::vertex_vertex, 0, 0});
  list.gap_at_build.assign(3, 0.0);
  list.slot_gap.assign(3, 0.0f);
  list.recording = true;
  size_slots(list);
  size_results(list);
  REQUIRE(list.force_i.capacity() >= 3);
  REQUIRE(list.records.capacity() >= 3);
  free_results(list);
  list.set_recording(false);
  for (std::size_t c : {list.force_i.capacity(), list.torque_i.capacity(), list.torque_j.capacity(),
                        list.touching.capacity(), list.linear_steps.capacity(),
                        list.block_contacts.capacity(), list.block_ended.capacity(), list.gap_at_build.capacity(),
                        list.slot_gap.capacity(), list.records.capacity()})
    CHECK(c == 0);
  CHECK(list.slots.size() == 3);  // the histories and the pairs' open energies stay: active_part reads them
}
