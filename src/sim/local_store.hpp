#pragma once
// One process's share of the bodies: the bodies it owns and ghosts of bodies owned elsewhere, in
// increasing global id (contact/local_bodies.hpp: why the order gives the bits of one process).
// A rank's one copy of its bodies' state between gathers: its passes integrate the owned bodies
// here (arrays_of), by local index, and its contact stage reads them here; a ghost carries only
// what contacts read (pose, velocities, shape, scale, mass, global id) and output (group, user
// id), written where its owner's parcel lands (sim/ghost_plan.hpp). The set changes only at
// list rebuilds. Its fields are named as Bodies', so a rank's writers, energies and checks read
// it through the same templates (body_rows.hpp). A rebuild makes the next store from the old
// one and the parcels that land (sim/rank_migration.hpp); the global Bodies arrays get the owned
// bodies' state only where a gather reads it (publish).
#include <cstdint>
#include <vector>

#include "contact/local_bodies.hpp"
#include "integrate/integrate.hpp"
#include "polydem/bodies.hpp"

namespace polydem {

struct LocalStore {
  std::vector<std::uint32_t> global_id;  // increasing
  std::vector<std::uint8_t> ghost;       // 1: a copy of a body owned elsewhere
  std::vector<Vec3> position, velocity, angular_velocity;  // m, m/s, rad/s
  std::vector<Vec3> velocity_end, angular_velocity_end;   // m/s, rad/s, predicted for the step's end
  std::vector<Quat> orientation;
  std::vector<Vec3> angular_momentum;  // kg m^2/s, principal frame (owned bodies)
  std::vector<int> shape;
  std::vector<double> scale, mass;  // -, kg
  std::vector<Vec3> inertia;        // kg m^2, principal moments
  std::vector<int> group;           // as Bodies' (output)
  std::vector<std::uint32_t> id;    // the user id (Bodies::id: files and messages name it)
  // N, N m: the owned bodies' forces as integration keeps them (m gravity, drag, then the
  // closing kick's contact sums added); a ghost's unused.
  std::vector<Vec3> force, torque;

  // Holds the bodies `ids` of `all` (increasing), ghosts where `is_ghost` is 1, their state
  // (forces included) copied.
  void select(const Bodies& all, std::vector<std::uint32_t> ids, std::vector<std::uint8_t> is_ghost);
  // A rebuild's store from parcels (sim/rank_migration.hpp): rows added, `from`'s rows `rows`
  // (every field), then all put in increasing global id.
  void append(const LocalStore& from, const std::vector<std::uint32_t>& rows);
  void sort_by_id();
  // A rebuild's store, each field written once: the rows `rows` of `from` (a rank's kept bodies)
  // merged with every row of `add` (the movers landed), both in increasing id, with room for
  // `spare` more rows (the ghosts merge_in lands next: no reallocation).
  void merge_of(const LocalStore& from, const std::vector<std::uint32_t>& rows, const LocalStore& add,
                std::size_t spare);
  // Every row of `add` (increasing id, none held here) merged in place from the back: a row moves
  // at most once, the rows below `add`'s least id not at all.
  void merge_in(const LocalStore& add);
  void resize(std::size_t n);
  std::size_t size() const { return global_id.size(); }
  // The owned bodies' integration state into `all` at their global ids (a gather:
  // RankContacts::sync_bodies); or back from it (pull: after something wrote them).
  void publish(Bodies& all) const;
  void pull(const Bodies& all);
  // The local index of the body of global id `g`, which the store holds.
  std::uint32_t local_of(std::uint32_t g) const;
  // The owned bodies' local indices (increasing global id).
  std::vector<std::uint32_t> owned_rows() const;
  // Calls f(mine, theirs) on each per-body array of this store and of `other` (the same field).
  template <class Other, class F>
  void with_arrays(Other& other, F&& f) {
    f(global_id, other.global_id), f(ghost, other.ghost), f(position, other.position);
    f(velocity, other.velocity), f(angular_velocity, other.angular_velocity);
    f(velocity_end, other.velocity_end), f(angular_velocity_end, other.angular_velocity_end);
    f(orientation, other.orientation), f(angular_momentum, other.angular_momentum), f(shape, other.shape);
    f(scale, other.scale), f(mass, other.mass), f(inertia, other.inertia), f(group, other.group), f(id, other.id);
    f(force, other.force), f(torque, other.torque);
  }
  LocalBodies view() {
    return {&position, &orientation, &velocity, &angular_velocity, &velocity_end, &angular_velocity_end,
            &shape,    &scale,       &mass,     &ghost,            &force,        &torque};
  }
};

// The rows of `ids` (distinct) in increasing id: a rebuild's store is a few runs in that order
// (its kept bodies, then each parcel's), merged; more runs are sorted.
std::vector<std::uint32_t> id_order(const std::vector<std::uint32_t>& ids);

// The integration passes' arrays (integrate.hpp's over_rotor_groups), by local index.
inline BodyArrays arrays_of(LocalStore& s) {
  return {s.position.data(),     s.orientation.data(),          s.velocity.data(),         s.angular_velocity.data(),
          s.velocity_end.data(), s.angular_velocity_end.data(), s.angular_momentum.data(), s.force.data(),
          s.torque.data(),       s.mass.data(),                 s.inertia.data()};
}

}  // namespace polydem
