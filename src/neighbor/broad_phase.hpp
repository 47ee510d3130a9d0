#pragma once
// Broad phase: every pair of bodies whose bounding spheres are within `skin` of touching.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "neighbor/body_pair.hpp"
#include "neighbor/cell_grid.hpp"
#include "neighbor/rebuild_trigger.hpp"  // the trigger goes with the lists it guards
#include "polydem/math.hpp"

namespace polydem {

// Cell-list search over size classes (LAMMPS' "multi" neighbour style), O(N) whatever the
// spread of bounding radii. The largest body sets the coarsest cell side, 2 max(R) + skin; each
// body goes to the finest grid, of side halved level by level, whose cells are at least
// 2 R + skin wide. Pairs within a grid lie in the same or adjacent cells; a body of a finer grid
// looks for its partners of every coarser grid in the 27 cells around it there (its reach is
// below that grid's side). So small bodies are binned by their own size, not by the largest
// one, and a few large bodies (a 1:10 size ratio, a long fibre) cost O(1) tests per small body.
// Equal-sized bodies form one grid: the plain cell list.
class CellList {
 public:
  // Writes all pairs with |x_i - x_j| < R_i + R_j + skin into `out`, sorted by (i, j), the same
  // for any thread count. Throws std::invalid_argument on mismatched sizes, negative or
  // non-finite radii or skin, and RunError on a non-finite centre.
  void build_pairs(const std::vector<Vec3>& centers, const std::vector<double>& radii, double skin,
                   std::vector<BodyPair>& out);
  // Sphere-sphere distance tests done by the last build_pairs (the cost that must stay O(N)).
  std::size_t candidate_tests() const { return candidate_count; }
  // Cells stored by the last build_pairs over all grids: dense grid sizes, or occupied cells
  // when hashed.
  std::size_t stored_cells() const;
  // Whether the last build_pairs fell back to hashed cells in some grid.
  bool hashed() const;
  // Size classes (grids) used by the last build_pairs.
  std::size_t levels() const { return used_levels; }
  // Bytes held by the search's arrays (their capacity), output excluded.
  std::size_t bytes() const;

  // Cell sides from 2 max(R) + skin down to 1/128 of it; smaller bodies share the finest grid.
  static constexpr int kMaxLevels = 8;

 private:
  struct SearchTeam;  // the threads' partial results (cell_list.cpp)
  void search(const std::vector<Vec3>& centers, const std::vector<double>& radii, double skin,
              SearchTeam& team, std::vector<BodyPair>& out);
  static double cell_side(const std::vector<double>& radii, double skin, SearchTeam& team, std::size_t& bad);
  bool bin_levels(const std::vector<Vec3>& centers, const std::vector<double>& radii, double skin,
                  double top_cell, SearchTeam& team);
  void collect_pairs(double skin, SearchTeam& team);
  void merge_pairs(std::size_t n, SearchTeam& team, std::vector<BodyPair>& out);

  std::size_t used_levels = 0;
  std::vector<CellGrid> grids;                       // coarsest first; the first used_levels
  std::vector<std::vector<std::uint32_t>> members;  // bodies of each level, in index order
  std::vector<std::size_t> cell_offset;              // flat cell numbering over the grids
  // Output assembly.
  std::vector<std::vector<BodyPair>> thread_pairs;
  std::vector<std::uint32_t> row_start;  // CSR of the output by first body
  std::size_t candidate_count = 0;
};

// Reference: the O(N^2) double loop, same test and same order as CellList::build_pairs.
void brute_force_pairs(const std::vector<Vec3>& centers, const std::vector<double>& radii,
                       double skin, std::vector<BodyPair>& out);

}  // namespace polydem
