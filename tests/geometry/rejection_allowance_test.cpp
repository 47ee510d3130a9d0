// A rejected feature pair's allowance (features.hpp, rejection_allowance): after any later motion
// of the two bodies whose displacement bounds (rebuild_trigger.hpp's: |dx| + 2 R sin(angle / 2), R
// the core reach, from the list's build) add up, with the bounds at the rejection, to less than
// the allowance, the kernel still rejects the pair. The slot scan skips such calls (pair_kernel.hpp's
// retire_slot), so a wrong allowance would drop a contact.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>

#include "random_pairs.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

// m, rebuild_trigger.hpp's displacement bound of `now` from `built` (the same formula).
double displacement_bound(const Posed& built, const Posed& now) {
  const Quat rel = now.q * built.q.conjugate();
  return (now.position - built.position).norm() + 2.0 * built.core_radius() * rel.vec().norm() / rel.norm();
}

// The body moved from `p` by a random translation and turn whose displacement bound is `budget`
// (m): a share of it along a random direction, the rest as the chord of its core reach.
Posed moved_by(const Posed& p, double budget, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> frac(0.0, 1.0);
  const double share = frac(rng), reach = std::max(p.core_radius(), 1e-12);
  const double chord = std::min((1.0 - share) * budget, 2.0 * reach);  // m, 2 R sin(angle / 2)
  const Quat turn(Eigen::AngleAxisd(2.0 * std::asin(chord / (2.0 * reach)), random_unit(rng)));
  return Posed(*p.shape, p.scale, p.position + share * budget * random_unit(rng), turn * p.q);
}

// Every vertex-face, face-vertex and edge-edge pair of a and b.
std::vector<FeaturePair> retirable_pairs(const Shape& a, const Shape& b) {
  std::vector<FeaturePair> out;
  for (std::size_t v = 0; v < a.vertices.size(); ++v)
    for (std::size_t f = 0; f < b.faces.size(); ++f) out.push_back({PairType::vertex_face, std::uint16_t(v), std::uint32_t(f)});
  for (std::size_t f = 0; f < a.faces.size(); ++f)
    for (std::size_t v = 0; v < b.vertices.size(); ++v) out.push_back({PairType::face_vertex, std::uint16_t(f), std::uint32_t(v)});
  for (std::size_t e = 0; e < a.edges.size(); ++e)
    for (std::size_t g = 0; g < b.edges.size(); ++g) out.push_back({PairType::edge_edge, std::uint16_t(e), std::uint32_t(g)});
  return out;
}

}  // namespace

TEST_CASE("a rejected feature pair stays rejected while the bodies move less than its allowance") {
  std::mt19937_64 rng(38);
  std::uniform_real_distribution<double> frac(0.0, 1.0);
  std::array<int, kPairTypeCount> checked{};
  int with_allowance = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const PairPose pose = random_pair_pose(rng, trial);
    const double ra = pose.scale_a * pose.sa->radius, rb = pose.scale_b * pose.sb->radius;
    const double along = touching_distance(pose) - 1.5 * (ra + rb) * frac(rng) + 0.02 * (frac(rng) - 0.5);
    // The list's build (0) and the rejection's step (1), each body moved by up to 0.01 m from the build.
    const Posed a0(*pose.sa, pose.scale_a, pose.lateral + along * pose.direction, pose.qa);
    const Posed b0(*pose.sb, pose.scale_b, Vec3::Zero(), pose.qb);
    const Posed a1 = moved_by(a0, 0.01 * frac(rng), rng), b1 = moved_by(b0, 0.01 * frac(rng), rng);
    const double moved1 = displacement_bound(a0, a1) + displacement_bound(b0, b1);  // m
    const double band = 0.05 * std::max(ra + rb, 0.1);  // m, a skin's size
    for (const FeaturePair f : retirable_pairs(*pose.sa, *pose.sb)) {
      ContactPoint c;
      if (feature_contact(a1.body(), b1.body(), f, band, c) || c.gap != 1.0) continue;
      const double allowance = rejection_allowance(a1.body(), b1.body(), f);  // m
      REQUIRE(allowance >= 0.0);
      if (allowance <= moved1) continue;
      ++with_allowance;
      // Later steps near the allowance's edge: both bodies' bounds then and at the rejection just under it.
      for (int later = 0; later < 4; ++later) {
        const double budget = (allowance - moved1) * (0.9 + 0.0999 * frac(rng)), share = frac(rng);  // m
        const Posed a2 = moved_by(a0, share * budget, rng), b2 = moved_by(b0, (1.0 - share) * budget, rng);
        if (moved1 + displacement_bound(a0, a2) + displacement_bound(b0, b2) > allowance) continue;  // round-off
        INFO("trial " << trial << " type " << int(f.type) << " features " << f.a << ", " << f.b << " allowance " << allowance);
        CHECK_FALSE(feature_contact(a2.body(), b2.body(), f, band, c));
        ++checked[std::size_t(f.type)];
      }
    }
  }
  // Every kind that makes an allowance was tried, many times over.
  CHECK(with_allowance > 1000);
  CHECK(checked[std::size_t(PairType::vertex_face)] > 1000);
  CHECK(checked[std::size_t(PairType::face_vertex)] > 1000);
  CHECK(checked[std::size_t(PairType::edge_edge)] > 1000);
}

