#pragma once
// Divided void fraction (CFDEM's dividedVoidFraction with sample points instead of its 29
// sphere points): each body's volume is split among the cells holding its sample points, a
// fixed lattice inside the rounded body, every point carrying an equal share of the volume.
#include <vector>

#include "field/field_bodies.hpp"
#include "field/fluid_grid.hpp"
#include "polydem/bodies.hpp"
#include "polydem/shape.hpp"

namespace polydem {

// Points of a lattice of n x n x n cell centres over the shape's bounding box that lie inside
// the rounded body (principal frame, unit scale); the centre of mass alone when none does.
std::vector<Vec3> shape_samples(const Shape& shape, int n);

// Distance from x to the core (0 inside a closed convex core; a non-convex core has no inside:
// the distance to its nearest vertex, edge or face); brute force, for set-up only.
double core_distance(const Shape& shape, const Vec3& x);

struct VoidFractionField {
  std::vector<double> alpha;      // per cell, fluid volume fraction, >= alpha_min
  double excess = 0.0;            // m^3, solid volume the alpha_min floor could not take
};

class VoidFraction {
 public:
  VoidFraction(const std::vector<Shape>& shapes, int samples, double alpha_min);

  // Vs of each owned row: its volume x the share of its sample points inside the grid (a
  // ghost's is left as it was).
  void particle_volumes(const FluidGrid& grid, const FieldBodies& rows, std::vector<double>& vs) const;
  void particle_volumes(const FluidGrid& grid, const Bodies& bodies, std::vector<double>& vs) const {
    particle_volumes(grid, field_rows(bodies), vs);
  }

  // alpha = 1 - (solid volume in the cell) / (cell volume), bodies taken in index order; a cell
  // that would fall below alpha_min stays at alpha_min and the rest goes to `excess`. Reads
  // every body: a distributed run's output gathers them first.
  VoidFractionField field(const FluidGrid& grid, const Bodies& bodies) const;

 private:
  template <class Fn>
  void for_samples(const FieldBodies& rows, std::size_t b, const Fn& fn) const;
  std::vector<std::vector<Vec3>> samples_;  // per shape
  std::vector<double> volume_;              // per shape, m^3 at unit scale
  std::vector<double> reach_;               // per shape, m: bounding radius at unit scale
  double alpha_min_;
};

}  // namespace polydem
