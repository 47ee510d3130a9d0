// Mass properties of non-convex rounded bodies (the union of the swept elements) against
// closed forms: a capsule, two overlapping balls (a lens taken off), the alpha3 cross
// (three capsules through one centre, by inclusion-exclusion), apart balls.
#include <catch2/catch.hpp>
#include <cmath>

#include "shape/mass.hpp"
#include "shape/union_mass.hpp"

using namespace polydem;

namespace {

// The exact answer: volume and second moments about the centre of mass (principal, any order).
struct Exact {
  double volume;      // m^3
  Vec3 second;        // m^5, int x^2, y^2, z^2 over the body, about its centre of mass
};

Vec3 inertia_per_mass(const Exact& e) {
  const double t = e.second.sum();
  return Vec3(t - e.second.x(), t - e.second.y(), t - e.second.z()) / e.volume;
}

// Error of the quadrature on `s` (vertices about the centre of mass, axes principal) against e.
struct Errors {
  double volume, inertia, bound;
};

Errors quadrature_errors(const Shape& s, const Exact& e, int cells) {
  double bound = 0.0;
  const Moments m = union_moments(s, cells, bound);
  const Vec3 c = m.first / m.volume;
  const Mat3 spread = m.second / m.volume - c * c.transpose();
  const Mat3 inertia = spread.trace() * Mat3::Identity() - spread;
  const Vec3 expected = inertia_per_mass(e);
  const double inertia_error = (inertia - Mat3(expected.asDiagonal())).norm() / expected.norm();
  return {std::abs(m.volume - e.volume) / e.volume, inertia_error, bound};
}

Shape faceless(const std::vector<Vec3>& vertices, std::vector<std::array<int, 2>> edges, double r) {
  Shape s;
  s.name = "test";
  s.radius = r;
  s.vertices = vertices;
  s.edges = std::move(edges);
  return s;
}

// Capsule along x, core half-length a, radius r.
Exact capsule(double a, double r) {
  const double cyl = kPi * r * r * 2 * a, ball = 4.0 / 3.0 * kPi * r * r * r;
  // Hemispheres at +-a: int (a + u)^2 over a half ball = V_h a^2 + 2 a pi r^4/4 + 2 pi r^5/15.
  const double axial = cyl * a * a / 3 + 2 * (0.5 * ball * a * a + 2 * a * kPi * std::pow(r, 4) / 4 +
                                              2 * kPi * std::pow(r, 5) / 15);
  const double transverse = 2 * a * kPi * std::pow(r, 4) / 4 + 4 * kPi * std::pow(r, 5) / 15;
  return {cyl + ball, Vec3(axial, transverse, transverse)};
}

// Two balls of radius r, centres d apart along x (d < 2r): two balls less the lens they share.
// The lens: |x| <= h = r - d/2, disc of radius^2 rho2(x) = r^2 - (|x| + d/2)^2.
Exact two_balls(double d, double r) {
  const double ball = 4.0 / 3.0 * kPi * r * r * r;
  const double h = r - d / 2;
  // Antiderivatives of pi rho2(x) x^k and pi rho2(x)^2 / 4 on [0, h], rho2 = (r^2 - d^2/4) - d x - x^2.
  const double c0 = r * r - d * d / 4;
  auto poly = [&](double x) {
    const double v = c0 * x - d * x * x / 2 - x * x * x / 3;                                   // int rho2
    const double x2 = c0 * x * x * x / 3 - d * std::pow(x, 4) / 4 - std::pow(x, 5) / 5;      // int rho2 x^2
    // int rho2^2 = int (c0 - d x - x^2)^2
    const double r4 = c0 * c0 * x - c0 * d * x * x + (d * d - 2 * c0) * x * x * x / 3 + d * std::pow(x, 4) / 2 +
                      std::pow(x, 5) / 5;
    return Vec3(v, x2, r4);
  };
  const Vec3 p = poly(h);
  const double lens = 2 * kPi * p[0], lens_xx = 2 * kPi * p[1], lens_yy = 2 * kPi * p[2] / 4;
  const double xx = 2 * (ball * d * d / 4 + ball * r * r / 5) - lens_xx;
  const double yy = 2 * ball * r * r / 5 - lens_yy;
  return {2 * ball - lens, Vec3(xx, yy, yy)};
}

// exaDEM's alpha3: capsules of half-length a along x, y and z through the origin (a >= r).
// Two of them meet in a bicylinder (V = 16 r^3/3; int of the squared coordinate along an axis
// 64 r^5/45, along the common normal 16 r^5/15), all three in a tricylinder
// (V = 8 (2 - sqrt 2) r^3): where |x| is the largest coordinate its section is the square
// |y|, |z| <= m(x) = min(x, sqrt(r^2 - x^2)), so int |p|^2 = 6 int_0^r (4 m^2 x^2 + 8 m^4/3) dx.
Exact cross(double a, double r) {
  const Exact one = capsule(a, r);
  const double c = r / std::sqrt(2.0);
  auto outer = [&](double x) {  // antiderivative of 4 (r^2 - x^2) x^2 + 8/3 (r^2 - x^2)^2
    return 4 * (r * r * x * x * x / 3 - std::pow(x, 5) / 5) +
           8.0 / 3.0 * (std::pow(r, 4) * x - 2 * r * r * x * x * x / 3 + std::pow(x, 5) / 5);
  };
  const double tri_p2 = 6 * (20.0 / 3.0 * std::pow(c, 5) / 5 + outer(r) - outer(c));
  const double tri_v = 8 * (2 - std::sqrt(2.0)) * r * r * r;
  const double bi_v = 16.0 / 3.0 * r * r * r;
  const double bi_axis = 64.0 / 45.0 * std::pow(r, 5), bi_normal = 16.0 / 15.0 * std::pow(r, 5);
  // int x^2: the x capsule axially, the y and z capsules across; pairs xy and xz along an axis,
  // pair yz along its common normal x; the tricylinder a third of int |p|^2.
  const double xx = one.second.x() + 2 * one.second.y() - 2 * bi_axis - bi_normal + tri_p2 / 3;
  return {3 * one.volume - 3 * bi_v + tri_v, Vec3(xx, xx, xx)};
}

const double kA = 0.48, kR = 0.24;  // m, the alpha3 of exaDEM's tutorials

std::vector<Vec3> cross_vertices(double a) {
  return {Vec3(a, 0, 0), Vec3(-a, 0, 0), Vec3(0, a, 0), Vec3(0, -a, 0), Vec3(0, 0, a), Vec3(0, 0, -a)};
}

}  // namespace

