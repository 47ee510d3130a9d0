#pragma once
// Reads and validates a scene file (shared/SCENE.md) once, into the settings of
// polydem/scene.hpp. Every later stage trusts what comes out of here.
#include <string>

#include "io/scene_settings.hpp"

namespace polydem {

// Throws InputError "FILE:LINE: key 'KEY': what is wrong (suggestion)" on any bad input,
// including a missing file, a YAML syntax error and missing shape, STL or field files.
Scene load_scene(const std::string& path);

}  // namespace polydem
