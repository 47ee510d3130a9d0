// The two builds of the feature kernels (features.hpp: SSE2's, and AVX's chosen where the CPU has
// it) give the same bits: a run's results do not depend on which machine it ran on.
#include <catch2/catch.hpp>

#include <array>
#include <cstring>

#include "random_pairs.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

// Every feature pair of a and b, of every type.
std::vector<FeaturePair> every_pair(const Shape& a, const Shape& b) {
  const std::array<std::size_t, 3> na = {a.vertices.size(), a.edges.size(), a.faces.size()};
  const std::array<std::size_t, 3> nb = {b.vertices.size(), b.edges.size(), b.faces.size()};
  // PairType -> (feature kind in A, in B): 0 vertex, 1 edge, 2 face.
  const std::array<std::array<int, 2>, kPairTypeCount> kinds = {{{0, 0}, {0, 1}, {1, 0}, {0, 2}, {2, 0}, {1, 1}}};
  std::vector<FeaturePair> out;
  for (int t = 0; t < kPairTypeCount; ++t)
    for (std::size_t i = 0; i < na[kinds[t][0]]; ++i)
      for (std::size_t j = 0; j < nb[kinds[t][1]]; ++j) out.push_back({PairType(t), std::uint16_t(i), std::uint32_t(j)});
  return out;
}

// The answer and every bit of what the kernel wrote (from the same filled start).
struct Answer {
  bool hit;
  ContactPoint c;
};

Answer evaluate(const std::array<FeatureKernel, kPairTypeCount>& table, const PosedBody& A, const PosedBody& B,
                FeaturePair f, double max_gap) {
  Answer r{false, {Vec3::Constant(7.0), Vec3::Constant(7.0), 7.0}};
  r.hit = table[std::size_t(f.type)](A, B, f.a, f.b, max_gap, r.c);
  return r;
}

bool same_bits(const Answer& x, const Answer& y) {
  return x.hit == y.hit && std::memcmp(x.c.normal.data(), y.c.normal.data(), sizeof(double) * 3) == 0 &&
         std::memcmp(x.c.point.data(), y.c.point.data(), sizeof(double) * 3) == 0 &&
         std::memcmp(&x.c.gap, &y.c.gap, sizeof(double)) == 0;
}

}  // namespace

TEST_CASE("the AVX and SSE2 builds of the feature kernels give the same bits") {
  if (!cpu_has_avx()) {
    WARN("no AVX on this CPU: its runs use the SSE2 kernels alone");
    return;
  }
  // The zoo's shapes, and each again as a non-convex body (two-sided faces, no turn-over rule).
  std::vector<Shape> open_zoo = shape_zoo();
  for (Shape& s : open_zoo) s.convex = false;
  std::mt19937_64 rng(44);
  std::uniform_real_distribution<double> frac(0.0, 1.0);
  std::array<int, kPairTypeCount> hits{};
  int compared = 0;
  for (int trial = 0; trial < 600; ++trial) {
    PairPose pose = random_pair_pose(rng, trial);
    if (trial % 4 == 1) pose.sb = &open_zoo[std::size_t(pose.sb - shape_zoo().data())];
    const double ra = pose.scale_a * pose.sa->radius, rb = pose.scale_b * pose.sb->radius;
    // From apart to cores crossing (overlap up to 3 (rA + rB)).
    const double along = touching_distance(pose) - 3.0 * (ra + rb) * frac(rng) + 0.02 * (frac(rng) - 0.5);
    const Posed a(*pose.sa, pose.scale_a, pose.lateral + along * pose.direction, pose.qa);
    const Posed b(*pose.sb, pose.scale_b, Vec3::Zero(), pose.qb);
    for (const FeaturePair& f : every_pair(*pose.sa, *pose.sb))
      for (const double max_gap : {0.0, 0.01, 1.0}) {  // m
        const Answer sse2 = evaluate(kSse2Kernels, a.body(), b.body(), f, max_gap);
        const Answer avx = evaluate(kAvxKernels, a.body(), b.body(), f, max_gap);
        REQUIRE(same_bits(sse2, avx));
        hits[std::size_t(f.type)] += sse2.hit;
        ++compared;
      }
  }
  INFO("feature pairs compared: " << compared);
  for (int t = 0; t < kPairTypeCount; ++t) CHECK(hits[t] > 50);  // every kernel's accepted path taken
  CHECK(kFeatureKernels == kAvxKernels);  // chosen where the CPU has it
}
