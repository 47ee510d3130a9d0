#pragma once
// Broad phase: every pair of bodies whose bounding spheres are within `skin` of touching.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "neighbor/body_pair.hpp"
#include "neighbor/cell_table.hpp"
#include "neighbor/rebuild_trigger.hpp"  // the trigger goes with the lists it guards
#include "polydem/math.hpp"

namespace polydem {

// Cell-list search, O(N) for a bounded ratio of largest to mean bounding radius.
// Cells have side 2 max(R) + skin, so a pair within reach lies in the same or adjacent cells.
// A dense grid over the bodies' bounding box when it has at most a few cells per body; else
// (sparse or huge domains, a body far away) only occupied cells, in a hash table. Memory is
// O(bodies) either way and is reused across calls.
class CellList {
 public:
  // Writes all pairs with |x_i - x_j| < R_i + R_j + skin into `out`, sorted by (i, j), the same
  // for any thread count. Throws std::invalid_argument on mismatched sizes, negative or
  // non-finite radii or skin, and RunError on a non-finite centre.
  void build_pairs(const std::vector<Vec3>& centers, const std::vector<double>& radii, double skin,
                   std::vector<BodyPair>& out);
  // Sphere-sphere distance tests done by the last build_pairs (the cost that must stay O(N)).
  std::size_t candidate_tests() const { return candidate_count; }
  // Cells stored by the last build_pairs: the dense grid size, or the occupied cells when hashed.
  std::size_t stored_cells() const { return cell_count; }
  // Whether the last build_pairs fell back to hashed cells.
  bool hashed() const { return !dense; }

 private:
  struct Sphere {
    double x, y, z, r;  // m, a body's centre and bounding radius, stored in cell order
  };
  static constexpr int kForward = 13;  // half of the 26 neighbour cells: each cell pair once

  void bin_bodies(const std::vector<Vec3>& centers, const std::vector<double>& radii, double cell);
  void number_dense_cells(const std::vector<Vec3>& centers, const Vec3& lo, double cell);
  void number_hashed_cells(const std::vector<Vec3>& centers, const Vec3& lo, double cell);
  void sort_into_cells(const std::vector<Vec3>& centers, const std::vector<double>& radii);
  void link_hashed_cells();
  void forward_cells(std::size_t c, std::uint32_t (&ids)[kForward]) const;
  void collect_pairs(double skin);
  void merge_pairs(std::size_t n, std::vector<BodyPair>& out);

  bool dense = true;
  std::int64_t dims[3] = {0, 0, 0};  // cells per axis of the dense grid
  std::size_t cell_count = 0;
  std::vector<std::uint32_t> body_cell_id;
  // CSR: the bodies of cell c are spheres[cell_start[c] .. cell_start[c + 1]).
  std::vector<std::uint32_t> cell_start;
  std::vector<Sphere> spheres;           // sorted by cell
  std::vector<std::uint32_t> sorted_id;  // body index of spheres[k]
  // Hashed mode only.
  CellTable table;
  std::vector<CellCoord> body_cell;    // cell of each body
  std::vector<CellCoord> cell_coord;   // coordinates of each occupied cell
  std::vector<std::uint32_t> forward;  // kForward neighbour cell ids per cell, or kNoCell
  // Output assembly.
  std::vector<std::vector<BodyPair>> thread_pairs;
  std::vector<std::uint32_t> row_start;  // CSR of the output by first body
  std::vector<std::uint32_t> row_fill;
  std::size_t candidate_count = 0;
};

// Reference: the O(N^2) double loop, same test and same order as CellList::build_pairs.
void brute_force_pairs(const std::vector<Vec3>& centers, const std::vector<double>& radii,
                       double skin, std::vector<BodyPair>& out);

}  // namespace polydem
