// Fast path against brute force: candidates built at one pose with a skin still hold every
// contact after each vertex moved by less than skin / 2 (SPEC "Verlet list").
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <tuple>

#include "random_pairs.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

using Contacts = std::vector<std::pair<FeaturePair, ContactPoint>>;

auto key(const FeaturePair& f) { return std::make_tuple(static_cast<int>(f.type), f.a, f.b); }

void sort_by_key(Contacts& c) {
  std::sort(c.begin(), c.end(), [](const auto& x, const auto& y) { return key(x.first) < key(y.first); });
}

// m, largest displacement of a vertex of `before` in `after` (same shape and scale).
double max_vertex_motion(const Posed& before, const Posed& after) {
  double m = 0.0;
  for (std::size_t i = 0; i < before.world.size(); ++i) m = std::max(m, (after.world[i] - before.world[i]).norm());
  return m;
}

// The body moved by a random translation and rotation that keep every vertex within `reach`.
Posed jiggle(const Posed& p, double reach, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> frac(0.0, 1.0);
  const double share = frac(rng);  // of `reach` spent on translation, the rest on rotation
  const double lever = std::max(p.core_radius(), 1e-12);
  const Vec3 shift = share * reach * frac(rng) * random_unit(rng);
  // A vertex at distance l from the centre moves at most l * angle when turned by angle.
  const double angle = (1.0 - share) * reach * frac(rng) / lever;
  const Quat turn(Eigen::AngleAxisd(angle, random_unit(rng)));
  return Posed(*p.shape, p.scale, p.position + shift, turn * p.q);
}

}  // namespace

TEST_CASE("contacts from Verlet candidates equal the brute-force contacts after motion < skin/2") {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> frac(0.0, 1.0);
  std::array<int, kPairTypeCount> seen{};
  std::size_t candidates_total = 0, pairs_total = 0;
  int trials_with_contacts = 0;
  const int trials = 3000;
  for (int trial = 0; trial < trials; ++trial) {
    const PairPose pose = random_pair_pose(rng, trial);
    const double ra = pose.scale_a * pose.sa->radius, rb = pose.scale_b * pose.sb->radius;
    // Overlap from none to 1.5 (rA + rB): past rA + rB the cores cross, the hard regime.
    const double along = touching_distance(pose) - 1.5 * (ra + rb) * frac(rng) + 0.02 * (frac(rng) - 0.5);
    const Posed a0(*pose.sa, pose.scale_a, pose.lateral + along * pose.direction, pose.qa);
    const Posed b0(*pose.sb, pose.scale_b, Vec3::Zero(), pose.qb);
    const double skin = 0.05 * std::max(ra + rb, 0.1);
    std::vector<FeaturePair> candidates;
    candidate_features(a0.body(), b0.body(), skin, candidates);
    // Deterministic order: strictly increasing (type, feature in A, feature in B), no repeats.
    for (std::size_t k = 1; k < candidates.size(); ++k) REQUIRE(key(candidates[k - 1]) < key(candidates[k]));
    const Posed a1 = jiggle(a0, 0.499 * skin, rng), b1 = jiggle(b0, 0.499 * skin, rng);
    REQUIRE(max_vertex_motion(a0, a1) < 0.5 * skin);
    REQUIRE(max_vertex_motion(b0, b1) < 0.5 * skin);

    Contacts fast;
    for (const FeaturePair& f : candidates) {
      ContactPoint c;
      if (feature_contact(a1.body(), b1.body(), f, 0.0, c)) fast.emplace_back(f, c);
    }
    Contacts brute = brute_force_contacts(a1.body(), b1.body());
    sort_by_key(fast);
    sort_by_key(brute);
    REQUIRE(fast.size() == brute.size());
    for (std::size_t k = 0; k < brute.size(); ++k) {
      REQUIRE(key(fast[k].first) == key(brute[k].first));
      REQUIRE(fast[k].second.gap == brute[k].second.gap);
      ++seen[static_cast<int>(brute[k].first.type)];
    }
    trials_with_contacts += !brute.empty();
    candidates_total += candidates.size();
    const Shape &sa = *pose.sa, &sb = *pose.sb;
    pairs_total += sa.vertices.size() * (sb.vertices.size() + sb.edges.size() + sb.faces.size()) +
                   sa.edges.size() * (sb.vertices.size() + sb.edges.size()) + sa.faces.size() * sb.vertices.size();
  }
  INFO("candidates " << candidates_total << " of " << pairs_total << " feature pairs");
  CHECK(trials_with_contacts > trials / 2);
  for (int type = 0; type < kPairTypeCount; ++type) CHECK(seen[type] > 20);
  // The bounding-sphere pre-filter and the distance test keep the lists short.
  CHECK(candidates_total * 10 < pairs_total);
}
