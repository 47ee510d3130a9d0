#pragma once
// The prescribed fluid: a regular grid of cells holding velocity, pressure, density and
// kinematic viscosity, the derived fields the CFD-DEM forces need, and the sampling rule.
#include <array>
#include <optional>
#include <vector>

#include "polydem/math.hpp"

namespace polydem {

using Index3 = Eigen::Vector3i;

// The most cells a grid may hold: cell indices are ints (2^31 - 1), and at ~100 bytes a cell
// (velocity, pressure, density, viscosity, their gradients) 2e8 cells take 20 GB.
constexpr double kMaxGridCells = 2e8;

struct FluidGrid {
  Vec3 origin = Vec3::Zero();     // m, lower corner of cell (0, 0, 0)
  Vec3 spacing = Vec3::Ones();    // m, cell size per axis
  Index3 cells = Index3::Ones();  // per axis
  bool trilinear = false;         // sampling: cell value, or trilinear between cell centres
  // Cell values, x fastest; a field the scene does not need may be empty.
  std::vector<Vec3> U;            // m/s
  std::vector<double> p;          // Pa
  std::vector<double> rho;        // kg/m^3
  std::vector<double> nu;         // m^2/s
  // Derived once (the fluid is prescribed and steady): empty unless an operator needs them.
  std::vector<Vec3> grad_p;       // Pa/m
  std::vector<Vec3> div_tau;      // N/m^3, -div(mu grad U) - div(mu dev(grad(U)^T)), mu = nu rho

  std::size_t size() const { return std::size_t(cells.x()) * std::size_t(cells.y()) * std::size_t(cells.z()); }
  // int arithmetic: grids are limited to kMaxGridCells cells
  std::size_t index(const Index3& c) const { return std::size_t(c.x() + cells.x() * (c.y() + cells.y() * c.z())); }
  Vec3 center(const Index3& c) const { return origin + (c.cast<double>().array() + 0.5).matrix().cwiseProduct(spacing); }
  double cell_volume() const { return spacing.prod(); }
  // The cell holding x (lower faces belong to the cell), or nothing outside the grid.
  std::optional<Index3> locate(const Vec3& x) const;

  // Cells and weights giving a field's value at x, which must lie in the grid: the cell's
  // value, or trilinear interpolation between the 8 nearest cell centres (the outer half
  // cell takes the boundary centres' values). Computed once per body, used for every field.
  struct Stencil {
    std::array<std::size_t, 8> cell;
    std::array<double, 8> weight;
    int count = 0;
  };
  Stencil stencil(const Vec3& x) const;

  template <class T>
  T at(const std::vector<T>& field, const Stencil& s) const {
    T sum = s.weight[0] * field[s.cell[0]];
    for (int k = 1; k < s.count; ++k) sum += s.weight[k] * field[s.cell[k]];
    return sum;
  }
  template <class T>
  T sample(const std::vector<T>& field, const Vec3& x) const { return at(field, stencil(x)); }
};

// Fills grad_p (when p is set) and div_tau (when U, rho and nu are set) by finite differences:
// central inside, second-order one-sided on the boundary cells (exact for quadratic fields);
// an axis of 2 cells uses the one difference, of 1 cell none.
void derive_fields(FluidGrid& grid, bool grad_p, bool div_tau);

}  // namespace polydem
