#pragma once
// Two sphere pairs through the exact step at once, one in each lane (geometry/lanes.hpp): the
// steady case, nearly every pair of a resting bed. What holds a pair up is its chain of dependent
// latencies (square root, the normal's division, the divisions by dt and by the pair mass, the
// spring's turn), not its instructions: two chains side by side take about the time of one. Each
// lane does sphere_pair_forces' operations in its order, so a lane has its pair's bits.
// Steady: touching now and at the last step (no onset, no release), the glued arc not letting go
// within the step, the tangential spring under its cap. For LawParts<NormalLinear, false, false,
// false> with the exact step and friction, outside the steps that record contacts (lanes_fit).
#include <type_traits>

#include "contact/sphere_kernel.hpp"
#include "geometry/lanes.hpp"
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace polydem {

using SteadyParts = LawParts<NormalLinear, false, false, false>;

// Whether this step's pairs may take the lanes.
template <class Parts>
bool lanes_fit(const LawParams& law, const PairList& list) {
  return std::is_same_v<Parts, SteadyParts> && law.exact_step && law.alpha_n > 0.0 && law.mu > 0.0 && law.kt > 0.0 &&
         !list.recording;
}

// Whether pair k may be steady: overlapping at the last step, its k', c' made.
template <class Sizes>
[[gnu::always_inline]] inline bool steady_candidate(const PairList& list, std::uint32_t k, const Sizes& sizes) {
  const std::uint32_t s = list.slot_begin[k];
  return s != list.slot_begin[k + 1] && list.active[s] && list.slots[s].history.gap < 0.0 &&
         sizes.linear_step(k)->k != 0.0;
}

namespace sphere_lanes_detail {
using V = lanes::Types<2>::V;
using V3 = lanes::Vec3Of<V>;
inline V sqrt2(V a) {  // sqrtpd: each lane std::sqrt's correctly rounded result
#if defined(__SSE2__)
  return (V)_mm_sqrt_pd((__m128d)a);
#else
  return lanes::sqrt(a);
#endif
}
inline V3 times(V s, const V3& a) { return {s * a.x, s * a.y, s * a.z}; }
}  // namespace sphere_lanes_detail

// Pairs two[0] and two[1] (steady candidates, in list order) side by side; then for l = 0, 1 in
// turn take(l, &totals) where lane l was steady (its slot advanced) or take(l, nullptr) where not
// (its slot untouched, for sphere_pair_forces).
template <class Sizes, class Take>
[[gnu::always_inline]] inline void steady_sphere_pairs(const LawParams& law, double band, double dt,
                                                       const BodyView& bodies, PairList& list,
                                                       const std::uint32_t two[2], const Sizes& sizes,
                                                       const Take& take) {
  using namespace lanes;
  using namespace sphere_lanes_detail;
  const BodyPair p[2] = {list.pairs[two[0]], list.pairs[two[1]]};
  ContactHistory* const h[2] = {&list.slots[list.slot_begin[two[0]]].history,
                                &list.slots[list.slot_begin[two[1]]].history};
  const LinearStep* const step[2] = {sizes.linear_step(two[0]), sizes.linear_step(two[1])};
  const auto each = [&](auto get) { return gather<V>(get); };
  const auto of_i = [&](const Vec3* a) { return load<V>([&](int l) -> const Vec3& { return a[p[l].i]; }); };
  const auto of_j = [&](const Vec3* a) { return load<V>([&](int l) -> const Vec3& { return a[p[l].j]; }); };
  const V zero = splat<V>(0.0), half = splat<V>(0.5), dt_v = splat<V>(dt);
  // sphere_pair_forces: the geometry and the motions
  const V ri = each([&](int l) { return sizes.radius(p[l].i); }), rj = each([&](int l) { return sizes.radius(p[l].j); });
  const V3 d = of_i(bodies.position) - of_j(bodies.position);
  const V reach = ri + rj + splat<V>(band);
  const V dist2 = dot(d, d);
  const V dist = sqrt2(dist2);
  const V3 n = {d.x / dist, d.y / dist, d.z / dist};
  const V gap = dist - ri - rj;  // m, < 0 where steady: the overlap is -gap
  const V lever_i = ri + half * gap, lever_j = rj + half * gap;
  const V3 spin = times(lever_i, of_i(bodies.angular_velocity)) + times(lever_j, of_j(bodies.angular_velocity));
  const V3 v_rel = (of_i(bodies.velocity) - of_j(bodies.velocity)) - cross(spin, n);
  const V3 v_end = of_i(bodies.velocity_end) - of_j(bodies.velocity_end);
  const V m = each([&](int l) { return sizes.pair_mass(p[l]); });  // kg
  // contact_force and exact_normal_force (weight 1: the law's products by it are exact)
  const V kn = splat<V>(law.kn);
  const V vn = dot(v_rel, n), r = -vn;  // m/s
  const V h_fd = each([&](int l) { return h[l]->fd; }), h_gap = each([&](int l) { return h[l]->gap; });
  const V spring = kn * -gap;                // N
  const V f_last = h_fd + kn * -h_gap;       // N
  const V f_rest = f_last + splat<V>(2.0) * m * (-dot(v_end, n) - r) / dt_v;  // N, rest_of_world
  const V sk = each([&](int l) { return step[l]->k; }), sc = each([&](int l) { return step[l]->c; });
  const V s_rest = each([&](int l) { return step[l]->rest; });
  const V u = sk * -gap + sc * r + s_rest * f_rest;  // N
  const V r_next = r + (f_rest - u) * dt_v / m;      // glued_ahead
  const V u_next = sk * (-gap + r_next * dt_v) + sc * r_next + s_rest * f_rest;
  const V fn = u + zero;  // N, + the push (0 here)
  const V fd = u - spring;
  const V dissipated = half * (h_fd + fd) * (h_gap - gap) + (zero + zero);  // + slip, started work
  // the tangential spring, turned and sticking
  const V3 vt = v_rel - times(vn, n);
  const V ft_max = splat<V>(law.mu) * fn;
  V3 ft = load<V>([&](int l) -> const Vec3& { return h[l]->ft; });
  const V length2 = dot(ft, ft);
  ft = ft - times(dot(ft, n), n);
  const V in_plane2 = dot(ft, ft);
  ft = select(in_plane2 > zero, times(sqrt2(length2 / in_plane2), ft), ft);
  ft = ft + times(-splat<V>(law.kt) * dt_v, vt);
  const V trial2 = dot(ft, ft);
  const auto steady = ~((dist2 >= reach * reach) | (dist2 == zero)) & (gap < zero) & (h_gap < zero) & (u > zero) &
                      ~(u_next <= zero) & (trial2 <= ft_max * ft_max);
  const V3 force = times(fn, n) + ft;
  const V3 nf = cross(n, force);  // N, n x F as sphere_pair_forces' scalars
  const V3 torque_i = {zero - lever_i * nf.x, zero - lever_i * nf.y, zero - lever_i * nf.z};
  const V3 torque_j = {-(lever_j * nf.x + zero), -(lever_j * nf.y + zero), -(lever_j * nf.z + zero)};
  for (int l = 0; l < 2; ++l) {
    if (!steady[l]) {
      take(l, nullptr);
      continue;
    }
    ContactHistory& hl = *h[l];
    hl.ft = lane(ft, l);
    hl.fd = fd[l];
    hl.gap = gap[l];
    hl.weight = 1.0;
    hl.slipping = false;  // under its cap
    PairTotals t;
    t.force_i = lane(force, l);
    t.torque_i = lane(torque_i, l);
    t.torque_j = lane(torque_j, l);
    t.energy = EnergyParts{dissipated[l], 0.0, 0.0, 0.0};
    t.contacts = 1;
    take(l, &t);
  }
}

}  // namespace polydem
