// Probes (output.probes): flow.csv against free fall, angle.csv against a surface placed on a
// known slope, both across a resume, and the InputErrors of their scene keys.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "io/scene.hpp"
#include "polydem/error.hpp"
#include "sim/probes.hpp"
#include "sim/runner.hpp"
#include "sim_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;
namespace fs = std::filesystem;

namespace {

constexpr double kG = 9.807;        // m/s^2
constexpr double kEvery = 0.01;     // s, csv_every
constexpr int kFallers = 6;

struct TempFolder {
  fs::path path;
  TempFolder() {
    path = fs::temp_directory_path() / ("polydem_probes_" + std::to_string(std::random_device{}()));
    fs::create_directories(path);
  }
  ~TempFolder() { fs::remove_all(path); }
};

std::vector<std::vector<double>> read_csv(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Body k starts at rest at the height it falls from to cross z = 0 at t_k = (k + 1.5) csv
// intervals under free fall (z = g t^2 / 2), half-way between two rows; densities differ so
// each crossing adds a different mass.
double crossing_time(int k) { return (k + 1.5) * kEvery; }

struct FreeFall {
  Scene scene = base_scene(law(1e5, 0.5), false, Vec3(0, 0, -kG));
  ShapeLibrary lib = library({sphere_shape(0.005)});
  std::vector<BodySpec> specs;
  FreeFall() {
    scene.simulation.dt = 1e-4;
    scene.simulation.duration = (kFallers + 2) * kEvery;
    scene.output.csv_every = kEvery;
    OutputSettings::FlowProbe outlet;
    outlet.name = "flow";
    outlet.normal = -Vec3::UnitZ();
    scene.output.flow_probes.push_back(outlet);
    for (int k = 0; k < kFallers; ++k) {
      const double t = crossing_time(k);
      BodySpec b = body("sphere", {0.05 * k, 0, 0.5 * kG * t * t});
      b.density = 1000.0 * (k + 1);
      specs.push_back(b);
    }
  }
};

RunSummary run(const FreeFall& f, const fs::path& dir, std::optional<double> until, const std::string& resume = "") {
  Simulation sim(f.scene, f.lib, f.specs);
  RunOptions o;
  o.out_dir = dir.string();
  o.until = until;
  o.resume = resume;
  o.progress = false;
  return run_simulation(sim, o);
}

}  // namespace

TEST_CASE("flow.csv counts the bodies that crossed a plane at their free-fall times", "[probes]") {
  const FreeFall f;
  TempFolder out;
  run(f, out.path, std::nullopt);
  const auto rows = read_csv(out.path / "flow.csv");
  REQUIRE(rows.size() == std::size_t(kFallers + 3));  // t = 0, 0.01, ..., duration
  Simulation reference(f.scene, f.lib, f.specs);       // for the body masses
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const double t = rows[r][0];
    double mass = 0.0;
    int count = 0;
    for (int k = 0; k < kFallers; ++k)
      if (crossing_time(k) < t) {  // t_k = sqrt(2 z_k / g): velocity Verlet is exact under constant gravity
        mass += reference.bodies.mass[k];
        ++count;
      }
    INFO("row " << r << " t = " << t);
    CHECK(t == Approx(r * kEvery).margin(1e-12));
    CHECK(rows[r][1] == Approx(mass).epsilon(1e-12));
    CHECK(rows[r][2] == count);
    const double rate = r == 0 ? 0.0 : (rows[r][1] - rows[r - 1][1]) / (t - rows[r - 1][0]);  // kg/s
    CHECK(rows[r][3] == Approx(rate).epsilon(1e-12));
  }
  CHECK(rows.back()[2] == kFallers);
}

TEST_CASE("flow.csv of a resumed run equals the uninterrupted one, rate included", "[probes]") {
  const FreeFall f;
  TempFolder full, half;
  run(f, full.path, std::nullopt);
  // Stop between two rows (0.045 s): the resumed run's first rate must use the 0.04 s row of the file.
  run(f, half.path, 0.045);
  std::string checkpoint;
  for (const auto& e : fs::directory_iterator(half.path))
    if (e.path().filename().string().rfind("checkpoint_", 0) == 0) checkpoint = e.path().string();
  REQUIRE(!checkpoint.empty());
  run(f, half.path, std::nullopt, checkpoint);
  CHECK(text_of(half.path / "flow.csv") == text_of(full.path / "flow.csv"));
}

namespace {

// n bodies: a surface layer exactly on y = tan(theta) h across the drum's section and a
// random fill below it, inside the drum of radius R.
Bodies heap(const DrumSection& drum, double theta, double radius) {
  const Vec3 across = drum.up.cross(drum.axis);
  std::vector<Vec3> points;
  for (double h = -0.8 * radius; h <= 0.8 * radius; h += 0.002)
    points.push_back(drum.center + h * across + h * std::tan(theta) * drum.up + 0.01 * drum.axis);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-radius, radius);
  while (points.size() < 600) {
    const double h = u(rng), y = u(rng), s = 0.02 * u(rng);
    if (h * h + y * y < radius * radius && y < h * std::tan(theta) - 0.004)
      points.push_back(drum.center + h * across + y * drum.up + s * drum.axis);
  }
  Bodies b;
  b.resize(points.size());
  b.position = points;
  return b;
}

}  // namespace

