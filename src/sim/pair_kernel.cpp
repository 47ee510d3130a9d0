#include "sim/pair_kernel.hpp"

#include <limits>

namespace polydem {

void hand_over_history(PairList& list, std::uint32_t slot_begin, std::uint32_t slot_end,
                       const std::vector<FoundContact>& found, std::vector<std::uint8_t>& now_on) {
  now_on.assign(slot_end - slot_begin, 0);
  for (const FoundContact& c : found) now_on[c.slot - slot_begin] = 1;
  for (const FoundContact& c : found) {
    ContactSlot& fresh = list.slots[c.slot];
    if (fresh.active) continue;                       // key lives on: history already here
    std::uint32_t nearest = slot_end;
    double best = std::numeric_limits<double>::infinity();
    for (std::uint32_t s = slot_begin; s < slot_end; ++s) {
      const ContactSlot& old = list.slots[s];
      if (!old.active || now_on[s - slot_begin]) continue;  // only contacts that just ended
      const double d2 = (old.point - c.geometry.point).squaredNorm();
      if (d2 < best) { best = d2; nearest = s; }
    }
    if (nearest == slot_end) {
      fresh.history = ContactHistory{};
    } else {
      fresh.history = list.slots[nearest].history;
      list.slots[nearest].active = false;             // given once
      list.slots[nearest].history = ContactHistory{};
    }
  }
  for (std::uint32_t s = slot_begin; s < slot_end; ++s) {
    ContactSlot& slot = list.slots[s];
    slot.active = now_on[s - slot_begin] != 0;
    if (!slot.active) { slot.history = ContactHistory{}; slot.fn = 0.0; slot.force = Vec3::Zero(); }
  }
}

}  // namespace polydem
