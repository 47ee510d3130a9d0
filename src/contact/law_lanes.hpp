#pragma once
// Two sub-contacts of one pair through the linear law at once (four in the AVX builds), one in
// each lane (geometry/lanes.hpp), or a lone one through the same code: the steady sticking case,
// nearly every sub-contact of a resting pile. Each lane does contact_force's operations in its
// order, so a lane has its bits; a lane whose contact is not steady is left untouched for
// contact_force (the caller's fallback).
// Steady: touching now and at the last step (dn < 0, gap < 0: no onset, no release), the clamp
// not letting go, kt_w > 0, the tangential spring under its cap. For the law of
// LawParts<NormalLinear, false, false, false> without the exact step or the contact's mass.
#include "contact/law.hpp"
#include "geometry/features.hpp"
#include "geometry/lanes.hpp"

namespace polydem {

// What the pair's sub-contacts share: apply_law's pair values (the motions relative to i's
// centre xi) and the law's constants.
struct LaneConstants {
  Vec3 xi, v_centre, w_rel, v_centre_end, w_rel_end;  // m, m/s, rad/s
  double m_eff, nu;                                  // kg, N s/m (the pair's, before weights)
  double kn, kt, mu, dt;                             // N/m, N/m, -, s
};

// m, m/s: a sub-contact's lever from i's centre and its relative velocities (apply_law's).
struct SubContactMotion {
  Vec3 lever, v_rel, v_end;
};
inline SubContactMotion sub_contact_motion(const Vec3& point, const Vec3& xi, const Vec3& v_centre, const Vec3& w_rel,
                                           const Vec3& v_centre_end, const Vec3& w_rel_end) {
  const Vec3 lever = point - xi;
  return {lever, v_centre + w_rel.cross(lever), v_centre_end + w_rel_end.cross(lever)};
}

// N = 4 runs only inlined into the AVX builds' copies (pair_loop.hpp's walk_chunk_avx): no call
// passes a 256-bit vector (the helpers here and in lanes.hpp are inlined: POLYDEM_LANE_INLINE), so
// GCC's note on their ABI without AVX does not apply.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
// Applies the law to sub-contacts g[0..N) (weights w, histories h), one per lane, where steady:
// N = 2 or 4, sub-contacts side by side; N = 1, a lone one through the same operations. Lane l's
// pair values are pc[l]'s: kAcross, two pairs' (their lone contacts, pair_lanes.hpp), else pc[0]'s
// for every lane (one pair's); the law's constants (kn, kt, mu, dt) are pc[0]'s.
// Bit l of the result is set when lane l was: its force is in out[l], its torque about its xi (N m)
// in torque[l], and its history h[l] is advanced; another lane's h, out and torque are left as they were.
// H: ContactHistory, or a sparse list's SlotState (the same springs by name, read and written in place).
template <int N, bool kAcross = false, class H>
[[gnu::always_inline]] inline unsigned steady_law(const LaneConstants* const pc[N], const ContactPoint* const g[N],
                                                  const double w_of[N], H* const h[N],
                                                  ContactForce out[N], Vec3 torque[N]) {
  using namespace lanes;
  using V = typename Types<N>::V;
  using V3 = Vec3Of<V>;
  const LaneConstants& p = *pc[0];
  const auto each = [&](auto get) POLYDEM_LANE_LAMBDA { return gather<V>(get); };
  // A pair value: lane by lane across pairs, one splat within a pair.
  const auto pair_vec = [&](Vec3 LaneConstants::*member) POLYDEM_LANE_LAMBDA {
    if constexpr (kAcross) return load<V>([&](int l) -> const Vec3& { return pc[l]->*member; });
    else return splat<V>(p.*member);
  };
  const auto pair_value = [&](double LaneConstants::*member) POLYDEM_LANE_LAMBDA {
    if constexpr (kAcross) return each([&](int l) { return pc[l]->*member; });
    else return splat<V>(p.*member);
  };
  const V3 n = load<V>([&](int l) -> const Vec3& { return g[l]->normal; });
  const V dn = each([&](int l) { return g[l]->gap; }), w = each([&](int l) { return w_of[l]; });
  const V3 lever = load<V>([&](int l) -> const Vec3& { return g[l]->point; }) - pair_vec(&LaneConstants::xi);
  const V3 v_rel = pair_vec(&LaneConstants::v_centre) + cross(pair_vec(&LaneConstants::w_rel), lever);
  const V3 v_end = pair_vec(&LaneConstants::v_centre_end) + cross(pair_vec(&LaneConstants::w_rel_end), lever);
  const V h_fd = each([&](int l) { return h[l]->fd; }), h_gap = each([&](int l) { return h[l]->gap; }),
          h_w = each([&](int l) { return h[l]->weight; });
  const V kn = splat<V>(p.kn), zero = splat<V>(0.0);
  // contact_force, the normal part (dashpot_normal_force of the linear law)
  const V vn = dot(v_rel, n);
  const V overlap = max0(-dn);
  const V spring = w * kn * overlap;
  const V overlap_last = max0(-h_gap);
  const V f_last = h_fd + h_w * kn * overlap_last;
  const V f_last_unit = h_w > zero ? f_last / h_w : zero;
  const V hm = splat<V>(0.5 * p.dt) / pair_value(&LaneConstants::m_eff);
  const V c = pair_value(&LaneConstants::nu);
  const V vn_e = (dot(v_end, n) + hm * (splat<V>(1.0) * kn * overlap - f_last_unit)) / (splat<V>(1.0) + hm * c);
  const V u = w * kn * -dn - (w * c) * vn_e;
  const V fp = max0(u);
  const V fn = fp + zero;  // + the push (0 here)
  const V fd = fp - spring;
  const V dissipated = splat<V>(0.5) * (h_fd + fd) * (h_gap - dn);
  // the tangential spring
  const V kt_w = w * splat<V>(p.kt);
  V3 ft = load<V>([&](int l) -> const Vec3& { return h[l]->ft; });
  // Where every lane kept its weight (a lone contact's 1), a steady lane's patch work is +0: the
  // normal spring's 1/2 kn x_last x (w - w_last) is +-0, the tangential one's select adds +0. So it
  // is not computed in the lanes of lone contacts (across pairs, or alone); within a pair weights move.
  V patch = zero;
  if (!((kAcross || N == 1) && all(h_w == w))) {
    patch = splat<V>(0.5) * kn * overlap_last * overlap * (w - h_w);
    const V reweighted = splat<V>(0.5) * dot(ft, ft) * (h_w - w) / (splat<V>(p.kt) * h_w * w);
    patch = patch + (h_w == w ? zero : reweighted);
  }
  const V3 vt = v_rel - vn * n;
  const V ft_max = splat<V>(p.mu) * fn;
  const V length2 = dot(ft, ft);
  ft = ft - dot(ft, n) * n;
  const V in_plane2 = dot(ft, ft);
  const V scale = sqrt(length2 / in_plane2);
  const auto turn = in_plane2 > zero;
  ft = select(turn, scale * ft, ft);
  ft = ft + (-kt_w * splat<V>(p.dt)) * vt;
  const V trial2 = dot(ft, ft);
  const auto steady = (dn < zero) & (h_gap < zero) & ~((f_last > zero) & (u <= zero)) & (kt_w > zero) &
                      (trial2 <= ft_max * ft_max);
  const V3 force = fn * n + ft;
  const V3 moment = cross(lever, force);
  const V dissipated_all = dissipated + (zero + zero);  // + the slip (0) and a started spring's work (0)
  unsigned done = 0;
  for (int l = 0; l < N; ++l) {
    if (!at(steady, l)) continue;
    done |= 1u << l;
    h[l]->ft = lane(ft, l);
    h[l]->fd = at(fd, l);
    h[l]->gap = at(dn, l);
    h[l]->weight = at(w, l);
    h[l]->slipping = false;  // under its cap (steady)
    out[l] = ContactForce{lane(force, l), Vec3::Zero(), at(fn, l), at(dissipated_all, l), 0.0, at(patch, l), 0.0, 0.0};
    torque[l] = lane(moment, l);
  }
  return done;
}
#pragma GCC diagnostic pop

// Sub-contacts a and b side by side (steady_law<2>).
template <class H>
[[gnu::always_inline]] inline unsigned steady_lanes(const LaneConstants& p, const ContactPoint& ga,
                                                    const ContactPoint& gb, double wa, double wb, H& ha, H& hb,
                                                    ContactForce out[2], Vec3 torque[2]) {
  const LaneConstants* const pc[2] = {&p, &p};
  const ContactPoint* const g[2] = {&ga, &gb};
  const double w[2] = {wa, wb};
  H* const h[2] = {&ha, &hb};
  return steady_law<2>(pc, g, w, h, out, torque);
}

// One sub-contact (steady_law<1>): true when it was steady and done.
template <class H>
[[gnu::always_inline]] inline bool steady_alone(const LaneConstants& p, const ContactPoint& g, double w, H& h,
                                                ContactForce& out, Vec3& torque) {
  const LaneConstants* const pc[1] = {&p};
  const ContactPoint* const gs[1] = {&g};
  H* const hs[1] = {&h};
  return steady_law<1>(pc, gs, &w, hs, &out, &torque) != 0;
}

}  // namespace polydem