TEST_CASE("angle of repose of a surface placed on a known slope", "[probes]") {
  DrumSection drum;
  drum.radius = 0.15;
  drum.length = 0.1;
  const Vec3 tilted_axis = Vec3(1, 0.2, 0).normalized();  // a drum whose axis is not a coordinate axis
  for (const auto& [axis, up] : {std::pair{Vec3(Vec3::UnitY()), Vec3(Vec3::UnitZ())},
                                 {tilted_axis, Vec3(Vec3::UnitZ())}}) {
    drum.axis = axis;
    drum.up = up;
    drum.center = Vec3(0.3, -0.2, 0.5);
    for (double degrees : {0.0, 12.0, 31.0, -35.0}) {
      const Bodies b = heap(drum, degrees * kPi / 180.0, drum.radius);
      const SurfaceFit fit = repose_angle(b, drum, 0.01, 0.6);
      INFO("axis " << axis.transpose() << " slope " << degrees << " deg");
      CHECK(fit.angle == Approx(std::abs(degrees)).margin(1e-9));  // every column's top lies on the line
      CHECK(fit.points >= 10);
    }
  }
}

TEST_CASE("angle.csv: a drum driver and bodies on a 25 degree slope", "[probes]") {
  Scene scene = base_scene(law(1e5, 0.5), false, Vec3(0, 0, -kG));
  DriverSettings d;
  d.name = "drum";
  d.kind = CylinderSettings{Vec3::Zero(), Vec3::UnitY(), 0.15, 0.1};
  scene.drivers.push_back(d);
  scene.simulation.dt = 1e-4;
  scene.output.csv_every = kEvery;
  OutputSettings::ReposeProbe probe;
  probe.driver = "drum";
  probe.column = 0.01;
  scene.output.repose_probes.push_back(probe);
  DrumSection section;
  section.radius = 0.15;
  const Bodies placed = heap(section, 25.0 * kPi / 180.0, 0.14);
  std::vector<BodySpec> specs;
  for (const Vec3& x : placed.position) specs.push_back(body("grain", x));
  Simulation sim(scene, library({sphere_shape(1e-4, "grain")}), specs);  // far apart: no contacts at t = 0
  TempFolder out;
  RunOptions o;
  o.out_dir = out.path.string();
  o.until = 0.0;
  o.progress = false;
  run_simulation(sim, o);
  const auto rows = read_csv(out.path / "angle.csv");
  REQUIRE(rows.size() == 1);
  CHECK(rows[0][1] == Approx(25.0).margin(1e-9));
}

TEST_CASE("mean equivalent diameter: a sphere's is its diameter", "[probes]") {
  Bodies b;
  b.resize(2);
  b.scale = {1.0, 2.0};
  const std::vector<Shape> shapes = {sphere_shape(0.005)};
  CHECK(mean_equivalent_diameter(b, shapes) == Approx(0.5 * (0.01 + 0.02)).epsilon(1e-12));
}

