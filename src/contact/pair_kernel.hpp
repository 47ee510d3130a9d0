#pragma once
// Forces of one interacting pair: evaluates its candidate feature pairs, shares the patch
// between sub-contacts, hands history over, applies the contact law. Templated on the
// partner (another body or a driver) so the hot loop has no virtual call.
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "contact/contact_mass.hpp"
#include "contact/law.hpp"
#include "contact/law_lanes.hpp"
#include "contact/made_pose.hpp"
#include "geometry/shadowing.hpp"
#include "contact/contact_lists.hpp"
#include "contact/contact_regions.hpp"
#include "contact/patch_push.hpp"

namespace polydem {

// The first moment about n+1 (N m s^2, about each body's centre) of the torques that the
// impulses at the steps miss where a patch's shares moved within the step (patch_push.hpp): the
// step's drift, at v(n+1/2), misses the turn they made within it, an angle error of O(lag dt)
// (issue 16: a cube landing almost flat). Each body turns by I^-1 moment after the step
// (ContactEngine::take_turns, integrate/turn_table.hpp's turn_bodies), as the impulses' true timing would
// have turned it. Torques only: the forces' same moment, shifting the centres, moved the
// almost-flat landing's error by 1.4% at 0.1 x critical (4.15e-4 -> 4.10e-4), and a rank drifts
// its ghosts' centres itself (body_exchange.hpp) where their orientations come from their owners.
struct PairTurn {
  std::uint32_t i, j;
  bool driver;               // j is a driver: it takes no turn
  Vec3 moment_i, moment_j;   // N m s^2, world
};

// A body's summed PairTurn moments (N m s^2, world), by its local index.
struct BodyTurn {
  std::uint32_t body;
  Vec3 moment;
};

// What a pair kernel needs to know about body i (the particle side of every pair).
struct BodyView {
  const PosedBody* posed;   // per body, posed for this step
  const Vec3* position;     // m, centres (compact: the sphere path reads nothing else of the pose)
  const double* radius;     // m, scaled Minkowski radii
  const Vec3* velocity;     // m/s
  const Vec3* angular_velocity;  // rad/s
  const Vec3* velocity_end;       // m/s, predicted for the end of the step (Bodies::velocity_end)
  const Vec3* angular_velocity_end;  // rad/s, likewise
  const double* mass;       // kg
  bool any_sphere = true;   // some body is a sphere: else no body pair takes the exact step (no shape read per pair)
  std::vector<PairTurn>* turns = nullptr;  // where a pair whose patch pushed leaves its turn (rare)
  ShapeBoxes boxes;         // a made walk's boxes: their poses made where read (made_pose.hpp)
};
// Every body of the contact stage the same sphere: one radius (m) and mass (kg) for all.
struct EqualSpheres {
  double radius, mass;
};

// Equal spheres' k', c' of the exact step for pairs of mass m (kg), made once a step as a pair's
// cache makes them (the same bits); empty where the law reads none.
template <class Parts>
LinearStep same_linear_step(const LawParams& law, double m, double dt) {
  if (!Parts::Normal::kCurved && law.exact_step && law.alpha_n > 0.0) return linear_step(law.kn, law.alpha_n, m, dt);
  return LinearStep{};
}

// True when the two bodies are farther apart than `band` along the line of their centres:
// the gap between their support planes normal to it bounds their distance from below.
inline bool separated_along_centres(const PosedBody& a, const PosedBody& b, double band) {
  const Vec3 axis = b.position - a.position;  // m, from a to b
  const double length = axis.norm();
  if (length == 0.0) return false;
  const Vec3 d = axis / length;
  double reach_a = -1e300, reach_b = -1e300;  // m, support of a along d and of b along -d
  for (std::size_t v = 0; v < a.shape->vertices.size(); ++v) reach_a = std::max(reach_a, (a.vertices[v] - a.position).dot(d));
  for (std::size_t v = 0; v < b.shape->vertices.size(); ++v) reach_b = std::max(reach_b, (b.position - b.vertices[v]).dot(d));
  return length - reach_a - reach_b - a.radius - b.radius >= band;
}

// One sub-contact found this step, before forces.
struct FoundContact {
  FoundContact() {}  // left unset, not zeroed: find_contacts appends one per candidate, the kernel fills it
  FoundContact(std::uint32_t s, const ContactPoint& g) : slot(s), geometry(g) {}
  std::uint32_t slot;
  ContactPoint geometry;
  SlotState* state;  // the slot's in a sparse list (find_contacts): the law's springs and the record's point
};

// Patch weights (SPEC "faces in contact"): the sub-contacts of one pair share the pair's
// stiffness and damping in proportion to their depth inside the interaction band,
// w_k = s_k / sum(s), s_k = band - gap_k. A face landing flat (equal depths) then acts as one
// contact of stiffness kn whatever its vertex count; a lone contact has w = 1; a sub-contact
// that appears at the band edge has w = 0, so forces stay continuous.
// Only weight[0, found.size()) is set and read: the vector keeps its largest size, not shrunk and
// grown again (zeroed through a call) from pair to pair.
inline void patch_weights(const std::vector<FoundContact>& found, double band,
                          std::vector<double>& weight) {
  const std::size_t n = found.size();
  if (weight.size() < n) weight.resize(n);
  if (n == 1) { weight[0] = 1.0; return; }  // the common lone contact
  double total = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    weight[k] = band - found[k].geometry.gap;
    total += weight[k];
  }
  if (!(total > 0.0)) { std::fill_n(weight.begin(), n, 1.0 / double(n)); return; }
  const double scale = 1.0 / total;  // one division per pair
  for (std::size_t k = 0; k < n; ++k) weight[k] *= scale;
}

