#pragma once
// A scene file parsed into plain settings structs, one per YAML block (see shared/SCENE.md).
// Every field is SI; the parser converts unit strings ("5 mm", "30 rpm") on the way in.
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "polydem/contact_params.hpp"
#include "polydem/math.hpp"

namespace polydem {

// Where a value came from, for error messages: "scene.yaml:12: key 'radius': ...".
struct SourceLoc {
  std::string file;
  int line = 0;  // 1-based; 0 when unknown
};

struct SimulationSettings {
  double duration = 1.0;          // s of simulated time
  std::optional<double> dt;       // s; empty means `auto` (a safe fraction of the critical step)
  int threads = 0;                // 0: all cores
  std::optional<double> skin;     // m, Verlet skin; empty: 0.1 x smallest body bounding radius
  std::uint64_t seed = 0;         // every random choice derives from it
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

struct Motion {                   // how a driver moves; fixed when all are unset
  Vec3 velocity = Vec3::Zero();   // m/s, constant translation
  bool rotates = false;
  Vec3 rotation_axis = Vec3::UnitZ();     // unit
  Vec3 rotation_center = Vec3::Zero();    // m
  double omega = 0.0;             // rad/s
  std::optional<double> force;    // N along the driver normal/axis (servo)
  std::optional<double> pressure; // Pa (servo, force = pressure x area)
  std::optional<double> area;     // m^2, the area the servo pressure acts on
  std::optional<double> gain;     // m/(N s), servo speed per newton of force error; empty: 0.1 / (kn dt)
  std::optional<Vec3> direction;  // unit, servo direction of a ball or mesh (wall: normal; cylinder: axis)
  std::optional<double> remove_at;  // s, the driver disappears at this time
  double start = 0.0;             // s, motion begins
  std::optional<double> stop;     // s, motion ends
};

struct DriverSpec {
  enum class Kind { wall, cylinder, ball, stl } kind = Kind::wall;
  std::string name;
  Vec3 point = Vec3::Zero();      // m, wall: a point on the plane
  Vec3 normal = Vec3::UnitZ();    // wall: unit normal towards the particles
  std::optional<double> size;     // m, wall: side of the square drawn about `point`; empty: cut to the view frame
  Vec3 center = Vec3::Zero();     // m, cylinder: middle of its axis; ball: centre
  Vec3 axis = Vec3::UnitZ();      // cylinder axis, unit
  double radius = 0.0;            // m, cylinder / ball
  std::optional<double> length;   // m, cylinder; empty: infinite
  bool inside = true;             // cylinder: particles inside
  std::string file;               // stl: path (resolved against the scene folder)
  SourceLoc file_loc;             // stl: the `file` key, for errors in the file
  double scale = 1.0;             // stl
  Vec3 translation = Vec3::Zero();  // m, stl placement
  Quat rotation = Quat::Identity(); // stl placement
  Motion motion;
  SourceLoc loc;
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

struct ForceSettings {
  std::optional<Vec3> gravity;    // m/s^2, gravity_force; empty: no gravity
  ContactOperator contact;
  struct Quadratic { double cx = 0.38, mu = 0.000015; };
  std::optional<Quadratic> quadratic;     // quadratic_force
  struct FluidFriction { std::string field; double cx = 1.0; };  // field: a .vti, or "" (fluid_field)
  std::optional<FluidFriction> fluid_friction;  // sphere_fluid_friction
  // fluid_field: the prescribed fluid on a regular grid of cells, from a .vti file or analytic:
  // U(x) = velocity + velocity_gradient (x - reference), p(x) = pressure + pressure_gradient . (x - reference).
  struct FluidField {
    std::string file;             // .vti (resolved); empty: the analytic field on the grid below
    Vec3 grid_min = Vec3::Zero(), grid_max = Vec3::Zero();  // m, analytic grid box
    Eigen::Vector3i cells = Eigen::Vector3i::Ones();  // analytic grid cells per axis
    Vec3 velocity = Vec3::Zero();           // m/s at `reference`
    Mat3 velocity_gradient = Mat3::Zero();  // 1/s, shear or solid-body rotation
    Vec3 reference = Vec3::Zero();          // m
    double pressure = 0.0;                  // Pa at `reference`
    Vec3 pressure_gradient = Vec3::Zero();  // Pa/m, hydrostatic: rho g
    std::optional<double> rho, nu;          // kg/m^3, m^2/s; with a file: used when it lacks the array
    bool trilinear = false;       // sampling: the particle's cell value, or trilinear between cell centres
    SourceLoc loc, file_loc;      // the operator, and the key naming the file (for file errors)
    std::string file_key = "file";  // that key: file, or sphere_fluid_friction's field
  };
  std::optional<FluidField> fluid;
  struct CfdForce { double added_mass = 0.0; };  // C_added_mass, dimensionless
  std::optional<CfdForce> pressure_force;        // pressure_force: -Vs grad(p) (1 + C_added_mass)
  std::optional<CfdForce> viscous_force;         // viscous_force: -Vs div(tau) (1 + C_added_mass)
  bool archimedes = false;                       // archimedes_force: -rho_f Vs g
  struct VoidFraction { double alpha_min = 0.0; int samples = 6; };  // samples: lattice points per axis
  std::optional<VoidFraction> void_fraction;     // void_fraction: Vs split among cells
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
  std::vector<DriverSpec> drivers;
  ForceSettings forces;
  OutputSettings output;
};

}  // namespace polydem
