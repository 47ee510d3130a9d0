#pragma once
// The `probes:` list of the `output:` block: time series polydem computes itself (flow
// through a plane, angle of repose in a drum), each written to NAME.csv on csv_every.
#include "io/scene_settings.hpp"
#include "io/yaml_reader.hpp"

namespace polydem {

// Reads output.probes into scene.output; needs the drivers, forces and csv_every read first.
void read_probes(const YamlMap& root, Scene& scene);

}  // namespace polydem
