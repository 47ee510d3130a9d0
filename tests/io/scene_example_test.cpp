// SCENE.md's example scene: every key parses into the settings it names, in SI.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "io/scene.hpp"
#include "io_fixture.hpp"

using namespace polydem;
namespace fs = std::filesystem;

namespace {

const char* kHead = R"(simulation:
  duration: 1.5            # s of simulated time
  dt: auto                 # s, or auto: a safe fraction of the critical step (printed)
  threads: 2               # optional; default: all cores
  skin: "1 mm"             # Verlet skin distance (optional, sensible default)
  seed: 42                 # every random choice in the scene derives from it

shapes:                    # shape library files, .shp (Rockable format) or .yaml
  - ../../shapes/platonic.shp

bodies:                    # lists of bodies; each entry is an explicit body or a generator
  - shape: cube
    position: [0, 0, 0.3]
    orientation: {axis: [1, 0, 0], angle: "30 deg"}   # or quaternion: [w, x, y, z]
    velocity: [0, 0, -1]
    angular_velocity: [0, 0, 0]
    density: 2700
    group: 0
  - generate: random       # or lattice
    shapes: {cube: 0.7, octahedron: 0.3}   # name or mix by number fraction
    count: 5000
    region: {box: {min: [-0.1, -0.1, 0.0], max: [0.1, 0.1, 0.6]}}  # or cylinder: {...}
    scale: {min: 0.8, max: 1.2}            # homothety of the library shape
    orientation: random
    velocity: [0, 0, 0]
    density: 2700
    group: 1

drivers:
  - wall:     {name: floor, point: [0, 0, 0], normal: [0, 0, 1]}
  - cylinder: {name: drum, center: [0, 0, 0], axis: [0, 1, 0], radius: 0.15,
               length: 0.1, inside: true,
               motion: {rotate: {axis: [0, 1, 0], center: [0, 0, 0], omega: "30 rpm"}}}
  - ball:     {name: impactor, center: [0, 0, 1], radius: 0.05,
               motion: {velocity: [0, 0, -2]}}
  - stl:      {name: hopper, file: hopper.stl, scale: 0.001}
  - wall:     {name: gate, point: [0, 0, 0.05], normal: [0, 0, 1],
               motion: {remove_at: "0.5 s"}}
  - wall:     {name: piston, point: [0, 0, 0.4], normal: [0, 0, -1],
               motion: {force: 50}}          # servo: moves to hold 50 N

forces:                    # the force field; exaDEM's operator names
  - gravity_force: {gravity: [0, 0, -9.807]}
)";

const char* kContact = R"(  - contact_polyhedron:    # contact_sphere for sphere-only scenes
      config:        {kn: 1.0e5, kt: 1.0e5, mu: 0.5, en: 0.5}
      config_driver: {kn: 1.0e5, kt: 1.0e5, mu: 0.3, damp_rate: 0.9}
)";

const char* kCohesion = R"(  - contact_polyhedron_with_cohesion:   # instead of contact_polyhedron
      config:        {kn: 1.0e5, kt: 1.0e5, kr: 0.01, mur: 0.1, mu: 0.5,
                      en: 0.5, fc: 0.05, dncut: "0.1 mm"}
)";

const char* kTail = R"(  - quadratic_force: {cx: 0.38, mu: 0.000015}
  - sphere_fluid_friction: {field: fluid.vti, cx: 1.0}

output:
  dir: out                 # default: out/ beside the scene
  vtk_every: "10 ms"       # bodies, drivers, contacts as .vtu/.vtp, one .pvd series
  csv_every: "1 ms"        # energy.csv and the other time series
  checkpoint_every: "0.1 s"
  contacts: true           # write the contact network (force chains)
)";

Scene load_example(const test::TempDir& dir, const char* contact) {
  dir.write("shapes/platonic.shp", "stub\n");
  dir.write("samples/drum/hopper.stl", "solid stub\nendsolid stub\n");
  dir.write("samples/drum/fluid.vti", "stub\n");
  return load_scene(dir.write("samples/drum/scene.yaml", std::string(kHead) + contact + kTail));
}

