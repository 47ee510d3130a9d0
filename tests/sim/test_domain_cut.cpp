// Recursive coordinate bisection (sim/domain_cut.hpp) on constructed centres: equal weights
// give equal counts, a weighted bed and its falling grains get equal shares of the weight
// where equal counts leave one rank 10 times the other's, the levels cut the longest side
// of their own part, and the ghost distance is the Euclidean distance to a part's box.
#include <algorithm>
#include <cmath>

#include <catch2/catch.hpp>

#include "sim/domain_cut.hpp"
#include "sim/ghost_plan.hpp"
#include "sim/rank_energy.hpp"

using namespace polydem;

TEST_CASE("bisection at equal weights: collinear centres in 3 equal parts, ghosts within the halo") {
  std::vector<Vec3> x;
  for (int k = 0; k < 12; ++k) x.push_back(Vec3(0.1 * k, 0.01 * (k % 3), 0.0));
  const DomainCut s = cut_domain(x, std::vector<double>(12, 1.0), 3);
  REQUIRE(s.nodes.size() == 2);
  CHECK(s.nodes[0].axis == 0);  // 1 part below, 2 above: a third of the weight below
  CHECK(s.nodes[0].at == x[4].x());
  CHECK(s.nodes[1].axis == 0);
  CHECK(s.nodes[1].at == x[8].x());
  int owned[3] = {0, 0, 0};
  for (const Vec3& c : x) ++owned[s.owner(c)];
  CHECK(owned[0] == 4);
  CHECK(owned[1] == 4);
  CHECK(owned[2] == 4);
  const GhostPlan plan = plan_ghosts(s, 1, x, 0.15);  // bodies 4..7 owned; 3, 8 and 9 within 0.15 m of [0.4, 0.8)
  CHECK(plan.local == std::vector<std::uint32_t>{3, 4, 5, 6, 7, 8, 9});
  CHECK(plan.ghost == std::vector<std::uint8_t>{1, 0, 0, 0, 0, 1, 1});
}

TEST_CASE("weights from the contact work balance a bed and its falling grains") {
  // A column of 200 centres 1 cm apart: the lower 100 a bed (weight 20: the body's own 2 and
  // 18 halves of candidate feature pairs), the upper 100 falling alone (weight 2).
  std::vector<Vec3> x;
  std::vector<double> w;
  for (int k = 0; k < 200; ++k) {
    x.push_back(Vec3(0.0, 0.0, 0.01 * k));
    w.push_back(k < 100 ? 20.0 : 2.0);
  }
  const DomainCut counts = cut_domain(x, std::vector<double>(200, 1.0), 2);
  CHECK(part_loads(counts, x, w) == std::vector<double>{2000.0, 200.0});  // the bed on one rank: 10 to 1
  CHECK(imbalance(part_loads(counts, x, w)) == Approx(2000.0 / 1100.0));
  const DomainCut two = cut_domain(x, w, 2);
  CHECK(part_loads(two, x, w) == std::vector<double>{1100.0, 1100.0});  // 55 bed bodies, then 45 and the grains
  CHECK(imbalance(part_loads(two, x, w)) == 1.0);
  const DomainCut three = cut_domain(x, w, 3);
  const std::vector<double> loads = part_loads(three, x, w);
  REQUIRE(loads.size() == 3);
  for (double l : loads) CHECK(std::abs(l - 2200.0 / 3.0) <= 20.0);  // within one bed body of the mean
  CHECK(imbalance(loads) < 1.05);
}

TEST_CASE("each level cuts the longest side of its part, ghosts by the distance to a box") {
  // A plate of 8 x 6 centres 0.25 m apart: the first cut across x (1.75 m > 1.25 m), then
  // each half (0.75 m x 1.25 m) across y: 4 parts of 12.
  std::vector<Vec3> x;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 6; ++j) x.push_back(Vec3(0.25 * i, 0.25 * j, 0.0));
  const DomainCut cut = cut_domain(x, std::vector<double>(x.size(), 1.0), 4);
  REQUIRE(cut.nodes.size() == 3);
  CHECK(cut.nodes[0].axis == 0);
  CHECK(cut.nodes[0].at == 1.0);
  CHECK(cut.nodes[1].axis == 1);
  CHECK(cut.nodes[2].axis == 1);
  CHECK(part_loads(cut, x, std::vector<double>(x.size(), 1.0)) == std::vector<double>{12.0, 12.0, 12.0, 12.0});
  for (const Vec3& c : x) CHECK(cut.distance(cut.owner(c), c) == 0.0);
  const double y = cut.nodes[1].at;  // m, part 0 is x < 1, y < this
  CHECK(cut.distance(0, Vec3(1.3, y + 0.4, 5.0)) == Approx(std::sqrt(0.3 * 0.3 + 0.4 * 0.4)).epsilon(1e-12));
  CHECK(cut.distance(0, Vec3(-50.0, -50.0, -50.0)) == 0.0);  // open to infinity outside the centres
  CHECK(cut.owner(Vec3(-50.0, -50.0, -50.0)) == 0);
}

