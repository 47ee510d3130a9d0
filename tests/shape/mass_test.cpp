// Mass properties of rounded bodies against closed forms and independent numeric integration.
#include "shape/mass.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <catch2/catch.hpp>
#include <random>

#include "polydem/error.hpp"
#include "reference_body.hpp"
#include "shape/hull.hpp"

using namespace polydem;

namespace {

std::vector<Vec3> box_points(double a, double b, double c) {
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i)
    p.emplace_back((i & 1 ? 0.5 : -0.5) * a, (i & 2 ? 0.5 : -0.5) * b, (i & 4 ? 0.5 : -0.5) * c);
  return p;
}

Vec3 sorted(Vec3 v) {
  std::sort(v.data(), v.data() + 3);
  return v;
}

Vec3 eigenvalues(const Mat3& m) {
  Eigen::SelfAdjointEigenSolver<Mat3> solver(m);
  return solver.eigenvalues();
}

double relative_error(const Vec3& a, const Vec3& b) { return (a - b).norm() / b.norm(); }

}  // namespace

TEST_CASE("sphere: V = 4/3 pi r^3, I/m = 2/5 r^2, centre at the point", "[mass]") {
  const double r = 0.005;
  const Shape s = build_hull_shape({Vec3(1, 2, 3)}, r, "ball");
  CHECK(s.volume == Approx(4.0 / 3.0 * kPi * r * r * r).epsilon(1e-13));
  for (int k = 0; k < 3; ++k) CHECK(s.inertia_per_mass[k] == Approx(0.4 * r * r).epsilon(1e-13));
  CHECK((s.input_center - Vec3(1, 2, 3)).norm() < 1e-14);
  CHECK(s.bounding_radius == Approx(r));
}

TEST_CASE("segment: cylinder plus two hemispheres", "[mass]") {
  const double r = 0.2, L = 1.5;
  const Shape s = build_hull_shape({Vec3(0, 0, 0), Vec3(0.5, 0, 0), Vec3(L, 0, 0)}, r, "rod");
  REQUIRE(s.vertices.size() == 2);
  const double vc = kPi * r * r * L, vs = 4.0 / 3.0 * kPi * r * r * r;
  CHECK(s.volume == Approx(vc + vs).epsilon(1e-13));
  // Axis: cylinder r^2/2, ball 2/5 r^2. Transverse: cylinder r^2/4 + L^2/12; each hemisphere
  // 2/5 r^2 about its flat face, moved by parallel axes to its centroid 3r/8 off the face.
  const double hemi = 0.5 * vs, c = 3.0 * r / 8.0;
  const double transverse = vc * (r * r / 4 + L * L / 12) +
                            2 * (hemi * 0.4 * r * r - hemi * c * c + hemi * (L / 2 + c) * (L / 2 + c));
  const Vec3 expected = sorted(Vec3((vc * r * r / 2 + vs * 0.4 * r * r), transverse, transverse)) / (vc + vs);
  CHECK(relative_error(s.inertia_per_mass, expected) < 1e-13);
}

TEST_CASE("cube with r -> 0: V = a^3, I/m = a^2/6", "[mass]") {
  const Shape s = build_hull_shape(box_points(2, 2, 2), 0.0, "cube");
  CHECK(s.volume == Approx(8.0).epsilon(1e-14));
  CHECK(relative_error(s.inertia_per_mass, Vec3::Constant(4.0 / 6.0)) < 1e-14);
}

TEST_CASE("box a x b x c: I/m = (b^2 + c^2)/12 ...", "[mass]") {
  const Shape s = build_hull_shape(box_points(2, 1, 1), 0.0, "box");
  CHECK(relative_error(s.inertia_per_mass, Vec3(2.0 / 12, 5.0 / 12, 5.0 / 12)) < 1e-14);
  // Principal axis of the smallest moment is the long side: vertices have |x| = 1 there.
  for (const Vec3& v : s.vertices) CHECK(std::abs(v.x()) == Approx(1.0));
  CHECK(s.input_rotation.coeffs() == Quat::Identity().coeffs());  // already principal: axes kept
}

TEST_CASE("rounded cube: exact Steiner volume, inertia against quasi-Monte-Carlo", "[mass]") {
  const double r = 0.3;
  Shape s = build_hull_shape(box_points(1, 1, 1), r, "rounded cube");
  CHECK(s.volume == Approx(1 + 6 * r + 3 * kPi * r * r + 4.0 / 3.0 * kPi * r * r * r).epsilon(1e-14));
  // 2^18 Halton points: measured error ~1e-4; 2e-3 leaves margin.
  const test::NumericMoments m = test::integrate_rounded(s, 1 << 18);
  CHECK(m.volume == Approx(s.volume).epsilon(2e-3));
  CHECK(relative_error(s.inertia_per_mass, eigenvalues(m.inertia_per_mass)) < 2e-3);
  CHECK(m.center.norm() < 2e-3);
}

