// The rebuild's feature candidates against brute force: the slab, sphere, plane, box and line
// filters of candidate_features may only skip pairs the exact distance rejects, so the list must
// be every feature pair of the two cores closer than rA + rB + range, in key order, with the
// very distances (bit for bit) the exact tests give.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>

#include "geometry/segment.hpp"
#include "random_pairs.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

struct Candidate {
  FeaturePair pair;
  double distance2;  // m^2, between the cores
};

// Every feature pair, by type, then feature of A, then of B, with the exact core distance^2 the
// candidate list stores (point-polygon: its plane when that alone is beyond the cutoff).
std::vector<Candidate> brute_force_candidates(const PosedBody& A, const PosedBody& B, double range) {
  const double cutoff = A.radius + B.radius + range;
  const double cutoff2 = cutoff * cutoff;
  std::vector<Candidate> all;
  auto keep = [&](PairType t, std::size_t i, std::size_t j, double d2) {
    if (d2 < cutoff2) all.push_back({{t, std::uint16_t(i), std::uint32_t(j)}, d2});
  };
  auto segment = [](const PosedBody& body, std::size_t e, Vec3& p0) {
    p0 = body.vertices[body.shape->edges[e][0]];
    return Vec3(body.vertices[body.shape->edges[e][1]] - p0);
  };
  auto face = [&](const Vec3& p, const PosedBody& body, std::size_t f) {
    const Vec3 n = body.rotation * body.shape->face_normals[f];
    const std::vector<int>& vs = body.shape->faces[f];
    const double d = (p - body.vertices[vs[0]]).dot(n);
    return d * d >= cutoff2 ? d * d : point_polygon_distance_sq(p, body.vertices, vs, n);
  };
  const Shape &sa = *A.shape, &sb = *B.shape;
  Vec3 p0, q0;
  for (std::size_t i = 0; i < sa.vertices.size(); ++i)
    for (std::size_t j = 0; j < sb.vertices.size(); ++j)
      keep(PairType::vertex_vertex, i, j, (A.vertices[i] - B.vertices[j]).squaredNorm());
  for (std::size_t i = 0; i < sa.vertices.size(); ++i)
    for (std::size_t j = 0; j < sb.edges.size(); ++j) {
      const Vec3 e = segment(B, j, q0);
      keep(PairType::vertex_edge, i, j, point_segment_distance_sq(A.vertices[i], q0, e));
    }
  for (std::size_t i = 0; i < sa.edges.size(); ++i)
    for (std::size_t j = 0; j < sb.vertices.size(); ++j) {
      const Vec3 e = segment(A, i, p0);
      keep(PairType::edge_vertex, i, j, point_segment_distance_sq(B.vertices[j], p0, e));
    }
  for (std::size_t i = 0; i < sa.vertices.size(); ++i)
    for (std::size_t j = 0; j < sb.faces.size(); ++j) keep(PairType::vertex_face, i, j, face(A.vertices[i], B, j));
  for (std::size_t i = 0; i < sa.faces.size(); ++i)
    for (std::size_t j = 0; j < sb.vertices.size(); ++j) keep(PairType::face_vertex, i, j, face(B.vertices[j], A, i));
  for (std::size_t i = 0; i < sa.edges.size(); ++i)
    for (std::size_t j = 0; j < sb.edges.size(); ++j) {
      const Vec3 da = segment(A, i, p0), db = segment(B, j, q0);
      keep(PairType::edge_edge, i, j, segment_segment_distance_sq(p0, da, q0, db));
    }
  return all;
}

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

}  // namespace

