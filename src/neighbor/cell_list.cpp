// The pair search over cells and the deterministic assembly of its output.
#include <omp.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "neighbor/broad_phase.hpp"
#include "neighbor/cell_common.hpp"
#include "polydem/error.hpp"
#include "polydem/parallel.hpp"

namespace polydem {
namespace {

using cells::kMinParallel;

// Cells are this much wider than the reach: cell coordinates (up to the 2^40 clamp) are rounded
// by at most 2^-12 cells each, so a pair within reach can never land two cells apart.
constexpr double kCellMargin = 1.0 + 1.0 / 1024.0;

// Throws on arguments no search can take (before the team: an exception may not leave a region).
void check_arguments(const std::vector<Vec3>& centers, const std::vector<double>& radii, double skin) {
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

// What the threads of one search share: their partial results, one slot a thread, and the first bad
// body (n when none), thrown after the team (an exception may not leave a region).
struct CellList::SearchTeam {
  SearchTeam(std::size_t n, std::size_t threads)
      : max_radius(threads, 0.0), bad_in(threads, n), parts(threads, LevelBoxes(n)), tests(threads, 0),
        rows(threads, 0), bad_radius(n), bad_position(n) {}
  std::vector<double> max_radius;  // m, of each thread's bodies
  std::vector<std::size_t> bad_in;  // each thread's first body with a bad radius
  std::vector<LevelBoxes> parts;    // each thread's run of bodies by level
  std::vector<std::size_t> tests;   // each thread's distance tests
  std::vector<std::uint32_t> rows;  // pairs in each thread's run of rows (merge_pairs)
  std::size_t bad_radius, bad_position;
};

// The whole search in one team (one region; it was seven a pour's rebuild, issue 19): every thread
// runs every stage, the loops shared, the serial joins on one thread.
void CellList::build_pairs(const std::vector<Vec3>& centers, const std::vector<double>& radii,
                           double skin, std::vector<BodyPair>& out) {
  check_arguments(centers, radii, skin);
  out.clear();
  candidate_count = 0;
  used_levels = 0;
  const std::size_t n = radii.size();
  assert(omp_get_level() == 0);  // the team's shared state below is this thread's
  const bool worth_waking = n >= kMinParallel;
  const std::size_t threads = worth_waking ? std::size_t(omp_get_max_threads()) : 1;
  SearchTeam team(n, threads);
  thread_pairs.resize(threads);
  for (auto& buffer : thread_pairs) buffer.clear();
  in_team(worth_waking, [&] { search(centers, radii, skin, team, out); });
  if (team.bad_radius < n) {
    throw std::invalid_argument("build_pairs: body " + std::to_string(team.bad_radius) + " has bounding radius " +
                                std::to_string(radii[team.bad_radius]));
  }
  if (team.bad_position < n) {
    throw RunError("broad phase: body " + std::to_string(team.bad_position) + " has a non-finite position");
  }
  for (std::size_t tests : team.tests) candidate_count += tests;
}

// One thread's part of build_pairs (every thread of the team runs it).
void CellList::search(const std::vector<Vec3>& centers, const std::vector<double>& radii, double skin,
                      SearchTeam& team, std::vector<BodyPair>& out) {
  std::size_t bad = 0;
  const double cell = cell_side(radii, skin, team, bad);
  // With a zero cell side every reach is 0 and no distance is < 0: there is nothing to find.
  if (bad < radii.size() || centers.size() < 2 || !(cell > 0.0)) return;  // the same on every thread
  if (!bin_levels(centers, radii, skin, cell, team)) return;
  collect_pairs(skin, team);
  merge_pairs(centers.size(), team, out);
}

// m, side of the coarsest cells: two bodies within reach are less than 2 max(R) + skin apart; and
// `bad`, the first body with a bad radius (n when none): every thread finds the same.
double CellList::cell_side(const std::vector<double>& radii, double skin, SearchTeam& team, std::size_t& bad) {
  const std::size_t n = radii.size(), t = std::size_t(omp_get_thread_num());
  double max_r = 0.0;  // m, exact in any order
  bad = n;
#pragma omp for schedule(static) nowait
  for (std::size_t i = 0; i < n; ++i) {
    if (!(radii[i] >= 0.0) || !std::isfinite(radii[i])) bad = std::min(bad, i);
    else max_r = std::max(max_r, radii[i]);
  }
  team.max_radius[t] = max_r;
  team.bad_in[t] = bad;
#pragma omp barrier
  const std::size_t threads = std::size_t(omp_get_num_threads());
  for (std::size_t u = 0; u < threads; ++u) {
    max_r = std::max(max_r, team.max_radius[u]);
    bad = std::min(bad, team.bad_in[u]);
  }
  if (t == 0) team.bad_radius = bad;  // read after the team
  return (2.0 * max_r + skin) * kCellMargin;
}

// Each body to its level; the non-empty levels become the grids, coarsest first. False (on every
// thread) when a centre is not finite: the first such body in team.bad_position.
bool CellList::bin_levels(const std::vector<Vec3>& centers, const std::vector<double>& radii,
                          double skin, double top_cell, SearchTeam& team) {
  double sides[kMaxLevels];  // m, exact halvings of the top cell side
  for (int level = 0; level < kMaxLevels; ++level) sides[level] = std::ldexp(top_cell, -level);
  const std::size_t n = radii.size();
  const std::size_t t = std::size_t(omp_get_thread_num()), threads = std::size_t(omp_get_num_threads());
  LevelBoxes& mine = team.parts[t];  // a smaller team's rest: empty
  for (std::size_t i = n * t / threads; i < n * (t + 1) / threads; ++i)
    mine.add(level_of(radii[i], skin, sides), i, centers[i]);
#pragma omp barrier
#pragma omp single
  {
    LevelBoxes& all = team.parts[0];  // the runs joined in order: each level's bodies in index order
    for (std::size_t u = 1; u < team.parts.size(); ++u) all.join(team.parts[u]);
    team.bad_position = all.bad;
    members.resize(kMaxLevels);
    for (int l = 0; l < kMaxLevels; ++l) std::swap(members[static_cast<std::size_t>(l)], all.members[l]);
    for (int l = 0; l < kMaxLevels && all.bad == n; ++l) {
      if (members[static_cast<std::size_t>(l)].empty()) continue;
      std::swap(members[used_levels], members[static_cast<std::size_t>(l)]);
      if (grids.size() <= used_levels) grids.resize(used_levels + 1);
      grids[used_levels].prepare(members[used_levels].size(), sides[l], all.lo[l], all.hi[l], threads);
      ++used_levels;
    }
  }
  if (team.bad_position < n) return false;
  // The grids built side by side: the team meets four times for all of them.
  for (std::size_t g = 0; g < used_levels; ++g) grids[g].number(centers, members[g]);
#pragma omp barrier
#pragma omp single
  {
    cell_offset.assign(1, 0);
    for (std::size_t g = 0; g < used_levels; ++g) {
      grids[g].lay_out();
      cell_offset.push_back(cell_offset.back() + grids[g].cell_count());
    }
  }
  KeyRun runs[kMaxLevels];  // this thread's cells and their first spheres, by grid
  for (std::size_t g = 0; g < used_levels; ++g) {
    grids[g].link();
    runs[g] = grids[g].count_cells();
  }
#pragma omp barrier
  for (std::size_t g = 0; g < used_levels; ++g) grids[g].place(centers, radii, members[g], runs[g]);
#pragma omp barrier
  return true;
}

void CellList::collect_pairs(double skin, SearchTeam& team) {
  const std::size_t total_cells = cell_offset[used_levels];
  const std::size_t t = std::size_t(omp_get_thread_num());
  std::size_t tests = 0;
  std::vector<BodyPair>& buffer = thread_pairs[t];
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
#pragma omp for schedule(dynamic, 256)
  for (std::size_t flat = 0; flat < total_cells; ++flat) {
    std::size_t level = 0;
    while (flat >= cell_offset[level + 1]) ++level;
    const std::size_t c = flat - cell_offset[level];
    pairs_within(grids[level], c, test);
    for (std::size_t coarse = 0; coarse < level; ++coarse) {
      pairs_across(grids[level], c, grids[coarse], test);
    }
  }
  team.tests[t] = tests;  // summed after the team
}

std::size_t CellList::stored_cells() const { return used_levels ? cell_offset[used_levels] : 0; }

bool CellList::hashed() const {
  for (std::size_t g = 0; g < used_levels; ++g)
    if (grids[g].hashed()) return true;
  return false;
}

std::size_t CellList::bytes() const {
  std::size_t total = cell_offset.capacity() * sizeof(std::size_t) +
                      row_start.capacity() * sizeof(std::uint32_t);
  for (const CellGrid& g : grids) total += g.bytes();
  for (const auto& list : members) total += list.capacity() * sizeof(std::uint32_t);
  for (const auto& buffer : thread_pairs) total += buffer.capacity() * sizeof(BodyPair);
  return total;
}

// Counting sort by first body, then each row by second body: independent of which thread found
// what. Each thread of the team takes a run of rows: it counts their pairs in every buffer, lays them
// out after the runs before its own, fills and sorts them.
void CellList::merge_pairs(std::size_t n, SearchTeam& team, std::vector<BodyPair>& out) {
#pragma omp single nowait  // out and row_start written after the barrier below
  {
    std::size_t total = 0;
    for (const auto& buffer : thread_pairs) total += buffer.size();
    out.resize(total);
    row_start.resize(n + 1);
    row_start[n] = std::uint32_t(total);
  }
  KeyRun run = count_run(n, [this](const auto& count) {
    for (const auto& buffer : thread_pairs)
      for (const BodyPair& p : buffer) count(p.i);
  });
  team.rows[std::size_t(omp_get_thread_num())] = run.items;
#pragma omp barrier
  place_run(run, team.rows, row_start.data());
  for (const auto& buffer : thread_pairs)
    for (const BodyPair& p : buffer)
      if (run.holds(p.i)) out[run.take(p.i)] = p;
  for (std::size_t i = run.first; i < run.last; ++i) {  // row i ends at its next slot (the next thread's starts may be unwritten)
    std::sort(out.begin() + row_start[i], out.begin() + run.next[i - run.first],
              [](const BodyPair& a, const BodyPair& b) { return a.j < b.j; });
  }
}

}  // namespace polydem
