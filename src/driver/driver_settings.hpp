#pragma once
// The settings of one driver as the scene parser builds them: its kind's own settings, its
// name, its motion. A new kind adds its settings type here (and its parser entry in
// io/scene_drivers.cpp); the factory (drivers.cpp) makes the kind from it.
#include <string>
#include <variant>

#include "driver/ball.hpp"
#include "driver/cylinder.hpp"
#include "driver/mesh_driver.hpp"
#include "driver/motion.hpp"
#include "driver/wall.hpp"
#include "polydem/source_loc.hpp"

namespace polydem {

using KindSettings = std::variant<WallSettings, CylinderSettings, BallSettings, MeshSettings>;

struct DriverSettings {
  std::string name;
  KindSettings kind;
  MotionSettings motion;
  SourceLoc loc;                  // its entry in the scene, for errors (a servo without a gain)
};

}  // namespace polydem
