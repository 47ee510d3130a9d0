#pragma once
// A running simulation: bodies, drivers, the contact engine and the step that moves them.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contact/contact_engine.hpp"
#include "driver/drivers.hpp"
#include "field/external_forces.hpp"
#include "integrate/integrate.hpp"
#include "integrate/turn_table.hpp"
#include "io/scene_settings.hpp"
#include "polydem/bodies.hpp"
#include "polydem/shape_library.hpp"
#include "sim/rank_contacts.hpp"
#include "sim/time_step.hpp"
#include "sim/trailing_pass.hpp"

namespace polydem {

// Energy accumulated over the run (J); the state energies are computed on demand.
struct EnergyLedger {
  double dissipated = 0.0;    // by dashpots, friction and rolling slip, less what patch weight changes add
  double driver_work = 0.0;   // done by moving drivers on the particles
  double external_work = 0.0; // done by drag and fluid forces on the particles
  Vec3 initial_mass_moment = Vec3::Zero();  // kg m, sum m x at t = 0: gravity work = m g . dx
  // Shares of `dissipated` (checkpoint format 05 on):
  double sliding = 0.0;     // by Coulomb slip, and tangential springs let go
  double rolling = 0.0;     // by rolling slip, and rolling springs let go
  double patch_work = 0.0;  // added to the springs by patch weight changes (taken off `dissipated`)
};

struct EnergyRow {
  double kinetic, rotational, elastic, dissipated, gravity_work, driver_work;
  std::size_t contacts;
  double external_work;  // J, by drag and fluid forces
  StoredParts elastic_parts;  // J, `elastic` per spring
  double dissipated_dashpot, dissipated_sliding, dissipated_rolling;  // J, `dissipated` + patch_work by mechanism
  double patch_work;          // J
};

class Simulation {
 public:
  // `specs` by value: a temporary is moved in and freed once the bodies are built, before the
  // first list build (the run's memory peak; ~200 bytes a body). `link`: the ranks of a
  // distributed run (null or one rank: one process).
  // `order`: the user id per index of the arrays (a checkpoint's, sim/body_order.hpp); empty:
  // as the scene's simulation.body_order makes it.
  Simulation(const Scene& scene, const ShapeLibrary& library, std::vector<BodySpec> specs,
             const RankLink* link = nullptr, std::optional<std::vector<std::uint32_t>> order = std::nullopt);

  // One velocity-Verlet step of dt. `leave_kick_open`: its closing kick is left to the next
  // step's opening pass (one pass over the bodies for both: each body's arithmetic and bits as
  // two passes'), so nothing may read the bodies before that step or close_step(). With
  // contacts only (a distributed run's rank: its owned bodies); elsewhere the step closes as usual.
  void step(bool leave_kick_open = false);
  // On: after a step left open the caller's next call is step() (the run loop), so one process
  // may run that step's joined pass right behind this step's pair walk (TrailingPass, spheres'
  // lists). The signature of step() stays: the counting tools toggle on it.
  void open_steps_follow(bool on) { open_steps_follow_ = on; }
  // Applies a closing kick left open (nothing to do otherwise): the bodies at the full step. After
  // a step whose next one has begun (open_steps_follow) nothing: the next step() closes it.
  void close_step();
  bool kick_open() const { return kick_open_; }
  bool ran_ahead() const { return trailed_; }  // the last step ran the next one's joined pass (open_steps_follow)

  // The contacts' energies enter `ledger` when it closes, at the end of every kLedgerSteps-th
  // step (close_ledger; a collective); between, each pair sums its own, flushed exactly when its
  // contact ends (ContactEngine::take_energy), and energy() adds what is still open. A
  // checkpoint holds the open sums (format 07), so a run may stop and resume at any step.
  static constexpr std::int64_t kLedgerSteps = 100;
  static bool ledger_closes(std::int64_t step) { return step % kLedgerSteps == 0; }
  void close_ledger();

  // A CSV row's energies; distributed runs: as the last sum_energy() summed them (a
  // collective: each rank's owned bodies and pairs, reduced exactly: no state gathered).
  EnergyRow energy() const;
  void sum_energy();
  const TimeStepEstimate& time_step() const { return dt_estimate_; }
  double dt() const { return dt_; }
  double time() const { return double(step_) * dt_; }
  std::int64_t step_index() const { return step_; }

  const Scene& scene() const { return scene_; }
  const std::vector<Shape>& shapes() const { return library_.shapes; }
  Bodies bodies;
  Drivers drivers;
  ContactEngine& engine() { return *engine_; }
  const ContactEngine& engine() const { return *engine_; }
  EnergyLedger ledger;
  // Drag and fluid operators; null when the scene has none.
  const ExternalForces* external() const { return external_.get(); }
  // Bodies whose centre is outside the fluid grid (no grid force on them) at the last step, over
  // every rank (a collective in distributed runs).
  std::size_t bodies_outside_grid() const;
  // The set-up's warning of impacts too fast for the contacts' stiffness or dt ("": none; rank 0's,
  // which prints it): from the bodies' state at the start, which a rank drops after its cut.
  const std::string& fast_impact_warning() const { return impact_warning_; }

