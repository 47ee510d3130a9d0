// Separation distance: for separated convex bodies, the smallest feature-pair gap is the true
// distance between the rounded bodies, computed independently by GJK on the vertex sets.
#include <catch2/catch.hpp>

#include <limits>

#include "random_pairs.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Smallest gap over every feature pair, interior rules applied, no gap limit.
double min_feature_gap(const PosedBody& a, const PosedBody& b, PairType& type) {
  double best = kInfinity;
  const Shape &sa = *a.shape, &sb = *b.shape;
  auto visit = [&](PairType t, std::size_t na, std::size_t nb) {
    for (std::size_t i = 0; i < na; ++i)
      for (std::size_t j = 0; j < nb; ++j) {
        ContactPoint c;
        if (feature_contact(a, b, {t, std::uint16_t(i), std::uint16_t(j)}, kInfinity, c) && c.gap < best) {
          best = c.gap;
          type = t;
        }
      }
  };
  visit(PairType::vertex_vertex, sa.vertices.size(), sb.vertices.size());
  visit(PairType::vertex_edge, sa.vertices.size(), sb.edges.size());
  visit(PairType::edge_vertex, sa.edges.size(), sb.vertices.size());
  visit(PairType::vertex_face, sa.vertices.size(), sb.faces.size());
  visit(PairType::face_vertex, sa.faces.size(), sb.vertices.size());
  visit(PairType::edge_edge, sa.edges.size(), sb.edges.size());
  return best;
}

}  // namespace

TEST_CASE("min feature gap equals the GJK distance of separated rounded bodies") {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> frac(0.0, 1.0);
  std::array<int, kPairTypeCount> closest_type{};
  const int trials = 2000;
  for (int trial = 0; trial < trials; ++trial) {
    const PairPose pose = random_pair_pose(rng, trial);
    const double along = touching_distance(pose) + 0.3 * frac(rng);
    const Posed a(*pose.sa, pose.scale_a, pose.lateral + along * pose.direction, pose.qa);
    const Posed b(*pose.sb, pose.scale_b, Vec3::Zero(), pose.qb);
    const double truth = rounded_distance(pose, along);
    REQUIRE(truth > 0.0);
    PairType type = PairType::vertex_vertex;
    const double gap = min_feature_gap(a.body(), b.body(), type);
    INFO("trial " << trial << " " << pose.sa->name << " / " << pose.sb->name);
    REQUIRE(gap == Approx(truth).margin(1e-8));
    ++closest_type[static_cast<int>(type)];
    // Candidates use point-set distances: none just below the distance, some just above it.
    std::vector<FeaturePair> below, above;
    candidate_features(a.body(), b.body(), truth - 1e-8, below);
    candidate_features(a.body(), b.body(), truth + 1e-8, above);
    CHECK(below.empty());
    CHECK_FALSE(above.empty());
  }
  // Every kind of pair was the closest one in some trial.
  for (int t = 0; t < kPairTypeCount; ++t) CHECK(closest_type[t] > 10);
}

TEST_CASE("a sphere-sphere pair is a single vertex_vertex candidate") {
  const Shape s = make_sphere(0.5);
  const Posed a(s, 1.0, Vec3(0, 0, 1.05)), b(s, 1.0, Vec3::Zero());
  std::vector<FeaturePair> c;
  candidate_features(a.body(), b.body(), 0.1, c);
  REQUIRE(c.size() == 1);
  CHECK(c[0].type == PairType::vertex_vertex);
  c.clear();
  candidate_features(a.body(), b.body(), 0.04, c);
  CHECK(c.empty());
}