TEST_CASE("a rejection's allowance is 0 where no bound is made") {
  // A half-size cube high above a unit cube: its vertices project inside the top and bottom faces,
  // rejected by their distance to them; outside the side faces, with an allowance.
  static const Shape cube = make_cube(0.5, 0.05);
  const Posed a(cube, 0.5, Vec3(0.0, 0.0, 3.0)), b(cube, 1.0, Vec3::Zero());
  int by_distance = 0;
  for (std::uint16_t v = 0; v < cube.vertices.size(); ++v)
    for (std::uint32_t f = 0; f < cube.faces.size(); ++f) {
      ContactPoint c;
      REQUIRE_FALSE(feature_contact(a.body(), b.body(), {PairType::vertex_face, v, f}, 0.01, c));
      if (c.gap == 0.0) ++by_distance;
    }
  CHECK(by_distance == 16);  // each vertex over the top face (too far) and the bottom one (behind it)
  CHECK(rejection_allowance(a.body(), b.body(), {PairType::vertex_vertex, 0, 0}) == 0.0);
}

TEST_CASE("an edge-edge allowance stays below the shift that makes the contact") {
  // A unit cube turned 45 deg about x rests its bottom edge (along x) on a unit cube's top edge
  // (along y at x = 0.5), 0.1 m past that edge's end: a shift of A by 0.1 m along -y (a
  // displacement bound of 0.1 m) brings the lines' closest point onto the edge.
  static const Shape cube = make_cube(0.5, 0.05);
  const Quat turned(Eigen::AngleAxisd(0.25 * M_PI, Vec3::UnitX()));
  const Posed b(cube, 1.0, Vec3::Zero());
  const auto a_at = [&](double y) { return Posed(cube, 1.0, Vec3(0.5, y, 0.5 + 0.5 * std::sqrt(2.0)), turned); };
  int edge_pairs = 0;
  for (std::uint16_t e = 0; e < cube.edges.size(); ++e)
    for (std::uint32_t g = 0; g < cube.edges.size(); ++g) {
      const FeaturePair f{PairType::edge_edge, e, g};
      ContactPoint c;
      if (feature_contact(a_at(0.6).body(), b.body(), f, 0.01, c) || c.gap != 1.0) continue;
      if (!feature_contact(a_at(0.49).body(), b.body(), f, 0.01, c)) continue;  // not a pair the shift makes
      ++edge_pairs;
      const double allowance = rejection_allowance(a_at(0.6).body(), b.body(), f);  // m
      CHECK(allowance > 0.001);
      CHECK(allowance < 0.1);
    }
  CHECK(edge_pairs >= 1);
}