TEST_CASE("feature candidates are every feature pair within the cutoff, with the exact distances") {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> frac(0.0, 1.0);
  std::size_t compared = 0, pairs_with_candidates = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const PairPose pose = random_pair_pose(rng, trial);
    // From overlapping to beyond the range: the filters are tested on both sides of the cutoff.
    const double along = touching_distance(pose) + 0.15 * (frac(rng) - 0.3);
    const Posed a(*pose.sa, pose.scale_a, pose.lateral + along * pose.direction, pose.qa);
    const Posed b(*pose.sb, pose.scale_b, Vec3::Zero(), pose.qb);
    const double range = 0.1 * frac(rng);  // m
    std::vector<FeaturePair> found;
    std::vector<double> distances2;
    const double nearest = candidate_features(a.body(), b.body(), range, found, &distances2);
    const std::vector<Candidate> truth = brute_force_candidates(a.body(), b.body(), range);
    INFO("trial " << trial << " " << pose.sa->name << " / " << pose.sb->name << " range " << range);
    REQUIRE(found.size() == truth.size());
    REQUIRE(distances2.size() == truth.size());
    double nearest2 = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < truth.size(); ++k) {
      CHECK(found[k].type == truth[k].pair.type);
      CHECK(found[k].a == truth[k].pair.a);
      CHECK(found[k].b == truth[k].pair.b);
      CHECK(same_bits(distances2[k], truth[k].distance2));
      nearest2 = std::min(nearest2, truth[k].distance2);
    }
    if (!truth.empty()) {
      CHECK(same_bits(nearest, std::sqrt(nearest2) - a.body().radius - b.body().radius));
      ++pairs_with_candidates;
    } else {
      CHECK(nearest == std::numeric_limits<double>::infinity());
    }
    compared += truth.size();
  }
  // Both outcomes are common: pairs apart and pairs with many candidates.
  CHECK(pairs_with_candidates > 1000);
  CHECK(pairs_with_candidates < 2900);
  CHECK(compared > 10000);
}

// The face-plane test drops features that lie beyond one of the other cube's face planes: here
// cubes rest on each other (face on face, turned, tilted, overhanging), where many vertices lie
// within round-off of those planes, near the origin and 100 m from it.
TEST_CASE("resting cubes: feature candidates are every feature pair within the cutoff, bit for bit") {
  std::mt19937_64 rng(1919);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Shape cube = make_cube(0.5, 0.05);  // m, half side and rounding
  std::size_t compared = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 origin = trial % 2 == 0 ? Vec3::Zero() : Vec3(100.0, -37.5, 12.25);  // m
    const Quat qb = trial % 4 < 2 ? Quat::Identity() : random_axis_rotation(rng);
    // A on B's top face: turned about the normal, tilted up to 0.01 rad (none every third trial).
    const double tilt = trial % 3 == 0 || trial % 5 == 0 ? 0.0 : 0.01 * u(rng);
    const Quat qa = qb * Quat(Eigen::AngleAxisd(kPi * u(rng), Vec3::UnitZ())) *
                    Quat(Eigen::AngleAxisd(tilt, Vec3(u(rng), u(rng), 0.0).normalized()));
    const Vec3 lateral(0.9 * u(rng), 0.9 * u(rng), 0.0);  // m: up to overhanging by 0.4
    const double range = 0.05 * (u(rng) + 1.0);  // m
    // m, between the centres: the rounded cubes touch at 1.1; every fifth trial, A's lower
    // vertices lie on the cutoff above B's top face plane (up to round-off).
    const double height = trial % 5 == 0 ? 1.0 + 0.1 + range : 1.1 + 0.12 * u(rng);
    const Posed b(cube, 1.0, origin, qb);
    const Posed a(cube, 1.0, origin + qb * (lateral + height * Vec3::UnitZ()), qa);
    std::vector<FeaturePair> found;
    std::vector<double> distances2;
    candidate_features(a.body(), b.body(), range, found, &distances2);
    const std::vector<Candidate> truth = brute_force_candidates(a.body(), b.body(), range);
    INFO("trial " << trial << " range " << range);
    REQUIRE(found.size() == truth.size());
    for (std::size_t k = 0; k < truth.size(); ++k) {
      CHECK(found[k].type == truth[k].pair.type);
      CHECK(found[k].a == truth[k].pair.a);
      CHECK(found[k].b == truth[k].pair.b);
      CHECK(same_bits(distances2[k], truth[k].distance2));
    }
    compared += truth.size();
  }
  CHECK(compared > 10000);  // 17,468
}
