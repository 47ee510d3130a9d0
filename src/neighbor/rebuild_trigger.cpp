#include "neighbor/rebuild_trigger.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "polydem/parallel.hpp"
#include "polydem/release.hpp"

namespace polydem {
namespace {

// Bodies below which the check runs on one thread: forking (~10 us) costs more than the loop
// (~30 ns a body).
constexpr std::size_t kMinParallel = 1024;

// One body's part of the pair rule: its bound d (m) against its skin s (m).
template <bool kUniform>
[[gnu::always_inline]] inline void add_margin(PairMargins& m, double d, double s, double driver_shift) {
  if (!(d + driver_shift <= s)) m.alone = true;  // past a driver's reach, or NaN
  m.add(kUniform ? d : d - 0.5 * s);
}

// margins' loop, one per kind of bound and skin (no test of the kind a body), the ghosts left out.
template <bool kUniform, class Bound, class Skin>
void add_margins(PairMargins& m, std::size_t n, const std::uint8_t* ghost, double driver_shift, Bound d_of, Skin s_of) {
  for (std::size_t i = 0; i < n; ++i) {
    if (ghost && ghost[i]) continue;  // its owner's part answers for it
    add_margin<kUniform>(m, d_of(i), s_of(i), driver_shift);
  }
}

}  // namespace

double displacement_bound(const Vec3& dx, const Quat& q_now, const Quat& q_built,
                          double bounding_radius) {
  return trigger_detail::displacement_bound(dx, q_now, q_built, bounding_radius);
}

void RebuildTrigger::mark_built(const std::vector<Vec3>& x, const std::vector<Quat>& q, bool points) {
  if (x.size() != q.size()) {
    throw std::invalid_argument("mark_built: " + std::to_string(x.size()) + " positions but " +
                                std::to_string(q.size()) + " orientations");
  }
  x_built = x;
  skin_.clear();  // set_skins, if any, comes after
  if (points) {
    release(q_built);
    release(displacement_);
    round_points();
  } else {
    q_built = q;
    displacement_.assign(x.size(), 0.0);
    release(x_near);
  }
  exceeded_.store(false, std::memory_order_relaxed);
  ++rebuild_count;
}

void RebuildTrigger::round_points() {
  x_near.resize(x_built.size());
  near_rounding_ = 0.0;
  for (std::size_t i = 0; i < x_built.size(); ++i) {
    x_near[i] = x_built[i].cast<float>();
    const double rounding = (x_built[i] - x_near[i].cast<double>()).norm();  // m
    if (!(rounding <= near_rounding_))  // a NaN (or an overflow's inf): every test reads x_built
      near_rounding_ = rounding == rounding ? rounding : std::numeric_limits<double>::infinity();
  }
}

bool RebuildTrigger::needs_rebuild(const std::vector<Vec3>& x, const std::vector<Quat>& q,
                                   const std::vector<double>& bounding_radius, double skin) {
  const std::size_t n = x.size();
  if (q.size() != n || bounding_radius.size() != n) {
    throw std::invalid_argument("needs_rebuild: sizes of positions, orientations and radii differ");
  }
  in_team(n >= kMinParallel, [&] {
    measure(x, q, bounding_radius, skin);
#pragma omp barrier
  });  // the barrier: for a caller inside a team already
  return take_exceeded();
}

void RebuildTrigger::measure(const std::vector<Vec3>& x, const std::vector<Quat>& q,
                             const std::vector<double>& bounding_radius, double skin, TeamCut cut,
                             const OwnedPart* owned) {
  const std::size_t n = x.size();  // q and bounding_radius: as many (needs_rebuild checks)
  if (rebuild_count == 0 || x_built.size() != n) {
    exceeded_.store(true, std::memory_order_relaxed);
    return;
  }
  const double limit = move_limit(skin);  // m
  bool exceeded = false;            // by this thread's bodies
  if (q_built.empty()) {  // points: radius 0, displacement_bound is |dx|, and no bound is kept
    exceeded = points_exceed(x, limit, cut);
  } else if (owned) {
    exceeded = measure_owned(x, q, bounding_radius, skin, cut, *owned);
  } else if (skin_.empty()) {
    for (const auto [first, last] : team_shares(n, cut))
      for (std::size_t i = first; i < last; ++i) {
        const double d = displacement_bound(x[i] - x_built[i], q[i], q_built[i], bounding_radius[i]);
        displacement_[i] = d;
        // Written as !(d <= limit) so a NaN state also asks for a rebuild.
        if (!(d <= limit)) exceeded = true;
      }
  } else {  // each body its own half skin
    for (const auto [first, last] : team_shares(n, cut))
      for (std::size_t i = first; i < last; ++i) {
        const double d = displacement_bound(x[i] - x_built[i], q[i], q_built[i], bounding_radius[i]);
        displacement_[i] = d;
        if (!(d <= move_limit(skin_[i]))) exceeded = true;
      }
  }
  // Only ever set: any order gives the same. No barrier here: take_exceeded comes after the
  // region's end (needs_rebuild, ContactEngine::lists_stale, Simulation::step), its barrier.
  if (exceeded) exceeded_.store(true, std::memory_order_relaxed);
}

namespace {

// measure_owned's loop over [first, last) (kUniform: every skin `skin`, else skins[i]), on plain
// pointers and locals: the out-of-line bound's call makes the compiler reload anything reachable.
template <bool kUniform>
bool owned_loop(std::size_t first, std::size_t last, const Vec3* x, const Quat* q, const double* radius,
                const Vec3* x_built, const Quat* q_built, const double* skins, double skin, const OwnedPart& owned,
                double* bound, PairMargins& m) {
  const std::uint8_t* ghost = owned.ghost;
  const double driver_shift = owned.driver_shift;  // m
  const bool ghosts_later = owned.ghosts_later;
  bool exceeded = false;
  PairMargins top;  // a local copy: kept in registers
  for (std::size_t i = first; i < last; ++i) {
    if (ghost && ghost[i]) {  // its owner's part answers for it
      if (!ghosts_later) bound[i] = displacement_bound(x[i] - x_built[i], q[i], q_built[i], radius[i]);
      continue;
    }
    const double d = displacement_bound(x[i] - x_built[i], q[i], q_built[i], radius[i]);  // m
    bound[i] = d;
    const double s = kUniform ? skin : skins[i];  // m
    if (!(d <= move_limit(s))) exceeded = true;
    add_margin<kUniform>(top, d, s, driver_shift);
  }
  m.join(top);
  return exceeded;
}

}  // namespace

// Out of line, so one process's loops stay as they were. The threads' margins join in any
// order: the two largest of a set, `alone` ORed.
[[gnu::noinline]] bool RebuildTrigger::measure_owned(const std::vector<Vec3>& x, const std::vector<Quat>& q,
                                                     const std::vector<double>& bounding_radius, double skin,
                                                     TeamCut cut, const OwnedPart& owned) {
  bool exceeded = false;  // by this thread's bodies
  PairMargins m;          // of this thread's owned bodies: add_margin's arithmetic
  for (const auto [first, last] : team_shares(x.size(), cut)) {
    const auto loop = skin_.empty() ? owned_loop<true> : owned_loop<false>;
    if (loop(first, last, x.data(), q.data(), bounding_radius.data(), x_built.data(), q_built.data(), skin_.data(),
             skin, owned, displacement_.data(), m))
      exceeded = true;
  }
#pragma omp critical(polydem_owned_margins)
  {
    owned_.join(m);
    owned_kept_ = true;
  }
  return exceeded;
}

// Not inlined: measure with both loops no longer inlines displacement_bound (+12% of its cost, cubes).
[[gnu::noinline]] bool RebuildTrigger::points_exceed(const std::vector<Vec3>& x, double limit, TeamCut cut) const {
  bool exceeded = false;
  for (const auto [first, last] : team_shares(x.size(), cut))
    for (std::size_t i = first; i < last; ++i)
      if (moved_past(x[i], x_built[i], limit)) exceeded = true;
  return exceeded;
}

void RebuildTrigger::remeasure(const std::vector<Vec3>& x, const std::vector<Quat>& q,
                               const std::vector<double>& bounding_radius, const std::vector<std::uint32_t>& some) {
  if (q_built.empty() || x_built.size() != x.size()) return;  // points, or no build: measure answered
  for (std::uint32_t i : some)
    displacement_[i] = displacement_bound(x[i] - x_built[i], q[i], q_built[i], bounding_radius[i]);
}

bool RebuildTrigger::watch_bounds(const std::vector<Quat>& q, const std::vector<double>& bounding_radius,
                                  double skin, BoundWatch& watch) {
  const std::size_t n = q.size();
  if (rebuild_count == 0 || x_built.size() != n || q_built.empty()) return false;  // measure's other paths
  watch = {x_built.data(), q_built.data(), q.data(), bounding_radius.data(), skin_.empty() ? nullptr : skin_.data(),
           move_limit(skin), displacement_.data(), &exceeded_};
  return true;
}

bool RebuildTrigger::watch_points(std::size_t n, double skin, PointWatch& watch) {
  if (rebuild_count == 0 || x_built.size() != n || !q_built.empty()) return false;  // measure's other paths
  const double limit = move_limit(skin);
  watch = {x_built.data(), x_near.data(), limit, near_limit(limit, near_rounding_), &exceeded_};
  return true;
}

// One process is one part: the pair rule over all its bodies (pair_rule_exceeded). Kept points'
// margins give margins' answer: `alone` where one d passes d + driver_shift > skin is where the
// largest does (rounding is monotone), or a d is not a number.
bool RebuildTrigger::pair_exceeded(const std::vector<Vec3>& x, double skin, double driver_shift) const {
  const PairMargins all = point_margins(x, skin, driver_shift, nullptr);  // polyhedra: margins
  return pair_rule_exceeded(&all, 1, skin);
}

PairMargins RebuildTrigger::point_margins(const std::vector<Vec3>& x, double skin, double driver_shift,
                                          const std::uint8_t* ghost) const {
  if (!points_kept_) return margins(x, skin, driver_shift, ghost);
  PairMargins all = points_;
  all.alone = points_.alone || !(points_.top[0] + driver_shift <= skin);
  return all;
}

namespace {

// keep_point_margins' loop over [first, last), the ghosts left out where kGhosts.
template <bool kGhosts>
void add_point_margins(PairMargins& m, std::size_t first, std::size_t last, const Vec3* x, const Vec3* x_built,
                       const std::uint8_t* ghost) {
  for (std::size_t i = first; i < last; ++i) {
    if (kGhosts && ghost[i]) continue;  // its owner's part answers for it
    const double d = (x[i] - x_built[i]).norm();  // m, margins' bound of a point
    if (d == d) m.add(d);  // a NaN added would stand as the second largest
    else m.alone = true;
  }
}

}  // namespace

void RebuildTrigger::keep_point_margins(const std::vector<Vec3>& x, TeamCut cut, const std::uint8_t* ghost) {
  if (rebuild_count == 0 || x_built.size() != x.size() || !q_built.empty()) return;  // margins' other paths
  PairMargins m;  // of this thread's bodies; alone: a NaN (pair_exceeded adds the driver's reach)
  for (const auto [first, last] : team_shares(x.size(), cut)) {
    if (ghost) add_point_margins<true>(m, first, last, x.data(), x_built.data(), ghost);
    else add_point_margins<false>(m, first, last, x.data(), x_built.data(), nullptr);
  }
#pragma omp critical(polydem_point_margins)
  {
    points_.join(m);
    points_kept_ = true;
  }
}

PairMargins RebuildTrigger::margins(const std::vector<Vec3>& x, double skin, double driver_shift,
                                    const std::uint8_t* ghost) const {
  PairMargins m;
  if (rebuild_count == 0 || x_built.size() != x.size()) {
    m.alone = true;
    return m;
  }
  m.uniform = skin_.empty();
  const auto scene_skin = [skin](std::size_t) { return skin; };
  if (q_built.empty())
    add_margins<true>(m, x.size(), ghost, driver_shift, [&](std::size_t i) { return (x[i] - x_built[i]).norm(); }, scene_skin);
  else if (m.uniform)
    add_margins<true>(m, x.size(), ghost, driver_shift, [&](std::size_t i) { return displacement_[i]; }, scene_skin);
  else
    add_margins<false>(m, x.size(), ghost, driver_shift, [&](std::size_t i) { return displacement_[i]; },
                       [&](std::size_t i) { return skin_[i]; });
  return m;
}

PairMargins RebuildTrigger::take_margins(const std::vector<Vec3>& x, double skin, double driver_shift,
                                         const std::uint8_t* ghost) {
  if (!owned_kept_) return margins(x, skin, driver_shift, ghost);
  PairMargins m = std::exchange(owned_, PairMargins{});
  owned_kept_ = false;
  m.uniform = skin_.empty();
  return m;
}

bool pair_rule_exceeded(const PairMargins* parts, std::size_t n, double skin) {
  const bool uniform = std::all_of(parts, parts + n, [](const PairMargins& p) { return p.uniform; });
  PairMargins all;  // the two largest of every part's
  for (std::size_t k = 0; k < n; ++k) {
    if (parts[k].alone) return true;
    for (double v : parts[k].top)  // a uniform part's bound as a margin: d - skin/2, as a per-body part's
      all.add(uniform || !parts[k].uniform ? v : v - 0.5 * skin);
  }
  return uniform ? !(all.top[0] + all.top[1] <= skin) : all.top[0] + all.top[1] > 0.0;
}

RuleVerdict rule_verdict(const PairMargins* parts, std::size_t n, double skin) {
  bool past = false, exact = true;
  for (std::size_t k = 0; k < n; ++k) {
    if (parts[k].alone) return RuleVerdict::rebuild;
    past = past || parts[k].past;
    exact = exact && parts[k].exact;
  }
  if (!past) return RuleVerdict::keep;
  if (!exact) return RuleVerdict::measure;
  return pair_rule_exceeded(parts, n, skin) ? RuleVerdict::rebuild : RuleVerdict::keep;
}

bool RebuildTrigger::take_exceeded() { return exceeded_.exchange(false, std::memory_order_relaxed); }

}  // namespace polydem