TEST_CASE("rounded elongated box against quasi-Monte-Carlo", "[mass]") {
  const Shape s = build_hull_shape(box_points(2, 1, 0.5), 0.15, "slab");
  const test::NumericMoments m = test::integrate_rounded(s, 1 << 18);
  CHECK(m.volume == Approx(s.volume).epsilon(2e-3));
  CHECK(relative_error(s.inertia_per_mass, eigenvalues(m.inertia_per_mass)) < 2e-3);
}

TEST_CASE("plate: slab, wedges and sectors of a flat square", "[mass]") {
  const double a = 1.0, r = 0.1;
  std::vector<Vec3> p{{0, 0, 0}, {a, 0, 0}, {a, a, 0}, {0, a, 0}, {0.5, 0.5, 0}, {0.5, 0, 0}};
  const Shape s = build_hull_shape(p, r, "plate");
  CHECK(s.vertices.size() == 4);
  CHECK(s.faces.size() == 2);
  CHECK(s.edges.size() == 4);
  // Steiner: Vp = 0, area 2 a^2, M = 1/2 * 4 a * pi.
  CHECK(s.volume == Approx(2 * a * a * r + 2 * kPi * a * r * r + 4.0 / 3.0 * kPi * r * r * r).epsilon(1e-14));
  const test::NumericMoments m = test::integrate_rounded(s, 1 << 18);
  CHECK(relative_error(s.inertia_per_mass, eigenvalues(m.inertia_per_mass)) < 3e-3);
}

TEST_CASE("a plate given as one polygon gets its back face", "[mass]") {
  Shape s;
  s.name = "square";
  s.radius = 0.1;
  s.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  s.faces = {{0, 1, 2, 3}};
  compute_mass_properties(s);
  CHECK(s.faces.size() == 2);
  CHECK(s.edges.size() == 4);
  CHECK(s.volume == Approx(2 * 0.1 + 2 * kPi * 0.01 + 4.0 / 3.0 * kPi * 0.001).epsilon(1e-14));
}

TEST_CASE("random rock: Steiner volume from its faces, inertia against quasi-Monte-Carlo", "[mass]") {
  const double r = 0.1;
  const Shape s = build_hull_shape(test::rock_points(7, 40, 1.0, 0.7, 0.5), r, "rock");
  // Steiner, computed here from the polygons: Vp by divergence, Ap, Mp from face normals.
  double vp = 0, ap = 0, mp = 0;
  for (size_t f = 0; f < s.faces.size(); ++f) {
    const auto& poly = s.faces[f];
    Vec3 area = Vec3::Zero();
    for (size_t i = 1; i + 1 < poly.size(); ++i)
      area +=
          0.5 *
          (s.vertices[poly[i]] - s.vertices[poly[0]]).cross(s.vertices[poly[i + 1]] - s.vertices[poly[0]]);
    ap += area.norm();
    vp += area.dot(s.vertices[poly[0]]) / 3.0;
    for (size_t i = 0; i < poly.size(); ++i) {
      const int a = poly[i], b = poly[(i + 1) % poly.size()];
      for (size_t g = 0; g < s.faces.size(); ++g) {
        const auto& q = s.faces[g];
        for (size_t j = 0; j < q.size(); ++j)
          if (q[j] == b && q[(j + 1) % q.size()] == a)  // each edge seen once from each side
            mp += 0.25 * (s.vertices[a] - s.vertices[b]).norm() *
                  std::acos(std::clamp(s.face_normals[f].dot(s.face_normals[g]), -1.0, 1.0));
      }
    }
  }
  CHECK(s.volume == Approx(vp + ap * r + mp * r * r + 4.0 / 3.0 * kPi * r * r * r).epsilon(1e-12));
  const test::NumericMoments m = test::integrate_rounded(s, 1 << 18);
  CHECK(m.volume == Approx(s.volume).epsilon(2e-3));
  CHECK(m.center.norm() < 2e-3);
  CHECK(relative_error(s.inertia_per_mass, eigenvalues(m.inertia_per_mass)) < 2e-3);
  for (int k = 0; k < 3; ++k)  // principal frame: off-diagonal products vanish
    for (int l = k + 1; l < 3; ++l) CHECK(std::abs(m.inertia_per_mass(k, l)) < 2e-3 * s.inertia_per_mass[2]);
}

