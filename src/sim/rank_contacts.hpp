#pragma once
// The contact stage of a distributed run (issue 20): each rank integrates the bodies it owns
// (their centres in its box of a recursive bisection weighted by each body's measured contact
// work, cut again at a rebuild that finds the load unbalanced: sim/domain_cut.hpp) and computes their pairs with ghosts within reach, in global id order, so each body's force
// sum is the one of one process. Between rebuilds the ghosts' velocities (and orientations,
// when bodies turn) come point to point from their owners (sim/ghost_plan.hpp), each rank
// drifting its ghosts' positions as their owners do (sim/body_exchange.hpp), their parcels carrying each rank's word for the
// step's decision (its requests and its owned bodies' pair-rule margins: one process's rebuild
// steps) when every rank is every other's neighbour (else one gather a step decides); a gather shares the drivers' reactions (summed in the one-process
// pair order) at the steps that read them; the contact count and the energy ledger's exact
// sums are reduced only at output rows and when the ledger closes (sim/rank_energy.hpp). At a rebuild each rank sends the owned bodies that
// change owner, with the histories of their pairs, to their new owners, then its owned bodies
// to the ranks that hold them as ghosts, point to point (sim/rank_migration.hpp); a cut again
// reads the loads summed over the ranks and a sample of the centres. A rank integrates its owned
// bodies in its LocalStore (one copy of their state), and a rebuild after the first sends and
// lands bodies store to store; it keeps the constants of all bodies, and their state only where a
// gather writes it (sync_bodies: the start and a one-file resume; rank 0 at output with probes or
// fluid); a resume of pieces lands each rank's share in its store (land, sim/rank_landing.hpp).
// Drag and fluid forces act on each rank's owned bodies in its store (add_external).
#include <functional>
#include <memory>
#include <vector>

#include "contact/contact_engine.hpp"
#include "field/external_forces.hpp"
#include "integrate/integrate.hpp"
#include "integrate/turn_table.hpp"
#include "sim/body_exchange.hpp"
#include "sim/contact_table.hpp"
#include "sim/domain_cut.hpp"
#include "sim/ghost_plan.hpp"
#include "sim/local_store.hpp"
#include "sim/rank_energy.hpp"
#include "sim/rank_landing.hpp"
#include "sim/rank_link.hpp"
#include "sim/state_energy.hpp"

namespace polydem {

// A driver pair's reaction, for the sum in the one-process pair order (body, then driver).
struct ReactionShare {
  std::uint32_t i, j;
  double force_i[3], torque_j[3];  // N on body i, N m on driver j
};

// Sets each driver's reaction from every rank's touching driver pairs, in one-process order.
void add_reactions(std::vector<ReactionShare> all, Drivers& drivers);

class RankContacts {
 public:
  RankContacts(const RankLink& link, const std::vector<Shape>& shapes, const Bodies& bodies, ContactSettings settings);

