#pragma once
// The contact stage of a step: poses the bodies, keeps the Verlet lists (rebuilt when two bodies
// may have closed the skin between them), evaluates every pair in parallel and sums the forces on
// each body in a fixed order, so results do not depend on the thread count.
#include <optional>
#include <vector>

#include "driver/drivers.hpp"
#include "geometry/box_pose.hpp"
#include "polydem/parallel.hpp"
#include "polydem/shape.hpp"
#include "contact/body_pose.hpp"
#include "contact/candidate_memory.hpp"
#include "contact/contact_lists.hpp"
#include "contact/exact_sum.hpp"
#include "contact/local_bodies.hpp"
#include "contact/pair_kernel.hpp"
#include "contact/pair_split.hpp"

namespace polydem {

struct ContactSettings {
  LawParams particle;       // `config`
  LawParams driver;         // `config_driver`
  double skin = 0.0;        // m, Verlet skin
  // A rank's share of a distributed run (sim/rank_contacts.hpp): the sphere fast path as
  // chosen for the whole scene (1 or 0; -1: for the bodies given).
  int spheres_only = -1;
  bool equal_spheres = true;  // false: each sphere's radius and mass read even when all are alike (tests)
  // A box's world vertices: made where the walk reads them (1, made_pose.hpp) or stored by each
  // step's pose pass (0); -1: made from kMadeVerticesBodies bodies (the same bits either way).
  int made_vertices = -1;
  // Rebuild when the two largest motions since the build could close the skin between two bodies
  // (RebuildTrigger::pair_exceeded), not as soon as one body moved skin/2. false: skin/2 each
  // (and no per-body skins).
  bool pair_trigger = true;
  // m, the largest skin a body may get. Above `skin` (and with pair_trigger, and some body not a
  // sphere), each rebuild gives each body its own skin s_i: what it moves in kSkinSteps steps at its
  // speed then, times 2, clamped to [skin, skin_max] (set_step gives the step). Pairs are listed
  // within range + (s_i + s_j) / 2, a body and a driver within range + s_i.
  double skin_max = 0.0;
};

// Bodies from which a box's world vertices are made where read (ContactSettings::made_vertices):
// a step streams ~2 KB a cube (34 lines at 216,000, README "The bytes a cube-step streams"), so
// from ~16,000 cubes the stored vertices leave a 32 MB last level before the walk reads them.
// Counted (cachegrind's Ir + 10 L1 + 100 LL a cube-step, made / stored): 13,500 cubes +5.9%, 30,375 -6.7%,
// 54,000 -5.8% (README "The made corners' cost and threshold").
constexpr std::size_t kMadeVerticesBodies = 16384;
// Steps a body's own skin lasts at its speed at the rebuild (ContactSettings::skin_max): the pour
// counted at 20, 30 and 50 (README, "A skin per body").
constexpr double kSkinSteps = 30.0;
// skin_max over the skin where the scene gives none: the pours counted at 4 (box-fill -8.3%, the
// cubes pour -17.9% instructions), a settled pile +0.07% (README, "A skin per body").
constexpr double kSkinMaxFactor = 4.0;
// Whether lists give each body its own skin (ContactEngine::choose_skins): the pair trigger, a
// skin_max above the skin, and some body not a sphere (a rank's ghost halo holds skin_max then).
inline bool per_body_skins(const ContactSettings& s, bool spheres_only) {
  return s.pair_trigger && s.skin_max > s.skin && !spheres_only;
}

// Over this process's lists: a pair across a cut between processes is listed by both.
struct ContactStats {
  std::size_t rebuilds = 0;
  std::size_t body_pairs = 0, driver_pairs = 0;   // in the Verlet lists
  std::size_t slots = 0;                          // candidate feature pairs
  std::size_t contacts = 0;                       // active sub-contacts this step
  std::size_t broad_tests = 0;    // bounding-sphere tests of the broad phase, all rebuilds
  std::size_t broad_levels = 0;   // size classes (cell grids) of the last rebuild
  std::size_t broad_bytes = 0;    // held by the broad phase's cells, largest seen
};

// Adds the pairs' forces and torques on a body to its force and torque (N, N m): its body
// pairs' sum made in their loop and its late terms after (pair order, DirectSums), then its driver pairs in list order
// (the same bits for any thread count). Called per body from the closing
// kick's pass (Simulation::step), which copies it into each thread's loop: the lists'
// addresses then stay in registers.
struct ForceSums {
  BodySum* body;                      // per body, cleared once read (DirectSums::zero)
  LateTerms late;                     // per body, its pairs after its sum's chunk
  const std::uint32_t* driver_begin;  // per body, its driver pairs [driver_begin[b], driver_begin[b + 1])
  const std::uint16_t* touching;      // per driver pair
  const Vec3 *force_i, *torque_i;     // per driver pair
  Vec3* force;
  Vec3* torque;
  // kg, per body. Set: the closing first makes force = m gravity and torque = 0, which a pass
  // of close_and_start_step<true> (nothing but gravity acts) did not keep.
  const double* gravity_mass = nullptr;
  Vec3 gravity = Vec3::Zero();  // m/s^2
  [[gnu::always_inline]] void operator()(std::size_t b) const {
    if (gravity_mass) force[b] = gravity_mass[b] * gravity, torque[b].setZero();
    add_to(b, force[b], torque[b]);
  }
  // Body b's sum (its pairs', then its touching driver pairs') added to f_to and t_to (N, N m).
  // kLate false: b has no late term (every pair of it in its home chunk), `late` is not read.
  template <bool kLate = true>
  [[gnu::always_inline]] void add_to(std::size_t b, Vec3& f_to, Vec3& t_to) const {
    Vec3 f = body[b].force, t = body[b].torque;
    body[b] = BodySum{};
    if constexpr (kLate) late.add_to(b, f, t);
    for (std::uint32_t k = driver_begin[b]; k < driver_begin[b + 1]; ++k) {
      if (!touching[k]) continue;
      f += force_i[k];
      t += torque_i[k];
    }
    f_to += f;
    t_to += t;
  }
};

class ContactEngine {
 public:
  // `was` (a rank's rebuild: its engine of the bodies before, null otherwise) lends its poses'
  // storage, so only the bodies past its count are cleared: a rebuild poses every listed body
  // before any read (new engine: ~128 bytes a body written, ~30% of a rank's adopt).
  ContactEngine(const std::vector<Shape>& shapes, const LocalBodies& bodies, ContactSettings settings,
                ContactEngine* was = nullptr);

