// The pair search over cells and the deterministic assembly of its output.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "neighbor/broad_phase.hpp"
#include "neighbor/cell_common.hpp"
#include "polydem/error.hpp"

namespace polydem {
namespace {

using cells::kMinParallel;

// Cells are this much wider than the reach: cell coordinates (up to the 2^40 clamp) are rounded
// by at most 2^-12 cells each, so a pair within reach can never land two cells apart.
constexpr double kCellMargin = 1.0 + 1.0 / 1024.0;

// m, side of the coarsest cells: two bodies within reach are less than 2 max(R) + skin apart.
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
  const std::size_t n = radii.size();
  double max_r = 0.0;   // m, exact in any order
  std::size_t bad = n;  // the first body with a negative or non-finite radius
#pragma omp parallel for schedule(static) reduction(max : max_r) reduction(min : bad) if (n >= kMinParallel)
  for (std::size_t i = 0; i < n; ++i) {
    if (!(radii[i] >= 0.0) || !std::isfinite(radii[i])) bad = std::min(bad, i);
    else max_r = std::max(max_r, radii[i]);
  }
  if (bad < n) {
    throw std::invalid_argument("build_pairs: body " + std::to_string(bad) + " has bounding radius " +
                                std::to_string(radii[bad]));
  }
  return (2.0 * max_r + skin) * kCellMargin;
}

// The finest level whose cells (of side top 2^-level, m) still hold the body's reach, 2 R + skin.
int level_of(double radius, double skin, const double (&sides)[CellList::kMaxLevels]) {
  const double need = (2.0 * radius + skin) * kCellMargin;
  int level = 0;
  while (level + 1 < CellList::kMaxLevels && need <= sides[level + 1]) ++level;
  return level;
}

// Tests every pair of spheres a, b of grid g with a in cell c and b after a in the same cell or
// in a forward neighbour cell: each pair of the grid once.
template <class Test>
void pairs_within(const CellGrid& g, std::size_t c, const Test& test) {
  const std::uint32_t begin = g.begin(c);
  const std::uint32_t end = g.end(c);
  if (begin == end) return;
  for (std::uint32_t a = begin; a < end; ++a) {
    for (std::uint32_t b = a + 1; b < end; ++b) test(g, a, g, b);
  }
  std::uint32_t from[CellGrid::kForward];
  std::uint32_t to[CellGrid::kForward];
  const int ranges = g.forward_ranges(c, from, to);
  for (int k = 0; k < ranges; ++k) {
    for (std::uint32_t a = begin; a < end; ++a) {
      for (std::uint32_t b = from[k]; b < to[k]; ++b) test(g, a, g, b);
    }
  }
}

// Tests every sphere of cell c of the finer grid against those of the 27 cells around it in the
// coarser grid: each pair across the two grids once.
template <class Test>
void pairs_across(const CellGrid& fine, std::size_t c, const CellGrid& coarse, const Test& test) {
  for (std::uint32_t a = fine.begin(c); a < fine.end(c); ++a) {
    std::uint32_t begin[CellGrid::kAround];
    std::uint32_t end[CellGrid::kAround];
    const int ranges = coarse.ranges_around(fine.sphere(a), begin, end);
    for (int k = 0; k < ranges; ++k) {
      for (std::uint32_t b = begin[k]; b < end[k]; ++b) test(fine, a, coarse, b);
    }
  }
}

// Some bodies (a thread's run) by level: each level's bodies in index order and the bounding box
// of their centres, and the first body with a non-finite centre.
struct LevelBoxes {
  explicit LevelBoxes(std::size_t none) : bad(none) {
    for (int l = 0; l < CellList::kMaxLevels; ++l) {
      lo[l] = Vec3::Constant(std::numeric_limits<double>::infinity());
      hi[l] = -lo[l];
    }
  }
  void add(int l, std::size_t i, const Vec3& x) {
    members[l].push_back(static_cast<std::uint32_t>(i));
    if (!x.allFinite()) {
      bad = std::min(bad, i);
      return;
    }
    lo[l] = lo[l].cwiseMin(x);
    hi[l] = hi[l].cwiseMax(x);
  }
  // The bodies after this one's (a later run): appended, boxes joined (min and max: exact in any order).
  void join(const LevelBoxes& later) {
    bad = std::min(bad, later.bad);
    for (int l = 0; l < CellList::kMaxLevels; ++l) {
      members[l].insert(members[l].end(), later.members[l].begin(), later.members[l].end());
      lo[l] = lo[l].cwiseMin(later.lo[l]);
      hi[l] = hi[l].cwiseMax(later.hi[l]);
    }
  }
  std::vector<std::uint32_t> members[CellList::kMaxLevels];
  Vec3 lo[CellList::kMaxLevels], hi[CellList::kMaxLevels];  // m
  std::size_t bad;
};

}  // namespace

