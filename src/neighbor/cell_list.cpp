// The pair search over cells and the deterministic assembly of its output.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "neighbor/broad_phase.hpp"
#include "neighbor/cell_common.hpp"

namespace polydem {
namespace {

using cells::kMinParallel;

// Cells are this much wider than the reach: cell coordinates (up to the 2^40 clamp) are rounded
// by at most 2^-12 cells each, so a pair within reach can never land two cells apart.
constexpr double kCellMargin = 1.0 + 1.0 / 1024.0;

// m, side of a cell: two bodies within reach are less than 2 max(R) + skin apart.
double cell_side(const std::vector<Vec3>& centers, const std::vector<double>& radii, double skin) {
  if (centers.size() != radii.size()) {
    throw std::invalid_argument("build_pairs: " + std::to_string(centers.size()) + " centres but " +
                                std::to_string(radii.size()) + " radii");
  }
  if (!(skin >= 0.0) || !std::isfinite(skin)) {
    throw std::invalid_argument("build_pairs: skin must be finite and >= 0, got " +
                                std::to_string(skin));
  }
  if (centers.size() >= std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument("build_pairs: 2^32 - 1 bodies or more");
  }
  double max_r = 0.0;
  for (std::size_t i = 0; i < radii.size(); ++i) {
    if (!(radii[i] >= 0.0) || !std::isfinite(radii[i])) {
      throw std::invalid_argument("build_pairs: body " + std::to_string(i) +
                                  " has bounding radius " + std::to_string(radii[i]));
    }
    max_r = std::max(max_r, radii[i]);
  }
  return (2.0 * max_r + skin) * kCellMargin;
}

}  // namespace

void CellList::build_pairs(const std::vector<Vec3>& centers, const std::vector<double>& radii,
                           double skin, std::vector<BodyPair>& out) {
  const double cell = cell_side(centers, radii, skin);
  out.clear();
  candidate_count = 0;
  cell_count = 0;
  dense = true;
  // With a zero cell side every reach is 0 and no distance is < 0: there is nothing to find.
  if (centers.size() < 2 || !(cell > 0.0)) return;
  bin_bodies(centers, radii, cell);
  collect_pairs(skin);
  merge_pairs(centers.size(), out);
}

void CellList::collect_pairs(double skin) {
  thread_pairs.resize(static_cast<std::size_t>(omp_get_max_threads()));
  for (auto& buffer : thread_pairs) buffer.clear();
  std::size_t tests = 0;
#pragma omp parallel reduction(+ : tests) if (spheres.size() >= kMinParallel)
  {
    std::vector<BodyPair>& buffer = thread_pairs[static_cast<std::size_t>(omp_get_thread_num())];
    const auto test = [&](std::uint32_t a, std::uint32_t b) {
      const Sphere& p = spheres[a];
      const Sphere& q = spheres[b];
      ++tests;
      if (within_reach(p.x, p.y, p.z, p.r, q.x, q.y, q.z, q.r, skin)) {
        const std::uint32_t i = sorted_id[a];
        const std::uint32_t j = sorted_id[b];
        buffer.push_back({std::min(i, j), std::max(i, j)});
      }
    };
    // Dynamic: clustered scenes put very unequal work in each cell; the merge restores order.
#pragma omp for schedule(dynamic, 256)
    for (std::size_t c = 0; c < cell_count; ++c) {
      const std::uint32_t begin = cell_start[c];
      const std::uint32_t end = cell_start[c + 1];
      if (begin == end) continue;
      for (std::uint32_t a = begin; a < end; ++a) {
        for (std::uint32_t b = a + 1; b < end; ++b) test(a, b);
      }
      std::uint32_t others[kForward];
      forward_cells(c, others);
      for (const std::uint32_t other : others) {
        if (other == CellTable::kNoCell) continue;
        const std::uint32_t other_end = cell_start[other + 1];
        for (std::uint32_t a = begin; a < end; ++a) {
          for (std::uint32_t b = cell_start[other]; b < other_end; ++b) test(a, b);
        }
      }
    }
  }
  candidate_count = tests;
}

// Counting sort by first body, then each row by second body: independent of which thread found
// what.
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
#pragma omp parallel for schedule(dynamic, 1024) if (n >= kMinParallel)
  for (std::size_t i = 0; i < n; ++i) {
    std::sort(out.begin() + row_start[i], out.begin() + row_start[i + 1],
              [](const BodyPair& a, const BodyPair& b) { return a.j < b.j; });
  }
}

}  // namespace polydem
