#include "contact/pair_loop.hpp"
#include "contact/sphere_kernel.hpp"

namespace polydem {

void sphere_pair_loop(const LawParams& law, double band, double dt, const BodyView& bodies, PairList& list,
                      DirectSums& direct, const EqualSpheres* equal) {
  with_law(law, [&](auto parts) {
    using Parts = decltype(parts);
    const auto run = [&](const auto& sizes) {
      all_pair_forces<true>(list, [&](std::uint32_t k, PairScratch&) __attribute__((always_inline)) {
        return sphere_pair_forces<Parts>(law, band, dt, bodies, list, k, sizes);
      }, &direct);
    };
    if (!equal) return run(EachSphere{bodies, list});
    const double r = equal->radius, m = equal->mass;  // m, kg
    const double pair_mass = m * m / (m + m);         // kg, as EachSphere's: the same bits
    // Made here, not at first use: the loop's threads would share the cache.
    LinearStep step = same_linear_step<Parts>(law, pair_mass, dt);
    run(SameSpheres{r, pair_mass, r * r / (r + r), &step});
  });
}

}  // namespace polydem
