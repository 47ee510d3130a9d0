// Sorting bodies into cells: a dense grid when the bounding box is compact, hashed cells when not.
#include "neighbor/cell_grid.hpp"

#include <algorithm>
#include <cmath>

#include <omp.h>

#include "neighbor/cell_common.hpp"

namespace polydem {
namespace {

using cells::kOffsets;

// A dense grid may have this many cells per body before the hashed cells are used instead.
constexpr double kDenseCellsPerBody = 8.0;

// Cell coordinates are clamped here: clamping is monotone and never moves two cells apart, so
// far-away bodies only share cells (still correct) instead of overflowing integers. Members are
// never below 0; a body of another size class below -1 has no stored neighbour either way.
constexpr double kMaxCoord = 1099511627776.0;  // 2^40 cells per axis
constexpr double kMinCoord = -2.0;

// Cell index along one axis, as a double so a huge domain cannot overflow.
double cell_coordinate(double x, double lo, double cell) {
  return std::clamp(std::floor((x - lo) / cell), kMinCoord, kMaxCoord);
}

}  // namespace

void CellGrid::prepare(std::size_t n, double cell, const Vec3& box_lo, const Vec3& hi, std::size_t threads) {
  lo = box_lo;
  side = cell;
  double grid_cells = 1.0;
  for (int d = 0; d < 3; ++d) grid_cells *= cell_coordinate(hi[d], lo[d], cell) + 1.0;
  // The dense ids must also fit in 32 bits.
  dense = grid_cells <= kDenseCellsPerBody * static_cast<double>(n) + 64.0 && grid_cells < 4.0e9;
  member_cell.resize(n);
  if (dense) {
    for (int d = 0; d < 3; ++d) dims[d] = static_cast<std::int64_t>(cell_coordinate(hi[d], lo[d], cell)) + 1;
    cells = static_cast<std::size_t>(dims[0] * dims[1] * dims[2]);
  } else {
    member_coord.resize(n);
  }
  thread_total.assign(threads, 0);
}

CellCoord CellGrid::coord_of(double x, double y, double z) const {
  return {static_cast<std::int64_t>(cell_coordinate(x, lo.x(), side)),
          static_cast<std::int64_t>(cell_coordinate(y, lo.y(), side)),
          static_cast<std::int64_t>(cell_coordinate(z, lo.z(), side))};
}

// Dense cell id = (z ny + y) nx + x: bodies end up sorted along the grid, neighbours nearby in
// memory. Members' cells are inside the grid by construction.
std::uint32_t CellGrid::dense_id(const CellCoord& c) const {
  return static_cast<std::uint32_t>((c.z * dims[1] + c.y) * dims[0] + c.x);
}

void CellGrid::number(const std::vector<Vec3>& centers, const std::vector<std::uint32_t>& members) {
  const std::size_t n = members.size();
  if (dense) {
#pragma omp for schedule(static) nowait
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3& x = centers[members[k]];
      member_cell[k] = dense_id(coord_of(x.x(), x.y(), x.z()));
    }
  } else {
#pragma omp for schedule(static) nowait
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3& x = centers[members[k]];
      member_coord[k] = coord_of(x.x(), x.y(), x.z());
    }
  }
}

// Hashed: occupied cells numbered in order of their first body, which is deterministic.
void CellGrid::lay_out() {
  const std::size_t n = member_cell.size();
  if (!dense) {
    table.reset(n);
    cell_coord.clear();
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t c = table.insert(member_coord[k]);
      if (c == cell_coord.size()) cell_coord.push_back(member_coord[k]);
      member_cell[k] = c;
    }
    cells = table.size();
    forward.resize(cells * kForward);
  }
  cell_start.resize(cells + 1);
  cell_start[cells] = std::uint32_t(n);
  spheres.resize(n);
  sorted_id.resize(n);
}

void CellGrid::link() {
  if (dense) return;
#pragma omp for schedule(static) nowait
  for (std::size_t c = 0; c < cells; ++c) {
    const CellCoord& a = cell_coord[c];
    for (int k = 0; k < kForward; ++k) {
      const CellCoord b = {a.x + kOffsets[k][0], a.y + kOffsets[k][1], a.z + kOffsets[k][2]};
      forward[c * kForward + k] = table.find(b);
    }
  }
}