void CellList::build_pairs(const std::vector<Vec3>& centers, const std::vector<double>& radii,
                           double skin, std::vector<BodyPair>& out) {
  const double cell = cell_side(centers, radii, skin);
  out.clear();
  candidate_count = 0;
  used_levels = 0;
  // With a zero cell side every reach is 0 and no distance is < 0: there is nothing to find.
  if (centers.size() < 2 || !(cell > 0.0)) return;
  bin_levels(centers, radii, skin, cell);
  collect_pairs(skin, centers.size());
  merge_pairs(centers.size(), out);
}

// Each body to its level; the non-empty levels become the grids, coarsest first.
void CellList::bin_levels(const std::vector<Vec3>& centers, const std::vector<double>& radii,
                          double skin, double top_cell) {
  double sides[kMaxLevels];  // m, exact halvings of the top cell side
  for (int level = 0; level < kMaxLevels; ++level) sides[level] = std::ldexp(top_cell, -level);
  const std::size_t n = radii.size();
  const std::size_t threads = n >= kMinParallel ? std::size_t(omp_get_max_threads()) : 1;
  std::vector<LevelBoxes> parts(threads, LevelBoxes(n));  // a smaller team's rest: empty
#pragma omp parallel num_threads(int(threads)) if (threads > 1)
  {
    const std::size_t t = std::size_t(omp_get_thread_num()), team = std::size_t(omp_get_num_threads());
    LevelBoxes& mine = parts[t];
    for (std::size_t i = n * t / team; i < n * (t + 1) / team; ++i)
      mine.add(level_of(radii[i], skin, sides), i, centers[i]);
  }
  LevelBoxes& all = parts[0];  // the runs joined in order: each level's bodies in index order
  for (std::size_t t = 1; t < threads; ++t) all.join(parts[t]);
  if (all.bad < n) {
    throw RunError("broad phase: body " + std::to_string(all.bad) + " has a non-finite position");
  }
  members.resize(kMaxLevels);
  for (int l = 0; l < kMaxLevels; ++l) std::swap(members[static_cast<std::size_t>(l)], all.members[l]);
  double used_sides[kMaxLevels];
  int used_level[kMaxLevels];
  for (int l = 0; l < kMaxLevels; ++l) {
    if (members[static_cast<std::size_t>(l)].empty()) continue;
    std::swap(members[used_levels], members[static_cast<std::size_t>(l)]);
    used_level[used_levels] = l;
    used_sides[used_levels++] = sides[l];
  }
  if (grids.size() < used_levels) grids.resize(used_levels);
  cell_offset.assign(1, 0);
  for (std::size_t g = 0; g < used_levels; ++g) {
    grids[g].build(centers, radii, members[g], used_sides[g], all.lo[used_level[g]], all.hi[used_level[g]]);
    cell_offset.push_back(cell_offset.back() + grids[g].cell_count());
  }
}

void CellList::collect_pairs(double skin, std::size_t n) {
  thread_pairs.resize(static_cast<std::size_t>(omp_get_max_threads()));
  for (auto& buffer : thread_pairs) buffer.clear();
  const std::size_t total_cells = cell_offset[used_levels];
  std::size_t tests = 0;
#pragma omp parallel reduction(+ : tests) if (n >= kMinParallel)
  {
    std::vector<BodyPair>& buffer = thread_pairs[static_cast<std::size_t>(omp_get_thread_num())];
    const auto test = [&](const CellGrid& g, std::uint32_t a, const CellGrid& h, std::uint32_t b) {
      const CellSphere& p = g.sphere(a);
      const CellSphere& q = h.sphere(b);
      ++tests;
      if (within_reach(p.x, p.y, p.z, p.r, q.x, q.y, q.z, q.r, skin)) {
        const std::uint32_t i = g.body(a);
        const std::uint32_t j = h.body(b);
        buffer.push_back({std::min(i, j), std::max(i, j)});
      }
    };
    // Dynamic: clustered scenes put very unequal work in each cell; the merge restores order.
    // No barrier of its own: the region's end follows.
#pragma omp for schedule(dynamic, 256) nowait
    for (std::size_t flat = 0; flat < total_cells; ++flat) {
      std::size_t level = 0;
      while (flat >= cell_offset[level + 1]) ++level;
      const std::size_t c = flat - cell_offset[level];
      pairs_within(grids[level], c, test);
      for (std::size_t coarse = 0; coarse < level; ++coarse) {
        pairs_across(grids[level], c, grids[coarse], test);
      }
    }
  }
  candidate_count = tests;
}

std::size_t CellList::stored_cells() const { return used_levels ? cell_offset[used_levels] : 0; }

bool CellList::hashed() const {
  for (std::size_t g = 0; g < used_levels; ++g)
    if (grids[g].hashed()) return true;
  return false;
}

std::size_t CellList::bytes() const {
  std::size_t total = cell_offset.capacity() * sizeof(std::size_t) +
                      row_start.capacity() * sizeof(std::uint32_t) +
                      row_fill.capacity() * sizeof(std::uint32_t);
  for (const CellGrid& g : grids) total += g.bytes();
  for (const auto& list : members) total += list.capacity() * sizeof(std::uint32_t);
  for (const auto& buffer : thread_pairs) total += buffer.capacity() * sizeof(BodyPair);
  return total;
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