TEST_CASE("large radius on an irregular core: wedges and sectors dominate", "[mass]") {
  // r comparable to the core: the edge and vertex pieces carry most of the inertia.
  const Shape s =
      build_hull_shape({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.2, 0.6, 0), Vec3(0.1, 0.3, 0.4)}, 0.5, "tet");
  const test::NumericMoments m = test::integrate_rounded(s, 1 << 18);
  CHECK(m.volume == Approx(s.volume).epsilon(2e-3));
  CHECK(relative_error(s.inertia_per_mass, eigenvalues(m.inertia_per_mass)) < 2e-3);
}

TEST_CASE("mass properties do not depend on where and how the input points are placed", "[mass]") {
  const std::vector<Vec3> points = test::rock_points(11, 30, 1.0, 0.8, 0.6);
  const Shape s = build_hull_shape(points, 0.05, "rock");
  const Quat q = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())).normalized();
  const Vec3 shift(10, -5, 3);
  std::vector<Vec3> moved;
  for (const Vec3& p : points) moved.push_back(q * p + shift);
  const Shape t = build_hull_shape(moved, 0.05, "rock");
  CHECK(t.volume == Approx(s.volume).epsilon(1e-12));
  CHECK(relative_error(t.inertia_per_mass, s.inertia_per_mass) < 1e-12);
  CHECK((t.input_center - (q * s.input_center + shift)).norm() < 1e-12);
  CHECK(t.bounding_radius == Approx(s.bounding_radius).epsilon(1e-12));
  // Principal-frame vertices map back onto hull points of the input.
  for (const Vec3& v : t.vertices) {
    const Vec3 x = t.input_center + t.input_rotation * v;
    double nearest = 1e9;
    for (const Vec3& p : moved) nearest = std::min(nearest, (p - x).norm());
    CHECK(nearest < 1e-12);
  }
  CHECK(t.input_rotation.toRotationMatrix().determinant() == Approx(1.0));
  // Done again on the principal-frame shape: centre at the origin, axes unchanged.
  Shape again = t;
  compute_mass_properties(again);
  CHECK(again.input_center.norm() < 1e-12);
  CHECK(std::abs(again.input_rotation.toRotationMatrix().diagonal().cwiseAbs().minCoeff() - 1.0) < 1e-9);
  CHECK(t.inertia_per_mass[0] <= t.inertia_per_mass[1]);
  CHECK(t.inertia_per_mass[1] <= t.inertia_per_mass[2]);
}

TEST_CASE("bad shapes for the mass computation are InputErrors", "[mass]") {
  Shape s;
  s.name = "odd";
  s.radius = 0.1;
  s.vertices = {Vec3(0, 0, 0), Vec3(0, 0, 0)};
  s.edges = {{0, 1}};
  CHECK_THROWS_WITH(compute_mass_properties(s), Catch::Contains("vertices 0 and 1 coincide"));
  s.edges.clear();
  s.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(0, 1, 0)};
  s.faces = {{0, 1, 2}, {1, 0, 3}, {2, 1, 3}, {0, 2, 3}};  // face 0: collinear corners
  CHECK_THROWS_WITH(compute_mass_properties(s), Catch::Contains("faces lie in one plane"));
  // A solid (apex 4 above the base 0 2 3) whose face 0 has collinear corners.
  s.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(1, 1, 0), Vec3(1, 0.5, 1)};
  s.faces = {{0, 1, 2}, {0, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  CHECK_THROWS_WITH(compute_mass_properties(s), Catch::Contains("zero area"));
  s.faces.clear();
  s.radius = -1;
  s.vertices = {Vec3(0, 0, 0)};
  CHECK_THROWS_WITH(compute_mass_properties(s), Catch::Contains("must be >= 0"));
}

TEST_CASE("an octahedron flattened to a plate, with two vertices at one point, is refused", "[mass]") {
  // The octahedron's 8 faces with its two apices both moved to the origin: it used to load with
  // a centre of mass off the origin for a body symmetric about it.
  Shape s;
  s.name = "flat";
  s.radius = 0.0005;
  s.vertices = {Vec3(0, -1, 0), Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 0)};
  s.faces = {{0, 1, 2}, {1, 4, 2}, {4, 3, 2}, {3, 0, 2}, {1, 0, 5}, {4, 1, 5}, {3, 4, 5}, {0, 3, 5}};
  CHECK_THROWS_WITH(compute_mass_properties(s), Catch::Contains("vertices 2 and 5 coincide"));
}

TEST_CASE("a shape whose volume overflows a double is refused as such, not as zero volume", "[mass]") {
  Shape s;
  s.name = "huge";
  s.radius = 1e300;
  s.vertices = {Vec3::Zero()};
  CHECK_THROWS_WITH(compute_mass_properties(s), Catch::Contains("radius 1e+300 m") && Catch::Contains("overflow"));
}