TEST_CASE("capsule: the quadrature against the closed form, within its bound", "[union]") {
  // Along a tilted axis, so that the lines cross it obliquely.
  const Vec3 t = Vec3(1, 2, 3).normalized();
  const Shape s = faceless({-0.6 * t, 0.6 * t}, {{0, 1}}, 0.2);
  const Exact e = capsule(0.6, 0.2);
  const Errors err = quadrature_errors(s, e, kQuadratureCells);
  // Principal frame of the tilted capsule: compare invariants instead of the diagonal.
  double bound = 0.0;
  const Moments m = union_moments(s, kQuadratureCells, bound);
  CHECK(std::abs(m.volume - e.volume) / e.volume <= bound);
  CHECK(bound < 1e-4);
  CHECK(err.bound == bound);
  // The compiled closed form (convex path) agrees with this test's formula.
  Shape exact = s;
  compute_mass_properties(exact);
  CHECK(exact.mass_error == 0.0);
  CHECK(exact.volume == Approx(e.volume).epsilon(1e-13));
  const Vec3 i = inertia_per_mass(e);
  CHECK(exact.inertia_per_mass.x() == Approx(i.x()).epsilon(1e-12));
  CHECK(exact.inertia_per_mass.z() == Approx(i.y()).epsilon(1e-12));
}

