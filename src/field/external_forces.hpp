#pragma once
// The force operators that act on each body from outside the contact network, gravity apart:
// quadratic drag, friction against the fluid grid, and the CFD-DEM pressure-gradient,
// viscous and Archimedes forces with the divided void fraction. Built only when the scene has
// one of them; all act at the centre of mass (no torque).
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "contact/exact_sum.hpp"
#include "field/field_bodies.hpp"
#include "field/fluid_grid.hpp"
#include "field/void_fraction.hpp"
#include "polydem/bodies.hpp"
#include "field/field_settings.hpp"
#include "polydem/shape.hpp"

namespace polydem {

class ExternalForces {
 public:
  // Whether `forces` holds an operator this class applies.
  static bool wanted(const FieldSettings& forces);

  // Reads the fluid grid (InputError at the scene key for a bad file); set for `bodies`' rows.
  ExternalForces(const FieldSettings& forces, const std::vector<Shape>& shapes, const Bodies& bodies);

  // The per-row constants (volume, drag area) for `rows`: before the first add() on other
  // rows than the last ones (a rank's store after a rebuild).
  void set_rows(const FieldBodies& rows);
  // Adds each operator's force to each owned row's force; returns their power
  // sum_b f_b . v_b (W), summed exactly: the same bits however the rows are split among
  // threads and ranks (each rank sums its own, the ranks' words are added).
  ExactSum add(const FieldBodies& rows);
  // One process, every body: the power rounded (ExactSum::rounded_sum, add()'s value()).
  double add(Bodies& bodies);

  const FluidGrid* grid() const { return grid_ ? &*grid_ : nullptr; }
  // Owned rows whose centre was outside the grid at the last add(): no grid force acts on them.
  std::size_t outside() const { return outside_; }
  // The void fraction field now (every body: a distributed run gathers them first); empty
  // without a void_fraction operator.
  std::optional<VoidFractionField> void_fraction(const Bodies& bodies) const;

 private:
  Vec3 grid_force(const FieldBodies& rows, std::size_t b) const;
  void apply(const FieldBodies& rows);  // the forces; each row's power in power_

  FieldSettings::Quadratic quadratic_{};
  bool quadratic_on_ = false;
  std::optional<double> friction_cx_;          // sphere_fluid_friction
  std::optional<double> pressure_, viscous_;   // 1 + C_added_mass
  bool archimedes_ = false;
  Vec3 gravity_ = Vec3::Zero();                // m/s^2
  std::optional<FluidGrid> grid_;
  std::unique_ptr<VoidFraction> void_fraction_;
  const std::vector<Shape>& shapes_;
  std::vector<double> volume_, area_;          // per row: m^3, and pi r^2 of the equivalent sphere (m^2)
  std::vector<double> vs_;                     // per row, m^3
  std::vector<double> power_;                  // per row, W
  std::vector<std::uint8_t> outside_flag_;
  std::size_t outside_ = 0;
};

}  // namespace polydem