  // The contact forces and torques of this step, left in the lists for owned_sums, and the
  // drivers' reactions, on every rank (a collective). `whole`: the engine over all bodies,
  // whose lists hold the table of histories (read at a forced rebuild, written by
  // gather_table).
  void compute(Bodies& bodies, Drivers& drivers, double dt, ContactEngine& whole);
  // The passes over the owned bodies, in the store (its one copy of their state): a step's
  // opening (start: integrate.hpp's start_step), its closing kick with their contact sums
  // (after compute), alone (kick_closing) or joined to the next step's opening pass
  // (close_and_start); called by every thread of a team; then sums_taken(), which clears the
  // ghosts' sums too, so the next pair loop starts from zeros. Here, not in Simulation's unit:
  // beside one process's passes there, GCC outlined an Eigen += of the cubes' opening pass
  // (+0.6% a step).
  void start(double h, double dt, const Vec3& gravity);
  void kick_closing(double h);
  // `watch`: from watch_motion, the pass runs the rebuild trigger's test on each owned body it
  // moves (the step's measure then only poses).
  void close_and_start(double h, double dt, const Vec3& gravity, const PointWatch* watch = nullptr);
  // Nothing but m gravity (m/s^2) and the contacts acts (no drag or fluid force): the joined
  // pass makes each owned body's force in registers (close_and_start_step<true>), as one process's.
  void only_gravity(const Vec3& gravity) {
    gravity_only_ = true;
    gravity_ = gravity;
  }
  // True, with `watch` set, where this step's joined pass can run the trigger's test on the
  // owned bodies (points: spheres' lists; a ghost's owner answers for it). Outside any team.
  bool watch_motion(PointWatch& watch);
  void sums_taken();
  // After a closing kick: turns the owned bodies as this rank's pair loops asked (ContactEngine::
  // take_turns, integrate/turn_table.hpp's turn_bodies), its work booked with the ended contacts' energies;
  // the ghosts' copies turn with their owners' next motion parcel.
  void turn_owned();
  bool turns_left() const { return engine_ && engine_->turns_left(); }
  // The same where the kick was left open: keep_turns() before the next step's team, whose
  // close_and_start turns each body between its closing kick and its opening kick, then
  // book_kept_turns() after it.
  void keep_turns();
  void book_kept_turns();
  void add_sums();  // the same with no kick: each owned body's sum added to its force
  // Drag and fluid forces on the owned bodies, in the store; returns their power over every
  // rank (W), summed exactly (a collective: one sum of ExactSum::kWords words, no body sent).
  double add_external(ExternalForces& forces);
  // Whether the next steps share the drivers' reactions (the servo and the driver work of a
  // moving driver read them each step, output only at its rows); when not, only the contact
  // count, and the drivers keep their last reactions.
  void want_reactions(bool wanted) { reactions_wanted_ = wanted; }
  // The step's one collective ORs each rank's stop request (an interrupt) with the rebuild
  // decision; a step that sees one keeps the records and reactions a checkpoint reads.
  void ask_stop(bool asked) { stop_asked_ = asked; }
  bool stop_seen() const { return stop_seen_; }  // some rank asked before this step's collective
  // Rebuilds at the next step from `whole`'s lists and `bodies` (a checkpoint read: the table
  // and the state on every rank), the store taking its owned bodies' state from `bodies` now
  // (what reads the state before that step reads the store); where `bodies` holds no state
  // (dropped), the store is the current one and that step gathers it (sync_bodies).
  void force_rebuild(const Bodies& bodies) {
    forced_ = true;
    if (bodies.has_state()) store_.pull(bodies);
  }
  // A resume from checkpoint pieces (sim/checkpoint_pieces.hpp): this rank holds `share`, the
  // bodies and contacts of the pieces it read, as its owned bodies (its passes move them) until
  // the next step's contact stage cuts the domain from a sample of every rank's centres and
  // sends each body and slot to its owner (sim/rank_landing.hpp); the pieces' ended contacts
  // are this rank's open sum. Until then what a rank writes is `share` (output_bodies,
  // output_slots, output_flushed).
  void land(LandedShare share);
  // `bodies`' state arrays freed again where a rank keeps only the constants (after its first
  // cut), once what a gather gave rank 0 was read (output of probes and the fluid).
  void release_state(Bodies& bodies) const {
    if (engine_ || landed_) bodies.drop_state();
  }
  // Rebuilds at the next step from every rank's own lists, as a rebuild the motion asks for
  // (a checkpoint written: the table went to rank 0 only).
  void rebuild_next_step() { rebuild_asked_ = true; }
  // Gathers every rank's active slots into `whole`'s lists (global ids), on every rank or on
  // rank 0 only (`to_root`: checkpoints, output; the other ranks' `whole` is left alone).
  void gather_table(ContactEngine& whole, bool to_root = false) const;

  // Gives every rank (or rank 0 only, `to_root`) every body's state: each rank's owned
  // bodies, published and gathered (a collective: the start and a resume on every rank; output
  // of probes and the fluid on rank 0); `bodies`' state arrays grown back first where dropped,
  // on the ranks that receive.
  void sync_bodies(Bodies& bodies, bool to_root = false) const;
  // What this rank writes of the state (VTK pieces, checkpoint pieces): the bodies it owns in
  // increasing id and the active slots it answers for (its body pairs whose lower body it owns,
  // its driver pairs); before its first step (no cut yet), rank 0 every body and `whole`'s
  // lists (read from a checkpoint, or none), the other ranks nothing.
  std::vector<std::uint32_t> output_bodies() const;
  // Calls f(arrays, rows) with the rows of output_bodies() (in that order) in what holds their
  // state: after the first step the store (its owned bodies), before it `bodies`.
  template <class F>
  void with_output_rows(const Bodies& bodies, F&& f) const {
    if (engine_ || landed_) f(store_, store_.owned_rows());
    else f(bodies, output_bodies());
  }
  std::vector<TableSlot> output_slots(const ContactEngine& whole, bool driver) const;
  // The ended contacts' energies this rank holds since the ledger last closed (J; rank 0 alone
  // before its first step: `whole`'s), the rest of its share being its slots' pending energies.
  ExactEnergy output_flushed(const ContactEngine& whole) const;
  // The smallest id of an owned body whose state is not finite over all ranks, or -1 (a collective).
  long first_non_finite() const;
  long first_non_finite_owned() const;  // this rank's alone
  // This rank's lists (null before its first step) and their bodies (local ids).
  const ContactEngine* lists() const { return engine_.get(); }
  const LocalStore& store() const { return store_; }
  std::size_t owned() const { return plan_.owned.size(); }
  std::size_t ghosts() const { return plan_.local.size() - plan_.owned.size(); }

