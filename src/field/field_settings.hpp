#pragma once
// The settings of the field stage (gravity, drag, the prescribed fluid and its CFD-DEM forces),
// one field per operator of the scene's `forces:` list; the scene parser fills them.
#include <optional>
#include <string>

#include "polydem/math.hpp"
#include "polydem/source_loc.hpp"

namespace polydem {

struct FieldSettings {
  std::optional<Vec3> gravity;    // m/s^2, gravity_force; empty: no gravity
  SourceLoc gravity_loc;          // its line in the scene (the run limits name it)
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

}  // namespace polydem
