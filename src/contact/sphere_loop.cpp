#include <cassert>

#include "contact/pair_loop.hpp"
#include "contact/sphere_kernel.hpp"
#include "contact/sphere_lanes.hpp"

namespace polydem {

namespace {
// The pair loop's kernel: sphere_pair_forces for pair k.
template <class Parts, class Sizes>
struct SphereKernel {
  static constexpr bool kDense = true;  // a sphere list is dense: each pair's energy on its slot
  const LawParams& law;
  double band, dt;  // m, s
  const BodyView& bodies;
  PairList& list;
  const Sizes& sizes;
  [[gnu::always_inline]] PairTotals operator()(std::uint32_t k, PairScratch&) const {
    return sphere_pair_forces<Parts>(law, band, dt, bodies, list, k, sizes);
  }
};
// The same, and steady pairs two at a time (sphere_lanes.hpp, pair_loop.hpp's paired_pairs), or
// one alone through the same steady kernel (steady_alone).
template <class Sizes>
struct SphereLanesKernel : SphereKernel<SteadyParts, Sizes> {
  static constexpr bool kTwoLanes = true;
  [[gnu::always_inline]] bool candidate(std::uint32_t k) const { return steady_candidate(this->list, k, this->sizes); }
  template <int N, class Take>
  [[gnu::always_inline]] void steady(const std::uint32_t pairs[N], const Take& take) const {
    steady_sphere_pairs<N>(this->law, this->band, this->dt, this->bodies, this->list, pairs, this->sizes, take);
  }
};
}  // namespace

void sphere_pair_loop(const LawParams& law, double band, double dt, const BodyView& bodies, PairList& list,
                      DirectSums& direct, const EqualSpheres* equal, bool lanes, const WalkTrail* trail) {
  assert(!list.sparse);
  with_law(law, [&](auto parts) {
    using Parts = decltype(parts);
    const auto run = [&](const auto& sizes) {
      using Sizes = std::decay_t<decltype(sizes)>;
      if constexpr (std::is_same_v<Parts, SteadyParts>) {
        if (lanes && lanes_fit<Parts>(law, list))
          return all_pair_forces<true>(list, SphereLanesKernel<Sizes>{{law, band, dt, bodies, list, sizes}}, &direct,
                                       trail);
      }
      all_pair_forces<true>(list, SphereKernel<Parts, Sizes>{law, band, dt, bodies, list, sizes}, &direct, trail);
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
