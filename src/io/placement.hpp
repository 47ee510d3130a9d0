#pragma once
// Geometry for body generators: where a sphere fits in a box or cylinder region, a uniform
// grid that answers "does this sphere overlap a placed one?" in O(1), and the drivers a
// generated body must stay clear of.
#include <array>
#include <random>
#include <variant>
#include <vector>

#include "driver/drivers.hpp"
#include "io/scene_settings.hpp"

namespace polydem {

class Region {
 public:
  explicit Region(const std::variant<BoxRegion, CylinderRegion>& region);

  // True when a sphere of this radius fits somewhere inside.
  bool fits(double radius) const;
  // A centre uniform over the positions where a sphere of this radius lies fully inside.
  Vec3 sample(double radius, std::mt19937_64& rng) const;
  // Centres of a cubic lattice of this spacing whose spheres of diameter `spacing` lie fully
  // inside: x (or the cylinder's first radial direction) fastest, then y, then z (the axis).
  std::vector<Vec3> lattice(double spacing) const;

  Vec3 lower() const { return lower_; }  // m, bounding box
  Vec3 upper() const { return upper_; }

 private:
  bool is_box_;
  BoxRegion box_;
  CylinderRegion cylinder_;
  Vec3 e1_ = Vec3::UnitX(), e2_ = Vec3::UnitY();  // cylinder: radial directions
  Vec3 lower_, upper_;
};

// Placed spheres binned in cells at least one largest diameter wide.
class SphereGrid {
 public:
  SphereGrid(const Vec3& lower, const Vec3& upper, double max_radius, std::size_t expected);

  bool overlaps(const Vec3& center, double radius) const;
  void insert(const Vec3& center, double radius);

 private:
  int cell_coord(double x, int axis) const;
  std::size_t cell_of(int i, int j, int k) const;

  Vec3 lower_;
  double cell_size_;
  int dims_[3];
  std::vector<int> head_;  // first sphere in each cell, -1 when empty
  std::vector<int> next_;  // next sphere in the same cell
  std::vector<Vec3> centers_;
  std::vector<double> radii_;
};

// The drivers present at t = 0 (not removed at 0) as obstacles to generated bodies: walls
// (half-spaces behind the plane), cylinders (inside: beyond R from the axis; outside: within R
// of the axis segment), balls and STL meshes (the triangles, two-sided).
class DriverClearance {
 public:
  // Makes the drivers' kinds (reads the STL meshes; throws InputError, file, line and key, for a
  // missing or broken one).
  explicit DriverClearance(const std::vector<DriverSettings>& drivers);

  // True when a sphere overlaps no driver (an overlap below 1e-9 x radius is a touch).
  bool clear(const Vec3& center, double radius) const;
  bool empty() const { return present_.empty(); }

 private:
  Drivers drivers_;
  std::vector<std::uint32_t> present_;  // the drivers not removed at t = 0
};

}  // namespace polydem
