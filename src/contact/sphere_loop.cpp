#include "contact/pair_loop.hpp"
#include "contact/sphere_kernel.hpp"

namespace polydem {

void sphere_pair_loop(const LawParams& law, double band, double dt, const BodyView& bodies, PairList& list,
                      DirectSums& direct) {
  with_law(law, [&](auto parts) {
    all_pair_forces<true>(list, [&](std::uint32_t k, PairScratch&) __attribute__((always_inline)) {
      return sphere_pair_forces<decltype(parts)>(law, band, dt, bodies, list, k);
    }, &direct);
  });
}

}  // namespace polydem
