#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "neighbor/broad_phase.hpp"
#include "polydem/error.hpp"

namespace polydem {
namespace {

// Cell coordinates are clamped here: clamping is monotone and never moves two cells apart, so
// far-away bodies only share cells (still correct) instead of overflowing the integers.
constexpr double kMaxCoord = 1099511627776.0;  // 2^40 cells per axis

// Forward half of the 26 neighbour offsets: exactly one of each (+d, -d) couple.
constexpr int kOffsets[13][3] = {{1, 0, 0},  {-1, 1, 0}, {0, 1, 0},  {1, 1, 0},   {-1, -1, 1},
                                 {0, -1, 1}, {1, -1, 1}, {-1, 0, 1}, {0, 0, 1},   {1, 0, 1},
                                 {-1, 1, 1}, {0, 1, 1},  {1, 1, 1}};

// m, side of a cell: two bodies within reach are at most 2 max(R) + skin apart.
double cell_side(const std::vector<Vec3>& centers, const std::vector<double>& radii, double skin) {
  if (centers.size() != radii.size()) {
    throw std::invalid_argument("build_pairs: " + std::to_string(centers.size()) + " centres but " +
                                std::to_string(radii.size()) + " radii");
  }
  if (!(skin >= 0.0) || !std::isfinite(skin)) {
    throw std::invalid_argument("build_pairs: skin must be finite and >= 0, got " +
                                std::to_string(skin));
  }
  if (centers.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument("build_pairs: more than 2^32 - 1 bodies");
  }
  double max_r = 0.0;
  for (std::size_t i = 0; i < radii.size(); ++i) {
    if (!(radii[i] >= 0.0) || !std::isfinite(radii[i])) {
      throw std::invalid_argument("build_pairs: body " + std::to_string(i) +
                                  " has bounding radius " + std::to_string(radii[i]));
    }
    max_r = std::max(max_r, radii[i]);
  }
  return 2.0 * max_r + skin;
}

// m, lowest corner of the bodies' bounding box; throws on a non-finite centre (blown-up run).
Vec3 lower_corner(const std::vector<Vec3>& centers) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < centers.size(); ++i) {
    if (!centers[i].allFinite()) {
      throw RunError("broad phase: body " + std::to_string(i) + " has a non-finite position");
    }
    lo = lo.cwiseMin(centers[i]);
  }
  return lo;
}

std::int64_t cell_index(double x, double lo, double cell) {
  return static_cast<std::int64_t>(std::min((x - lo) / cell, kMaxCoord));
}

}  // namespace

void CellList::build_pairs(const std::vector<Vec3>& centers, const std::vector<double>& radii,
                           double skin, std::vector<BodyPair>& out) {
  const double cell = cell_side(centers, radii, skin);
  out.clear();
  candidate_count = 0;
  table.reset(0);
  // With a zero cell side every reach is 0 and no distance is < 0: there is nothing to find.
  if (centers.size() < 2 || !(cell > 0.0)) return;
  bin_bodies(centers, radii, cell);
  link_forward_cells();
  collect_pairs(skin);
  merge_pairs(centers.size(), out);
}

// Counting sort of the bodies into occupied cells, numbered in order of first body.
void CellList::bin_bodies(const std::vector<Vec3>& centers, const std::vector<double>& radii,
                          double cell) {
  const std::size_t n = centers.size();
  const Vec3 lo = lower_corner(centers);
  body_cell.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = centers[i];
    body_cell[i] = {cell_index(x.x(), lo.x(), cell), cell_index(x.y(), lo.y(), cell),
                    cell_index(x.z(), lo.z(), cell)};
  }
  table.reset(n);
  body_cell_id.resize(n);
  cell_coord.clear();
  cell_start.assign(n + 2, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t c = table.insert(body_cell[i]);
    if (c == cell_coord.size()) cell_coord.push_back(body_cell[i]);
    body_cell_id[i] = c;
    ++cell_start[c + 2];
  }
  const std::size_t cells = table.size();
  cell_start.resize(cells + 2);
  for (std::size_t c = 2; c < cells + 2; ++c) cell_start[c] += cell_start[c - 1];
  spheres.resize(n);
  sorted_id.resize(n);
  // Stable scatter: cell_start[c + 1] walks from the start of cell c to its end.
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t k = cell_start[body_cell_id[i] + 1]++;
    spheres[k] = {centers[i].x(), centers[i].y(), centers[i].z(), radii[i]};
    sorted_id[k] = static_cast<std::uint32_t>(i);
  }
  cell_start.resize(cells + 1);
}

