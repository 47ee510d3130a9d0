#pragma once
// Two sub-contacts of one pair through the linear law at once, one in each lane (geometry/lanes.hpp):
// the steady sticking case, nearly every sub-contact of a resting pile. Each lane does
// contact_force's operations in its order, so a lane has its bits; a lane whose contact is not
// steady is left untouched for contact_force (the caller's fallback).
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

// Applies the law to sub-contacts a and b (points g, weights w, histories h) where steady. Bit l
// of the result is set when lane l was: its force is in out[l], its torque about xi (N m) in
// torque[l], and its history h is advanced; the other lane's h, out and torque are left as they were.
[[gnu::always_inline]] inline unsigned steady_lanes(const LaneConstants& p, const ContactPoint& ga,
                                                    const ContactPoint& gb, double wa, double wb, ContactHistory& ha,
                                                    ContactHistory& hb, ContactForce out[2],
                                                    Vec3 torque[2]) {
  using namespace lanes;
  const V3 n = load(ga.normal, gb.normal);
  const V2 dn = V2{ga.gap, gb.gap}, w = V2{wa, wb};
  const V3 lever = load(ga.point, gb.point) - splat(p.xi);
  const V3 v_rel = splat(p.v_centre) + cross(splat(p.w_rel), lever);
  const V3 v_end = splat(p.v_centre_end) + cross(splat(p.w_rel_end), lever);
  const V2 h_fd = V2{ha.fd, hb.fd}, h_gap = V2{ha.gap, hb.gap}, h_w = V2{ha.weight, hb.weight};
  const V2 kn = splat(p.kn), zero = splat(0.0);
  // contact_force, the normal part (dashpot_normal_force of the linear law)
  const V2 vn = dot(v_rel, n);
  const V2 overlap = max0(-dn);
  const V2 spring = w * kn * overlap;
  const V2 overlap_last = max0(-h_gap);
  const V2 f_last = h_fd + h_w * kn * overlap_last;
  const V2 f_last_unit = h_w > zero ? f_last / h_w : zero;
  const V2 hm = splat(0.5 * p.dt) / splat(p.m_eff);
  const V2 c = splat(p.nu);
  const V2 vn_e = (dot(v_end, n) + hm * (splat(1.0) * kn * overlap - f_last_unit)) / (splat(1.0) + hm * c);
  const V2 u = w * kn * -dn - (w * c) * vn_e;
  const V2 fp = max0(u);
  const V2 fn = fp + zero;  // + the push (0 here)
  const V2 fd = fp - spring;
  const V2 dissipated = splat(0.5) * (h_fd + fd) * (h_gap - dn);
  V2 patch = splat(0.5) * kn * overlap_last * overlap * (w - h_w);
  // the tangential spring
  const V2 kt_w = w * splat(p.kt);
  V3 ft = load(ha.ft, hb.ft);
  const V2 reweighted = splat(0.5) * dot(ft, ft) * (h_w - w) / (splat(p.kt) * h_w * w);
  patch = patch + (h_w == w ? zero : reweighted);
  const V3 vt = v_rel - vn * n;
  const V2 ft_max = splat(p.mu) * fn;
  const V2 length2 = dot(ft, ft);
  ft = ft - dot(ft, n) * n;
  const V2 in_plane2 = dot(ft, ft);
  const V2 scale = sqrt(length2 / in_plane2);
  const Mask turn = in_plane2 > zero;
  ft = select(turn, scale * ft, ft);
  ft = ft + (-kt_w * splat(p.dt)) * vt;
  const V2 trial2 = dot(ft, ft);
  const Mask steady = (dn < zero) & (h_gap < zero) & ~((f_last > zero) & (u <= zero)) & (kt_w > zero) &
                      (trial2 <= ft_max * ft_max);
  const V3 force = fn * n + ft;
  const V3 moment = cross(lever, force);
  const V2 dissipated_all = dissipated + (zero + zero);  // + the slip (0) and a started spring's work (0)
  ContactHistory* h[2] = {&ha, &hb};
  unsigned done = 0;
  for (int l = 0; l < 2; ++l) {
    if (!steady[l]) continue;
    done |= 1u << l;
    h[l]->ft = lane(ft, l);
    h[l]->fd = fd[l];
    h[l]->gap = dn[l];
    h[l]->weight = w[l];
    h[l]->slipping = false;  // under its cap (steady)
    out[l] = ContactForce{lane(force, l), Vec3::Zero(), fn[l], dissipated_all[l], 0.0, patch[l], 0.0, 0.0};
    torque[l] = lane(moment, l);
  }
  return done;
}

}  // namespace polydem