TEST_CASE("imbalance is the largest load over the mean") {
  CHECK(imbalance({3.0, 1.0}) == 1.5);
  CHECK(imbalance({2.0, 2.0, 2.0}) == 1.0);
  CHECK(imbalance({0.0, 0.0}) == 1.0);
}

TEST_CASE("A kept cut is cut again once its imbalance has cost more than a cut, never within the floor") {
  RecutRule rule;  // floor 1.05
  const std::vector<double> loads{110.0, 90.0};  // a step: the run waits 10 for the most loaded part
  CHECK_FALSE(rule.pays(loads, 10, 250.0));      // lost 100
  CHECK_FALSE(rule.pays(loads, 10, 250.0));      // 200
  CHECK(rule.pays(loads, 10, 250.0));            // 300: past the cost
  rule.cut();
  CHECK_FALSE(rule.pays(loads, 20, 250.0));      // from zero again: 200
  CHECK(rule.pays({140.0, 60.0}, 2, 250.0));     // 200 + 2 x 40: a larger wait pays sooner
  RecutRule fine;
  for (int k = 0; k < 100; ++k) CHECK_FALSE(fine.pays({102.0, 98.0}, 1000, 250.0));  // 1.02: within the floor
  CHECK(fine.lost == 2000.0 * 100);  // lost all the same: a cut once past the floor
  CHECK(fine.pays({106.0, 94.0}, 1, 250.0));
}

namespace {

// A list of `pairs`, each with `slots` candidate feature pairs and `touching` active sub-contacts.
PairList list_of(const std::vector<BodyPair>& pairs, const std::vector<std::uint32_t>& slots,
                 const std::vector<std::uint16_t>& touching) {
  PairList list;
  list.pairs = pairs;
  list.slot_begin = {0};
  for (std::uint32_t s : slots) list.slot_begin.push_back(list.slot_begin.back() + s);
  list.touching = touching;
  return list;
}

// A column of 120 bodies 1 cm apart, all owned: the lower 60 a bed chained by pairs (k, k + 1) of
// 6 candidate feature pairs each with `contacts` active sub-contacts, the upper 60 free. Each
// body's cut weight (CutWeight, an isotropic body's passes) from owned_work.
std::vector<double> column_weights(std::uint16_t contacts, std::vector<Vec3>& x) {
  LocalStore store;
  std::vector<BodyPair> pairs;
  for (std::uint32_t k = 0; k < 120; ++k) {
    store.global_id.push_back(k);
    store.ghost.push_back(0);
    x.push_back(Vec3(0.0, 0.0, 0.01 * k));
    if (k + 1 < 60) pairs.push_back(BodyPair{k, k + 1});
  }
  const OwnedWork work = owned_work(list_of(pairs, std::vector<std::uint32_t>(pairs.size(), 6),
                                            std::vector<std::uint16_t>(pairs.size(), contacts)),
                                    PairList{}, store);
  std::vector<double> w;
  for (std::size_t k = 0; k < 120; ++k) w.push_back(double(CutWeight::of(280.0f, work.candidates[k], work.contacts[k])));
  return w;
}

}  // namespace

TEST_CASE("A body's work counts its pairs' candidates and sub-contacts on both sides, a ghost's pair and a driver pair twice") {
  LocalStore store;
  store.global_id = {0, 1, 2};
  store.ghost = {0, 0, 1};  // body 2 a ghost: this rank computes the pair (1, 2) whole
  const PairList bodies = list_of({BodyPair{0, 1}, BodyPair{1, 2}}, {3, 5}, {2, 1});
  const PairList drivers = list_of({BodyPair{0, 0}}, {4}, {4});  // a wall on body 0
  const OwnedWork work = owned_work(bodies, drivers, store);
  CHECK(work.candidates == std::vector<std::uint32_t>{3 + 2 * 4, 3 + 2 * 5});
  CHECK(work.contacts == std::vector<std::uint32_t>{2 + 2 * 4, 2 + 2 * 1});
}

TEST_CASE("A touching bed weighs its sub-contacts: its rank takes fewer bodies, the weights split equally") {
  std::vector<Vec3> x, same;
  const std::vector<double> near = column_weights(0, x), touching = column_weights(4, same);
  const double heaviest = *std::max_element(touching.begin(), touching.end());
  const DomainCut by_near = cut_domain(x, near, 2), by_touching = cut_domain(x, touching, 2);
  const std::vector<double> loads = part_loads(by_touching, x, touching);
  CHECK(std::abs(loads[0] - loads[1]) <= heaviest);  // the plane where the summed weights meet
  int below_near = 0, below_touching = 0;
  for (const Vec3& c : x) {
    below_near += by_near.owner(c) == 0;
    below_touching += by_touching.owner(c) == 0;
  }
  // Touching pairs cost the kernels and the law beyond their candidates (counted): the bed's
  // rank holds fewer bodies than where its pairs are only near, every bed body weighing more.
  CHECK(below_touching < below_near);
  CHECK(below_touching < 60);
  for (std::size_t k = 0; k < 60; ++k) CHECK(touching[k] > near[k]);
  for (std::size_t k = 60; k < 120; ++k) CHECK(touching[k] == near[k]);
}
