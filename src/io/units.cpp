#include "io/units.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

#include "polydem/error.hpp"

namespace polydem {
namespace {

// Exponents of metre, kilogram, second and radian.
struct Dims {
  int m = 0, kg = 0, s = 0, rad = 0;
  bool operator==(const Dims&) const = default;
};

struct Unit {
  const char* name;
  double factor;  // SI value of one unit
  Dims dims;
  bool prefixable;  // accepts an SI prefix: mm, kN, kPa, ms
};

constexpr Dims kForce{1, 1, -2, 0};
constexpr std::array kUnits = {
    Unit{"m", 1.0, {1, 0, 0, 0}, true},      Unit{"g", 1e-3, {0, 1, 0, 0}, true},
    Unit{"s", 1.0, {0, 0, 1, 0}, true},      Unit{"min", 60.0, {0, 0, 1, 0}, false},
    Unit{"h", 3600.0, {0, 0, 1, 0}, false},  Unit{"rad", 1.0, {0, 0, 0, 1}, true},
    Unit{"deg", kPi / 180.0, {0, 0, 0, 1}, false},
    Unit{"\u00b0", kPi / 180.0, {0, 0, 0, 1}, false},  // the degree sign
    Unit{"rpm", 2.0 * kPi / 60.0, {0, 0, -1, 1}, false},
    Unit{"N", 1.0, kForce, true},            Unit{"J", 1.0, {2, 1, -2, 0}, true},
    Unit{"Pa", 1.0, {-1, 1, -2, 0}, true},   Unit{"bar", 1e5, {-1, 1, -2, 0}, false},
    Unit{"%", 0.01, {0, 0, 0, 0}, false},
};

struct Prefix {
  const char* name;
  double factor;
};
constexpr std::array kPrefixes = {
    Prefix{"n", 1e-9}, Prefix{"u", 1e-6}, Prefix{"\u00b5", 1e-6}, Prefix{"m", 1e-3},
    Prefix{"c", 1e-2}, Prefix{"k", 1e3},  Prefix{"M", 1e6},       Prefix{"G", 1e9},
};

Dims dims_of(Dimension dim) {
  switch (dim) {
    case Dimension::dimensionless: return {0, 0, 0, 0};
    case Dimension::length: return {1, 0, 0, 0};
    case Dimension::time: return {0, 0, 1, 0};
    case Dimension::velocity: return {1, 0, -1, 0};
    case Dimension::acceleration: return {1, 0, -2, 0};
    case Dimension::angle: return {0, 0, 0, 1};
    case Dimension::angular_velocity: return {0, 0, -1, 1};
    case Dimension::density: return {-3, 1, 0, 0};
    case Dimension::mass: return {0, 1, 0, 0};
    case Dimension::force: return kForce;
    case Dimension::stiffness: return {0, 1, -2, 0};
    case Dimension::pressure: return {-1, 1, -2, 0};
    case Dimension::rolling_stiffness: return {2, 1, -2, -1};
  }
  return {};
}

constexpr std::array kAllDimensions = {
    Dimension::dimensionless, Dimension::length, Dimension::time, Dimension::velocity,
    Dimension::acceleration, Dimension::angle, Dimension::angular_velocity,
    Dimension::density, Dimension::mass, Dimension::force, Dimension::stiffness,
    Dimension::pressure, Dimension::rolling_stiffness};

struct Scaled {
  double factor = 1.0;
  Dims dims;
};

std::optional<Scaled> lookup_unit(const std::string& token) {
  for (const Unit& u : kUnits)
    if (token == u.name) return Scaled{u.factor, u.dims};
  for (const Prefix& p : kPrefixes) {
    const std::string prefix = p.name;
    if (token.size() <= prefix.size() || token.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = token.substr(prefix.size());
    for (const Unit& u : kUnits)
      if (u.prefixable && rest == u.name) return Scaled{p.factor * u.factor, u.dims};
  }
  return std::nullopt;
}

bool is_unit_char(unsigned char c) { return std::isalpha(c) || c == '%' || c >= 0x80; }

// Reads "^3", "^-1" or nothing after a unit name; returns the power or nullopt on bad syntax.
std::optional<int> read_power(const std::string& s, std::size_t& i) {
  if (i >= s.size() || s[i] != '^') return 1;
  ++i;
  int power = 0;
  const char* end = s.data() + s.size();
  auto [ptr, ec] = std::from_chars(s.data() + i, end, power);
  if (ec != std::errc()) return std::nullopt;
  i = static_cast<std::size_t>(ptr - s.data());
  return power;
}

struct UnitParse {
  Scaled value;
  std::string bad_token;  // unknown unit name
  bool syntax_error = false;
  bool bare = true;  // no unit at all: the number is SI
};

// Parses the unit part "kg/m^3", "N m/rad": factors joined by spaces or '*', '/' divides
// the next factor only.
UnitParse parse_units(const std::string& s) {
  UnitParse out;
  std::size_t i = 0;
  bool divide = false;
  while (i < s.size()) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (std::isspace(c) || c == '*') { ++i; continue; }
    if (s.compare(i, 2, "\u00b7") == 0) { i += 2; continue; }  // middle dot, as in "N\u00b7m"

    if (c == '/') { divide = true; ++i; continue; }
    if (c == '1' && (i + 1 == s.size() || s[i + 1] == '/')) { out.bare = false; ++i; continue; }  // "1/s"

    if (!is_unit_char(c)) { out.syntax_error = true; return out; }
    const std::size_t start = i;
    while (i < s.size() && is_unit_char(static_cast<unsigned char>(s[i]))) ++i;
    const std::string token = s.substr(start, i - start);
    out.bare = false;
    const std::optional<int> power = read_power(s, i);
    const std::optional<Scaled> unit = lookup_unit(token);
    if (!power) { out.syntax_error = true; return out; }
    if (!unit) { out.bad_token = token; return out; }
    const int p = divide ? -*power : *power;
    out.value.factor *= std::pow(unit->factor, p);
    out.value.dims.m += p * unit->dims.m;
    out.value.dims.kg += p * unit->dims.kg;
    out.value.dims.s += p * unit->dims.s;
    out.value.dims.rad += p * unit->dims.rad;
    divide = false;
  }
  return out;
}

// The radian is a ratio: a unit without any angle unit is accepted where one is expected.
bool compatible(const Dims& given, const Dims& expected) {
  if (given == expected) return true;
  Dims no_angle = expected;
  no_angle.rad = 0;
  return given.rad == 0 && given == no_angle;
}

std::string describe(const Dims& d) {
  for (Dimension dim : kAllDimensions)
    if (dims_of(dim) == d) return dimension_name(dim);
  std::string s;
  const std::pair<const char*, int> parts[] = {{"m", d.m}, {"kg", d.kg}, {"s", d.s}, {"rad", d.rad}};
  for (const auto& [name, power] : parts) {
    if (power == 0) continue;
    if (!s.empty()) s += " ";
    s += name;
    if (power != 1) s += "^" + std::to_string(power);
  }
  return "a quantity in " + s;
}

}  // namespace

std::string dimension_name(Dimension dim) {
  switch (dim) {
    case Dimension::dimensionless: return "a plain number";
    case Dimension::length: return "a length";
    case Dimension::time: return "a time";
    case Dimension::velocity: return "a velocity";
    case Dimension::acceleration: return "an acceleration";
    case Dimension::angle: return "an angle";
    case Dimension::angular_velocity: return "an angular velocity";
    case Dimension::density: return "a density";
    case Dimension::mass: return "a mass";
    case Dimension::force: return "a force";
    case Dimension::stiffness: return "a stiffness";
    case Dimension::pressure: return "a pressure";
    case Dimension::rolling_stiffness: return "a rolling stiffness";
  }
  return "a quantity";
}

std::string dimension_example(Dimension dim) {
  switch (dim) {
    case Dimension::dimensionless: return "0.5";
    case Dimension::length: return "5 mm";
    case Dimension::time: return "2 ms";
    case Dimension::velocity: return "2 m/s";
    case Dimension::acceleration: return "9.807 m/s^2";
    case Dimension::angle: return "30 deg";
    case Dimension::angular_velocity: return "30 rpm";
    case Dimension::density: return "2700 kg/m^3";
    case Dimension::mass: return "0.1 kg";
    case Dimension::force: return "50 N";
    case Dimension::stiffness: return "1e5 N/m";
    case Dimension::pressure: return "10 kPa";
    case Dimension::rolling_stiffness: return "0.01 N m/rad";
  }
  return "1";
}

double parse_quantity(const std::string& text, Dimension dim, const SourceLoc& loc,
                      const std::string& key) {
  const std::string expected = dimension_name(dim) + ", e.g. \"" + dimension_example(dim) + "\"";
  auto fail = [&](const std::string& what) {
    throw InputError(input_message(loc.file, loc.line, key, what));
  };
  std::size_t i = 0;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  if (i < text.size() && text[i] == '+') ++i;
  double number = 0.0;
  auto [ptr, ec] = std::from_chars(text.data() + i, text.data() + text.size(), number);
  if (ec == std::errc::result_out_of_range) fail("\"" + text + "\" is out of range");
  if (ec != std::errc() || !std::isfinite(number))
    fail("expected a number or a quantity string like \"" + dimension_example(dim) + "\" (" +
         dimension_name(dim) + "), got \"" + text + "\"");
  const UnitParse units = parse_units(std::string(ptr, text.data() + text.size()));
  if (units.syntax_error)
    fail("cannot read the unit in \"" + text + "\"; expected " + expected);
  if (!units.bad_token.empty())
    fail("unknown unit '" + units.bad_token + "' in \"" + text + "\"; expected " + expected);
  if (units.bare) return number;
  if (!compatible(units.value.dims, dims_of(dim)))
    fail("\"" + text + "\" is " + describe(units.value.dims) + ", expected " + expected);
  return number * units.value.factor;
}

}  // namespace polydem