// A slot that starts touching inherits the history of the nearest slot of the same pair
// that stopped touching this step (a vertex sliding from a face onto an edge keeps its
// spring), matched closest pair first; each ended slot gives its history once. Beyond
// kMaxHandOver changes in one step for one pair, the rest start from zero.
constexpr int kMaxHandOver = 32;
// True when the pair touches through the same slots as at the last step (`was_active` of them):
// nothing to hand over, the common case of a resting contact. Inline: every touching pair asks.
inline bool same_contacts(const PairList& list, int was_active, const std::vector<FoundContact>& found) {
  if (was_active != int(found.size())) return false;
  for (const FoundContact& c : found)
    if (!list.active[c.slot]) return false;
  return true;
}

// `was_active`: how many slots of the pair were active before this step. Returns J, the
// energy released by the contacts that ended with no successor (law.hpp, released_energy;
// 0 without a law).
// `r_star`: m, the pair's curvature radius (Hertz; 0 for the linear law).
EnergyParts hand_over_history(PairList& list, std::uint32_t slot_begin, std::uint32_t slot_end, int was_active,
                              const std::vector<FoundContact>& found, std::vector<std::uint8_t>& now_on,
                              const LawParams* law = nullptr, double r_star = 0.0);

struct PairTotals {
  Vec3 force_i = Vec3::Zero(), torque_i = Vec3::Zero(), torque_j = Vec3::Zero();
  EnergyParts energy;        // J dissipated this step (net: less what patch weight changes added)
  int contacts = 0;
};

// Per-thread scratch so the pair loop does not allocate.
struct PairScratch {
  std::vector<FoundContact> found;
  std::vector<std::uint8_t> drop;
  std::vector<double> weight;
  std::vector<std::uint32_t> region;  // contact region of each found contact (non-convex pairs)
  std::vector<std::uint8_t> now_on;
  std::vector<double> patch_mass;     // kg, damping_mass: contact on a patch (patch_dashpot_masses)
  std::vector<double> patch_depth;    // m, per found contact: ContactKinematics::patch_depth (patch_onsets)
  bool onsets = false;                // patch_depth is set for this pair (rare: the contact set changed)
  mutable std::vector<PatchPush> patch_push;  // per found contact where `onsets` and the band is 0 (patch_pushes); the law sets each one's moment
  std::vector<std::uint8_t> pushing;  // per found contact: its region's shares move, patch_push is its push
  std::vector<PatchDrift> all_drift;  // the pair's sub-contacts over the step (patch_pushes)
  std::vector<PatchDrift> drift;      // one region's of them
  bool pushes = false;                // patch_push is set for some contact of this pair
  std::unique_ptr<MadeWalk> made;     // box corners made in this walk (with_vertices), from its first box
};

// The walked pair's side i as the kernels read it: stored (posed[i]), or a box made
// (with_vertices) in the walk's boxes `w` (made_walk).
[[gnu::always_inline]] inline const PosedBody& pose_of_i(const PosedBody* posed, std::uint32_t i, ShapeBoxes boxes,
                                                         MadeWalk& w) {
  return with_vertices(posed, i, boxes, w.corners, w.made_i, w.made_j);
}

// The sub-contacts whose overlap starts this step (none at n) in a patch of several (their region;
// the pair on convex bodies) act as one contact, whose force starts at the patch's first touch:
//  - another overlapped at n: the patch's force is continuous, the new one entering at weight ~0
//    and taking its share from the others, so its start is no onset (patch_depth -1). Counted as
//    one, its dashpot's share looked like a jump from zero: an O(dt) impulse where the new vertex
//    is as deep as the others after a step (a cube landing almost flat: issue 16's tilted pair);
//  - none did: each one's onset dates from the touch of the deepest (patch_depth its overlap),
//    its weighted shares then summing to the patch's dashpot jump at that touch.
inline void patch_onsets(bool regions, PairScratch& scratch) {
  const std::size_t n = scratch.found.size();
  scratch.patch_depth.assign(n, 0.0);
  scratch.onsets = true;
  const auto same = [&](std::size_t c, std::size_t o) { return !regions || scratch.region[o] == scratch.region[c]; };
  for (std::size_t c = 0; c < n; ++c) {
    if (scratch.found[c].state->gap < 0.0) continue;  // overlapped at n (or took a history)
    double depth = 0.0;  // m
    for (std::size_t o = 0; o < n && depth >= 0.0; ++o) {
      if (!same(c, o)) continue;
      if (scratch.found[o].state->gap < 0.0) depth = -1.0;
      else depth = std::max(depth, -scratch.found[o].geometry.gap);
    }
    scratch.patch_depth[c] = depth;
  }
}

