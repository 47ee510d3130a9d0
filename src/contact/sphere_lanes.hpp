#pragma once
// Two sphere pairs through the exact step at once, one in each lane (geometry/lanes.hpp), or one
// alone through the same code: the steady case, nearly every pair of a resting bed. What holds a
// pair up is its chain of dependent latencies (square root, the normal's division, the divisions by
// dt and by the pair mass, the spring's turn), not its instructions: two chains side by side take
// about the time of one. Each
// lane does sphere_pair_forces' operations in its order, so a lane has its pair's bits: the
// geometry, torques and exact step are the scalar path's own templates (sphere_contact,
// sphere_torques, rest_of_world, glued_ahead) taken on two lanes; what is written here is
// contact_force's steady branch, its tests turned into a mask.
// Steady: touching now and at the last step (no onset, no release), the glued arc not letting go
// within the step, the tangential spring under its cap. For LawParts<NormalLinear, false, false,
// false> with the exact step and friction, outside the steps that record contacts (lanes_fit).
#include <type_traits>

#include "contact/sphere_kernel.hpp"

namespace polydem {

using SteadyParts = LawParts<NormalLinear, false, false, false>;

// Whether the law is one steady_linear_law computes: linear with the exact step and friction.
template <class Parts>
bool steady_law_fits(const LawParams& law) {
  return std::is_same_v<Parts, SteadyParts> && law.exact_step && law.alpha_n > 0.0 && law.mu > 0.0 && law.kt > 0.0;
}
// Whether this step's pairs may take the lanes.
template <class Parts>
bool lanes_fit(const LawParams& law, const PairList& list) {
  return steady_law_fits<Parts>(law) && !list.recording;
}

// Whether pair k may be steady: overlapping at the last step, its k', c' made.
template <class Sizes>
[[gnu::always_inline]] inline bool steady_candidate(const PairList& list, std::uint32_t k, const Sizes& sizes) {
  const std::uint32_t s = list.slot_begin[k];
  return s != list.slot_begin[k + 1] && list.active[s] && list.slots[s].history.gap < 0.0 &&
         sizes.linear_step(k)->k != 0.0;
}

// What a steady contact's law gives (V: one contact, or two side by side), and where it is steady.
template <class V>
struct SteadyLawOf {
  V fn, fd;                 // N, the normal force and its dashpot share
  V dissipated;             // J, this step
  lanes::Vec3Of<V> ft;      // N, the tangential spring, turned and loaded
  lanes::Vec3Of<V> force;   // N, on i: fn n + ft
  typename lanes::Types<lanes::kWidth<V>>::Mask steady;  // overlapping now and at n, glued over the step, sticking
};
// Lanes' last steps: each one's history (H: ContactHistory or a sparse list's SlotState) and k',
// c' (read where the law reads them, in its order).
template <int N, class H = ContactHistory>
struct LastSteps {
  const H* h[N];
  const LinearStep* step[N];
};
// contact_force's steady branch for LawParts<NormalLinear> at weight 1 (the law's products by it
// are exact) with the exact step, written once for the sphere pairs and the sphere-wall pairs: n
// (unit, j to i), gap (m), v_rel and v_end (m/s, at the half step and the end), m (kg, the dashpot's
// mass) and the lanes' last steps.
template <class V, int N = lanes::kWidth<V>, class H = ContactHistory>
[[gnu::always_inline]] inline SteadyLawOf<V> steady_linear_law(const LawParams& law, double dt, const lanes::Vec3Of<V>& n,
                                                                V gap, const lanes::Vec3Of<V>& v_rel,
                                                                const lanes::Vec3Of<V>& v_end, V m,
                                                                const LastSteps<N, H>& last) {
  using namespace lanes;
  using V3 = Vec3Of<V>;
  const V zero = splat<V>(0.0), dt_v = splat<V>(dt);
  // exact_normal_force
  const V kn = splat<V>(law.kn);
  const auto each = [&](auto get) { return gather<V>(get); };
  const V vn = dot(v_rel, n), r = -vn;  // m/s
  const V h_fd = each([&](int l) { return last.h[l]->fd; }), h_gap = each([&](int l) { return last.h[l]->gap; });
  const V spring = kn * -gap;           // N
  const V f_last = h_fd + kn * -h_gap;  // N
  const V f_rest = rest_of_world(f_last, m, dt_v, r, -dot(v_end, n));  // N
  const LinearStepOf<V> k_c{each([&](int l) { return last.step[l]->k; }), each([&](int l) { return last.step[l]->c; }),
                            each([&](int l) { return last.step[l]->rest; })};
  const V u = k_c.force(-gap, r, f_rest);  // N
  const GluedAheadOf<V> next = glued_ahead(k_c, m, dt_v, -gap, r, u, f_rest);
  SteadyLawOf<V> out;
  out.fn = u + zero;  // N, + the push (0 here)
  out.fd = u - spring;
  out.dissipated = 0.5 * (h_fd + out.fd) * (h_gap - gap) + (zero + zero);  // + slip, started work
  // the tangential spring, turned and sticking
  const V3 vt = v_rel - vn * n;
  const V ft_max = splat<V>(law.mu) * out.fn;
  V3 ft = load<V>([&](int l) -> const Vec3& { return last.h[l]->ft; });
  const V length2 = dot(ft, ft);
  ft = ft - dot(ft, n) * n;
  const V in_plane2 = dot(ft, ft);
  ft = select(in_plane2 > zero, sphere_detail::root(length2 / in_plane2) * ft, ft);
  out.ft = ft + (-splat<V>(law.kt) * dt_v) * vt;
  const V trial2 = dot(out.ft, out.ft);
  // The glued arc not letting go within the step (!(u_next <= 0), as exact_normal_force's test).
  out.steady = (!(next.u <= zero)) & (gap < zero) & (h_gap < zero) & (u > zero) & (trial2 <= ft_max * ft_max);
  out.force = out.fn * n + out.ft;
  return out;
}

// Pairs ks[0..N) (steady candidates, in list order) side by side, N = 2, or one alone through the same
// operations, N = 1; then for each l in turn take(l, &totals) where lane l was steady (its slot
// advanced) or take(l, nullptr) where not (its slot untouched, for sphere_pair_forces).
template <int N, class Sizes, class Take>
[[gnu::always_inline]] inline void steady_sphere_pairs(const LawParams& law, double band, double dt,
                                                       const BodyView& bodies, PairList& list,
                                                       const std::uint32_t ks[N], const Sizes& sizes,
                                                       const Take& take) {
  using namespace lanes;
  using V = typename Types<N>::V;
  using V3 = Vec3Of<V>;
  BodyPair p[N];
  ContactHistory* h[N];
  LastSteps<N> last;
  for (int l = 0; l < N; ++l) {
    p[l] = list.pairs[ks[l]];
    last.h[l] = h[l] = &list.slots[list.slot_begin[ks[l]]].history;
    last.step[l] = sizes.linear_step(ks[l]);
  }
  const auto each = [&](auto get) { return gather<V>(get); };
  const auto of_i = [&](const Vec3* a) { return load<V>([&](int l) -> const Vec3& { return a[p[l].i]; }); };
  const auto of_j = [&](const Vec3* a) { return load<V>([&](int l) -> const Vec3& { return a[p[l].j]; }); };
  const V zero = splat<V>(0.0);
  // sphere_pair_forces: the geometry and the motions
  const V ri = each([&](int l) { return sizes.radius(p[l].i); }), rj = each([&](int l) { return sizes.radius(p[l].j); });
  const V3 d = of_i(bodies.position) - of_j(bodies.position);
  const V reach = ri + rj + splat<V>(band);
  const V dist2 = dot(d, d);
  const SphereContactOf<V> c = sphere_contact(d, dist2, ri, rj, of_i(bodies.velocity), of_j(bodies.velocity),
                                              of_i(bodies.angular_velocity), of_j(bodies.angular_velocity));
  const V3& n = c.n;
  const V gap = c.gap;  // m, < 0 where steady: the overlap is -gap
  const V3 v_end = of_i(bodies.velocity_end) - of_j(bodies.velocity_end);
  const V m = each([&](int l) { return sizes.pair_mass(p[l]); });  // kg
  const SteadyLawOf<V> f = steady_linear_law(law, dt, n, gap, c.v_rel, v_end, m, last);
  const auto steady = ~((dist2 >= reach * reach) | (dist2 == zero)) & f.steady;
  const V3& force = f.force;
  const PairTorquesOf<V> torques = sphere_torques(n, force, V3{zero, zero, zero}, c.lever_i, c.lever_j);  // no rolling moment
  for (int l = 0; l < N; ++l) {
    if (!at(steady, l)) {
      take(l, nullptr);
      continue;
    }
    ContactHistory& hl = *h[l];
    hl.ft = lane(f.ft, l);
    hl.fd = at(f.fd, l);
    hl.gap = at(gap, l);
    hl.weight = 1.0;
    hl.slipping = false;  // under its cap
    PairTotals t;
    t.force_i = lane(force, l);
    t.torque_i = lane(torques.i, l);
    t.torque_j = lane(torques.j, l);
    t.energy = EnergyParts{at(f.dissipated, l), 0.0, 0.0, 0.0};
    t.contacts = 1;
    take(l, &t);
  }
}

}  // namespace polydem
