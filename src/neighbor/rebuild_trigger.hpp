#pragma once
// Decides when the Verlet lists must be rebuilt, not on a fixed period: when two bodies (or a
// body and a driver) may have closed the skin between them since the last build (pair_exceeded,
// asked once some core point moved more than skin/2).
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "polydem/math.hpp"
#include "polydem/parallel.hpp"

namespace polydem {

// m, upper bound on how far any point within `bounding_radius` (m) of the centre moved when the
// centre moved by `dx` and the orientation went from q_built to q_now: |dx| + 2 R sin(theta/2),
// theta the angle of q_now q_built^-1. The chord 2 R sin(theta/2) is the exact largest rotational
// displacement, tighter than the arc R theta and free of trigonometry. R = 0: |dx| alone.
double displacement_bound(const Vec3& dx, const Quat& q_now, const Quat& q_built,
                          double bounding_radius);
namespace trigger_detail {
// displacement_bound's arithmetic, inlined where a pass holds the body (BoundWatch).
[[gnu::always_inline]] inline double displacement_bound(const Vec3& dx, const Quat& q_now, const Quat& q_built,
                                                        double bounding_radius) {
  if (bounding_radius == 0.0) return dx.norm();  // a point (a sphere's core): turning moves it nowhere
  const Quat q_rel = q_now * q_built.conjugate();
  // sin(theta/2) = |vector part| of the unit relative rotation; dividing by the norm forgives
  // quaternions that drifted slightly off unit length.
  const double sin_half = q_rel.vec().norm() / q_rel.norm();
  return dx.norm() + 2.0 * bounding_radius * sin_half;
}
}  // namespace trigger_detail

// m: how far each body may move from where the lists were built (half the skin).
inline double move_limit(double skin) { return 0.5 * skin; }

// Whether a point moved from x_built by more than limit (m), or to a NaN.
[[gnu::always_inline]] inline bool moved_past(const Vec3& x, const Vec3& x_built, double limit) {
  return !((x - x_built).norm() <= limit);
}

// measure's test of points, body by body, for a pass that has just moved them (the joined
// opening pass, integrate.hpp): moved_past sets the answer.
// The pass reads each point's x at the build rounded to floats (12 bytes a body-step, not 24:
// issue 19), and the exact one only where that cannot decide: the same answers as moved_past.
struct PointWatch {
  const Vec3* x_built;          // m
  const Eigen::Vector3f* x_near;  // m, x_built rounded to float
  double limit;                 // m, move_limit
  double near2;                 // m^2, |x - x_near|^2 <= near2 proves |x - x_built| <= limit (near_limit)
  std::atomic<bool>* exceeded;  // set, never cleared here: any order gives the same
  [[gnu::always_inline]] void operator()(std::size_t i, const Vec3& x) const {
    if ((x - x_near[i].cast<double>()).squaredNorm() <= near2) return;  // nearly every body-step (no root)
    if (moved_past(x, x_built[i], limit) && !exceeded->load(std::memory_order_relaxed))
      exceeded->store(true, std::memory_order_relaxed);
  }
};

// measure's test of polyhedra for the pass that has just moved and turned them (the joined opening
// pass, integrate.hpp): each body's bound kept (displacement()) and its answer set as measure's
// loop keeps and sets them, with no loop of its own (~19 instructions a body-step, and the
// bound's call, on the settled cubes).
struct BoundWatch {
  const Vec3* x_built;          // m
  const Quat* q_built;
  const Quat* q;                // the pass's orientations: turned before it shows the position
  const double* radius;         // m, per body, measure's bounding radius (the core's reach)
  const double* skin;           // m, per body (set_skins); null: `limit` for every body
  double limit;                 // m, move_limit of the scene's skin
  double* bound;                // m, per body
  std::atomic<bool>* exceeded;  // set, never cleared here: any order gives the same
  [[gnu::always_inline]] void operator()(std::size_t i, const Vec3& x) const {
    const double d = trigger_detail::displacement_bound(x - x_built[i], q[i], q_built[i], radius[i]);  // m
    bound[i] = d;
    // Written as !(d <= limit) so a NaN state also asks for a rebuild.
    if (!(d <= (skin ? move_limit(skin[i]) : limit)) && !exceeded->load(std::memory_order_relaxed))
      exceeded->store(true, std::memory_order_relaxed);
  }
};

// m^2: the square of `limit` less the largest rounding of x_built to x_near (`rounding`, m) and a
// margin of 1e-9 limit (the norms' and squares' few ulps): by the triangle inequality a point
// within it of x_near is within limit of x_built. -1 when none is left (huge coordinates): every
// test reads x_built.
inline double near_limit(double limit, double rounding) {
  const double near = limit - rounding - 1e-9 * limit;  // m
  return near > 0.0 ? near * near : -1.0;
}

// One part's answer to the pair rule (a rank's owned bodies, RebuildTrigger::margins): the parts'
// answers together decide as pair_exceeded over all their bodies would (pair_rule_exceeded),
// whatever the order they are met in (the two largest of a set).
struct PairMargins {
  bool alone = false;    // some body past a driver's reach (d + driver shift > s), or not finite
  bool uniform = true;   // every body at the scene's skin: `top` holds bounds d, else margins d - s/2
  bool past = true;      // some body moved past skin/2 or a driver as far: else none of this part's
                         // bodies can close a pair's skin with a body past it (the rule needs one)
  bool exact = true;     // `top` holds the part's two largest; false: not measured (points at skin/2)
  char unused[4] = {};   // zeros: a rank sends the record as bytes
  double top[2] = {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};  // m, top[0] >= top[1]
  void add(double v) {
    if (v <= top[1]) return;  // most bodies
    if (v > top[0]) {
      top[1] = top[0];
      top[0] = v;
    } else {
      top[1] = v;
    }
  }
  // Another part of the same kind of bound (a thread's): the two largest of both, `alone` ORed.
  void join(const PairMargins& part) {
    for (double v : part.top) add(v);
    alone = alone || part.alone;
  }
};
static_assert(sizeof(PairMargins) == 24, "a rank sends it each step: 24 bytes");

// True when the parts' bodies together may have closed a pair's skin (m, `skin` the scene's):
// with uniform skins the two largest bounds past the skin (pair_exceeded's d1 + d2), else the
// two largest margins d - s/2 past 0, a uniform part's bounds read as margins d - skin/2.
bool pair_rule_exceeded(const PairMargins* parts, std::size_t n, double skin);

// The parts' answer where some may not have measured their margins (`exact` false: a rank's points,
// whose pass tests skin/2 alone): `rebuild` where one is `alone`; `keep` where none is `past` (every
// body within skin/2 and the drivers as near: no pair can have closed its skin); else the pair
// rule's answer when every part's `top` is exact, and `measure` when one is not (each part's
// margins are then needed: RebuildTrigger::margins). pair_exceeded's answer over all the bodies.
enum class RuleVerdict { keep, rebuild, measure };
RuleVerdict rule_verdict(const PairMargins* parts, std::size_t n, double skin);

// A rank's part for RebuildTrigger::measure: its ghosts (1) and the drivers' shift (m) its margins
// read; `ghosts_later`: the ghosts are a step old, measured once landed (remeasure), so left out.
struct OwnedPart {
  const std::uint8_t* ghost = nullptr;
  double driver_shift = 0.0;
  bool ghosts_later = false;
};

class RebuildTrigger {
 public:
  // Remembers the state the lists were built at; counts one rebuild. `points`: every body's
  // bounding radius given to measure is 0 (spheres' cores), so no orientation is kept (32
  // bytes a body): turning moves no point; nor the bounds, which only polyhedra read (8 bytes).
  // The radii are then not read either: each step's pass reads x and x at the build alone.
  void mark_built(const std::vector<Vec3>& x, const std::vector<Quat>& q, bool points = false);
  // m, per body, the skins the lists were built with (pairs within range + (s_i + s_j) / 2, a body
  // and a driver within range + s_i), from the build just marked; empty: the scene's skin each.
  // Not for points (mark_built's `points`: their one pass watches skin/2).
  void set_skins(const std::vector<double>& skins) { skin_ = skins; }
  // True when some body's displacement_bound exceeds skin/2 (its own skin's half, set_skins) (or is not finite), or when no build
  // was marked for this many bodies. Parallel reduction, cheap enough for every step. Keeps
  // each body's bound in displacement().
  bool needs_rebuild(const std::vector<Vec3>& x, const std::vector<Quat>& q,
                     const std::vector<double>& bounding_radius, double skin);
  // needs_rebuild in two halves, so the measure can be a stage of a team's region (parallel.hpp):
  // `measure` keeps each body's bound (every thread of the team calls it), then, after the
  // region, `take_exceeded` answers as needs_rebuild would and clears the answer. Inside a team
  // the threads leave `measure` without meeting: the region's end is the barrier before the answer.
  // Each thread measures its bodies of `cut` (those its passes moved). With `owned` (a rank's
  // polyhedra): the same pass keeps the owned bodies' margins for take_margins (the ghosts
  // unmeasured where they land later).
  void measure(const std::vector<Vec3>& x, const std::vector<Quat>& q, const std::vector<double>& bounding_radius,
               double skin, TeamCut cut = {}, const OwnedPart* owned = nullptr);
  bool take_exceeded();
  // The sharper test once some body moved past skin/2 or a driver as far (m, `driver_shift`: the
  // largest driver surface motion since the build): true when the two largest bounds d1 >= d2
  // could bring two bodies, or d1 and the driver shift a body and a driver, within the skin:
  // !(d1 + max(d2, driver_shift) <= skin). A pair's relative motion is at most the sum of its
  // two bounds, so the lists hold while this is false, whatever one body alone moved (up to
  // the skin). Serial: called only on the steps after a body passed skin/2, before the rebuild.
  // With per-body skins s_i (set_skins), the same test on e_i = d_i - s_i / 2: true when the two
  // largest e's sum above 0, or some d_i + driver_shift passes s_i.
  // Needs this step's measure (or watch) of every body; points read x, or keep_point_margins'.
  bool pair_exceeded(const std::vector<Vec3>& x, double skin, double driver_shift) const;
  // pair_exceeded's answer for the bodies `ghost` leaves out (null: all), to be joined with other
  // parts' (pair_rule_exceeded): their two largest bounds (or margins d - s/2 with per-body skins),
  // and whether one alone passes a driver's reach. Needs this step's measure of them (points: x).
  PairMargins margins(const std::vector<Vec3>& x, double skin, double driver_shift, const std::uint8_t* ghost) const;
  // margins as measure's pass with `owned` kept them (`driver_shift` and `ghost` the same as
  // there), else margins itself; the kept ones are cleared for the next step's measure.
  PairMargins take_margins(const std::vector<Vec3>& x, double skin, double driver_shift, const std::uint8_t* ghost);
  // The same for points: the kept ones (keep_point_margins with the same `ghost`), else margins.
  PairMargins point_margins(const std::vector<Vec3>& x, double skin, double driver_shift, const std::uint8_t* ghost) const;
  // measure's test of n points done by the pass that moves them (true: `watch` set), where the
  // bodies are points and a build was marked for as many; the pass then stands for measure.
  bool watch_points(std::size_t n, double skin, PointWatch& watch);
  // The same for polyhedra (a build kept their orientations): `watch` makes measure's bounds of the
  // n bodies, orientations q and radii `bounding_radius`, in the pass. False where measure must run.
  bool watch_bounds(const std::vector<Quat>& q, const std::vector<double>& bounding_radius, double skin,
                    BoundWatch& watch);
  // pair_exceeded's margins of points, kept by a team's threads after the pass that moved them
  // (each its bodies of `cut`, joined in any order: the two largest of a set), on the steps where
  // the pair rule is likely read, so pair_exceeded answers from them without a serial loop.
  // forget_point_margins (outside any region) drops the last step's first.
  // `ghost` (a rank's, null: none): those bodies left out, their owners answer for them.
  void keep_point_margins(const std::vector<Vec3>& x, TeamCut cut, const std::uint8_t* ghost = nullptr);
  void forget_point_margins() {
    points_kept_ = false;
    points_ = PairMargins{};
  }
  // measure's bounds again for the bodies `some` alone, the answer unchanged (a rank's ghosts:
  // their owners answer for them); nothing for points, which keep no bound.
  void remeasure(const std::vector<Vec3>& x, const std::vector<Quat>& q, const std::vector<double>& bounding_radius,
                 const std::vector<std::uint32_t>& some);
  // m, per body, the displacement_bound found by the last needs_rebuild (0 right after a build):
  // two features closer than their distance at the build minus both bounds cannot have met.
  // Empty for points.
  const std::vector<double>& displacement() const { return displacement_; }
  // Calls to mark_built so far.
  std::size_t rebuilds() const { return rebuild_count; }