// The pushes of patch_push.hpp for each sub-contact of a pair whose contact set changed, from
// its region's overlaps (no band: the weights are the overlaps') and closing rates at the half
// step (v_centre, m/s: i's velocity less j's at i's centre xi, m; w_rel, rad/s). A sub-contact
// new this step and closing touched x / r before n+1; else it counts as touching at n. Only a
// region where one touched within the step (x < r dt) pushes: a set that changes otherwise (a
// vertex letting go, a feature handed over, a vertex at rest flickering by round-off) moves no
// share by O(1) within a step.
inline void patch_pushes(const Vec3& xi, const Vec3& v_centre, const Vec3& w_rel, bool regions, double dt,
                         PairScratch& scratch) {
  const std::size_t n = scratch.found.size();
  scratch.all_drift.clear();
  bool touched = false;  // a sub-contact touched within the step
  for (std::size_t o = 0; o < n; ++o) {
    const ContactPoint& g = scratch.found[o].geometry;
    const double x = -g.gap, r = -(v_centre + w_rel.cross(g.point - xi)).dot(g.normal);  // m, m/s
    const bool old = scratch.found[o].state->gap < 0.0 || !(x < r * dt);
    scratch.all_drift.push_back({x, r, old ? dt : x / r, old});
    touched = touched || !old;
  }
  if (!touched) return;
  scratch.patch_push.assign(n, PatchPush{0.0, 0.0});
  scratch.pushing.assign(n, 0);
  for (std::size_t c = 0; c < n; ++c) {
    scratch.drift.clear();
    std::size_t self = 0;
    bool region_touched = false, region_old = false;
    double first = dt, last = 0.0;  // s before n+1: the region's earliest and latest touch
    for (std::size_t o = 0; o < n; ++o) {
      if (regions && scratch.region[o] != scratch.region[c]) continue;
      if (o == c) self = scratch.drift.size();
      scratch.drift.push_back(scratch.all_drift[o]);
      region_touched = region_touched || !scratch.all_drift[o].old;
      region_old = region_old || scratch.all_drift[o].old;
      first = std::min(first, scratch.all_drift[o].touch), last = std::max(last, scratch.all_drift[o].touch);
    }
    // All touched at once (a cube landing flat): the shares hold still, the lone onset pushes
    // (patch_onsets) are the patch's; the patch push's was coarser there (flat cube at 0.1 x
    // critical, worst of 8: 3.11e-4 with them, 6.32e-4 with it).
    const bool together = !region_old && last - first <= 1e-9 * dt;
    if (!region_touched || together) continue;
    scratch.patch_push[c] = patch_push(scratch.drift, self, dt);
    scratch.pushing[c] = 1;
    scratch.pushes = true;
  }
}

// damping_mass: contact on a patch of several sub-contacts: they act as one spring (the patch
// weights), so each one's dashpot takes the mass at the patch's centre of pressure, the levers
// and normals averaged with the weights over its region (the whole pair on convex bodies). A
// face landing flat then sees the body's mass, not a quarter of it at each corner (which gave
// a rebound of 0.672 for en 0.5). `b`: partner j's pose (Partner::posed_of).
template <class Partner, class Posed>
void patch_dashpot_masses(const PosedBody& a, double mass_i, const Vec3& xi, const Partner& partner, const Posed& b,
                          std::uint32_t j, bool regions, PairScratch& scratch) {
  const std::size_t n = scratch.found.size();
  scratch.patch_mass.resize(n);
  for (std::size_t r = 0; r < n; ++r) {  // region labels are sub-contact indices (contact_regions.hpp)
    Vec3 lever = Vec3::Zero(), normal = Vec3::Zero();
    bool any = false;
    for (std::size_t c = 0; c < n; ++c)
      if ((regions ? scratch.region[c] : 0) == r) {
        lever += scratch.weight[c] * (scratch.found[c].geometry.point - xi);
        normal += scratch.weight[c] * scratch.found[c].geometry.normal;
        any = true;
      }
    if (!any) continue;
    const double length = normal.norm();
    if (length > 0.0) normal /= length;
    else normal = scratch.found[r].geometry.normal;  // opposed normals cancel: take the region's first
    const double m = 1.0 / (point_inverse_mass(a, mass_i, lever, normal) + partner.point_inverse_mass(b, j, xi + lever, normal));
    for (std::size_t c = 0; c < n; ++c)
      if ((regions ? scratch.region[c] : 0) == r) scratch.patch_mass[c] = m;
  }
}