  // Checkpoint support: the step counter is part of the state.
  void set_step_index(std::int64_t s) { step_ = s; }
  // Rebuilds the contact lists at the next step from engine()'s lists (a checkpoint read or
  // written: the same lists, the same bits either way). `table_on_every_rank`: false when
  // engine()'s lists were gathered to rank 0 only (a checkpoint written by a distributed run:
  // the ranks rebuild from their own lists then).
  void force_rebuild(bool table_on_every_rank = true);
  // A distributed run resumed from checkpoint pieces: this rank's share of them
  // (RankContacts::land) and a rebuild at the next step; engine() keeps no table.
  void land_share(LandedShare share);
  // After a state is read: spheres take the identity orientation, their L folded into the
  // world frame (checkpoints written before Rotor::sphere turned them; integrate.hpp).
  void drop_sphere_orientations() { polydem::drop_sphere_orientations(bodies, rotors_); }

  // Distributed runs: `bodies` holds every body's state and engine() every rank's contacts
  // (global ids) only after gather_state(), a collective, called before output, checkpoints and
  // checks read them; between, a rank's bodies are current in its store alone (the rank
  // integrates them there, and its own writers and checks read them there), and `bodies` holds
  // no state at all after its first cut (dropped). Onto rank 0 only
  // (it writes the files), or onto every rank (`onto_every_rank`: tests comparing the ranks).
  // gather_bodies: the state alone onto rank 0 (the other ranks grow nothing), for output
  // that reads every body (probes, the fluid's rows and files); release_bodies frees it after.
  bool distributed() const { return bool(ranks_); }
  void gather_bodies() {
    if (ranks_) ranks_->sync_bodies(bodies, true);
  }
  void release_bodies() {
    if (ranks_) ranks_->release_state(bodies);
  }
  int rank() const { return link_ ? link_->rank() : 0; }
  void gather_state(bool onto_every_rank = false);
  // The smallest index of a body whose state is not finite, or -1; distributed runs: each rank
  // checks the bodies it owns (a collective), the same answer as the whole state's.
  long first_non_finite() const;
  // Distributed runs: the bodies this rank owns and holds as ghosts since the last rebuild.
  std::size_t owned_bodies() const { return ranks_ ? ranks_->owned() : bodies.size(); }
  std::size_t ghost_bodies() const { return ranks_ ? ranks_->ghosts() : 0; }
  const RankContacts* rank_contacts() const { return ranks_.get(); }  // null: one process
  RankContacts* rank_contacts() { return ranks_.get(); }
  const RankLink* link() const { return ranks_ ? link_ : nullptr; }  // null: one process
  // The next step's driver reactions are read (output after it); a moving driver's are read
  // every step (servo, driver work), a fixed one's only then (its work is +0 either way).
  void want_driver_reactions(bool read) {
    if (ranks_) ranks_->want_reactions(read || drivers_move_);
    else engine_->want_reactions(read || drivers_move_);
  }
  bool any_rank(bool mine) const { return ranks_ ? link_->any(mine) : mine; }  // a collective
  // Distributed runs with contacts: the step's one collective ORs each rank's `asked` (the run
  // loop's interrupt) and a step that sees one keeps what a checkpoint reads; stop_seen() says
  // whether it did (nullopt: no such collective, ask any_rank).
  void ask_stop(bool asked) {
    if (ranks_) ranks_->ask_stop(asked);
  }
  std::optional<bool> stop_seen() const {
    if (ranks_ && scene_.forces.contact.present) return ranks_->stop_seen();
    return std::nullopt;
  }
  std::size_t contacts() const { return ranks_ ? ranks_->contacts() : engine_->stats().contacts; }  // active sub-contacts
  std::size_t rebuilds() const { return ranks_ ? ranks_->rebuilds() : engine_->stats().rebuilds; }

 private:
  void external_forces();
  double external_power();
  void driver_work_half();
  void contact_stage();
  void sums_taken();
  void turn_bodies_left();  // after a closing kick: the turns the pair loops left (ContactEngine::take_turns)
  bool turns_left() const;
  void keep_turns();        // the last step's turns, left open with its kick: for the joined pass
  void book_kept_turns();   // after the joined pass: their work
  // The next step's joined pass behind this one's walk (spheres: `watch`; cubes: `bounds`).
  bool trails_walk(bool next_follows, PointWatch& watch, BoundWatch& bounds);
  ForceSums closing_sums();  // one process: the sums a closing pass adds (from gravity where nothing else acts)
  StateEnergy state_energy() const;  // one process: summed now; many: the last sum_energy's

  Scene scene_;
  ShapeLibrary library_;
  std::unique_ptr<ContactEngine> engine_;
  RotorGroups rotors_;           // spheres turn no orientation, isotropic bodies take one rotation
  TurnTable kept_turns_;         // one process: the turns the joined pass applies (keep_turns)
  TrailingPass trailing_;        // one process's joined pass run behind the last step's walk
  bool trailed_ = false;         // the last step ran it: this step's first region moves the rest
  bool open_steps_follow_ = false;
  TimeStepEstimate dt_estimate_;
  std::string impact_warning_;  // fast_impact_warning
  double dt_ = 0.0;
  std::int64_t step_ = 0;
  Vec3 gravity_ = Vec3::Zero();  // m/s^2
  std::unique_ptr<ExternalForces> external_;
  const RankLink* link_ = nullptr;
  std::unique_ptr<RankContacts> ranks_;  // distributed runs: this rank's contact stage
  StateEnergy summed_;                   // distributed runs: at the last sum_energy
  bool drivers_move_ = false;            // a driver translates, turns or is a servo
  bool kick_open_ = false;               // the last step's closing kick is still to apply (step)
  bool external_split_ = false;          // the last drag and fluid forces acted on each rank's own bodies
};

// Index of the first body whose state is not finite, or -1.
long first_non_finite_body(const Bodies& bodies);

}  // namespace polydem
