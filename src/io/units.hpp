#pragma once
// Quantities with units in the scene file: a bare number is SI, a string "5 mm" is converted.
#include <string>

#include "io/scene_settings.hpp"

namespace polydem {

enum class Dimension {
  dimensionless,
  length,
  time,
  velocity,
  acceleration,
  angle,
  angular_velocity,
  density,
  mass,
  force,
  stiffness,
  pressure,
  rolling_stiffness
};

// "a length", "an angular velocity", ... for error messages.
std::string dimension_name(Dimension dim);
// A quantity string of that dimension, e.g. "5 mm", for error messages.
std::string dimension_example(Dimension dim);

// Parses "5 mm", "2700 kg/m^3", "30 rpm" or a bare number "0.005" into SI. Angles are radians
// (a bare number) or "deg"; the radian may be left out ("0.01 N m" as rolling stiffness).
// Throws InputError "FILE:LINE: key 'KEY': ..." naming the expected dimension and an example.
double parse_quantity(const std::string& text, Dimension dim, const SourceLoc& loc,
                      const std::string& key);

}  // namespace polydem
