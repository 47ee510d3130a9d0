#pragma once
// Turns body specifications (explicit and generated) into the body arrays of a run.
#include <vector>

#include "io/scene_settings.hpp"
#include "polydem/bodies.hpp"
#include "polydem/shape_library.hpp"

namespace polydem {

// Mass m = density * V * s^3 and principal inertia m * (I/m) * s^2 for homothety s; the
// orientation maps the shape's principal frame to the world through its input frame, so a
// body with the identity orientation looks as the shape was drawn.
Bodies build_bodies(const std::vector<BodySpec>& specs, const ShapeLibrary& library);

}  // namespace polydem