  // The ledger's contact energies of every rank's pairs since the last take (J; a collective):
  // ContactEngine::take_energy on each rank, summed exactly.
  EnergyParts take_energy();
  // A CSV row's energies over every rank (a collective): each rank's owned bodies and the
  // pairs it answers for, and what take_energy would return, changing nothing but contacts().
  StateEnergy state_energy(const Bodies& bodies, const Drivers& drivers);
  // The energies of the set-up's contact stage: not stepped, not counted (this rank's alone).
  void drop_energy();
  std::size_t contacts() const { return contacts_; }  // active sub-contacts, every rank's pairs, at the last state_energy
  std::size_t rebuilds() const { return rebuilds_; }
  std::size_t cuts() const { return cuts_; }          // rebuilds that cut the domain again
  double load_share() const { return load_share_; }   // this rank's share of the weight at the last rebuild
  const LinkCounts& rebuild_traffic() const { return rebuild_traffic_; }  // what the rebuilds sent, all told
  // The cut in time: from the next rebuild on, each rank's busy seconds between two rebuilds
  // (`busy`: seconds since some start, read at rebuilds) over the instructions its bodies' weights
  // counted then give its seconds an instruction (smoothed: kTimeSmoothing); its bodies weigh
  // their counted weights times that over the ranks' mean (time_scale, integers), so the next cut
  // balances time. The cut never changes a value: the bits hold. Unset: counted weights alone.
  void time_by(std::function<double()> busy) { busy_ = std::move(busy); }
  // The same from the process's CPU clock less the link's (RankLink::times: ghost waits, sums, gathers).
  void time_by_clock();
  double counted_done() const { return counted_done_; }  // instructions counted since time_by, read before busy
  double time_scale() const { return double(scale_) / double(kScaleOne); }  // at the last rebuild (1: none yet)
  // This rank's lists: pairs with an owned body and their candidate feature pairs.
  std::size_t pairs() const;
  std::size_t candidates() const;

  // Instructions a cut again costs the slower rank, a body of the scene (RecutRule): the gather and
  // cut of a sample point (~500) and the movers' parcels and new searches (a 5% shift moves ~2.5%
  // of the bodies at ~20,000 each); estimated from the pours' counted rebuilds.
  static constexpr double kCutCost = 1000.0;
  // Each interval's share in the smoothed seconds an instruction (the clock is noisy), and the
  // weights' scale in fixed point: 1 is kScaleOne, kept within 1/4 and 4.
  static constexpr double kTimeSmoothing = 0.25;
  static constexpr std::uint64_t kScaleOne = 1024;
  // Points of the sample a cut is made from, over all ranks (32 bytes each: 4 MB to each
  // rank at most) and at least per rank.
  static constexpr std::size_t kCutSample = std::size_t(1) << 17, kCutSampleRank = 64;

