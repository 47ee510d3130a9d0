// Sorting bodies into cells: a dense grid when the bounding box is compact, hashed cells when not.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "neighbor/broad_phase.hpp"
#include "neighbor/cell_common.hpp"
#include "polydem/error.hpp"

namespace polydem {
namespace {

using cells::kMinParallel;
using cells::kOffsets;

// A dense grid may have this many cells per body before the hashed cells are used instead.
constexpr double kDenseCellsPerBody = 8.0;

// Hashed cell coordinates are clamped here: clamping is monotone and never moves two cells
// apart, so far-away bodies only share cells (still correct) instead of overflowing integers.
constexpr double kMaxCoord = 1099511627776.0;  // 2^40 cells per axis

// Throws on a non-finite centre (a blown-up run); returns the bounding box corners.
void bounding_box(const std::vector<Vec3>& centers, Vec3& lo, Vec3& hi) {
  lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  hi = -lo;
  for (std::size_t i = 0; i < centers.size(); ++i) {
    if (!centers[i].allFinite()) {
      throw RunError("broad phase: body " + std::to_string(i) + " has a non-finite position");
    }
    lo = lo.cwiseMin(centers[i]);
    hi = hi.cwiseMax(centers[i]);
  }
}

// Cell index along one axis, as a double so a huge domain cannot overflow.
double cell_coordinate(double x, double lo, double cell) {
  return std::min(std::floor((x - lo) / cell), kMaxCoord);
}

}  // namespace

void CellList::bin_bodies(const std::vector<Vec3>& centers, const std::vector<double>& radii,
                          double cell) {
  Vec3 lo;
  Vec3 hi;
  bounding_box(centers, lo, hi);
  double grid_cells = 1.0;
  for (int d = 0; d < 3; ++d) grid_cells *= cell_coordinate(hi[d], lo[d], cell) + 1.0;
  // The dense ids must also fit in 32 bits.
  dense = grid_cells <= kDenseCellsPerBody * static_cast<double>(centers.size()) + 64.0 &&
          grid_cells < 4.0e9;
  body_cell_id.resize(centers.size());
  if (dense) {
    for (int d = 0; d < 3; ++d) {
      dims[d] = static_cast<std::int64_t>(cell_coordinate(hi[d], lo[d], cell)) + 1;
    }
    number_dense_cells(centers, lo, cell);
  } else {
    number_hashed_cells(centers, lo, cell);
  }
  sort_into_cells(centers, radii);
}

// Cell id = (z ny + y) nx + x: bodies end up sorted along the grid, neighbours nearby in memory.
void CellList::number_dense_cells(const std::vector<Vec3>& centers, const Vec3& lo, double cell) {
  const std::size_t n = centers.size();
  cell_count = static_cast<std::size_t>(dims[0] * dims[1] * dims[2]);
#pragma omp parallel for schedule(static) if (n >= kMinParallel)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = centers[i];
    const auto ix = static_cast<std::int64_t>(cell_coordinate(x.x(), lo.x(), cell));
    const auto iy = static_cast<std::int64_t>(cell_coordinate(x.y(), lo.y(), cell));
    const auto iz = static_cast<std::int64_t>(cell_coordinate(x.z(), lo.z(), cell));
    body_cell_id[i] = static_cast<std::uint32_t>((iz * dims[1] + iy) * dims[0] + ix);
  }
}

// Occupied cells numbered in order of their first body, which is deterministic.
void CellList::number_hashed_cells(const std::vector<Vec3>& centers, const Vec3& lo, double cell) {
  const std::size_t n = centers.size();
  body_cell.resize(n);
#pragma omp parallel for schedule(static) if (n >= kMinParallel)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = centers[i];
    body_cell[i] = {static_cast<std::int64_t>(cell_coordinate(x.x(), lo.x(), cell)),
                    static_cast<std::int64_t>(cell_coordinate(x.y(), lo.y(), cell)),
                    static_cast<std::int64_t>(cell_coordinate(x.z(), lo.z(), cell))};
  }
  table.reset(n);
  cell_coord.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t c = table.insert(body_cell[i]);
    if (c == cell_coord.size()) cell_coord.push_back(body_cell[i]);
    body_cell_id[i] = c;
  }
  cell_count = table.size();
  link_hashed_cells();
}

// Counting sort by cell id, stable in body index.
void CellList::sort_into_cells(const std::vector<Vec3>& centers, const std::vector<double>& radii) {
  const std::size_t n = centers.size();
  cell_start.assign(cell_count + 2, 0);
  for (std::size_t i = 0; i < n; ++i) ++cell_start[body_cell_id[i] + 2];
  for (std::size_t c = 2; c < cell_count + 2; ++c) cell_start[c] += cell_start[c - 1];
  spheres.resize(n);
  sorted_id.resize(n);
  // cell_start[c + 1] walks from the start of cell c to its end, which is the start of c + 1.
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t k = cell_start[body_cell_id[i] + 1]++;
    spheres[k] = {centers[i].x(), centers[i].y(), centers[i].z(), radii[i]};
    sorted_id[k] = static_cast<std::uint32_t>(i);
  }
  cell_start.resize(cell_count + 1);
}

void CellList::link_hashed_cells() {
  forward.resize(cell_count * kForward);
#pragma omp parallel for schedule(static) if (cell_count >= kMinParallel)
  for (std::size_t c = 0; c < cell_count; ++c) {
    const CellCoord& a = cell_coord[c];
    for (int k = 0; k < kForward; ++k) {
      const CellCoord b = {a.x + kOffsets[k][0], a.y + kOffsets[k][1], a.z + kOffsets[k][2]};
      forward[c * kForward + k] = table.find(b);
    }
  }
}

void CellList::forward_cells(std::size_t c, std::uint32_t (&ids)[kForward]) const {
  if (!dense) {
    std::copy_n(forward.begin() + static_cast<std::ptrdiff_t>(c * kForward), kForward, ids);
    return;
  }
  const auto cell = static_cast<std::int64_t>(c);
  const std::int64_t at[3] = {cell % dims[0], (cell / dims[0]) % dims[1],
                              cell / (dims[0] * dims[1])};
  for (int k = 0; k < kForward; ++k) {
    std::int64_t b[3];
    bool inside = true;
    for (int d = 0; d < 3; ++d) {
      b[d] = at[d] + kOffsets[k][d];
      inside = inside && b[d] >= 0 && b[d] < dims[d];
    }
    ids[k] = inside ? static_cast<std::uint32_t>((b[2] * dims[1] + b[1]) * dims[0] + b[0])
                    : CellTable::kNoCell;
  }
}

}  // namespace polydem