  // Adds the contact forces and torques of this step to the owned bodies' force / torque and
  // the reactions to the drivers; rebuilds the lists first when lists_stale says so.
  void compute(const LocalBodies& bodies, Drivers& drivers, double dt) { compute(bodies, drivers, dt, lists_stale(bodies, drivers)); }
  // The same with the rebuild decided by the caller (many processes: any process's `lists_stale`).
  void compute(const LocalBodies& bodies, Drivers& drivers, double dt, bool rebuild);
  // True when two local bodies (or a body and a driver) may have closed the skin between them
  // since the lists were built (skin/2 a body for a rank's lists), or a rebuild was forced. Once per step: it measures each body's
  // displacement, which the pair loop's skip test reads (`watched`: measure_motion's).
  bool lists_stale(const LocalBodies& bodies, const Drivers& drivers, bool watched = false);
  // A rank's share of a decision over all ranks (sim/rank_contacts.hpp): measures every local
  // body as lists_stale does, then answers for its owned bodies alone (RebuildTrigger::margins,
  // `alone` set too where a rebuild is due here); the ranks' answers join in pair_rule_exceeded.
  // Spheres alone (points) answer `past` when one moved skin/2 and give their margins (`exact`)
  // only once a step since the rebuild read the pair rule (pair_rule_read: then kept in the pass,
  // as one process's), else owned_point_margins on the step that asks (RuleVerdict::measure).
  // Polyhedra: the margins come from the measure's own pass (RebuildTrigger::take_margins);
  // `ghosts_later`: the ghosts are a step old and measured once landed (remeasure), so left out.
  PairMargins owned_margins(const LocalBodies& bodies, const Drivers& drivers, bool watched = false,
                            bool ghosts_later = false);
  // Points' margins of the owned bodies at their positions now, measured (a serial loop: the step
  // whose verdict asks for them); pair_rule_read: the next steps' are kept in the pass until the
  // rebuild, as one process's once it read the rule.
  PairMargins owned_point_margins(const LocalBodies& bodies, const Drivers& drivers) const;
  void pair_rule_read() { margins_read_ = settings_.pair_trigger; }
  // The same in stages, for a step run as one parallel region (parallel.hpp): every thread of
  // the team calls measure_motion, then one thread outside the region stale_after_measure
  // (true as lists_stale would be), then rebuild when stale, then every thread forces.
  // `watched`: the pass that moved the bodies ran the trigger's test (watch_motion), so only the poses.
  // `owned`: a rank's part (RebuildTrigger::measure).
  void measure_motion(const LocalBodies& bodies, bool watched = false, const OwnedPart* owned = nullptr);
  // Polyhedra's poses for this step's forces, by every thread of the team after measure_motion,
  // each its share of the cut (the bodies its opening pass moved), with no barrier: the region's
  // end is the one forces(..., pose_bodies false) needs. A rebuild then poses its newly listed bodies.
  void pose_before_forces(const LocalBodies& bodies) {
    if (!spheres_only_) pose(bodies, listed_, false);
  }
  // A rank's poses of the lists' bodies in two parts around its ghost exchange, outside any
  // region: `some` (increasing, of listed()) its owned bodies while the parcels travel, then its
  // landed ghosts; forces(..., pose_bodies false) follows. Spheres are posed by measure_motion.
  void pose_listed(const LocalBodies& bodies, const std::vector<std::uint32_t>& some) {
    if (!spheres_only_) pose(bodies, some);
  }
  const std::vector<std::uint32_t>& listed() const { return listed_; }  // the bodies of some pair, increasing
  // The listed bodies' poses for a pass that moves them (the next step's, behind the walk: TrailingPass),
  // as pose_before_forces makes them; valid until the next rebuild.
  ListedPoses listed_poses(const LocalBodies& bodies);
  // True, with `watch` set, where the trigger's test of every local body can run in the pass
  // that moves them (points: spheres' lists), instead of measure_motion's own read of the positions.
  // Once a step read the pair rule, the next steps' measure_motion keeps the points' margins for
  // it (RebuildTrigger::keep_point_margins: on the team, not a serial loop after the region).
  bool watch_motion(const LocalBodies& bodies, PointWatch& watch) {
    const bool watched = trigger_.watch_points(bodies.position->size(), settings_.skin, watch);
    keep_margins_ = watched && margins_read_;
    return watched;
  }
  // The same for polyhedra (not spheres' lists): true, with `watch` set, where the pass that moves
  // the bodies can make measure's bounds; measure_motion(bodies, true) then skips its own.
  bool watch_bounds(const LocalBodies& bodies, BoundWatch& watch) {
    return !spheres_only_ && trigger_.watch_bounds(*bodies.orientation, core_reach_, settings_.skin, watch);
  }
  // measure_motion's poses and bounds again for the bodies `some` alone, their answer left out:
  // a rank's ghosts, landed after its measure of all, which their owners' measures answered for.
  void remeasure(const LocalBodies& bodies, const std::vector<std::uint32_t>& some);
  bool stale_after_measure(const LocalBodies& bodies, const Drivers& drivers);
  // Outside any region: it opens its own. `listed_posed`: pose_before_forces posed the last
  // lists' bodies at these positions this step, so only the newly listed bodies are posed here.
  void rebuild(const LocalBodies& bodies, const Drivers& drivers, bool listed_posed = false);
  // What follows forces() in its parallel region: it ends at a barrier only before a read of the sums.
  enum class AfterPairs {
    sum_bodies,   // forces() adds every body's sum to its force and torque (reduce_bodies)
    read_sums,    // the caller calls force_sums(bodies)(b) for every owned body (a closing kick)
    region_ends,  // nothing before the region's end (which the sums' reader follows)
  };
  // The pairs' forces (a team stage, on every thread of the region); then, after the region,
  // close_forces on one thread. `pose_bodies`: false right after a rebuild (it posed them) or
  // after pose_before_forces; spheres are posed by measure_motion, which must come first.
  // `trail` (one process): a pass right behind the body pairs' walk (WalkTrail).
  void forces(const LocalBodies& bodies, Drivers& drivers, double dt, bool pose_bodies, AfterPairs then,
              const WalkTrail* trail = nullptr);
  bool spheres_only() const { return spheres_only_; }
  // After forces()' region, on one thread: the drivers' reactions, the step's contact count and
  // the ended contacts' energy (~23k instructions a bed step: no barrier inside the region for them).
  void close_forces(const LocalBodies& bodies, Drivers& drivers);
  // sums(b) adds the pairs' forces and torques on owned body b to its force and torque, in the
  // fixed order of its pairs (the same bits for any thread count); `sums` holds the lists'
  // addresses, for a loop over the bodies that keeps them in registers (integrate.hpp's kick_after).
  ForceSums force_sums(const LocalBodies& bodies);
  // Every body's sum was taken by force_sums (each cleared): the next loop starts from them.
  void sums_taken() { direct_.taken(); }
  // The bodies' cut of the body pairs' loop (pair_split.hpp), for the step's passes over bodies:
  // each thread then moves the bodies of its chunk's pairs as i. None before the first rebuild.
  TeamCut body_cut() const { return {direct_.split.body_cut.data(), direct_.split.threads}; }
  // Per body, its passes' instructions a step (kicks and drift by rotor: pass_weights), for pass_cut.
  void weigh_passes(std::vector<float> instructions) { pass_weight_ = std::move(instructions); }
  // The next step's joined pass runs behind the walk on most steps (TrailingPass): the walk's cut
  // weighs each body's pass and driver pairs where they run (weigh_bodies). From the next rebuild.
  void trail_walks(bool on) { trailed_ = on; }
  // The cut of the step's first region (kicks, drift, the rebuild check, the poses; each thread
  // reads only the bodies it moved): the walk's body cut, or one of its own where that leaves a
  // thread far above an even share of those passes (a pour: the falling bodies have no pairs, so
  // all of them go to the last chunk), folded on the walk's where it can be (TeamCut::folded: each
  // thread still moves the bodies it walks). Set at each rebuild (cut_passes).
  TeamCut pass_cut() const { return own_pass_cut_ ? TeamCut{pass_cut_.data(), pass_threads_, pass_folded_} : body_cut(); }
  // The body pairs' loop cut from the next step on with these shares of its work (per thread,
  // summing to 1), kept instead of following the threads' pace: no result may change (tests).
  void fix_shares(std::vector<double> shares) {
    direct_.shares = std::move(shares);
    direct_.follow_pace = false;
    direct_.split.threads = 0;
  }
  // Drops the lists so the next compute() rebuilds them (checkpoints rebuild at the same step
  // in an uninterrupted and in a resumed run).
  void force_rebuild() { must_rebuild_ = true; }
  // Whether the coming steps keep each active contact's point and forces (PairList::records),
  // which contact output and checkpoints read: on by default; the run loop turns it off for
  // steps after which nothing is written (a sphere list's 56 bytes a slot, a sparse list's 32 a
  // state saved between output steps; a sparse list keeps its points for the hand-over).
  void record_contacts(bool on) {
    record_contacts_ = on;
    // A dense list read from a checkpoint or table keeps its records for the rebuild to carry.
    if (spheres_only_ || body_list_.sparse) body_list_.set_recording(on);
    if (driver_list_.sparse) driver_list_.set_recording(on);
  }
  bool records_contacts() const { return record_contacts_; }
  // Whether close_forces sums the drivers' reactions (pair order, on one thread: ~24k
  // instructions a sphere bed step): on by default; the run loop turns it off for steps after
  // which nothing reads them (fixed drivers: no servo, no driver work). The drivers then keep
  // their last reactions, as a rank's do (RankContacts::want_reactions).
  void want_reactions(bool on) { reactions_wanted_ = on; }

