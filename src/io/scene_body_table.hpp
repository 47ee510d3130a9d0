#pragma once
// A table of bodies in a CSV file, named by a `- file: bodies.csv` item of `bodies:`.
#include <string>
#include <vector>

#include "io/scene_parts.hpp"

namespace polydem {

// Appends one BodySpec a row of the entry's file (resolved against `folder`); each body's loc
// is the file and row. Entry keys density, scale, group give the values of absent columns.
void read_body_table(const YamlMap& entry, const std::string& folder, std::vector<BodySpec>& out);

}  // namespace polydem