// Removes the found contacts that a vertex-face contact of the same vertex shadows (a face of a
// convex body only: `a_convex`, `b_convex`).
inline void drop_shadowed(const PairList& list, double radii, bool a_convex, bool b_convex, PairScratch& scratch) {
  auto& found = scratch.found;
  if (found.size() < 2) return;
  scratch.drop.resize(found.size());
  mark_shadowed(found.size(), [&](std::size_t k) { return list.features[found[k].slot]; },
                [&](std::size_t k) { return found[k].geometry.gap; }, radii, scratch.drop.data(), a_convex,
                b_convex);
  std::size_t kept = 0;
  for (std::size_t k = 0; k < found.size(); ++k)
    if (!scratch.drop[k]) found[kept++] = found[k];
  found.resize(kept);
}

// The rigid motion of one side of a pair, read once per pair: a point p moves at v + w x (p - pivot).
// `_end`: the same predicted for the end of the step (the dashpots read them; a driver's are its own).
// References into the partner's own arrays, not copies: a copy per pair cost ~36 instructions of
// moves through the stack (the kernels read each once).
struct RigidMotion {
  const Vec3& velocity;          // m/s, of the pivot
  const Vec3& angular_velocity;  // rad/s
  const Vec3& pivot;             // m
  const Vec3 &velocity_end, &angular_velocity_end;  // m/s, rad/s
  Vec3 at(const Vec3& p) const { return velocity + angular_velocity.cross(p - pivot); }
  Vec3 at_end(const Vec3& p) const { return velocity_end + angular_velocity_end.cross(p - pivot); }
};

// Candidate f (slot gap `slot_gap`) that its kernel rejected with an allowance (features.hpp's
// rejection_allowance, m: the rejection holds while the two bodies' displacement bounds at this
// step and at a later one add up to less): its gap raised to allowance - moved + band (rounded down
// to a float), so the slot scan skips it while `moved` (m, the bounds' sum, from the build) stays
// within the allowance. A skipped call would have been rejected: the same bits. Issue 19: ~700,000
// of the settled cubes' 3.12M kernel calls in 200 steps were rejected, nearly all again each step.
template <class Partner, class Posed>
[[gnu::noinline]] void retire_slot(const Partner& partner, const PosedBody& a, const Posed& b, FeaturePair f,
                                   double moved, double band, float& slot_gap) {
  const double allowance = partner.allowance(a, b, f);  // m
  const double gap = allowance - moved + band;          // m
  if (!(allowance > moved) || !(gap > double(slot_gap))) return;
  float low = float(gap);
  if (double(low) > gap) low = std::nextafter(low, -std::numeric_limits<float>::infinity());
  slot_gap = std::max(slot_gap, low);
}

// Partner must provide:
//   kMadeVertices: a box's pose may come without vertices (made_pose.hpp: with_vertices makes them)
//   posed_of(j, PairScratch&): what contact, separated and allowance take of partner j for one pair (a
//     body: its pose with vertices, with_vertices, the scratch's MadeWalk made first where kMadeVertices; a driver: j)
//   bool contact(const PosedBody& a, posed_of(j), FeaturePair f, double max_gap, ContactPoint&)
//   bool apart(const PairList&, std::uint32_t k, double band): true only when pair k cannot touch (O(1))
//   double moved(i, j): m, bound on how much closer two features got since the build
//   bool separated(const PosedBody& a, posed_of(j), double band): true only when no contact is possible
//   of b = posed_of(j) (a made box's pose is read where it was made):
//   double radius(b): the partner's rounding radius (m)
//   double r_star(r_i, b): m, the curvature radius of a contact of a body of rounding r_i with j (Hertz)
//   bool convex(b): the partner's core is convex (drivers: true; a mesh keeps its own rules)
//   const Shape* shape(b): the partner body's shape, null for a driver (contact regions)
//   double point_inverse_mass(b, j, point, n): 1/kg, the partner's share of 1/m* (contact_mass.hpp; a driver: 0)
//   Vec3 center(j), RigidMotion motion(j), double m_eff(i, j)
//   void prefetch(j): starts loading partner j's data for the next pair (a hint, no effect on results)
//   kRetires: a rejected candidate's allowance holds for it (bodies, whose displacement bounds `moved`
//     sums; not a driver, whose partner pose is made anew); then double allowance(a, posed_of(j), FeaturePair)