bool near(const Vec3& a, const Vec3& b) { return (a - b).norm() < 1e-12; }

}  // namespace

TEST_CASE("SCENE.md example: simulation, shapes, bodies, generator", "[scene]") {
  test::TempDir dir;
  const Scene s = load_example(dir, kContact);
  const fs::path folder = dir.path / "samples/drum";
  CHECK(s.simulation.duration == 1.5);
  CHECK_FALSE(s.simulation.dt.has_value());
  CHECK(s.simulation.threads == 2);
  CHECK(s.simulation.skin.value() == Approx(1e-3).epsilon(1e-15));
  CHECK(s.simulation.seed == 42);
  REQUIRE(s.shape_files.size() == 1);
  CHECK(fs::equivalent(s.shape_files[0], dir.path / "shapes/platonic.shp"));

  REQUIRE(s.bodies.size() == 1);
  const BodySpec& b = s.bodies[0];
  CHECK(b.shape == "cube");
  CHECK(near(b.position, Vec3(0, 0, 0.3)));
  // A rotation by 30 deg about x: q = (cos 15 deg, sin 15 deg, 0, 0).
  CHECK(b.orientation.w() == Approx(std::cos(kPi / 12)));
  CHECK(b.orientation.x() == Approx(std::sin(kPi / 12)));
  CHECK(near(b.velocity, Vec3(0, 0, -1)));
  CHECK(near(b.angular_velocity, Vec3::Zero()));
  CHECK(b.density == 2700.0);
  CHECK(b.group == 0);
  CHECK(b.loc.line == 12);

  REQUIRE(s.generators.size() == 1);
  const GeneratorSpec& g = s.generators[0];
  CHECK(g.kind == GeneratorSpec::Kind::random);
  REQUIRE(g.shapes.size() == 2);
  CHECK(g.shapes[0].first == "cube");
  CHECK(g.shapes[0].second == Approx(0.7));
  CHECK(g.shapes[1].first == "octahedron");
  CHECK(g.shapes[1].second == Approx(0.3));
  CHECK(g.count == 5000);
  const auto& box = std::get<BoxRegion>(g.region);
  CHECK(near(box.min, Vec3(-0.1, -0.1, 0.0)));
  CHECK(near(box.max, Vec3(0.1, 0.1, 0.6)));
  CHECK(g.scale_min == 0.8);
  CHECK(g.scale_max == 1.2);
  CHECK(g.random_orientation);
  CHECK(g.density == 2700.0);
  CHECK(g.group == 1);
  CHECK(g.loc.line == 19);
  CHECK(g.shapes_loc.line == 20);  // `shapes: {cube: 0.7, ...}`, the line after `- generate: random`
  CHECK(fs::path(s.folder) == folder);
}

TEST_CASE("SCENE.md example: drivers and their motions", "[scene]") {
  test::TempDir dir;
  const Scene s = load_example(dir, kContact);
  REQUIRE(s.drivers.size() == 6);
  const auto* floor = std::get_if<WallSettings>(&s.drivers[0].kind);
  REQUIRE(floor);
  CHECK((s.drivers[0].name == "floor" && near(floor->normal, Vec3::UnitZ())));
  const auto* drum = std::get_if<CylinderSettings>(&s.drivers[1].kind);
  REQUIRE(drum);
  CHECK(s.drivers[1].name == "drum");
  CHECK(near(drum->axis, Vec3::UnitY()));
  CHECK(drum->radius == 0.15);
  CHECK(drum->length.value() == 0.1);
  CHECK(drum->inside);
  const MotionSettings& turn = s.drivers[1].motion;
  CHECK(turn.rotates);
  CHECK(near(turn.rotation_axis, Vec3::UnitY()));
  CHECK(turn.omega == Approx(kPi));  // 30 rpm = 30 x 2 pi / 60 rad/s
  const auto* ball = std::get_if<BallSettings>(&s.drivers[2].kind);
  REQUIRE(ball);
  CHECK((ball->radius == 0.05 && near(ball->center, Vec3(0, 0, 1))));
  CHECK(near(s.drivers[2].motion.velocity, Vec3(0, 0, -2)));
  const auto* stl = std::get_if<MeshSettings>(&s.drivers[3].kind);
  REQUIRE(stl);
  CHECK(fs::equivalent(stl->file, dir.path / "samples/drum/hopper.stl"));
  CHECK(stl->scale == 0.001);
  CHECK(s.drivers[4].motion.remove_at.value() == 0.5);
  CHECK(s.drivers[5].motion.force.value() == 50.0);
  CHECK(near(std::get<WallSettings>(s.drivers[5].kind).normal, -Vec3::UnitZ()));
  CHECK(s.drivers[5].loc.line == 39);
}

