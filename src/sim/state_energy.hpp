#pragma once
// A CSV row's energies (energy.csv), each summed exactly (contact/exact_sum.hpp): the bodies'
// kinetic and rotational energy and mass moment, the springs' stored energy and the contacts'
// energies since the ledger last closed. A rank adds its owned bodies and the pairs it answers
// for, and the ranks add the words in one all-reduce: the row of one process for any rank and
// thread count, with no state gathered.
#include <array>
#include <cstdint>
#include <vector>

#include "contact/exact_sum.hpp"
#include "polydem/bodies.hpp"

namespace polydem {

struct StateEnergy {
  ExactSum kinetic, rotational;     // J
  std::array<ExactSum, 3> moment;  // kg m, sum m x
  ExactStored elastic;             // J
  ExactEnergy open;                // J

  // Body b of `a` (Bodies, or a rank's LocalStore).
  template <class Arrays>
  void add_body(const Arrays& a, std::size_t b) {
    const double m = a.mass[b];  // kg
    kinetic.add(0.5 * m * a.velocity[b].squaredNorm());
    const Vec3& L = a.angular_momentum[b];
    rotational.add(0.5 * L.cwiseProduct(L).cwiseQuotient(a.inertia[b]).sum());
    for (int d = 0; d < 3; ++d) moment[d].add(m * a.position[b][d]);
  }
  Vec3 mass_moment() const { return {moment[0].value(), moment[1].value(), moment[2].value()}; }
  std::vector<std::uint64_t> words() const;
  // The sum whose words (over `terms` ranks) are `w`.
  static StateEnergy from_words(const std::vector<std::uint64_t>& w, std::uint64_t terms);
};

}  // namespace polydem