namespace {

// A scene with a drum, a wall and gravity; `output` is the text of its output block.
std::string probe_error(const std::string& output, bool gravity = true) {
  TempFolder dir;
  const fs::path path = dir.path / "scene.yaml";
  std::ofstream(path) << "simulation: {duration: 1, dt: \"1 us\"}\n"                                  // 1
                      << "drivers:\n"                                                                // 2
                      << "  - cylinder: {name: drum, center: [0, 0, 0], axis: [0, 1, 0], radius: 0.1}\n"  // 3
                      << "  - wall: {name: floor, point: [0, 0, 0], normal: [0, 0, 1]}\n"            // 4
                      << "  - cylinder: {name: pipe, center: [0, 0, 0], axis: [0, 0, 1], radius: 0.1}\n"  // 5
                      << "forces:\n"                                                                 // 6
                      << (gravity ? "  - gravity_force: {gravity: [0, 0, -9.807]}\n" : "\n")         // 7
                      << output;                                                                     // 8...
  try {
    const Scene s = load_scene(path.string());
    CHECK(s.output.flow_probes.size() + s.output.repose_probes.size() > 0);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void check_probe_error(const std::string& output, int line, const std::string& key, const std::string& part,
                       bool gravity = true) {
  const std::string msg = probe_error(output, gravity);
  INFO("message: " << msg);
  CHECK(msg.find("scene.yaml:" + std::to_string(line) + ": key '" + key + "'") != std::string::npos);
  CHECK(msg.find(part) != std::string::npos);
}

}  // namespace

TEST_CASE("probe keys are read with units and defaults", "[probes][io]") {
  TempFolder dir;
  const fs::path path = dir.path / "scene.yaml";
  std::ofstream(path) << "simulation: {duration: 1}\n"
                      << "drivers: [{cylinder: {name: drum, center: [0, 0, 0], axis: [0, 1, 0], radius: 0.1}}]\n"
                      << "forces: [{gravity_force: {}}]\n"
                      << "output:\n  csv_every: \"1 ms\"\n  probes:\n"
                      << "    - flow: {name: outlet, point: [0, 0, \"-5 cm\"], normal: [0, 0, -2]}\n"
                      << "    - repose_angle: {driver: drum, column: \"8 mm\", fit: 0.5}\n"
                      << "    - flow: {point: [0, 0, 0], normal: [1, 0, 0]}\n";
  const Scene s = load_scene(path.string());
  REQUIRE(s.output.flow_probes.size() == 2);
  REQUIRE(s.output.repose_probes.size() == 1);
  CHECK(s.output.flow_probes[0].name == "outlet");
  CHECK(s.output.flow_probes[0].point.z() == Approx(-0.05));
  CHECK(s.output.flow_probes[0].normal.z() == Approx(-1.0));  // normalized
  CHECK(s.output.flow_probes[1].name == "flow");
  CHECK(s.output.repose_probes[0].name == "angle");
  CHECK(s.output.repose_probes[0].driver == "drum");
  CHECK(*s.output.repose_probes[0].column == Approx(0.008));
  CHECK(s.output.repose_probes[0].fit == 0.5);
}

TEST_CASE("bad probe keys name the file, line and key", "[probes][io]") {
  const std::string csv = "output:\n  csv_every: \"1 ms\"\n  probes:\n";  // lines 8-10; items from 11
  check_probe_error(csv + "    - repose_angle: {driver: drun}\n", 11, "driver", "did you mean 'drum'");
  check_probe_error(csv + "    - repose_angle: {driver: floor}\n", 11, "driver", "not a cylinder");
  check_probe_error(csv + "    - repose_angle: {driver: pipe}\n", 11, "driver", "axis along gravity");
  check_probe_error(csv + "    - repose_angle: {driver: drum}\n", 11, "driver", "gravity_force", false);
  check_probe_error(csv + "    - repose_angle: {driver: drum, fit: 1.5}\n", 11, "fit", "(0, 1]");
  check_probe_error(csv + "    - repose_angle: {driver: drum, column: \"-1 mm\"}\n", 11, "column", "> 0");
  check_probe_error(csv + "    - flow: {point: [0, 0, 0]}\n", 11, "normal", "normal: [0, 0, -1]");
  check_probe_error(csv + "    - flow: {point: [0, 0, 0], normal: [0, 0, 0]}\n", 11, "normal", "zero vector");
  check_probe_error(csv + "    - flow: {normal: [0, 0, -1], point: [0, 0, 0], nromal: 1}\n", 11, "nromal",
                    "did you mean 'normal'");
  check_probe_error(csv + "    - flow: {name: energy, point: [0, 0, 0], normal: [0, 0, -1]}\n", 11, "name",
                    "overwrite energy.csv");
  check_probe_error(csv + "    - flow: {name: a/b, point: [0, 0, 0], normal: [0, 0, -1]}\n", 11, "name", "letters");
  check_probe_error(csv + "    - flow: {point: [0, 0, 0], normal: [0, 0, -1]}\n" +
                        "    - flow: {point: [0, 0, 1], normal: [0, 0, -1]}\n",
                    12, "name", "already used at line 11");
  check_probe_error(csv + "    - flux: {point: [0, 0, 0]}\n", 11, "flux", "did you mean 'flow'");
  check_probe_error("output:\n  probes:\n    - flow: {point: [0, 0, 0], normal: [0, 0, -1]}\n", 9, "probes",
                    "csv_every");
  check_probe_error("output:\n  probes: {flow: 1}\n", 9, "probes", "list");
}

TEST_CASE("a repose probe in a scene without bodies asks for a column width", "[probes]") {
  Scene scene = base_scene(law(1e5, 0.5), false, Vec3(0, 0, -kG));
  DriverSettings d;
  d.name = "drum";
  d.kind = CylinderSettings{Vec3::Zero(), Vec3::UnitY(), 0.1};
  scene.drivers.push_back(d);
  scene.simulation.dt = 1e-4;
  scene.output.csv_every = kEvery;
  OutputSettings::ReposeProbe probe;
  probe.driver = "drum";
  probe.loc = {"scene.yaml", 12};
  scene.output.repose_probes.push_back(probe);
  Simulation sim(scene, library({sphere_shape(0.005)}), {});
  TempFolder out;
  RunOptions o;
  o.out_dir = out.path.string();
  o.progress = false;
  try {
    run_simulation(sim, o);
    FAIL("no InputError");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("scene.yaml:12: key 'column'") != std::string::npos);
  }
}
