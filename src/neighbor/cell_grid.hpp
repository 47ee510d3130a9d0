#pragma once
// One grid of cubic cells holding the bodies of one size class, sorted by cell (CSR). A dense
// grid over the bodies' bounding box when it has at most a few cells per body; else (sparse or
// huge domains, a body far away) only occupied cells, in a hash table. Memory is O(bodies)
// either way and is reused across calls.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "neighbor/cell_table.hpp"
#include "neighbor/team_sort.hpp"
#include "polydem/math.hpp"

namespace polydem {

struct CellSphere {
  double x, y, z, r;  // m, a body's centre and bounding radius, stored in cell order
};

class CellGrid {
 public:
  static constexpr int kForward = 13;  // half of the 26 neighbour cells: each cell pair once
  static constexpr int kAround = 27;   // a cell and its 26 neighbours

  // Sorts the bodies `members` (indices into centers and radii, finite) into cells of side `cell`
  // (m) over their centres' bounding box [lo, hi] (m), in phases so that a team builds several
  // grids at once and meets between the phases, not between the grids (CellList::bin_levels):
  // prepare (one thread), number (a shared loop), lay_out (one thread), link (a shared loop) and
  // count_cells (every thread), place (every thread, with count_cells' result).
  void prepare(std::size_t members, double cell, const Vec3& lo, const Vec3& hi, std::size_t threads);
  void number(const std::vector<Vec3>& centers, const std::vector<std::uint32_t>& members);
  void lay_out();
  void link();
  KeyRun count_cells();
  void place(const std::vector<Vec3>& centers, const std::vector<double>& radii,
             const std::vector<std::uint32_t>& members, KeyRun& run);

  std::size_t cell_count() const { return cells; }
  bool hashed() const { return !dense; }
  // The bodies of cell c are spheres [begin(c), end(c)).
  std::uint32_t begin(std::size_t c) const { return cell_start[c]; }
  std::uint32_t end(std::size_t c) const { return cell_start[c + 1]; }
  const CellSphere& sphere(std::uint32_t k) const { return spheres[k]; }
  std::uint32_t body(std::uint32_t k) const { return sorted_id[k]; }
  // The spheres of the forward neighbours of cell c, as ranges [begin[k], end[k]) of sphere
  // indices: in a dense grid 5 (the next cell along x, then 4 rows of three cells with
  // consecutive ids), one per stored cell when hashed. Returns the count.
  int forward_ranges(std::size_t c, std::uint32_t (&begin)[kForward],
                     std::uint32_t (&end)[kForward]) const;
  // The spheres of the cell containing the centre of `s` (which need not belong to this grid)
  // and of its 26 neighbours, as ranges [begin[k], end[k]) of sphere indices: one range per row
  // of three cells along x in a dense grid, one per stored cell when hashed. Returns the count.
  int ranges_around(const CellSphere& s, std::uint32_t (&begin)[kAround],
                    std::uint32_t (&end)[kAround]) const;
  // Bytes held by the grid's arrays (their capacity).
  std::size_t bytes() const;

 private:
  CellCoord coord_of(double x, double y, double z) const;
  std::uint32_t dense_id(const CellCoord& c) const;

  bool dense = true;
  Vec3 lo = Vec3::Zero();  // m, lower corner of the members' bounding box
  double side = 0.0;       // m, cell side
  std::int64_t dims[3] = {0, 0, 0};  // cells per axis of the dense grid
  std::size_t cells = 0;
  std::vector<std::uint32_t> member_cell;  // cell id of each member
  std::vector<std::uint32_t> cell_start;
  std::vector<CellSphere> spheres;       // sorted by cell
  std::vector<std::uint32_t> sorted_id;  // body index of spheres[k]
  std::vector<std::uint32_t> thread_total;  // spheres in each team thread's run of cells (count_cells)
  // Hashed mode only.
  CellTable table;
  std::vector<CellCoord> member_coord;  // cell of each member
  std::vector<CellCoord> cell_coord;    // coordinates of each occupied cell
  std::vector<std::uint32_t> forward;   // kForward neighbour cell ids per cell, or kNoCell
};

}  // namespace polydem
