// STL and servo drivers from a scene file: placement (scale, rotation, translation), a mesh
// turning with its motion, and one-line errors naming the scene's file, line and key.
#include <catch2/catch.hpp>

#include <fstream>

#include "../driver/mesh_fixtures.hpp"
#include "io/scene.hpp"
#include "output/frame.hpp"
#include "output/vtk.hpp"
#include "polydem/error.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

// A scene whose drivers list is `drivers` (YAML lines); its path.
std::string scene_with(const TempFolder& dir, const std::string& drivers) {
  const std::string path = dir.file("scene.yaml");
  std::ofstream(path) << "simulation: {duration: 1, dt: 1.0e-6}\n"  // line 1
                      << "drivers:\n"                               // line 2
                      << drivers;                                   // line 3 on
  return path;
}

std::string error_of(const std::string& path) {
  try {
    Drivers drivers(load_scene(path).drivers);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("an STL driver is placed by scale, rotation and translation, and turns with its motion", "[driver][stl]") {
  TempFolder dir;
  write_ascii_stl(dir.file("cube.stl"), cube_triangles(10.0));  // mm
  const std::string path = scene_with(dir, "  - stl: {name: box, file: cube.stl, scale: 0.001, translation: [0, 0, 0.1],\n"
                                           "           rotation: {axis: [0, 0, 1], angle: 30 deg},\n"
                                           "           motion: {rotate: {axis: [0, 0, 1], center: [0, 0, 0], omega: 2}}}\n");
  Drivers drivers(load_scene(path).drivers);
  const Quat placed(Eigen::AngleAxisd(kPi / 6, Vec3::UnitZ()));
  const std::vector<DriverMesh> at_start = drivers.meshes(ViewFrame{});
  REQUIRE(at_start.size() == 1);
  const Vec3 corner(0.01, 0.01, 0.01);  // a corner of the mesh, scaled
  auto has_point = [](const DriverMesh& m, const Vec3& p) {
    for (const Vec3& q : m.points)
      if ((q - p).norm() < 1e-12) return true;
    return false;
  };
  CHECK(has_point(at_start[0], Vec3(0, 0, 0.1) + placed * corner));
  const double dt = 1e-3;
  for (int s = 0; s < 100; ++s) drivers.advance(s * dt, dt);  // 0.2 rad about z through the origin
  const Quat turned(Eigen::AngleAxisd(0.2, Vec3::UnitZ()));
  CHECK(has_point(drivers.meshes(ViewFrame{})[0], turned * (Vec3(0, 0, 0.1) + placed * corner)));
  // A sphere just above the turned top face touches it, with the wall's velocity there.
  const Shape sphere = one_vertex_shape(0.002);
  const Vec3 above = turned * Vec3(0.003, -0.002, 0.1) + Vec3(0, 0, 0.0119);
  const Placed p(sphere, above);
  const auto contacts = driver_contacts(drivers, 0, p.body);
  REQUIRE(contacts.size() == 1);
  CHECK(contacts[0].second.gap == Approx(-1e-4).margin(1e-12));
  CHECK((drivers.velocity_at(0, contacts[0].second.point) - Vec3(0, 0, 2).cross(contacts[0].second.point)).norm() < 1e-12);
}

TEST_CASE("STL and servo mistakes in a scene file stop with file:line:key", "[driver][stl][errors]") {
  TempFolder dir;
  write_ascii_stl(dir.file("floor.stl"), floor_triangles(2, 0.01));
  std::ofstream(dir.file("broken.stl")) << "solid b\n facet normal 0 0 1\n  outer loop\n   vertex 0 0\n";
  const std::string scene = dir.file("scene.yaml");
  struct Case { std::string drivers, starts, mentions; };
  const Case cases[] = {
      {"  - stl: {file: nowhere.stl}\n", scene + ":3: key 'file'", "cannot open"},
      {"  - stl:\n      name: mesh\n      file: broken.stl\n", scene + ":5: key 'file': driver 'mesh'", "broken.stl:4"},
      {"  - stl: {file: floor.stl, scale: -1}\n", scene + ":3: key 'scale'", "> 0"},
      {"  - stl: {file: floor.stl, motion: {force: 5}}\n", scene + ":3: key 'direction'", "direction:"},
      {"  - wall: {point: [0, 0, 0], normal: [0, 0, 1], motion: {pressure: 100}}\n", scene + ":3: key 'area'", "area:"},
      {"  - wall: {point: [0, 0, 0], normal: [0, 0, 1], motion: {gain: 0.1}}\n", scene + ":3: key 'gain'", "force or pressure"},
      {"  - wall: {point: [0, 0, 0], normal: [0, 0, 1], motion: {force: 5, direction: [0, 0, 1]}}\n", scene + ":3: key 'direction'", "normal"},
      {"  - ball: {center: [0, 0, 0], radius: 0.01, motion: {force: 5, direction: [0, 0, 0]}}\n", scene + ":3: key 'direction'", ""},
      {"  - cylinder: {center: [0, 0, 0], radius: 0.01, axis: [0, 0, 0], inside: false}\n", scene + ":3: key 'axis'", ""},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(scene_with(dir, c.drivers));
    INFO(c.drivers);
    CHECK_THAT(message, Catch::StartsWith(c.starts) && Catch::Contains(c.mentions));
    CHECK(message.find('\n') == std::string::npos);
  }
  CHECK(error_of(scene_with(dir, "  - stl: {file: floor.stl, motion: {force: 5, direction: [0, 0, -1], gain: 0.01}}\n")) == "");
  CHECK(error_of(scene_with(dir, "  - cylinder: {center: [0, 0, 0], radius: 0.01, length: 0.1, inside: false}\n")) == "");
}
