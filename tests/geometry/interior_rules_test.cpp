// Interior rules: the lower-dimensional pair owns the boundary, so no contact is counted twice.
#include <catch2/catch.hpp>

#include "geometry/segment.hpp"
#include "test_shapes.hpp"

using namespace polydem;
using namespace polydem::test;

TEST_CASE("a vertex exactly above a face edge is a vertex_edge contact, not a vertex_face one") {
  const double h = 0.5, rc = 0.05, rs = 0.1;
  const Shape cube = make_cube(h, rc), sphere = make_sphere(rs);
  const Posed b(cube, 1.0, Vec3::Zero());
  const Posed a(sphere, 1.0, Vec3(h, 0.125, h + 0.125));  // above the edge x = h, z = h
  const auto contacts = brute_force_contacts(a.body(), b.body());
  REQUIRE(contacts.size() == 1);
  CHECK(contacts[0].first.type == PairType::vertex_edge);
  CHECK(contacts[0].second.normal.isApprox(Vec3::UnitZ(), 1e-15));
  CHECK(contacts[0].second.gap == Approx(0.125 - rs - rc));
  // Exactly above a corner: vertex_vertex alone.
  const Posed corner(sphere, 1.0, Vec3(h, h, h + 0.125));
  const auto at_corner = brute_force_contacts(corner.body(), b.body());
  REQUIRE(at_corner.size() == 1);
  CHECK(at_corner[0].first.type == PairType::vertex_vertex);
}

TEST_CASE("a cube lying flat on a bigger box has exactly four vertex_face contacts") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double h = 0.5, r = 0.05, overlap = 0.01;
  const Shape cube = make_cube(h, r), slab = make_box(Vec3(3.0, 3.0, 1.0), r);
  for (int trial = 0; trial < 200; ++trial) {
    const Quat spin(Eigen::AngleAxisd(kPi * u(rng), Vec3::UnitZ()));
    const Vec3 x(1.5 * u(rng), 1.5 * u(rng), 1.0 + h + 2 * r - overlap);
    const Posed a(cube, 1.0, x, spin), b(slab, 1.0, Vec3::Zero());
    const auto contacts = brute_force_contacts(a.body(), b.body());
    REQUIRE(contacts.size() == 4);
    for (const auto& [pair, c] : contacts) {
      CHECK(pair.type == PairType::vertex_face);
      CHECK(c.gap == Approx(-overlap).margin(1e-12));
      CHECK(c.normal.isApprox(Vec3::UnitZ(), 1e-14));
    }
  }
}

TEST_CASE("a vertex below a face plane keeps the outward normal and a deeper gap") {
  const double h = 0.5, rc = 0.05, rs = 0.1;
  const Shape cube = make_cube(h, rc), sphere = make_sphere(rs);
  const Posed b(cube, 1.0, Vec3::Zero());
  const PosedBody bb = b.body();
  ContactPoint c;
  const FeaturePair top{PairType::vertex_face, 0, 5};  // face 5 is +z
  for (double depth : {0.0, 0.05, 0.1}) {
    const Posed a(sphere, 1.0, Vec3(0.1, 0.2, h - depth));
    REQUIRE(feature_contact(a.body(), bb, top, 0.0, c));
    CHECK(c.normal.isApprox(Vec3::UnitZ(), 1e-15));
    CHECK(c.gap == Approx(-depth - rs - rc));
  }
  // Deeper than rA + rB below the plane the pair is dropped rather than flipped.
  const Posed deep(sphere, 1.0, Vec3(0.1, 0.2, h - 0.16));
  CHECK_FALSE(feature_contact(deep.body(), bb, top, 0.0, c));
  // Just under the top face near the +x side: the top face alone, no sideways push from the
  // side face (deeper under it) nor an inward one from the edge between them.
  const Posed near_side(sphere, 1.0, Vec3(h - 0.05, 0.0, h - 0.01));
  const auto contacts = brute_force_contacts(near_side.body(), bb);
  REQUIRE(contacts.size() == 1);
  CHECK(contacts[0].first.b == 5);
  CHECK(contacts[0].second.normal.isApprox(Vec3::UnitZ(), 1e-15));
}

TEST_CASE("contact points of one body pair are distinct, also for aligned and coincident features") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Shape cube = make_cube(0.5, 0.05), oct = make_octahedron(0.6, 0.05), prism = make_hex_prism(0.5, 0.3, 0.05);
  const std::vector<const Shape*> shapes = {&cube, &oct, &prism};
  int with_contacts = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Shape& sa = *shapes[trial % 3];
    const Shape& sb = *shapes[(trial / 3) % 3];
    const bool aligned = trial % 2 == 0;
    const Quat qa = aligned ? random_axis_rotation(rng) : random_rotation(rng);
    const Quat qb = aligned ? random_axis_rotation(rng) : random_rotation(rng);
    // Aligned trials sit on a 0.125 grid so vertices fall exactly above vertices, edges and faces.
    Vec3 x = aligned ? Vec3(0.125 * std::round(8 * u(rng)), 0.125 * std::round(8 * u(rng)), 1.0)
                     : Vec3(0.5 * u(rng), 0.5 * u(rng), 0.9 + 0.2 * u(rng));
    const Posed a(sa, 1.0, x, qa), b(sb, 1.0, Vec3::Zero(), qb);
    const auto contacts = brute_force_contacts(a.body(), b.body());
    with_contacts += !contacts.empty();
    for (std::size_t i = 0; i < contacts.size(); ++i)
      for (std::size_t j = i + 1; j < contacts.size(); ++j)
        REQUIRE((contacts[i].second.point - contacts[j].second.point).norm() > 1e-11);
  }
  CHECK(with_contacts > 500);
}

TEST_CASE("segment closest points satisfy the optimality conditions, parallel segments included") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec3 p1(u(rng), u(rng), u(rng)), d1(u(rng), u(rng), u(rng)), p2(u(rng), u(rng), u(rng));
    // A third of the trials are exactly parallel, a third nearly parallel.
    const Vec3 d2 = trial % 3 == 0 ? Vec3(-0.7 * d1) : trial % 3 == 1 ? Vec3(d1 + 1e-9 * Vec3(u(rng), u(rng), u(rng)))
                                                                         : Vec3(u(rng), u(rng), u(rng));
    const SegmentParams st = closest_segment_segment(p1, d1, p2, d2);
    const Vec3 w = p1 + st.s * d1 - p2 - st.t * d2;  // from the point on 2 to the point on 1
    // Nearly parallel (1e-9 rad) segments take the parallel branch: optimal to O(angle |d|^2).
    const double tol = trial % 3 == 1 ? 1e-8 : 1e-12;
    // KKT for min |w|^2 over the box [0,1]^2: the gradient along s is w.d1, along t is -w.d2.
    const double gs = w.dot(d1), gt = -w.dot(d2);
    CHECK((st.s > 0.0 || gs >= -tol));
    CHECK((st.s < 1.0 || gs <= tol));
    CHECK((st.s <= 0.0 || st.s >= 1.0 || std::abs(gs) <= tol));
    CHECK((st.t > 0.0 || gt >= -tol));
    CHECK((st.t < 1.0 || gt <= tol));
    CHECK((st.t <= 0.0 || st.t >= 1.0 || std::abs(gt) <= tol));
  }
}
