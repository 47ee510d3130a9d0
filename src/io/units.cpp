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
    Unit{"m", 1.0, {1, 0, 0, 0}, true},
    Unit{"g", 1e-3, {0, 1, 0, 0}, true},
    Unit{"s", 1.0, {0, 0, 1, 0}, true},
    Unit{"min", 60.0, {0, 0, 1, 0}, false},
    Unit{"h", 3600.0, {0, 0, 1, 0}, false},
    Unit{"rad", 1.0, {0, 0, 0, 1}, true},
    Unit{"deg", kPi / 180.0, {0, 0, 0, 1}, false},
    Unit{"\u00b0", kPi / 180.0, {0, 0, 0, 1}, false},  // the degree sign
    Unit{"rpm", 2.0 * kPi / 60.0, {0, 0, -1, 1}, false},
    Unit{"N", 1.0, kForce, true},
    Unit{"J", 1.0, {2, 1, -2, 0}, true},
    Unit{"Pa", 1.0, {-1, 1, -2, 0}, true},
    Unit{"bar", 1e5, {-1, 1, -2, 0}, false},
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

struct DimensionInfo {
  Dimension dim;
  Dims dims;
  const char* name;     // for messages: "expected a length"
  const char* example;  // a quantity string of this dimension
};

constexpr std::array kDimensions = {
    DimensionInfo{Dimension::dimensionless, {0, 0, 0, 0}, "a plain number", "0.5"},
    DimensionInfo{Dimension::length, {1, 0, 0, 0}, "a length", "5 mm"},
    DimensionInfo{Dimension::time, {0, 0, 1, 0}, "a time", "2 ms"},
    DimensionInfo{Dimension::velocity, {1, 0, -1, 0}, "a velocity", "2 m/s"},
    DimensionInfo{Dimension::acceleration, {1, 0, -2, 0}, "an acceleration", "9.807 m/s^2"},
    DimensionInfo{Dimension::angle, {0, 0, 0, 1}, "an angle", "30 deg"},
    DimensionInfo{Dimension::angular_velocity, {0, 0, -1, 1}, "an angular velocity", "30 rpm"},
    DimensionInfo{Dimension::density, {-3, 1, 0, 0}, "a density", "2700 kg/m^3"},
    DimensionInfo{Dimension::mass, {0, 1, 0, 0}, "a mass", "0.1 kg"},
    DimensionInfo{Dimension::force, kForce, "a force", "50 N"},
    DimensionInfo{Dimension::stiffness, {0, 1, -2, 0}, "a stiffness", "1e5 N/m"},
    DimensionInfo{Dimension::pressure, {-1, 1, -2, 0}, "a pressure", "10 kPa"},
    DimensionInfo{
        Dimension::rolling_stiffness, {2, 1, -2, -1}, "a rolling stiffness", "0.01 N m/rad"},
};

const DimensionInfo& info(Dimension dim) {
  for (const DimensionInfo& d : kDimensions)
    if (d.dim == dim) return d;
  return kDimensions[0];
}

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

// Length of the separator at s[i]: a space, '*' or the middle dot of "N\u00b7m"; 0 if none.
std::size_t separator_length(const std::string& s, std::size_t i) {
  if (std::isspace(static_cast<unsigned char>(s[i])) || s[i] == '*') return 1;
  return s.compare(i, 2, "\u00b7") == 0 ? 2 : 0;
}

void multiply(Scaled& total, const Scaled& unit, int power) {
  total.factor *= std::pow(unit.factor, power);
  total.dims.m += power * unit.dims.m;
  total.dims.kg += power * unit.dims.kg;
  total.dims.s += power * unit.dims.s;
  total.dims.rad += power * unit.dims.rad;
}

// Parses the unit part "kg/m^3", "N m/rad", "1/s": factors joined by separators; '/'
// divides the next factor only.
UnitParse parse_units(const std::string& s) {
  UnitParse out;
  std::size_t i = 0;
  int sign = 1;  // -1 after '/'
  while (i < s.size()) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (const std::size_t n = separator_length(s, i)) {
      i += n;
    } else if (c == '/') {
      sign = -1;
      ++i;
    } else if (c == '1' && (i + 1 == s.size() || s[i + 1] == '/')) {
      out.bare = false;  // the "1" of "1/s"
      ++i;
    } else if (!is_unit_char(c)) {
      out.syntax_error = true;
      return out;
    } else {
      const std::size_t start = i;
      while (i < s.size() && is_unit_char(static_cast<unsigned char>(s[i]))) ++i;
      const std::string token = s.substr(start, i - start);
      out.bare = false;
      const std::optional<int> power = read_power(s, i);
      const std::optional<Scaled> unit = lookup_unit(token);
      out.syntax_error = !power;
      if (!unit) out.bad_token = token;
      if (!power || !unit) return out;
      multiply(out.value, *unit, sign * *power);
      sign = 1;
    }
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
  for (const DimensionInfo& known : kDimensions)
    if (known.dims == d) return known.name;
  std::string s;
  const std::pair<const char*, int> parts[] = {
      {"m", d.m}, {"kg", d.kg}, {"s", d.s}, {"rad", d.rad}};
  for (const auto& [name, power] : parts) {
    if (power == 0) continue;
    if (!s.empty()) s += " ";
    s += name;
    if (power != 1) s += "^" + std::to_string(power);
  }
  return "a quantity in " + s;
}

}  // namespace

std::string dimension_name(Dimension dim) { return info(dim).name; }

std::string dimension_example(Dimension dim) { return info(dim).example; }

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
  if (units.syntax_error) fail("cannot read the unit in \"" + text + "\"; expected " + expected);
  if (!units.bad_token.empty())
    fail("unknown unit '" + units.bad_token + "' in \"" + text + "\"; expected " + expected);
  if (units.bare) return number;
  if (!compatible(units.value.dims, info(dim).dims))
    fail("\"" + text + "\" is " + describe(units.value.dims) + ", expected " + expected);
  const double si = number * units.value.factor;
  if (!std::isfinite(si)) fail("\"" + text + "\" is out of range in SI units (above 1.8e308)");
  return si;
}

}  // namespace polydem