// Evaluates the candidate feature pairs of pair k (slots [s0, s1)) into scratch.found and drops
// the shadowed ones. Inline in pair_forces (its own call cost ~17 instructions a touching cube pair, issue 19).
template <class Partner, class Posed>
[[gnu::always_inline]] inline void find_contacts(double band, const PosedBody& a, const Posed& b, const Partner& partner,
                                                 PairList& list, std::uint32_t k, PairScratch& scratch) {
  const BodyPair p = list.pairs[k];
  scratch.found.clear();
  const double moved = partner.moved(p.i, p.j);  // m, how much closer any two features may be than at the build
  unsigned types = 0;  // bit t: a contact of PairType t was found (one register: two flags spilled)
  // Read once: the stores to `found` might alias them.
  const std::uint32_t end = list.slot_begin[k + 1];
  const float* const slot_gap = list.slot_gap.data();  // m
  const FeaturePair* const features = list.features.data();
  for (std::uint32_t s = list.slot_begin[k]; s < end; ++s) {
    if (slot_gap[s] - moved >= band) continue;  // cannot touch yet
    FoundContact& next = scratch.found.emplace_back();  // the kernel fills it in place: no copy
    const FeaturePair f = features[s];
    if (!partner.contact(a, b, f, band, next.geometry)) {
      if constexpr (Partner::kRetires)
        if (next.geometry.gap > 0.0) [[unlikely]] retire_slot(partner, a, b, f, moved, band, list.slot_gap[s]);
      scratch.found.pop_back();
      continue;
    }
    next.slot = s;
    next.state = &list.touch(s);  // a shadowed one's too (rare): made, left as it was
    types |= 1u << unsigned(f.type);
    // The slot's state is read and written by the law, after the pair's other candidates: fetch it
    // now (its 80 bytes, two lines at most).
    const char* state = reinterpret_cast<const char*>(next.state);
    __builtin_prefetch(state, 1);
    __builtin_prefetch(state + 64, 1);
  }
  if (shadows_any(types) && may_be_shadowed_any(types))  // rare: nothing to drop otherwise
    drop_shadowed(list, a.radius + partner.radius(b), a.shape->convex, partner.convex(b), scratch);
}

// The partner's side of a pair as its kernels read it (Partner::posed_of): a body's pose or a driver's index.
template <class Partner>
using PartnerSide = std::remove_cvref_t<decltype(std::declval<const Partner&>().posed_of(0u, std::declval<PairScratch&>()))>;

// What the law of pair k's sub-contacts shares, made once per pair by apply_law: explicit, so the
// rare sub-contact through contact_force is a call with one pointer, no closures built per pair.
template <class Partner>
struct PairLaw {
  const LawParams& law;
  const BodyView& bodies;
  const Partner& partner;
  PairList& list;
  const PairScratch& scratch;
  std::uint32_t k;
  BodyPair p;
  const PosedBody* a;              // i's pose; null where the law reads no contact mass (the lanes')
  const PartnerSide<Partner>* b;   // j's side; likewise
  double r_star;      // m
  LaneConstants lc;   // the pair's motion relative to i's centre, m_eff, nu and the law's constants
  double nu_t;        // N s/m
  bool exact_step;
  PairTotals& totals;
};

// A pair of one sub-contact through the lanes' law, waiting for another such pair to run the
// two contacts side by side (lone_pairs.hpp): what apply_law made of it, its contact (copied out
// of the scratch only when it waits), its totals (the hand-over's energy) until the law adds it.
struct LonePair {
  std::uint32_t k;
  FoundContact contact;
  LaneConstants lc;
  double nu_t, r_star;  // N s/m, m
  bool exact_step;
  PairTotals totals;
};

// Adds sub-contact c's force f and torque about i's centre to the pair's totals and records it
// (its point always: the hand-over reads it; its force and fn while `list` records).
// kSteady: a steady lane's contact (law_lanes.hpp), whose sliding and rolling shares are +0: not
// added, as adding +0 to a sum changes it only from -0, and a sum that starts at +0 never is -0.
template <bool kSteady = false>
[[gnu::always_inline]] inline void add_to_totals(PairList& list, const FoundContact& found, PairTotals& totals,
                                                 const ContactForce& f, const Vec3& torque) {
  found.state->point = found.geometry.point;
  if (list.recording) [[unlikely]] {  // a step whose contacts are read
    SlotForce& record = list.states.force(list.state_of[found.slot]);
    record.force = f.force;  // member by member: an aggregate went through a copy on the stack
    record.fn = f.fn;
  }
  totals.force_i += f.force;
  totals.torque_i += torque;
  if constexpr (kSteady) {
    totals.energy.net += f.dissipated - f.patch;
    totals.energy.patch += f.patch;
  } else {
    totals.energy += energy_parts(f);  // net of the patch work: the patch share is not conservative (law.hpp)
  }
}
template <bool kSteady = false, class Partner>
[[gnu::always_inline]] inline void add_contact(const PairLaw<Partner>& pl, std::size_t c, const ContactForce& f,
                                               const Vec3& torque) {
  add_to_totals<kSteady>(pl.list, pl.scratch.found[c], pl.totals, f, torque);
}