TEST_CASE("SCENE.md example: forces and output", "[scene]") {
  test::TempDir dir;
  const Scene s = load_example(dir, kContact);
  CHECK(near(s.forces.gravity.value(), Vec3(0, 0, -9.807)));
  const ContactOperator& c = s.forces.contact;
  CHECK((c.present && !c.sphere && !c.cohesion && c.has_config_driver));
  CHECK((c.config.kn == 1e5 && c.config.kt == 1e5 && c.config.mu == 0.5 && c.config.en == 0.5));
  CHECK(c.config.damp_rate < 0.0);
  CHECK(
      (c.config_driver.mu == 0.3 && c.config_driver.damp_rate == 0.9 && c.config_driver.en < 0.0));
  CHECK(s.forces.quadratic->cx == 0.38);
  CHECK(s.forces.quadratic->mu == 0.000015);
  CHECK(fs::equivalent(s.forces.fluid_friction->field, dir.path / "samples/drum/fluid.vti"));
  CHECK(s.forces.fluid_friction->cx == 1.0);
  CHECK(fs::path(s.output.dir) == dir.path / "samples/drum/out");
  CHECK(s.output.vtk_every.value() == Approx(0.01).epsilon(1e-15));
  CHECK(s.output.csv_every.value() == Approx(0.001).epsilon(1e-15));
  CHECK(s.output.checkpoint_every.value() == Approx(0.1).epsilon(1e-15));
  CHECK(s.output.contacts);
}

TEST_CASE("SCENE.md example: the cohesion operator", "[scene]") {
  test::TempDir dir;
  const Scene s = load_example(dir, kCohesion);
  const ContactOperator& c = s.forces.contact;
  CHECK((c.present && c.cohesion && !c.sphere && !c.has_config_driver));
  CHECK((c.config.kr == 0.01 && c.config.mur == 0.1 && c.config.fc == 0.05));
  CHECK(c.config.dncut == Approx(1e-4).epsilon(1e-15));
  CHECK(c.config_driver.fc == c.config.fc);  // config_driver defaults to config
}

TEST_CASE("defaults: output beside the scene, optional blocks empty", "[scene]") {
  test::TempDir dir;
  const Scene s =
      load_scene(dir.write("a/minimal.yaml", "simulation: {duration: \"2 ms\", dt: \"1 us\"}\n"));
  CHECK(s.simulation.duration == Approx(2e-3).epsilon(1e-15));
  CHECK(s.simulation.dt.value() == Approx(1e-6).epsilon(1e-15));
  CHECK(s.simulation.threads == 0);
  CHECK_FALSE(s.simulation.skin.has_value());
  CHECK(fs::path(s.output.dir) == dir.path / "a/out");
  CHECK((s.bodies.empty() && s.generators.empty() && s.drivers.empty()));
  CHECK_FALSE(s.forces.contact.present);
  CHECK_FALSE(s.forces.gravity.has_value());
  // Empty lists and an operator without parameters take the defaults.
  const Scene e = load_scene(dir.write("a/empty.yaml",
                                       "simulation: {duration: 1}\nbodies:\n"
                                       "drivers:\nforces:\n  - gravity_force:\n"));
  CHECK((e.bodies.empty() && e.drivers.empty()));
  CHECK((e.forces.gravity.value() - Vec3(0, 0, -9.807)).norm() == 0.0);
}
