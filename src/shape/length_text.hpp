#pragma once
// Lengths typed by users: "0.0005", "0.5 mm", "0.05cm", "5e-4 m".
#include <optional>
#include <string>

namespace polydem {

// Metres from a plain number (m) or a number with unit m, cm or mm; nullopt when unreadable.
std::optional<double> parse_length(const std::string& text);

}  // namespace polydem
