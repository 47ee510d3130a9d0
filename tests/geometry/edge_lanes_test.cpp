// Two edge-edge pairs at once (edge_edge_lanes) against feature_contact on each, bit for bit, on
// bodies of every kind placed about touching (parallel edges and crossing cores included).
#include <catch2/catch.hpp>

#include <cstring>

#include "geometry/features.hpp"
#include "random_pairs.hpp"

using namespace polydem;
using namespace polydem::test;

TEST_CASE("edge-edge lanes find what edge_edge finds, with its bits") {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int touching = 0, rejected = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const PairPose p = random_pair_pose(rng, trial);
    const double along = touching_distance(p) - 0.1 * u(rng);  // m: overlaps up to 0.1, cores crossing at times
    const Posed a(*p.sa, p.scale_a, p.lateral + along * p.direction, p.qa), b(*p.sb, p.scale_b, Vec3::Zero(), p.qb);
    const PosedBody A = a.body(), B = b.body();
    const double max_gap = trial % 2 == 0 ? 0.0 : 0.05;  // m
    const int na = int(p.sa->edges.size()), nb = int(p.sb->edges.size());
    for (int k = 0; k + 1 < na * nb; k += 1) {
      const int fa[2] = {k / nb, (k + 1 + trial) % (na * nb) / nb}, fb[2] = {k % nb, (k + 1 + trial) % (na * nb) % nb};
      ContactPoint got[2], want[2];
      const unsigned found = edge_edge_lanes(A, B, fa, fb, max_gap, got);
      for (int l = 0; l < 2; ++l) {
        const FeaturePair f{PairType::edge_edge, std::uint16_t(fa[l]), std::uint32_t(fb[l])};
        const bool expected = feature_contact(A, B, f, max_gap, want[l]);
        REQUIRE(bool(found & (1u << l)) == expected);
        if (!expected) {
          ++rejected;
          continue;
        }
        ++touching;
        REQUIRE(std::memcmp(&got[l].normal, &want[l].normal, sizeof(Vec3)) == 0);
        REQUIRE(std::memcmp(&got[l].point, &want[l].point, sizeof(Vec3)) == 0);
        REQUIRE(std::memcmp(&got[l].gap, &want[l].gap, sizeof(double)) == 0);
      }
    }
  }
  CHECK(touching > 100);
  CHECK(rejected > 1000);
}