// The spheres sorted by cell id (team_sort.hpp), each thread of the team on a run of cells: it
// counts their members (reading every member's cell) ...
KeyRun CellGrid::count_cells() {
  KeyRun run = count_run(cells, [this](const auto& count) {
    for (const std::uint32_t c : member_cell) count(c);
  });
  thread_total[std::size_t(omp_get_thread_num())] = run.items;
  return run;
}

// ... then, once every thread counted, fills its cells (writing only their spheres).
void CellGrid::place(const std::vector<Vec3>& centers, const std::vector<double>& radii,
                     const std::vector<std::uint32_t>& members, KeyRun& run) {
  place_run(run, thread_total, cell_start.data());
  for (std::size_t k = 0; k < members.size(); ++k) {
    if (!run.holds(member_cell[k])) continue;
    const std::uint32_t at = run.take(member_cell[k]);
    const std::uint32_t i = members[k];
    spheres[at] = {centers[i].x(), centers[i].y(), centers[i].z(), radii[i]};
    sorted_id[at] = i;
  }
}

int CellGrid::forward_ranges(std::size_t c, std::uint32_t (&begin)[kForward],
                             std::uint32_t (&end)[kForward]) const {
  int count = 0;
  if (!dense) {
    for (int k = 0; k < kForward; ++k) {
      const std::uint32_t other = forward[c * kForward + static_cast<std::size_t>(k)];
      if (other == CellTable::kNoCell) continue;
      begin[count] = cell_start[other];
      end[count++] = cell_start[other + 1];
    }
    return count;
  }
  const auto cell = static_cast<std::int64_t>(c);
  const std::int64_t x = cell % dims[0];
  const std::int64_t y = (cell / dims[0]) % dims[1];
  const std::int64_t z = cell / (dims[0] * dims[1]);
  if (x + 1 < dims[0]) {  // offset (1, 0, 0)
    begin[count] = cell_start[c + 1];
    end[count++] = cell_start[c + 2];
  }
  const std::int64_t x0 = std::max<std::int64_t>(x - 1, 0);
  const std::int64_t x1 = std::min<std::int64_t>(x + 1, dims[0] - 1);
  // The rows (y + 1, z) and (y - 1 .. y + 1, z + 1), x - 1 .. x + 1: the other 12 offsets.
  constexpr std::int64_t kRows[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};
  for (const auto& [dy, dz] : kRows) {
    const std::int64_t ry = y + dy;
    const std::int64_t rz = z + dz;
    if (ry < 0 || ry >= dims[1] || rz >= dims[2]) continue;
    const std::int64_t row = (rz * dims[1] + ry) * dims[0];
    begin[count] = cell_start[static_cast<std::size_t>(row + x0)];
    end[count++] = cell_start[static_cast<std::size_t>(row + x1 + 1)];
  }
  return count;
}

int CellGrid::ranges_around(const CellSphere& s, std::uint32_t (&begin)[kAround],
                            std::uint32_t (&end)[kAround]) const {
  const CellCoord at = coord_of(s.x, s.y, s.z);
  int count = 0;
  for (std::int64_t z = at.z - 1; z <= at.z + 1; ++z) {
    for (std::int64_t y = at.y - 1; y <= at.y + 1; ++y) {
      if (dense) {  // the row's cells have consecutive ids: their spheres are one range
        const std::int64_t x0 = std::max<std::int64_t>(at.x - 1, 0);
        const std::int64_t x1 = std::min<std::int64_t>(at.x + 1, dims[0] - 1);
        if (z < 0 || z >= dims[2] || y < 0 || y >= dims[1] || x0 > x1) continue;
        const std::int64_t row = (z * dims[1] + y) * dims[0];
        begin[count] = cell_start[static_cast<std::size_t>(row + x0)];
        end[count++] = cell_start[static_cast<std::size_t>(row + x1 + 1)];
        continue;
      }
      for (std::int64_t x = at.x - 1; x <= at.x + 1; ++x) {
        const std::uint32_t c = table.find({x, y, z});
        if (c == CellTable::kNoCell) continue;
        begin[count] = cell_start[c];
        end[count++] = cell_start[c + 1];
      }
    }
  }
  return count;
}

std::size_t CellGrid::bytes() const {
  const auto of = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return of(member_cell) + of(cell_start) + of(spheres) + of(sorted_id) + table.bytes() +
         of(member_coord) + of(cell_coord) + of(forward) + of(thread_total);
}

}  // namespace polydem