// Sub-contact c through contact_force, as it computes a contact alone, added and recorded.
// Without rolling the moment is +0, and adding it changes no sum's bits (a -0 term becomes +0,
// which the sum, never -0 itself, absorbs alike).
template <class Parts, class Partner>
[[gnu::always_inline]] inline void contact_by_law(const PairLaw<Partner>& pl, std::size_t c) {
  using Normal = typename Parts::Normal;
  const LawParams& law = pl.law;
  const LaneConstants& lc = pl.lc;
  const ContactPoint& g = pl.scratch.found[c].geometry;
  const SubContactMotion motion = sub_contact_motion(g.point, lc.xi, lc.v_centre, lc.w_rel, lc.v_centre_end, lc.w_rel_end);
  double m_dashpot = lc.m_eff, nu_dashpot = lc.nu;  // kg, N s/m: the normal dashpot's mass and coefficient
  if (law.contact_mass) {  // damping_mass: contact: a lone contact's point, or its patch's
    m_dashpot = pl.scratch.found.size() == 1
                    ? 1.0 / (point_inverse_mass(*pl.a, pl.bodies.mass[pl.p.i], motion.lever, g.normal) +
                             pl.partner.point_inverse_mass(*pl.b, pl.p.j, g.point, g.normal))
                    : pl.scratch.patch_mass[c];
    nu_dashpot = Normal::pair_damping(law, m_dashpot, pl.r_star);
  }
  ContactKinematics kin{g.normal,
                        g.gap,
                        motion.v_rel,
                        motion.v_end,
                        lc.w_rel,
                        m_dashpot,
                        Parts::rolling && law.rolling ? motion.lever.norm() : 0.0,
                        pl.scratch.weight[c],
                        nu_dashpot,
                        pl.nu_t,
                        pl.r_star,
                        pl.exact_step,
                        law.contact_mass ? nullptr : &pl.list.linear_steps[pl.k],  // k', c' for the pair's fixed mass
                        pl.scratch.onsets ? pl.scratch.patch_depth[c] : 0.0,
                        pl.scratch.pushes && pl.scratch.pushing[c] ? &pl.scratch.patch_push[c] : nullptr};
  SlotState& state = *pl.scratch.found[c].state;
  Vec3* const moment = Parts::rolling && pl.list.states.rolls()  // N m, kept apart
                           ? &pl.list.states.moment(pl.list.state_of[pl.scratch.found[c].slot])
                           : nullptr;
  ContactHistory h = state.history(moment ? *moment : Vec3::Zero());
  const ContactForce f = contact_force<Parts, false, Stored::kSkip>(law, kin, h, lc.dt);
  state.keep(h);
  if (moment) *moment = h.mr;
  if constexpr (Parts::rolling) add_contact(pl, c, f, motion.lever.cross(f.force) + f.moment);
  else add_contact(pl, c, f, motion.lever.cross(f.force));
}

// The same out of line: the lanes' rare contact that is not steady leaves their registers alone.
template <class Parts, class Partner>
[[gnu::noinline]] void contact_by_law_apart(const PairLaw<Partner>& pl, std::size_t c) {
  contact_by_law<Parts>(pl, c);
}

// Sub-contacts [c, c + N) of a pair side by side (steady_law<N>, law_lanes.hpp), each added and
// recorded in order: a steady one from its lane, another through contact_force.
template <int N, class Parts, class Partner>
[[gnu::always_inline]] inline void sub_contacts_in_lanes(const PairLaw<Partner>& pl, std::size_t c) {
  const PairScratch& scratch = pl.scratch;
  const LaneConstants* pc[N];
  const ContactPoint* g[N];
  double w[N];
  SlotState* h[N];
  for (int l = 0; l < N; ++l) {
    pc[l] = &pl.lc;
    g[l] = &scratch.found[c + l].geometry;
    w[l] = scratch.weight[c + l];
    h[l] = scratch.found[c + l].state;
  }
  ContactForce f[N];
  Vec3 torque[N];
  const unsigned steady = steady_law<N>(pc, g, w, h, f, torque);
  for (int l = 0; l < N; ++l) {
    if (steady & (1u << l)) add_contact<true>(pl, c + l, f[l], torque[l]);
    else contact_by_law_apart<Parts>(pl, c + l);
  }
}

// The sub-contacts of a pair four at a time where kLanes is 4 (the AVX builds), then two at a time
// through steady_lanes (law_lanes.hpp), the last of an odd count through steady_alone, one that is
// not steady through contact_force; each added and recorded in order.
template <class Parts, int kLanes, class Partner>
[[gnu::always_inline]] inline void law_in_lanes(const PairLaw<Partner>& pl) {
  const PairScratch& scratch = pl.scratch;
  const std::size_t n = scratch.found.size();
  std::size_t c = 0;
  if constexpr (kLanes == 4)
    for (; c + 3 < n; c += 4) sub_contacts_in_lanes<4, Parts>(pl, c);
  for (; c + 1 < n; c += 2) {
    ContactForce f[2];
    Vec3 torque[2];
    const unsigned steady = steady_lanes(pl.lc, scratch.found[c].geometry, scratch.found[c + 1].geometry,
                                         scratch.weight[c], scratch.weight[c + 1],
                                         *scratch.found[c].state, *scratch.found[c + 1].state, f, torque);
    if (steady & 1u) add_contact<true>(pl, c, f[0], torque[0]);
    else contact_by_law_apart<Parts>(pl, c);
    if (steady & 2u) add_contact<true>(pl, c + 1, f[1], torque[1]);
    else contact_by_law_apart<Parts>(pl, c + 1);
  }
  if (c == n) return;
  ContactForce f;
  Vec3 torque;
  if (steady_alone(pl.lc, scratch.found[c].geometry, scratch.weight[c], *scratch.found[c].state, f, torque))
    add_contact<true>(pl, c, f, torque);
  else
    contact_by_law_apart<Parts>(pl, c);
}