 private:
  using Requests = std::uint64_t;  // bit 0: rebuild, bit 1: stop
  // A rank's word in the step's decision: its requests and its owned bodies' pair-rule margins
  // (ContactEngine::owned_margins), which every rank joins alike (pair_rule_exceeded).
  struct Ask {
    Requests requests = 0;
    PairMargins margins;
    bool rebuild_here() const { return (requests & 1) || margins.alone; }
  };
  Ask ask_here(const Drivers& drivers, bool ghosts_later);
  bool lists_stale(const Drivers& drivers);
  bool exchange_ghosts(const Drivers& drivers, double dt);
  bool fold_asks(const Ask& mine, const Drivers& drivers);
  bool decide(const std::vector<Ask>& asks, const Drivers& drivers);
  bool measured_rule(const Drivers& drivers);
  void redistribute(Bodies& bodies, const ContactEngine& whole);
  void spread_landed();
  void migrate_bodies();
  std::vector<int> row_owners() const;
  long first_non_finite_position() const;
  void adopt(const PairList& body_table, const PairList& driver_table);
  void adopt_slots(const std::vector<TableSlot>& body, const std::vector<TableSlot>& driver);
  void new_engine();
  std::vector<std::uint64_t> owned_weights(const std::vector<std::uint32_t>& rows) const;  // rows: store_.owned_rows()
  std::vector<double> summed_loads(const std::vector<std::uint32_t>& rows, const std::vector<std::uint64_t>& w) const;
  void recut_if_unbalanced(const std::vector<std::uint32_t>& rows);
  void cut_from_sample(const std::vector<std::uint32_t>& rows, const std::vector<std::uint64_t>& w);
  std::vector<char> cut_sample(const std::vector<std::uint32_t>& rows, const std::vector<std::uint64_t>& w) const;
  void set_load_share(const std::vector<double>& loads);
  std::uint64_t measure_time(const std::vector<std::uint64_t>& w);
  void pack_parcels(const Ask& mine);
  void unpack_parcels(double dt);
  void split_listed();
  ForceSums closing_sums();
  void size_parcels();
  void narrow_parcels();
  void share_results(Drivers& drivers);
  std::vector<ReactionShare> reaction_shares() const;

  const RankLink& link_;
  const std::vector<Shape>& shapes_;
  ContactSettings settings_;
  std::size_t n_bodies_;
  double halo_;  // m, ghosts: bodies within this distance of the box
  DomainCut cut_;  // the ranks' boxes, kept while balanced
  RecutRule recut_;  // whether the kept cut's imbalance has cost more than a new cut
  std::size_t cuts_ = 0;
  std::size_t steps_listed_ = 0;  // steps since the last rebuild (the same on every rank)
  std::function<double()> busy_;  // s, time_by; empty: counted weights alone
  double busy_mark_ = -1.0;       // s, busy_ at the last rebuild (< 0: none)
  double counted_done_ = 0.0;     // instructions counted over the measured intervals
  double unit_ = 0.0;             // s an instruction, smoothed (0: none yet)
  std::uint64_t scale_ = kScaleOne;  // this rank's weights' factor at the last rebuild
  double load_share_ = 0.0;
  GhostPlan plan_;
  RotorGroups owned_rotors_;  // the owned bodies by rotation path, local indices
  TurnTable kept_turns_;      // the turns close_and_start applies (keep_turns), by local index
  std::unique_ptr<ContactEngine> engine_;
  LocalStore store_;
  MotionFields motion_;  // what the motion parcels carry (body_exchange.hpp)
  std::vector<Parcel> out_, in_;  // the ghost exchange's, sized to plan_
  std::vector<std::vector<std::uint32_t>> send_local_, receive_local_;  // per parcel of out_, in_: its bodies' local indices
  std::vector<std::vector<Vec3>> drifted_;  // m, per parcel of in_: its bodies' positions at the last step
  std::vector<std::uint32_t> paired_ghosts_;  // the ghosts some listed pair reads, local indices (narrow_parcels)
  std::vector<std::uint32_t> owned_listed_, ghost_listed_;  // the lists' bodies (ContactEngine::listed), owned and ghosts
  bool gravity_only_ = false;  // only_gravity
  Vec3 gravity_ = Vec3::Zero();  // m/s^2
  bool watched_ = false;  // this step's opening pass ran the trigger's test (watch_motion)
  bool fold_ = false;  // the ghost parcels carry the step's requests: no reduction a step
  bool forced_ = true;
  bool landed_ = false;  // land: the store holds a resume's share, cut at the next step
  std::vector<TableSlot> landed_body_, landed_driver_;  // the share's slots (global ids) until then
  std::size_t external_rows_ = ~std::size_t(0);  // the rebuild whose store add_external's constants are for
  bool rebuild_asked_ = false;
  bool reactions_wanted_ = true;
  bool stop_asked_ = false, stop_seen_ = false;
  std::size_t rebuilds_ = 0;
  LinkCounts rebuild_traffic_;
  ExactEnergy taken_;        // J, the ended contacts' energies of earlier engines (rebuilds) since the last take_energy
  std::size_t contacts_ = 0;
};

}  // namespace polydem
