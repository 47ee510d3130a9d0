#include "sim/turned_pass.hpp"

namespace polydem {

namespace {
template <class B>
void close_turn_and_start_any(B& b, double h, double dt, const RotorGroups& groups, const Vec3& gravity,
                              const ForceSums& sums, bool from_gravity, PassTurns turns, TeamCut cut, bool wait) {
  if (from_gravity)
    close_and_start_step<true>(b, h, dt, groups, gravity, sums, cut, NoWatch{}, wait, turns);
  else
    close_and_start_step(b, h, dt, groups, gravity, sums, cut, NoWatch{}, wait, turns);
}
}  // namespace

void close_turn_and_start(Bodies& b, double h, double dt, const RotorGroups& groups, const Vec3& gravity,
                          const ForceSums& sums, bool from_gravity, PassTurns turns, TeamCut cut, bool wait) {
  close_turn_and_start_any(b, h, dt, groups, gravity, sums, from_gravity, turns, cut, wait);
}

void close_turn_and_start(LocalStore& b, double h, double dt, const RotorGroups& groups, const Vec3& gravity,
                          const ForceSums& sums, bool from_gravity, PassTurns turns) {
  close_turn_and_start_any(b, h, dt, groups, gravity, sums, from_gravity, turns, {}, true);
}

}  // namespace polydem