 private:
  // x_near and near_rounding_ from x_built (mark_built of points).
  void round_points();
  // measure's loop for points: |x - x_built| alone.
  bool points_exceed(const std::vector<Vec3>& x, double limit, TeamCut cut) const;
  // measure's loop with `owned`: true when one of the bodies measured passed its limit.
  bool measure_owned(const std::vector<Vec3>& x, const std::vector<Quat>& q, const std::vector<double>& bounding_radius,
                     double skin, TeamCut cut, const OwnedPart& owned);

  std::vector<Vec3> x_built;  // m
  std::vector<Eigen::Vector3f> x_near;  // m, x_built rounded to float, for points (PointWatch)
  double near_rounding_ = 0.0;  // m, the largest |x_built - x_near|
  std::vector<Quat> q_built;  // empty when mark_built was told the bodies are points
  std::vector<double> displacement_;  // m
  std::vector<double> skin_;  // m, per body (set_skins); empty: the skin given each call
  std::size_t rebuild_count = 0;
  std::atomic<bool> exceeded_{false};  // some body moved past skin/2 since the last take_exceeded
  PairMargins owned_;         // measure_owned's threads' margins, joined (take_margins)
  bool owned_kept_ = false;   // owned_ holds this step's
  PairMargins points_;        // keep_point_margins' threads' two largest |x - x_built| (m), joined; alone: a NaN
  bool points_kept_ = false;  // points_ holds this step's: pair_exceeded reads them
};

}  // namespace polydem