// The law runs its steady sub-contacts in lanes (law_lanes.hpp): the linear law without
// cohesion, rolling or the tangential dashpot.
template <class Parts>
constexpr bool lanes_law() {
  return !Parts::Normal::kCurved && !Parts::cohesion && !Parts::rolling && !Parts::tangential_dashpot;
}

// Applies the law to the sub-contacts in scratch.found (weights in scratch.weight) and adds
// their forces, torques and energy to `totals`. With `lone` (kLone), a pair whose one sub-contact
// goes through the lanes is left there instead (its totals too), for lone_pairs.hpp: false then.
// kLanes: the law's lanes within a pair (law_in_lanes), 4 in the AVX builds only. `a`, `b`: i's
// pose and j's side (Partner::posed_of).
template <class Parts, bool kLone = false, int kLanes = 2, class Partner>
[[gnu::always_inline]] inline bool apply_law(const LawParams& law, double dt, const BodyView& bodies, const Partner& partner,
                                 PairList& list, std::uint32_t k, const PairScratch& scratch, double r_star,
                                 const PosedBody& a, const PartnerSide<Partner>& b, PairTotals& totals,
                                 LonePair* lone = nullptr) {
  using Normal = typename Parts::Normal;
  const BodyPair p = list.pairs[k];
  const Vec3 xi = bodies.position[p.i];
  const RigidMotion mj = partner.motion(p.j);
  const Vec3 w_rel = bodies.angular_velocity[p.i] - mj.angular_velocity;  // rad/s
  // m/s, i's velocity less j's at i's centre: at a lever r from it they differ by v_centre + w_rel x r.
  const Vec3 v_centre = bodies.velocity[p.i] - mj.at(xi);
  const Vec3 w_rel_end = bodies.angular_velocity_end[p.i] - mj.angular_velocity_end;  // rad/s
  const Vec3 v_centre_end = bodies.velocity_end[p.i] - mj.at_end(xi);  // m/s
  const double m_eff = partner.m_eff(p.i, p.j);
  const double nu = Normal::pair_damping(law, m_eff, r_star), nu_t = pair_tangential_damping(law, m_eff);  // N s/m
  const Shape* shape_j = partner.shape(b);  // null: a driver, of infinite mass
  const bool exact_step =
      law.exact_step &&
      (law.contact_mass || (bodies.any_sphere && a.shape->is_sphere() && (!shape_j || shape_j->is_sphere())));
  // Through the lanes where the law allows it (law_lanes.hpp), in their order.
  bool laned = false;
  if constexpr (lanes_law<Parts>()) {
    laned = !law.contact_mass && !(law.exact_step && exact_step && law.alpha_n > 0.0) && law.mu > 0.0 && nu >= 0.0 &&
            !scratch.pushes;  // a changed patch's shares move: every one takes its push
    if constexpr (kLone) {
      if (laned && scratch.found.size() == 1) {  // `totals` are lone->totals (lone_paired_pairs)
        lone->k = k;  // its contact stays in the scratch until it waits (LonePairKernel::park)
        // Member by member: an aggregate went through a temporary on the stack and a copy of it.
        LaneConstants& lc = lone->lc;
        lc.xi = xi;
        lc.v_centre = v_centre;
        lc.w_rel = w_rel;
        lc.v_centre_end = v_centre_end;
        lc.w_rel_end = w_rel_end;
        lc.m_eff = m_eff;
        lc.nu = nu;
        lc.kn = law.kn;
        lc.kt = law.kt;
        lc.mu = law.mu;
        lc.dt = dt;
        lone->nu_t = nu_t;
        lone->r_star = r_star;
        lone->exact_step = exact_step;
        return false;
      }
    }
  }
  const PairLaw<Partner> pl{law,
                            bodies,
                            partner,
                            list,
                            scratch,
                            k,
                            p,
                            &a,
                            &b,
                            r_star,
                            {xi, v_centre, w_rel, v_centre_end, w_rel_end, m_eff, nu, law.kn, law.kt, law.mu, dt},
                            nu_t,
                            exact_step,
                            totals};
  if constexpr (lanes_law<Parts>()) {
    if (laned) law_in_lanes<Parts, kLanes>(pl);
  }
  if (!laned)
    for (std::size_t c = 0; c < scratch.found.size(); ++c) contact_by_law<Parts>(pl, c);
  // About j's centre the levers are longer by xi - xj: one cross product per pair, not per contact.
  totals.torque_j = -(totals.torque_i + (xi - partner.center(p.j)).cross(totals.force_i));
  totals.contacts = int(scratch.found.size());
  return true;
}

