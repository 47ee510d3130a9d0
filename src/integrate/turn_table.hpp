#pragma once
// The join step's turns (issue 16: pair_kernel.hpp's PairTurn) applied to a step's bodies:
// after a closing kick of its own (turn_bodies), or inside the next step's joined pass where
// the kick was left open (TurnTable, close_and_start_step), with the same arithmetic.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "integrate/integrate.hpp"
#include "integrate/pass_turn.hpp"
#include "polydem/shape.hpp"

namespace polydem {

// True where a body's orientation is integrated, so a turn moves it (a sphere's stays the identity).
template <class B>
bool takes_turns(const B& b, std::size_t i, const std::vector<Shape>& shapes) {
  return !keeps_no_orientation(shapes[b.shape[i]], b.inertia[i]);
}

// Turns body t.body by I_world^-1 t.moment for each t of `turns` (ContactEngine::take_turns)
// with turn_body. Where a patch's shares moved within a step the drift, at v(n+1/2), missed the
// turn they made within it (issue 16: pair_kernel.hpp, PairTurn). Called after the step's
// closing kick: `book(work)` takes each body's work against the torque then (J, -torque . angle
// to first order: what the springs gain), one term a body so that an exact sum gives any rank
// count's bits, for the ledger's patch work. B: Bodies or a rank's LocalStore.
template <class B, class Turns, class Book>
void turn_bodies(B& b, const Turns& turns, const std::vector<Shape>& shapes, const Book& book) {
  for (const auto& t : turns) {
    const std::size_t i = t.body;
    if (!takes_turns(b, i, shapes)) continue;
    const std::optional<Vec3> angle = turn_body(b.orientation[i], b.angular_momentum[i], b.angular_velocity[i],
                                                b.inertia[i], is_isotropic(b.inertia[i]), t.moment);
    if (angle) book(-b.torque[i].dot(*angle));
  }
}

// A step's turns kept by body row for the next step's joined pass (the kick left open):
// take() them after the step, pass() to close_and_start_step, then book() their work.
class TurnTable {
 public:
  // The turns of `turns` (increasing bodies) that move a body of `b` (Bodies or a LocalStore).
  template <class B, class Turns>
  void take(const B& b, const Turns& turns, const std::vector<Shape>& shapes) {
    slot_.resize(b.size(), PassTurns::kNone);  // every slot kNone: book() resets the ones it set
    for (const auto& t : turns) {
      if (!takes_turns(b, t.body, shapes)) continue;
      slot_[t.body] = std::uint32_t(turn_.size());
      rows_.push_back(t.body);
      turn_.push_back({t.moment, std::nullopt});
    }
  }
  bool empty() const { return turn_.empty(); }
  PassTurns pass() { return {slot_.data(), turn_.data()}; }
  // book(work) for each body the pass turned, in increasing rows (turn_bodies' order); then empty.
  template <class Book>
  void book(const Book& book) {
    for (std::size_t k = 0; k < turn_.size(); ++k) {
      if (turn_[k].work) book(*turn_[k].work);
      slot_[rows_[k]] = PassTurns::kNone;
    }
    rows_.clear();
    turn_.clear();
  }

 private:
  std::vector<std::uint32_t> slot_;  // per body row: its index in turn_, or kNone
  std::vector<std::uint32_t> rows_;  // turn_[k]'s body row
  std::vector<PassTurn> turn_;
};

}  // namespace polydem
