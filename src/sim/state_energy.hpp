#pragma once
// A CSV row's energies (energy.csv), each summed exactly (contact/exact_sum.hpp): the bodies'
// kinetic and rotational energy and mass moment, the springs' stored energy and the contacts'
// energies since the ledger last closed. A rank adds its owned bodies and the pairs it answers
// for, and the ranks add the words in one all-reduce: the row of one process for any rank and
// thread count, with no state gathered.
#include <array>
#include <cassert>
#include <cstdint>
#include <vector>

#include <omp.h>

#include "contact/exact_sum.hpp"
#include "polydem/bodies.hpp"
#include "polydem/parallel.hpp"

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
  // Bodies [0, n) of `a` (add_body each) on a team of its own from kParallelMinItems bodies
  // (a pour's CSV row: 2,000 bodies, ~0.45e6 instructions on one thread): each thread sums its
  // share apart, and the shares join in any order, exact: the words of the serial loop.
  template <class Arrays>
  void add_bodies(const Arrays& a, std::size_t n) {
    assert(omp_get_level() == 0);  // a region of its own: the shares join at its end
    in_team(n >= kParallelMinItems, [&] {
      StateEnergy share;
#pragma omp for schedule(static) nowait
      for (std::size_t b = 0; b < n; ++b) share.add_body(a, b);
#pragma omp critical(polydem_state_energy)
      add_body_sums(share);
    });
  }
  void add_body_sums(const StateEnergy& o);  // o's kinetic, rotational and mass moment sums
  Vec3 mass_moment() const { return {moment[0].value(), moment[1].value(), moment[2].value()}; }
  std::vector<std::uint64_t> words() const;
  // The sum whose words (over `terms` ranks) are `w`.
  static StateEnergy from_words(const std::vector<std::uint64_t>& w, std::uint64_t terms);
};

}  // namespace polydem
