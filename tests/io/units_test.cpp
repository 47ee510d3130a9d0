// Unit conversion: every SCENE.md unit against its SI definition, and the errors.
#include "io/units.hpp"

#include <catch2/catch.hpp>

#include "io_fixture.hpp"
#include "polydem/math.hpp"

using namespace polydem;
using polydem::test::contains;
using polydem::test::input_error_of;

namespace {
const SourceLoc kLoc{"scene.yaml", 7};
double q(const std::string& text, Dimension dim) { return parse_quantity(text, dim, kLoc, "x"); }
}  // namespace

TEST_CASE("unit strings convert to SI by their definitions", "[units]") {
  using Catch::Matchers::WithinRel;
  CHECK_THAT(q("5 mm", Dimension::length), WithinRel(5e-3, 1e-15));
  CHECK_THAT(q("0.1 m", Dimension::length), WithinRel(0.1, 1e-15));
  CHECK_THAT(q("3 cm", Dimension::length), WithinRel(0.03, 1e-15));
  CHECK_THAT(q("2 ms", Dimension::time), WithinRel(2e-3, 1e-15));
  CHECK_THAT(q("1.5 min", Dimension::time), WithinRel(90.0, 1e-15));
  CHECK_THAT(q("2700 kg/m^3", Dimension::density), WithinRel(2700.0, 1e-15));
  CHECK_THAT(q("2.7 g/cm^3", Dimension::density), WithinRel(2700.0, 1e-12));  // 1e-3 kg / 1e-6 m^3
  CHECK_THAT(q("30 deg", Dimension::angle), WithinRel(kPi / 6.0, 1e-15));
  CHECK_THAT(q("30\u00b0", Dimension::angle), WithinRel(kPi / 6.0, 1e-15));
  CHECK_THAT(q("30 rpm", Dimension::angular_velocity), WithinRel(30.0 * 2.0 * kPi / 60.0, 1e-15));
  CHECK_THAT(q("180 deg/s", Dimension::angular_velocity), WithinRel(kPi, 1e-15));
  CHECK_THAT(q("1e5 N/m", Dimension::stiffness), WithinRel(1e5, 1e-15));
  CHECK_THAT(q("9.807 m/s^2", Dimension::acceleration), WithinRel(9.807, 1e-15));
  CHECK_THAT(q("2 m/s", Dimension::velocity), WithinRel(2.0, 1e-15));
  CHECK_THAT(q("50 N", Dimension::force), WithinRel(50.0, 1e-15));
  CHECK_THAT(q("10 kPa", Dimension::pressure), WithinRel(1e4, 1e-15));
  CHECK_THAT(q("0.01 N m/rad", Dimension::rolling_stiffness), WithinRel(0.01, 1e-15));
  CHECK_THAT(q("0.2 kg", Dimension::mass), WithinRel(0.2, 1e-15));
  CHECK_THAT(q("50 %", Dimension::dimensionless), WithinRel(0.5, 1e-15));
}

TEST_CASE("a bare number is SI, angles in radians", "[units]") {
  CHECK(q("0.005", Dimension::length) == 0.005);
  CHECK(q("1.0e5", Dimension::stiffness) == 1.0e5);
  CHECK(q("0.5", Dimension::angle) == 0.5);           // rad
  CHECK(q("3", Dimension::angular_velocity) == 3.0);  // rad/s
  CHECK(q(" -2 ", Dimension::velocity) == -2.0);
}

TEST_CASE("the radian may be left out, other units may not", "[units]") {
  // rad is a ratio of lengths: N m and N m/rad are the same rolling stiffness.
  CHECK(q("0.01 N m", Dimension::rolling_stiffness) ==
        q("0.01 N m/rad", Dimension::rolling_stiffness));
  CHECK(q("2 1/s", Dimension::angular_velocity) == 2.0);
  CHECK_FALSE(input_error_of([] { q("30 deg", Dimension::dimensionless); }).empty());
}

TEST_CASE("a unit of the wrong dimension names the place, the expected dimension and an example",
          "[units]") {
  const std::string msg = input_error_of([] { q("5 s", Dimension::length); });
  CHECK(contains(msg, "scene.yaml:7:"));
  CHECK(contains(msg, "key 'x'"));
  CHECK(contains(msg, "is a time"));
  CHECK(contains(msg, "expected a length"));
  CHECK(contains(msg, "\"5 mm\""));
  CHECK(contains(input_error_of([] { q("1e5 N", Dimension::stiffness); }), "expected a stiffness"));
  CHECK(contains(input_error_of([] { q("30 deg", Dimension::angular_velocity); }), "an angle"));
}

TEST_CASE("unknown units, bad syntax and non-numbers are InputErrors", "[units]") {
  CHECK(contains(input_error_of([] { q("5 furlong", Dimension::length); }),
                 "unknown unit 'furlong'"));
  CHECK(contains(input_error_of([] { q("abc", Dimension::length); }),
                 "expected a number or a quantity string like \"5 mm\""));
  CHECK(contains(input_error_of([] { q("5 m^x", Dimension::length); }), "cannot read the unit"));
  CHECK(contains(input_error_of([] { q("5 m#", Dimension::length); }), "cannot read the unit"));
  CHECK_FALSE(input_error_of([] { q("inf", Dimension::length); }).empty());
  CHECK_FALSE(input_error_of([] { q("", Dimension::length); }).empty());
}