TEST_CASE("two overlapping balls: two balls less the lens, within the bound", "[union]") {
  const double r = 0.1, d = 0.12;
  const Shape s = faceless({Vec3(-d / 2, 0, 0), Vec3(d / 2, 0, 0)}, {}, r);
  const Exact e = two_balls(d, r);
  const Errors err = quadrature_errors(s, e, kQuadratureCells);
  INFO("volume error " << err.volume << ", inertia error " << err.inertia << ", bound " << err.bound);
  CHECK(err.volume <= err.bound);
  CHECK(err.inertia <= err.bound);
  CHECK(err.bound < 1e-4);
  Shape loaded = s;
  compute_mass_properties(loaded);
  CHECK_FALSE(loaded.convex);
  CHECK(loaded.mass_error == err.bound);
  CHECK(loaded.volume == Approx(e.volume).epsilon(err.bound));
}

TEST_CASE("alpha3 cross: inclusion-exclusion of three capsules, within the bound", "[union]") {
  const Shape s = faceless(cross_vertices(kA), {{0, 1}, {2, 3}, {4, 5}}, kR);
  const Exact e = cross(kA, kR);
  const Errors err = quadrature_errors(s, e, kQuadratureCells);
  INFO("volume error " << err.volume << ", inertia error " << err.inertia << ", bound " << err.bound);
  CHECK(err.volume <= err.bound);
  CHECK(err.inertia <= err.bound);
  CHECK(err.bound < 2e-4);
  Shape loaded = s;
  compute_mass_properties(loaded);
  CHECK_FALSE(loaded.convex);
  CHECK(loaded.volume == Approx(e.volume).epsilon(err.bound));
  CHECK(loaded.inertia_per_mass.x() == Approx(inertia_per_mass(e).x()).epsilon(err.bound));
}

TEST_CASE("the quadrature converges as the grid grows, its bound with it", "[union]") {
  const Shape s = faceless(cross_vertices(kA), {{0, 1}, {2, 3}, {4, 5}}, kR);
  const Exact e = cross(kA, kR);
  double last_bound = 1.0;
  for (int cells : {128, 256, 512, 1024, 2048}) {
    const Errors err = quadrature_errors(s, e, cells);
    INFO(cells << " cells: volume error " << err.volume << ", inertia error " << err.inertia << ", bound "
               << err.bound);
    CHECK(err.volume <= err.bound);
    CHECK(err.inertia <= err.bound);
    CHECK(err.bound < last_bound);
    last_bound = err.bound;
  }
  CHECK(last_bound < 1e-4);
}

TEST_CASE("balls apart: closed form, no quadrature", "[union]") {
  const double r = 0.05;
  Shape s = faceless({Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0, 0.3, 0)}, {}, r);
  compute_mass_properties(s);
  CHECK_FALSE(s.convex);
  CHECK(s.mass_error == 0.0);
  CHECK(s.volume == Approx(3 * 4.0 / 3.0 * kPi * r * r * r).epsilon(1e-14));
}

TEST_CASE("a quadrature too coarse for the shape is refused, not simulated", "[union]") {
  // Arms 10 m long swept by 0.1 mm: the 1024 lines are 2 cm apart, far wider than an arm.
  const double a = 10.0, r = 1e-4;
  Shape s = faceless(cross_vertices(a), {{0, 1}, {2, 3}, {4, 5}}, r);
  double bound = 0.0;
  union_moments(s, kQuadratureCells, bound);
  CHECK(bound > kMassErrorLimit);
  CHECK_THROWS_WITH(compute_mass_properties(s), Catch::Contains("shape 'test'") &&
                                                    Catch::Contains("quadrature error bound") &&
                                                    Catch::Contains("preCompDone y"));
}