// The turns this thread's pair loops left since ContactEngine::forces zeroed it (a trailing walk):
// a body that turns takes its turn between its kicks, so no pass moves it behind the walk (ChunkTrail).
inline thread_local std::uint32_t turns_left_here = 0;

// Pair p's PairTurn from its pushing sub-contacts' moments (the law's), appended to `turns`.
template <class Partner>
[[gnu::noinline]] void leave_turn(const BodyView& bodies, const Partner& partner, const PartnerSide<Partner>& b,
                                  BodyPair p, const PairScratch& scratch, std::vector<PairTurn>& turns) {
  ++turns_left_here;
  const Vec3 xi = bodies.position[p.i], xj = partner.center(p.j);  // m
  PairTurn turn{p.i, p.j, partner.shape(b) == nullptr, Vec3::Zero(), Vec3::Zero()};
  for (std::size_t c = 0; c < scratch.found.size(); ++c) {
    if (!scratch.pushing[c]) continue;
    const ContactPoint& g = scratch.found[c].geometry;
    const Vec3 impulse_moment = scratch.patch_push[c].moment * g.normal;  // N s^2, on i
    turn.moment_i += (g.point - xi).cross(impulse_moment);
    turn.moment_j -= (g.point - xj).cross(impulse_moment);
  }
#pragma omp critical(polydem_pair_turns)
  turns.push_back(turn);
}

// Pair k's forces, torques and energy in `totals`; true. With `lone` (kLone), false where the
// pair's one sub-contact waits there for the lanes' law instead (apply_law).
template <class Parts, bool kLone, int kLanes = 2, class Partner>
[[gnu::always_inline]] inline bool pair_forces_into(const LawParams& law, double band, double dt,
                                                    const BodyView& bodies, const Partner& partner, PairList& list,
                                                    std::uint32_t k, PairScratch& scratch, PairTotals& totals,
                                                    LonePair* lone) {
  const BodyPair p = list.pairs[k];
  if (k + 1 < list.size()) partner.prefetch(list.pairs[k + 1].j);
  const int was_touching = list.touching[k];
  if (!was_touching && partner.apart(list, k, band)) return true;  // most listed pairs, at a glance
  if constexpr (Partner::kMadeVertices) made_walk(scratch.made);  // posed_of and pose_of_i read it unchecked
  const PosedBody& a = Partner::kMadeVertices
                           ? pose_of_i(bodies.posed, p.i, bodies.boxes, *scratch.made)
                           : bodies.posed[p.i];
  decltype(auto) b = partner.posed_of(p.j, scratch);  // a body's pose (a reference) or a driver's index
  if (!was_touching && partner.separated(a, b, band)) return true;
  find_contacts(band, a, b, partner, list, k, scratch);
  const double r_star = Parts::Normal::kCurved ? partner.r_star(a.radius, b) : 0.0;  // m
  const bool changed = (was_touching || !scratch.found.empty()) && !same_contacts(list, was_touching, scratch.found);
  if (changed)
    totals.energy = hand_over_history(list, list.slot_begin[k], list.slot_begin[k + 1], was_touching,
                                      scratch.found, scratch.now_on, &law, r_star);
  if (scratch.found.empty()) return true;
  const bool regions = scratch.found.size() > 1 && !(a.shape->convex && partner.convex(b));
  if (regions)
    region_patch_weights(
        scratch.found.size(), [&](std::size_t c) { return list.features[scratch.found[c].slot]; },
        [&](std::size_t c) { return scratch.found[c].geometry.gap; }, *a.shape, partner.shape(b), band,
        scratch.weight, scratch.region);
  else
    patch_weights(scratch.found, band, scratch.weight);
  if (law.contact_mass && scratch.found.size() > 1)
    patch_dashpot_masses(a, bodies.mass[p.i], bodies.position[p.i], partner, b, p.j, regions, scratch);
  scratch.onsets = scratch.pushes = false;
  if (changed && scratch.found.size() > 1) {
    patch_onsets(regions, scratch);
    if (band == 0.0) {
      const RigidMotion mj = partner.motion(p.j);
      const Vec3& xi = bodies.position[p.i];
      patch_pushes(xi, bodies.velocity[p.i] - mj.at(xi), bodies.angular_velocity[p.i] - mj.angular_velocity, regions,
                   dt, scratch);
    }
  }
  if (!apply_law<Parts, kLone, kLanes>(law, dt, bodies, partner, list, k, scratch, r_star, a, b, totals, lone))
    return false;
  if (scratch.pushes && bodies.turns) [[unlikely]] leave_turn(bodies, partner, b, p, scratch, *bodies.turns);
  return true;
}

template <class Parts, int kLanes = 2, class Partner>
PairTotals pair_forces(const LawParams& law, double band, double dt, const BodyView& bodies,
                       const Partner& partner, PairList& list, std::uint32_t k, PairScratch& scratch) {
  PairTotals totals;
  pair_forces_into<Parts, false, kLanes>(law, band, dt, bodies, partner, list, k, scratch, totals, nullptr);
  return totals;
}

}  // namespace polydem
