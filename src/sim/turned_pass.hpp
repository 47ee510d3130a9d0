#pragma once
// close_and_start_step with the last step's turns (integrate/turn_table.hpp), in a unit of its
// own: beside the passes in simulation.cpp and rank_contacts.cpp its instances would move what
// GCC inlines in theirs (its unit growth limit). Here that limit is raised (CMakeLists.txt).
#include "contact/contact_engine.hpp"
#include "integrate/integrate.hpp"
#include "integrate/pass_turn.hpp"
#include "polydem/bodies.hpp"
#include "sim/local_store.hpp"

namespace polydem {

// One process's joined pass (Simulation::step), called by every thread of its team;
// `from_gravity`: close_and_start_step<true> (`sums` then sets m gravity first).
void close_turn_and_start(Bodies& b, double h, double dt, const RotorGroups& groups, const Vec3& gravity,
                          const ForceSums& sums, bool from_gravity, PassTurns turns, TeamCut cut, bool wait);
// A rank's, over its store's owned bodies (RankContacts::close_and_start).
void close_turn_and_start(LocalStore& b, double h, double dt, const RotorGroups& groups, const Vec3& gravity,
                          const ForceSums& sums, bool from_gravity, PassTurns turns);

}  // namespace polydem