void CellList::link_forward_cells() {
  const std::size_t cells = table.size();
  forward.resize(cells * kForward);
#pragma omp parallel for schedule(static)
  for (std::size_t c = 0; c < cells; ++c) {
    const CellCoord& a = cell_coord[c];
    for (int k = 0; k < kForward; ++k) {
      const CellCoord b = {a.x + kOffsets[k][0], a.y + kOffsets[k][1], a.z + kOffsets[k][2]};
      forward[c * kForward + k] = table.find(b);
    }
  }
}

void CellList::collect_pairs(double skin) {
  const std::size_t cells = table.size();
  thread_pairs.resize(static_cast<std::size_t>(omp_get_max_threads()));
  for (auto& buffer : thread_pairs) buffer.clear();
  std::size_t tests = 0;
#pragma omp parallel reduction(+ : tests)
  {
    std::vector<BodyPair>& buffer = thread_pairs[static_cast<std::size_t>(omp_get_thread_num())];
    const auto test = [&](std::uint32_t a, std::uint32_t b) {
      const Sphere& p = spheres[a];
      const Sphere& q = spheres[b];
      ++tests;
      if (within_reach(p.x, p.y, p.z, p.r, q.x, q.y, q.z, q.r, skin)) {
        buffer.push_back({std::min(sorted_id[a], sorted_id[b]), std::max(sorted_id[a], sorted_id[b])});
      }
    };
    // Dynamic: clustered scenes put very unequal work in each cell; order is restored by the merge.
#pragma omp for schedule(dynamic, 64)
    for (std::size_t c = 0; c < cells; ++c) {
      const std::uint32_t begin = cell_start[c];
      const std::uint32_t end = cell_start[c + 1];
      for (std::uint32_t a = begin; a < end; ++a) {
        for (std::uint32_t b = a + 1; b < end; ++b) test(a, b);
      }
      for (int k = 0; k < kForward; ++k) {
        const std::uint32_t other = forward[c * kForward + k];
        if (other == CellTable::kNoCell) continue;
        for (std::uint32_t a = begin; a < end; ++a) {
          for (std::uint32_t b = cell_start[other]; b < cell_start[other + 1]; ++b) test(a, b);
        }
      }
    }
  }
  candidate_count = tests;
}

// Counting sort by first body, then each row by second body: independent of which thread found what.
void CellList::merge_pairs(std::size_t n, std::vector<BodyPair>& out) {
  row_start.assign(n + 1, 0);
  std::size_t total = 0;
  for (const auto& buffer : thread_pairs) {
    total += buffer.size();
    for (const BodyPair& p : buffer) ++row_start[p.i + 1];
  }
  for (std::size_t i = 1; i <= n; ++i) row_start[i] += row_start[i - 1];
  row_fill.assign(row_start.begin(), row_start.end() - 1);
  out.resize(total);
  for (const auto& buffer : thread_pairs) {
    for (const BodyPair& p : buffer) out[row_fill[p.i]++] = p;
  }
#pragma omp parallel for schedule(dynamic, 1024)
  for (std::size_t i = 0; i < n; ++i) {
    std::sort(out.begin() + row_start[i], out.begin() + row_start[i + 1],
              [](const BodyPair& a, const BodyPair& b) { return a.j < b.j; });
  }
}

}  // namespace polydem
