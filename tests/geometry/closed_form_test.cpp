// Closed-form contacts: gap, normal and point derived by hand for simple placements.
#include <catch2/catch.hpp>

#include "test_shapes.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

constexpr double kTol = 1e-12;

// Middle of the overlap (SPEC): pA = cA - rA n, pB = cB + rB n, point = (pA + pB) / 2.
Vec3 expected_point(const Vec3& ca, const Vec3& cb, const Vec3& n, double ra, double rb) {
  return 0.5 * ((ca - ra * n) + (cb + rb * n));
}

void check_contact(const ContactPoint& c, double gap, const Vec3& n, const Vec3& point) {
  CHECK(c.gap == Approx(gap).margin(kTol));
  CHECK((c.normal - n).norm() < kTol);
  CHECK((c.point - point).norm() < kTol);
}

}  // namespace

TEST_CASE("two spheres: gap = |xA - xB| - rA - rB, normal along the centres") {
  const Shape s1 = make_sphere(0.5), s2 = make_sphere(0.25);
  const Posed a(s1, 2.0, Vec3(0.3, 1.0, -0.2)), b(s2, 3.0, Vec3(0.3 + 1.2, 1.0 + 0.9, -0.2));
  const double dist = 1.5;  // 3-4-5 triangle scaled by 0.3
  const double ra = 1.0, rb = 0.75;
  const Vec3 n = (a.position - b.position) / dist;
  ContactPoint c;
  REQUIRE(feature_contact(a.body(), b.body(), {PairType::vertex_vertex, 0, 0}, 0.0, c));
  check_contact(c, dist - ra - rb, n, expected_point(a.position, b.position, n, ra, rb));
  // The contact point lies on the segment of centres, rA + gap/2 from A's centre.
  CHECK((c.point - (a.position - (ra + 0.5 * c.gap) * n)).norm() < kTol);
  REQUIRE(brute_force_contacts(a.body(), b.body()).size() == 1);
  // Separated by 0.1: no contact at max_gap 0, a contact with gap 0.1 within max_gap 0.2.
  const Posed far(s2, 3.0, a.position + Vec3(0.0, 0.0, ra + rb + 0.1));
  CHECK_FALSE(feature_contact(a.body(), far.body(), {PairType::vertex_vertex, 0, 0}, 0.0, c));
  REQUIRE(feature_contact(a.body(), far.body(), {PairType::vertex_vertex, 0, 0}, 0.2, c));
  CHECK(c.gap == Approx(0.1).margin(kTol));
}

TEST_CASE("sphere on a rotated cube face: gap = height - h - rc - rs along the face normal") {
  const double h = 0.5, rc = 0.05, rs = 0.2, height = 0.72;
  const Shape cube = make_cube(h, rc), sphere = make_sphere(rs);
  const Quat q(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  const Vec3 centre(1.0, -2.0, 3.0);
  const Vec3 local(0.2, -0.3, height);  // above the +z face, inside it
  const Posed b(cube, 1.0, centre, q), a(sphere, 1.0, centre + q * local);
  const Vec3 n = q * Vec3::UnitZ();
  const double gap = height - h - rc - rs;
  const auto contacts = brute_force_contacts(a.body(), b.body());
  REQUIRE(contacts.size() == 1);
  CHECK(contacts[0].first.type == PairType::vertex_face);
  const Vec3 foot = centre + q * Vec3(0.2, -0.3, h);
  check_contact(contacts[0].second, gap, n, expected_point(a.position, foot, n, rs, rc));
  // Swapped order: the face_vertex adapter gives the same gap and point, the opposite normal.
  const auto back = brute_force_contacts(b.body(), a.body());
  REQUIRE(back.size() == 1);
  CHECK(back[0].first.type == PairType::face_vertex);
  check_contact(back[0].second, gap, -n, contacts[0].second.point);
}

TEST_CASE("cube edges crossed at 90 degrees: edge_edge with gap = zA - 2 h sqrt2 - rA - rB") {
  const double h = 1.0, r = 0.1, overlap = 0.03;
  const Shape cube = make_cube(h, r);
  const double reach = h * std::sqrt(2.0);  // centre to edge of a cube turned 45 degrees
  // B turned about y: its top is an edge along y; A turned about x: its bottom is an edge along x.
  const Posed b(cube, 1.0, Vec3::Zero(), Quat(Eigen::AngleAxisd(kPi / 4, Vec3::UnitY())));
  const double za = 2 * reach + 2 * r - overlap;
  const Posed a(cube, 1.0, Vec3(0, 0, za), Quat(Eigen::AngleAxisd(kPi / 4, Vec3::UnitX())));
  const auto contacts = brute_force_contacts(a.body(), b.body());
  REQUIRE(contacts.size() == 1);
  CHECK(contacts[0].first.type == PairType::edge_edge);
  const Vec3 n = Vec3::UnitZ();
  check_contact(contacts[0].second, -overlap, n, expected_point(Vec3(0, 0, za - reach), Vec3(0, 0, reach), n, r, r));
}

TEST_CASE("sphere on a cube edge: vertex_edge with the distance to the edge line") {
  const double h = 0.5, rc = 0.05, rs = 0.3;
  const Shape cube = make_cube(h, rc), sphere = make_sphere(rs);
  const Posed b(cube, 2.0, Vec3::Zero(), Quat(Eigen::AngleAxisd(kPi / 4, Vec3::UnitY())));
  const double top = 2.0 * h * std::sqrt(2.0);  // the top edge runs along y at x = 0, z = top
  const Vec3 offset(0.03, 0.0, 0.35);          // |x| < z: in the edge's Voronoi region
  const Posed a(sphere, 1.0, Vec3(0, 0.37, top) + offset);
  const auto contacts = brute_force_contacts(a.body(), b.body());
  REQUIRE(contacts.size() == 1);
  CHECK(contacts[0].first.type == PairType::vertex_edge);
  const Vec3 n = offset.normalized();
  const double gap = offset.norm() - rs - 2.0 * rc;
  check_contact(contacts[0].second, gap, n, expected_point(a.position, Vec3(0, 0.37, top), n, rs, 2.0 * rc));
}

TEST_CASE("scaled bodies: gap and point scale with the homothety") {
  const Shape cube = make_cube(0.5, 0.05);
  const Posed b1(cube, 1.0, Vec3::Zero()), a1(cube, 1.0, Vec3(0.2, 0.1, 1.08));
  const Posed b2(cube, 1e-3, Vec3::Zero()), a2(cube, 1e-3, Vec3(0.2, 0.1, 1.08) * 1e-3);
  const auto c1 = brute_force_contacts(a1.body(), b1.body());
  const auto c2 = brute_force_contacts(a2.body(), b2.body());
  REQUIRE(c1.size() == 4);
  REQUIRE(c2.size() == c1.size());
  for (std::size_t k = 0; k < c1.size(); ++k) {
    CHECK(c1[k].second.gap == Approx(-0.02).margin(kTol));
    CHECK(c2[k].second.gap == Approx(-0.02e-3).margin(kTol * 1e-3));
    CHECK((c2[k].second.point - 1e-3 * c1[k].second.point).norm() < 1e-15);
  }
}
