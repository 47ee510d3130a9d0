// The fluid operators of the `forces:` list: analytic fields as parsed, and the one-line
// errors for a missing grid file, a non-positive spacing, a missing fluid or constant.
#include <catch2/catch.hpp>

#include "io/scene.hpp"
#include "io_fixture.hpp"

using namespace polydem;
using test::contains;

namespace {

// A scene whose forces list ends with `fluid` (from line 6 on).
std::string scene_with(const std::string& fluid) {
  return "simulation: {duration: 1, dt: \"1 us\"}\n"          // 1
         "shapes: [lib.shp]\n"                                 // 2
         "bodies: [{shape: ball, position: [0, 0, 0]}]\n"      // 3
         "forces:\n"                                           // 4
         "  - gravity_force: {gravity: [0, 0, -10]}\n" +       // 5
         fluid;
}

struct Loaded {
  std::string error;
  Scene scene;
};

Loaded load(const std::string& fluid) {
  test::TempDir dir;
  dir.write("lib.shp", "stub\n");
  dir.write("flow.vti", "<VTKFile type=\"ImageData\"/>\n");
  const std::string path = dir.write("scene.yaml", scene_with(fluid));
  Loaded l;
  l.error = test::input_error_of([&] { l.scene = load_scene(path); });
  return l;
}

void check_error(const std::string& fluid, int line, const std::string& key, const std::string& part) {
  const std::string msg = load(fluid).error;
  INFO("message: " << msg);
  CHECK(contains(msg, "scene.yaml:" + std::to_string(line) + ": key '" + key + "': "));
  CHECK(contains(msg, part));
}

}  // namespace

TEST_CASE("fluid_field: analytic shear, hydrostatic pressure and the operators", "[scene][fluid]") {
  const Loaded l = load(
      "  - fluid_field:\n"
      "      grid: {min: [0, 0, 0], max: [0.1, 0.2, \"30 cm\"], cells: [2, 4, 6]}\n"
      "      velocity: {shear: {rate: 4, direction: [1, 0, 0], normal: [0, 0, 1]}}\n"
      "      pressure: {hydrostatic: {p0: \"1 kPa\"}}\n"
      "      reference: [0, 0, 0.3]\n"
      "      rho: 1000\n"
      "      nu: 1.0e-6\n"
      "      sampling: trilinear\n"
      "  - sphere_fluid_friction: {cx: 2}\n"
      "  - pressure_force: {C_added_mass: 0.5}\n"
      "  - viscous_force: {}\n"
      "  - archimedes_force: {}\n"
      "  - void_fraction: {alpha_min: 0.2, samples: 4}\n");
  REQUIRE(l.error == "");
  const ForceSettings& f = l.scene.forces;
  REQUIRE(f.fluid);
  CHECK(f.fluid->cells == Eigen::Vector3i(2, 4, 6));
  CHECK(f.fluid->grid_max.z() == Approx(0.3));
  CHECK(f.fluid->velocity_gradient(0, 2) == 4.0);  // du_x/dz
  CHECK(f.fluid->velocity_gradient.norm() == 4.0);
  CHECK(f.fluid->pressure == 1000.0);
  CHECK(f.fluid->pressure_gradient == Vec3(0, 0, -1.0e4));  // rho g with the scene's gravity
  CHECK(f.fluid->trilinear);
  CHECK(f.fluid_friction->cx == 2.0);
  CHECK(f.pressure_force->added_mass == 0.5);
  CHECK(f.viscous_force->added_mass == 0.0);
  CHECK(f.archimedes);
  CHECK(f.void_fraction->alpha_min == 0.2);
  CHECK(f.void_fraction->samples == 4);
}

TEST_CASE("fluid_field: a vortex is a solid-body rotation about the reference", "[scene][fluid]") {
  const Loaded l = load("  - fluid_field: {grid: {min: [-1, -1, -1], max: [1, 1, 1], cells: [1, 1, 1]}, "
                        "velocity: {vortex: {axis: [0, 0, 1], omega: \"2 rad/s\"}}}\n");
  REQUIRE(l.error == "");
  CHECK((l.scene.forces.fluid->velocity_gradient * Vec3(1, 0, 0) - Vec3(0, 2, 0)).norm() < 1e-15);
}

TEST_CASE("fluid operators: errors name the line and key", "[scene][fluid]") {
  check_error("  - fluid_field: {file: nothere.vti}\n", 6, "file", "cannot");
  check_error("  - sphere_fluid_friction: {field: gone.vti}\n", 6, "field", "cannot");
  check_error("  - fluid_field: {grid: {min: [0, 0, 0], max: [1, 0, 1], cells: [1, 1, 1]}}\n", 6, "max",
              "spacing must be positive");
  check_error("  - fluid_field: {grid: {min: [0, 0, 0], max: [1, 1, 1], cells: [1, 0, 1]}}\n", 6, "cells",
              ">= 1");
  check_error("  - archimedes_force: {}\n", 6, "archimedes_force", "needs a fluid");
  check_error("  - fluid_field: {grid: {min: [0, 0, 0], max: [1, 1, 1], cells: [1, 1, 1]}}\n"
              "  - viscous_force: {}\n", 6, "rho", "viscous_force needs it");
  check_error("  - fluid_field: {file: flow.vti, velocity: [1, 0, 0]}\n", 6, "velocity", "analytic fields need grid");
  check_error("  - fluid_field: {file: flow.vti, grid: {}}\n", 6, "grid", "give either");
  check_error("  - fluid_field: {file: flow.vti, sampling: nearest}\n", 6, "sampling", "cell or trilinear");
  check_error("  - fluid_field: {file: flow.vti}\n  - void_fraction: {alpha_min: 1}\n", 7, "alpha_min", "[0, 1)");
  check_error("  - fluid_field: {file: flow.vti}\n  - pressure_force: {C_added_mas: 1}\n", 7, "C_added_mas",
              "did you mean 'C_added_mass'?");
  check_error("  - fluid_field: {file: flow.vti}\n  - sphere_fluid_friction: {field: flow.vti}\n", 6, "file",
              "give it in one place");
}
