#pragma once
// `polydem shape ...`: inspect shape libraries and build shapes from point sets.
#include <string>
#include <vector>

namespace polydem {

// args: the words after `polydem shape`, e.g. {"info", "lib.shp", "--json"} or
// {"hull", "pts.txt", "--radius", "0.5 mm", "--name", "rock", "-o", "out.shp"}.
// Returns 0 on success, 1 on bad input (one line on stderr).
int cmd_shape(const std::vector<std::string>& args);

}  // namespace polydem