  // The turns the pair loops left this step (PairTurn, pair_kernel.hpp: rare, where a patch's
  // shares moved within the step), summed per owned body over its pairs in the order of their
  // local indices (global id order: any decomposition's and thread count's bits), then cleared.
  std::vector<BodyTurn> take_turns(const std::vector<std::uint8_t>* ghost);
  bool turns_left() const { return !turns_.empty(); }

  const ContactStats& stats() const { return stats_; }
  double skin() const { return settings_.skin; }  // m
  // s, the step: each body's own skin covers its motion over kSkinSteps of them (skin_max).
  void set_step(double dt) { skin_time_ = kSkinSteps * dt; }
  // m, per body, the skins of the last rebuild; empty: the scene's skin for every body.
  const std::vector<double>& body_skins() const { return skin_; }
  // The energy ledger's share of the contacts (J, by mechanism): each pair sums its own in
  // PairList::pending, in step order, carried through rebuilds with its history; when its
  // contact ends (the step's flagged blocks) it enters an exact sum (contact/exact_sum.hpp),
  // `flushed`, and is zeroed. flush_energy adds every pair's to it, take_energy flushes and
  // hands the sum over (Simulation's ledger, every kLedgerSteps steps), open_energy reads what
  // take_energy would hand over, changing nothing. `ghost` (per local body; null: none): the
  // pairs whose lower body is a ghost, another rank's to count, left out.
  void flush_energy(const std::vector<std::uint8_t>* ghost);
  ExactEnergy take_energy(const std::vector<std::uint8_t>* ghost);
  ExactEnergy open_energy(const std::vector<std::uint8_t>* ghost) const;
  // The ended contacts' sum alone (the pairs keep theirs: a rank's rebuild, a checkpoint).
  ExactEnergy& flushed() { return flushed_; }
  const ExactEnergy& flushed() const { return flushed_; }
  // A body's work against its torque in a join step's turn (J, integrate/turn_table.hpp): patch
  // work, which the net dissipation counts negative.
  void book_turn(double work) { flushed_.add(EnergyParts{-work, 0.0, 0.0, work}); }
  // J, stored in the springs of the active contacts now (from their histories: output steps
  // only), over this process's lists, summed exactly (any split over ranks gives one sum);
  // `ghost` as above.
  ExactStored elastic(const Drivers& drivers, const std::vector<std::uint8_t>* ghost = nullptr) const;
  const PairList& body_pairs() const { return body_list_; }
  const PairList& driver_pairs() const { return driver_list_; }
  PairList& body_pairs() { return body_list_; }
  PairList& driver_pairs() { return driver_list_; }
  // The body pairs' last searches: a rank hands them to the engine of its next bodies (relabelled).
  CandidateMemory& searches() { return memory_; }

