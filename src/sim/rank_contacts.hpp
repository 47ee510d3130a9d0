#pragma once
// The contact stage of a distributed run (issue 20, first version): every rank holds every
// body's state and integrates it (the same arithmetic on the same numbers: the same bits on
// every rank); the contact stage, the cost of a step, is cut in slabs. Each rank computes the
// pairs of the bodies it owns (their centres in its slab, cut at each rebuild at equal body
// counts along the longest side) with ghosts within reach, in global id order, so each body's
// force sum is the one of one process; then the ranks share the owned bodies' forces, the
// drivers' reactions (summed in the one-process pair order) and the pair energies (summed in
// the one-process blocks of kPairBlock pairs). Contacts migrate at rebuilds through the table
// of active slots in global ids (sim/contact_table.hpp). Replicated state bounds a run by one
// node's memory: ghost exchange of state between rebuilds is the next step (README).
#include <memory>
#include <vector>

#include "contact/contact_engine.hpp"
#include "sim/local_store.hpp"
#include "sim/rank_energy.hpp"
#include "sim/rank_link.hpp"
#include "sim/slabs.hpp"

namespace polydem {

// What a rank tells the others of a body it owns after the pair loop: its contact sums.
struct BodyShare {
  std::uint32_t id;
  double force[3], torque[3];  // N, N m
};

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

  // Adds every body's contact force and torque of this step, sets the drivers' reactions and
  // the step's energy, on every rank. `whole`: the engine over all bodies, whose lists hold
  // the table of histories (read at a forced rebuild, written by gather_table).
  void compute(Bodies& bodies, Drivers& drivers, double dt, ContactEngine& whole);
  // Rebuilds at the next step from `whole`'s lists (a checkpoint read or just written).
  void force_rebuild() { forced_ = true; }
  // Gathers every rank's active slots into `whole`'s lists (global ids): checkpoints, output.
  void gather_table(ContactEngine& whole) const;

  const EnergyParts& energy() const { return energy_; }  // J, this step, every rank's pairs
  std::size_t contacts() const { return contacts_; }    // active sub-contacts, every rank's pairs
  std::size_t rebuilds() const { return rebuilds_; }

 private:
  bool lists_stale(const Bodies& bodies, const Drivers& drivers);
  void redistribute(const Bodies& bodies, const ContactEngine& whole);
  void share_results(Bodies& bodies, Drivers& drivers);
  std::vector<BodyShare> body_shares() const;
  std::vector<ReactionShare> reaction_shares() const;

  const RankLink& link_;
  const std::vector<Shape>& shapes_;
  ContactSettings settings_;
  double halo_;  // m, ghosts: bodies within this distance of the slab
  std::unique_ptr<ContactEngine> engine_;
  LocalStore store_;
  std::vector<std::int32_t> local_of_;  // global id -> local index, -1 when not local
  bool forced_ = true;
  std::size_t rebuilds_ = 0;
  EnergyParts energy_;
  std::size_t contacts_ = 0;
};

}  // namespace polydem
