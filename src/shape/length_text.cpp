#include "shape/length_text.hpp"

#include <cmath>
#include <cstdlib>

namespace polydem {

std::optional<double> parse_length(const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (end == begin || !std::isfinite(value)) return std::nullopt;
  std::string unit(end);
  unit.erase(0, unit.find_first_not_of(" \t"));
  unit.erase(unit.find_last_not_of(" \t") + 1);
  if (unit.empty() || unit == "m") return value;
  if (unit == "cm") return value * 1e-2;
  if (unit == "mm") return value * 1e-3;
  return std::nullopt;
}

}  // namespace polydem