 private:
  // The bodies `some` (increasing: listed_ or some of it), each thread its share of the cut.
  // `wait`: a barrier at its end; min_items: the bodies that pay for waking a team outside one;
  // `box_vertices`: a box's world vertices stored too (a rebuild), else made where read (made_pose.hpp)
  void pose(const LocalBodies& bodies, const std::vector<std::uint32_t>& some, bool wait = true,
            std::size_t min_items = kParallelMinItems, bool box_vertices = false);
  void keep_sphere_poses(const LocalBodies& bodies, bool needed);
  void measure_in_team(const LocalBodies& bodies, bool watched, const OwnedPart* owned = nullptr);  // measure_motion in a team of its own, or the caller's
  // A sphere's pose, made where read: its one vertex, at the shape's origin, is its centre.
  PosedBody sphere_pose(const LocalBodies& bodies, std::size_t b) const {
    const Vec3& x = (*bodies.position)[b];
    return {&shapes_[(*bodies.shape)[b]], &x, Mat3::Identity(), x, radius_[b], (*bodies.scale)[b]};
  }
  // Every body the same radius and mass (spheres: the kernel then reads neither per pair), or none.
  std::optional<EqualSpheres> equal_spheres(const LocalBodies& bodies) const;
  void mark_listed(std::size_t n_bodies, const std::vector<BodyPair>& body_pairs, const std::vector<BodyPair>& driver_pairs);
  void reduce_bodies(const LocalBodies& bodies);
#ifdef POLYDEM_LINE_AUDIT
  void name_arrays(const LocalBodies& bodies) const;
#endif
  void reduce_drivers(Drivers& drivers) const;
  bool lists_past_skin(const LocalBodies& bodies, const Drivers& drivers);  // stale_after_measure's answer
  void add_totals();
  void flush_pair(PairList& list, std::size_t k, const std::vector<std::uint8_t>* ghost);
  void flush_pairs(PairList& list, const std::vector<std::uint32_t>& pairs, const std::vector<std::uint8_t>* ghost);
  void flush_ended(const std::vector<std::uint8_t>* ghost);
  void flush_idle(PairList& list, const std::vector<std::uint8_t>* ghost);  // pairs with no active slot
  // Body-driver pairs within each body's skin plus the driver band; marks the drivers (driver_shift).
  std::vector<BodyPair> near_drivers(const LocalBodies& bodies, const Drivers& drivers);
  // A rebuild's two lists, made at once on a team of two (two_tasks): each writes only its own.
  void close_body_list(const LocalBodies& bodies, PairList& old_body, PairList fresh, int team);
  std::vector<std::uint32_t> make_driver_list(const LocalBodies& bodies, const Drivers& drivers, PairList fresh,
                                              const PairList& old_driver, bool share_candidates);
  void weigh_bodies(bool passes);  // direct_.body_weight, at a rebuild
  // A team stage, no barrier; `by_bodies`: each thread its bodies' pairs (trail_driver_range's), polyhedra's too.
  void driver_pair_forces(const BodyView& view, Drivers& drivers, double dt, bool by_bodies = false);
  void trail_driver_range(const WalkTrail& trail) const;
  void cut_passes(int threads);  // pass_cut, at a rebuild (after the walk's cut and listed_)
  double driver_shift(const Drivers& drivers) const;  // m, the largest driver motion since the build
  // skin_, at a rebuild: each body's own skin from its speed, or none (skin_max not above skin,
  // or every body at the scene's skin).
  void choose_skins(const LocalBodies& bodies);
  double skin_of(std::size_t b) const { return skin_.empty() ? settings_.skin : skin_[b]; }  // m

