#pragma once
// A scene file parsed into plain settings structs, one per YAML block (see shared/SCENE.md).
// Every field is SI; the parser converts unit strings ("5 mm", "30 rpm") on the way in. The
// drivers and the field forces are the stages' own settings (driver/, field/): the parser
// builds them, the simulation hands them over.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "driver/driver_settings.hpp"
#include "field/field_settings.hpp"
#include "polydem/contact_params.hpp"
#include "polydem/math.hpp"
#include "polydem/source_loc.hpp"

namespace polydem {

// The range `simulation: accuracy` accepts (relative restitution error, dimensionless): within
// the sphere-wall errors measured in tools/bench/accuracy (1e-5 at 0.01 x critical).
constexpr double kMinAccuracy = 1e-5, kMaxAccuracy = 0.2;

struct SimulationSettings {
  double duration = 1.0;          // s of simulated time
  std::optional<double> dt;       // s; empty means `auto` (a safe fraction of the critical step)
  std::optional<double> accuracy; // relative restitution error of one impact `auto` aims at (sim/step_accuracy.hpp)
  bool exact_step = true;   // the linear law's exact step where it applies (contact/law/exact_linear.hpp); tests switch it
  int threads = 0;                // 0: all cores
  std::optional<double> skin;     // m, Verlet skin; empty: 0.1 x smallest body bounding radius
  std::optional<double> skin_max; // m, the largest skin of a body (ContactSettings::skin_max); empty: skin
  std::uint64_t seed = 0;         // every random choice derives from it
  // How a fresh run lays its bodies out in memory (sim/body_order.hpp): by cell, or as listed.
  enum class BodyOrder { space, input } body_order = BodyOrder::space;
};

struct BodySpec {                 // one explicit body
  std::string shape;              // shape name in the loaded libraries
  Vec3 position = Vec3::Zero();   // m
  Quat orientation = Quat::Identity();
  Vec3 velocity = Vec3::Zero();   // m/s
  Vec3 angular_velocity = Vec3::Zero();  // rad/s, world frame
  double density = 2700.0;        // kg/m^3
  double scale = 1.0;             // homothety of the library shape
  int group = 0;
  SourceLoc loc;
};

struct BoxRegion { Vec3 min = Vec3::Zero(), max = Vec3::Zero(); };            // m
struct CylinderRegion {                                                    // m
  Vec3 center = Vec3::Zero();     // centre of the base disc
  Vec3 axis = Vec3::UnitZ();      // unit
  double radius = 0.0, length = 0.0;
};

struct GeneratorSpec {            // `generate: random` or `generate: lattice`
  enum class Kind { random, lattice } kind = Kind::random;
  std::vector<std::pair<std::string, double>> shapes;  // name -> number fraction (sums to 1)
  int count = 0;
  std::variant<BoxRegion, CylinderRegion> region;
  double scale_min = 1.0, scale_max = 1.0;
  bool random_orientation = true;
  Vec3 velocity = Vec3::Zero();   // m/s
  double density = 2700.0;        // kg/m^3
  int group = 0;
  SourceLoc loc;                  // the generator's first line
  SourceLoc shapes_loc;           // the `shapes` line: unknown names in the mix are reported there
};

struct ContactOperator {          // contact_sphere / contact_polyhedron [_with_cohesion]
  bool present = false;
  bool sphere = false;            // contact_sphere*: the scene promises spheres only
  bool cohesion = false;          // *_with_cohesion
  ContactParams config;           // particle-particle
  ContactParams config_driver;    // particle-driver
  bool has_config_driver = false; // else config_driver = config
  SourceLoc loc;
};

// The `forces:` list: the field stage's operators and the contact law.
struct ForceSettings : FieldSettings {
  ContactOperator contact;
};

struct OutputSettings {
  std::string dir;                // resolved; default: out/ beside the scene
  std::optional<double> vtk_every;         // s; empty: no VTK output
  std::optional<double> csv_every;         // s; empty: no CSV output
  std::optional<double> checkpoint_every;  // s; empty: only the final checkpoint
  bool contacts = true;           // write the contact network
  bool rounded = false;           // draw bodies with their rounding (the swept surface), not their cores
  struct FlowProbe {              // probes: flow; mass and count of bodies past a plane
    std::string name = "flow";    // written to NAME.csv
    Vec3 point = Vec3::Zero();    // m, a point on the plane
    Vec3 normal = -Vec3::UnitZ(); // unit, towards the discharged side
    SourceLoc loc;
  };
  struct ReposeProbe {            // probes: repose_angle; free-surface slope in a drum
    std::string name = "angle";   // written to NAME.csv
    std::string driver;           // a cylinder driver (the drum)
    std::optional<double> column; // m, width of the surface columns; empty: mean equivalent diameter
    double fit = 0.6;             // central fraction of the free surface's width that is fitted
    SourceLoc loc;
  };
  std::vector<FlowProbe> flow_probes;      // on the csv_every schedule
  std::vector<ReposeProbe> repose_probes;  // on the csv_every schedule
};

struct Scene {
  std::string path;               // the scene file
  std::string folder;             // its folder: relative paths are resolved against it
  SimulationSettings simulation;
  std::vector<std::string> shape_files;   // resolved paths
  std::vector<BodySpec> bodies;
  std::vector<GeneratorSpec> generators;
  std::vector<DriverSettings> drivers;
  ForceSettings forces;
  OutputSettings output;
  // "simulation.dt", "output.csv_every", ...: where each given key was, for the limits checked
  // once the time step is known (sim/run_limits).
  std::map<std::string, SourceLoc> key_locs;
};

}  // namespace polydem
