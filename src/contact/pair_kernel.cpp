#include "contact/pair_kernel.hpp"

#include <limits>

namespace polydem {

EnergyParts hand_over_history(PairList& list, std::uint32_t slot_begin, std::uint32_t slot_end, int was_active,
                              const std::vector<FoundContact>& found, std::vector<std::uint8_t>& now_on,
                              const LawParams* law, double r_star) {
  if (same_contacts(list, was_active, found)) return {};  // keys keep their history
  now_on.assign(slot_end - slot_begin, 0);
  for (const FoundContact& c : found) now_on[c.slot - slot_begin] = 1;
  // Contacts that start now (no history of their own) and those that just ended.
  std::uint32_t fresh[kMaxHandOver], ended[kMaxHandOver];
  int n_fresh = 0, n_ended = 0;
  for (std::size_t c = 0; c < found.size(); ++c)
    if (!list.active[found[c].slot] && n_fresh < kMaxHandOver) fresh[n_fresh++] = std::uint32_t(c);
  for (std::uint32_t s = slot_begin; s < slot_end && n_ended < kMaxHandOver; ++s)
    if (list.active[s] && !now_on[s - slot_begin]) ended[n_ended++] = s;
  for (int k = 0; k < n_fresh; ++k) list.set_history(found[fresh[k]].slot, ContactHistory{});
  // Greedy matching, closest pair first: each ended contact gives its history once.
  while (n_fresh > 0 && n_ended > 0) {
    int best_f = 0, best_e = 0;
    double best = std::numeric_limits<double>::infinity();
    for (int f = 0; f < n_fresh; ++f)
      for (int e = 0; e < n_ended; ++e) {
        const double d2 = (list.record(ended[e]).point - found[fresh[f]].geometry.point).squaredNorm();
        if (d2 < best) { best = d2; best_f = f; best_e = e; }
      }
    list.set_history(found[fresh[best_f]].slot, list.history(ended[best_e]));
    list.set_history(ended[best_e], ContactHistory{});  // handed over: nothing released
    fresh[best_f] = fresh[--n_fresh];
    ended[best_e] = ended[--n_ended];
  }
  EnergyParts released;  // J
  for (std::uint32_t s = slot_begin; s < slot_end; ++s) {
    const bool on = now_on[s - slot_begin] != 0;
    if (list.active[s] && !on) {
      if (law) released += released_energy(*law, list.history(s), r_star);
      list.set_history(s, ContactHistory{});  // its record is read no more: only active slots' are
    }
    list.active[s] = on;
  }
  return released;
}

}  // namespace polydem