  const std::vector<Shape>& shapes_;
  ContactSettings settings_;
  double band_particle_, band_driver_;    // m, interaction band beyond touching (cohesion)
  std::vector<std::uint32_t> vertex_offset_;
  std::vector<std::optional<BoxCorners>> boxes_;  // per shape: its corners when it is a box (posed by pose_box)
  std::vector<Vec3> world_vertices_;
  std::vector<PosedBody> posed_;           // spheres: empty unless keep_sphere_poses keeps them
  std::vector<std::uint32_t> listed_;      // bodies in some pair: the only ones posed each step
  std::vector<double> bounding_;           // m, scaled bounding radius per body
  // m, per body, the farthest core point from the centre: gaps are core distances less the
  // radii, so turning moves no feature farther than this times the chord (0 for a sphere).
  std::vector<double> core_reach_;
  std::vector<double> radius_;             // m, scaled Minkowski radius per body
  std::vector<double> skin_;               // m, per body, from choose_skins; empty: settings_.skin each
  double skin_time_ = 0.0;                 // s, set_step
  CellList cells_;
  CandidateMemory memory_;                 // the body pairs' last searches (not for spheres only)
  RebuildTrigger trigger_;
  bool must_rebuild_ = true;
  bool spheres_only_ = false;              // every body a sphere: the sphere fast path
  bool any_sphere_ = true;                 // some body is a sphere (BodyView::any_sphere)
  bool made_vertices_ = false;             // a step's poses leave a box's vertices unmade (made_pose.hpp)
  bool boxes_only_ = false;                // every body a box: a made walk asks no body's shape (ShapeBoxes::all_boxes)
  bool alike_ = false;                     // every body body 0's shape, scale and mass (ShapeBoxes::body_mask)
  // Every body a box a made walk makes: the pass behind the walk would leave each pose as it was
  // (pose_body), so it reads none of the listed bodies' indices and shapes (8 bytes a cube-step, issue 19).
  bool unposed_boxes() const { return boxes_only_ && made_vertices_; }
  std::optional<EqualSpheres> equal_spheres_;  // spheres only, all alike (set at rebuilds): the body list has no linear_steps
  bool record_contacts_ = true;            // the lists keep their records (record_contacts)
  bool reactions_wanted_ = true;           // close_forces sums the drivers' reactions (want_reactions)
  bool margins_read_ = false;              // a step since the last rebuild read the pair rule (watch_motion)
  // owned_margins' part for points: measured where margins_read_, else `past` alone.
  PairMargins point_part(const LocalBodies& bodies, double shift, bool past_half);
  bool keep_margins_ = false;              // this step's measure_motion keeps the points' margins
  // Spheres: some listed driver pair is not a wall, so the general driver path reads their poses
  // each step (set at rebuilds; the sphere and sphere-wall kernels read the centres themselves;
  // false before the first, which needs none: keep_sphere_poses sizes posed_ there).
  bool spheres_posed_each_step_ = false;
  PairList body_list_, driver_list_;
  // Each driver's placement and whether it was active when the lists were built: all the
  // rebuild trigger compares (no names, shapes or meshes copied at a rebuild).
  struct DriverAtBuild {
    Placement placement;
    bool active;
  };
  std::vector<DriverAtBuild> drivers_at_build_;
  double driver_lever_ = 0.0;              // m, farthest body surface from any driver reference point
  std::vector<std::uint32_t> driver_begin_;  // per body + 1: its driver pairs (pairs_by_body)
  DirectSums direct_;                      // the body pairs' sums, made by their loop
  std::vector<float> pass_weight_;         // per body, its passes' instructions a step (weigh_passes)
  std::vector<std::uint32_t> pass_cut_;    // pass_threads_ + 1 bodies (pass_cut), when own_pass_cut_; folded: 2 pass_threads_ + 1
  int pass_threads_ = 0;
  bool pass_folded_ = false;               // pass_cut_ is folded on the walk's (fold_cut)
  bool own_pass_cut_ = false;
  bool trailed_ = false;                   // trail_walks
  ContactStats stats_;
  ExactEnergy flushed_;                    // J, the pending energies flushed since the last take_energy
  std::vector<PairTurn> turns_;            // left by this step's pair loops, in no set order (take_turns)
};

inline ForceSums ContactEngine::force_sums(const LocalBodies& bodies) {
  return {direct_.sums.data(),          direct_.late_terms(),        driver_begin_.data(),        driver_list_.touching.data(),
          driver_list_.force_i.data(), driver_list_.torque_i.data(), bodies.force->data(),
          bodies.torque->data()};
}

}  // namespace polydem
