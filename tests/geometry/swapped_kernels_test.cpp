// The swapped kernels (face_vertex, edge_vertex) are vertex_face and vertex_edge with the bodies
// swapped and the normal turned back, bit for bit: they store -n themselves (kernels.cpp's kFlip)
// rather than turning the stored normal after. And a quadrilateral face's unrolled edge-plane
// tests answer as the loop over any other face's planes does, a NaN vertex included.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>

#include "random_pairs.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

struct Answer {
  bool hit;
  ContactPoint c;
};

Answer evaluate(const std::array<FeatureKernel, kPairTypeCount>& table, PairType type, const PosedBody& A,
                const PosedBody& B, int a, int b, double max_gap) {
  Answer r{false, {Vec3::Constant(7.0), Vec3::Constant(7.0), 7.0}};
  r.hit = table[std::size_t(type)](A, B, a, b, max_gap, r.c);
  return r;
}

bool same_bits(const double* x, const double* y, std::size_t n) { return std::memcmp(x, y, n * sizeof(double)) == 0; }

// `swapped` (B's feature a against A's b, its normal from A to B) told from B to A.
bool mirrors(const Answer& direct, const Answer& swapped) {
  if (direct.hit != swapped.hit || !same_bits(&direct.c.gap, &swapped.c.gap, 1)) return false;
  if (!direct.hit) return true;
  const Vec3 turned = -swapped.c.normal;
  return same_bits(direct.c.normal.data(), turned.data(), 3) && same_bits(direct.c.point.data(), swapped.c.point.data(), 3);
}

}  // namespace

TEST_CASE("face_vertex and edge_vertex are vertex_face and vertex_edge swapped, bit for bit") {
  std::vector<Shape> open_zoo = shape_zoo();
  for (Shape& s : open_zoo) s.convex = false;
  std::mt19937_64 rng(45);
  std::uniform_real_distribution<double> frac(0.0, 1.0);
  int face_hits = 0, edge_hits = 0;
  for (int trial = 0; trial < 300; ++trial) {
    PairPose pose = random_pair_pose(rng, trial);
    if (trial % 4 == 1) pose.sa = &open_zoo[std::size_t(pose.sa - shape_zoo().data())];
    const double ra = pose.scale_a * pose.sa->radius, rb = pose.scale_b * pose.sb->radius;
    const double along = touching_distance(pose) - 3.0 * (ra + rb) * frac(rng) + 0.02 * (frac(rng) - 0.5);
    const Posed a(*pose.sa, pose.scale_a, pose.lateral + along * pose.direction, pose.qa);
    const Posed b(*pose.sb, pose.scale_b, Vec3::Zero(), pose.qb);
    for (const auto* table : {&kSse2Kernels, &kAvxKernels}) {
      if (table == &kAvxKernels && !cpu_has_avx()) continue;
      for (const double max_gap : {0.0, 0.01}) {  // m
        for (int f = 0; f < int(pose.sa->faces.size()); ++f)
          for (int v = 0; v < int(pose.sb->vertices.size()); ++v) {
            const Answer direct = evaluate(*table, PairType::face_vertex, a.body(), b.body(), f, v, max_gap);
            REQUIRE(mirrors(direct, evaluate(*table, PairType::vertex_face, b.body(), a.body(), v, f, max_gap)));
            face_hits += direct.hit;
          }
        for (int e = 0; e < int(pose.sa->edges.size()); ++e)
          for (int v = 0; v < int(pose.sb->vertices.size()); ++v) {
            const Answer direct = evaluate(*table, PairType::edge_vertex, a.body(), b.body(), e, v, max_gap);
            REQUIRE(mirrors(direct, evaluate(*table, PairType::vertex_edge, b.body(), a.body(), v, e, max_gap)));
            edge_hits += direct.hit;
          }
      }
    }
  }
  CHECK(face_hits > 100);
  CHECK(edge_hits > 50);
}

TEST_CASE("a NaN vertex over a quadrilateral face answers as over a hexagonal one") {
  // No edge-plane test `dot <= offset` holds for NaN: inside every face's polygon, then a NaN gap.
  const Shape cube = make_cube(0.5, 0.05), prism = make_hex_prism(0.5, 0.3, 0.05);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Vec3> vertex = {Vec3(nan, 0.1, 0.2)};
  const Shape point = make_sphere(0.01);
  const PosedBody A{&point, vertex.data(), Mat3::Identity(), Vec3::Zero(), 0.01, 1.0};
  for (const Shape* face_body : {&cube, &prism}) {
    const Posed b(*face_body, 1.0, Vec3(0.0, 0.0, -1.0));
    for (int f = 0; f < int(face_body->faces.size()); ++f) {
      const std::size_t planes = face_body->edge_plane_begin[f + 1] - face_body->edge_plane_begin[f];
      INFO("face " << f << " of " << planes << " edges");
      const Answer got = evaluate(kFeatureKernels, PairType::vertex_face, A, b.body(), 0, f, 0.0);
      CHECK(got.hit);
      CHECK(std::isnan(got.c.gap));
    }
  }
}
