#pragma once
// The contact force law (SPEC "Contact force law"), composed of parts in a fixed order as in
// LAMMPS GranularModel::calculate_forces: normal, damping, cohesion, tangential, rolling. Each
// part is a header in contact/law/ (its coefficients, force, stored energy, dissipation);
// LawParts<...> names the scene's choice and `contact_force<Parts>` is compiled without the
// parts it lacks. with_law (pair_loop.hpp) picks the instantiation once per step. The kernel is
// pure, (const LawParams&, const ContactKinematics&, ContactHistory&) -> ContactForce, and
// inline: it runs once per sub-contact per step.
//
// Energy budget, per sub-contact and step n -> n+1. Velocity Verlet's kicks apply F(n) and
// F(n+1) to the displacement of the step by the trapezoid rule (the kinetic energy changes by
// (F(n) + F(n+1))/2 . dx, up to dt^2/(8m) |F|^2, which does not accumulate), so each term is
// counted that way, second order in dt, and kinetic + elastic + sum(dissipated) - sum(patch)
// stays constant up to O(dt^2):
//  - the normal spring and cohesion are conservative: `elastic` holds w U(x) (1/2 kn_w x^2
//    for the linear spring) and the cohesion potential (negative: energy is needed to pull the
//    pair apart);
//  - the dashpot dissipates (f_d(n) + f_d(n+1))/2 (x(n+1) - x(n)), f_d = (clamped normal force)
//    - (spring force), x the overlap. Counting f_d(n+1) vn(n+1/2) dt instead (the force on the
//    velocity half a step before it) is first order: 1.5-3.5% of the input high at
//    dt = 0.1 x critical;
//  - the tangential and rolling springs store |f|^2/(2k); slip under the Coulomb cap
//    dissipates (capped_spring: already the trapezoid rule), and what they hold when the
//    contact ends is lost;
//  - patch weights change from step to step, so w U(x) and |f|^2/(2k_w) are not potentials:
//    `patch` is what a weight (or stiffness) change adds to the springs (normal linear: 1/2 kn
//    x(n) x(n+1) (w(n+1) - w(n)), the trapezoid work minus the change of 1/2 kn w x^2), 0 for a
//    lone linear contact; the pair kernels count dissipated - patch in the ledger's `dissipated`
//    (1% of the input in a box fill: the largest term after the dashpot's);
//  - a contact that starts was a stroke vn dt apart one step back (its dashpot force acts on
//    the whole step), and one that ends takes its dashpot force to zero overlap.
// What is left is the spring's own O(dt^2) error where the force switches on or off within
// a step (random in sign). ContactHistory keeps the last step's f_d, gap and weight.
//
// Coulomb and rolling caps use the compressive force fp = max(kn_w x - nu_w vn, 0) (cohesion
// excluded), not SPEC's elastic part kn_w x: with the no-pull clamp the contact releases
// while x > 0, and kn_w x keeps a friction force with no normal force on the tail, so the
// tangential impulse is mu (J_n - nu x_c/2) and the oblique sliding law is off by
// 2 alpha^2 e/(1+e) (11% of the spin at e = 0.3); with fp it is exact (test_law_oblique.cpp).
#include <algorithm>
#include <cmath>

#include "contact/law/cohesion.hpp"
#include "contact/law/damping_linear.hpp"
#include "contact/law/exact_linear.hpp"
#include "contact/law/normal_hertz.hpp"
#include "contact/law/normal_linear.hpp"
#include "contact/law/rolling.hpp"
#include "contact/law/second_order.hpp"
#include "contact/law/tangential_dashpot.hpp"
#include "contact/law/tangential_spring.hpp"
#include "contact/law/types.hpp"
#include "polydem/contact_params.hpp"

namespace polydem {

// The law of p (the parser has checked its ranges): solves alpha_n from en when en is given,
// and for Hertz combines the moduli of p's material with `particle`'s (the driver law: config;
// nullptr: p's own, the particle law).
LawParams prepare_law(const ContactParams& p, const ContactParams* particle = nullptr);

// The scene's law: a normal part (with its damping) and which optional parts it has. The
// tangential spring is always compiled in and switched by mu > 0 and kt_w > 0 at run time
// (a sub-contact at the band edge has w = 0), as it was.
template <class NormalPart, bool kCohesion, bool kRolling, bool kTangentialDashpot>
struct LawParts {
  using Normal = NormalPart;
  static constexpr bool cohesion = kCohesion, rolling = kRolling, tangential_dashpot = kTangentialDashpot;
};
// Every optional part switched by LawParams' flags at run time: for callers of one contact.
template <class Normal>
using AllParts = LawParts<Normal, true, true, true>;

// Calls run(parts) with AllParts of law's normal part: the run-time choice for cold callers.
template <class Run>
decltype(auto) with_normal(const LawParams& law, const Run& run) {
  if (law.normal == NormalModel::hertz) return run(AllParts<NormalHertz>{});
  return run(AllParts<NormalLinear>{});
}

namespace law_detail {
// N/m, the tangential stiffness of the last step's state in h (weight included).
template <class Parts>
double last_tangential_stiffness(const LawParams& law, const ContactHistory& h, double r_star) {
  return h.weight * Parts::Normal::tangential_stiffness(law, r_star, std::max(-h.gap, 0.0));
}
}  // namespace law_detail

// J, stored in the normal, cohesion, tangential and rolling springs of a contact whose last
// step left h (0 for one with no last step), per spring: energy.csv sums them on output steps.
template <class Parts>
StoredParts stored_parts(const LawParams& law, const ContactHistory& h, double r_star = 0.0) {
  const double w = h.weight;
  const double overlap = std::max(-h.gap, 0.0);  // m
  StoredParts e;
  e.normal = Parts::Normal::energy(law, r_star, w, overlap);
  if (Parts::cohesion && law.cohesion) e.normal += cohesion_potential(w * law.fc, law.dncut, h.gap);
  const double kt_w = law_detail::last_tangential_stiffness<Parts>(law, h, r_star);  // N/m
  if (law.mu > 0.0 && kt_w > 0.0) e.tangential = spring_energy(h.ft, kt_w);
  if (Parts::rolling && law.rolling) e.rolling = spring_energy(h.mr, w * law.kr);
  return e;
}
// J, their sum (ContactForce::elastic, for callers of one contact).
template <class Parts>
double stored_energy(const LawParams& law, const ContactHistory& h, double r_star = 0.0) {
  const StoredParts e = stored_parts<Parts>(law, h, r_star);
  return e.normal + e.tangential + e.rolling;
}

// J, dissipated by a contact that ends (its last state in h): the dashpot's last force over
// the way out to zero overlap (with the clamp on, all the normal spring held), cohesion out to
// the band edge, and the energy of the tangential (`sliding`) and rolling springs. Nothing for
// a contact with no last step (h.gap = kNoGap, fd = 0) but its springs.
template <class Parts>
EnergyParts released_energy(const LawParams& law, const ContactHistory& h, double r_star = 0.0) {
  EnergyParts e;
  e.sliding = spring_energy(h.ft, law_detail::last_tangential_stiffness<Parts>(law, h, r_star));
  e.rolling = spring_energy(h.mr, h.weight * law.kr);
  e.net = 0.5 * h.fd * std::min(h.gap, 0.0) + e.sliding + e.rolling;
  if (Parts::cohesion && law.cohesion) e.net += cohesion_dissipated(law, h.weight, std::min(h.gap, law.dncut), h.weight, law.dncut);
  return e;
}

namespace law_detail {
// N, the compressive normal force fp = max(spring - nu_w vn_e, 0) at n+1, vn_e the dashpot's
// velocity (second_order.hpp), with the linear law's dashpot push where the overlap starts
// (Hertz: onset_force and released_force, normal_hertz.hpp); and `push`, the spring's part of that push and the push where the clamp lets go
// or the overlap ends. The push is a correction of the spring's impulse: kept out of the dashpot's share (the
// ledger, the last force in h.fd), so an elastic contact dissipates nothing and a release is
// seen once. kLone: the weight is 1 at n and n+1 (the sphere path), so nothing is divided by it.
struct NormalForce {
  double fp = 0.0, push = 0.0;  // N
  // N, the patch push's dashpot and spring parts (in push: h.fd keeps the force at n+1 without
  // them, as a weight near 0 at a late touch would blow them up per unit weight next step).
  double patch_dashpot = 0.0, patch_spring = 0.0;
  bool sampled = false;  // the exact step's force: a two-step average, not the force at n+1
  double since_touch = 0.0;  // s, the exact onset's time since its arc's touch (0: no exact onset)
};
// The linear law's normal pair of a contact whose m_eff is its point's mass (exact_linear.hpp).
template <bool kLone>
[[gnu::always_inline]] inline NormalForce exact_normal_force(const LawParams& law, const ContactKinematics& k,
                                                             const ContactHistory& h, double dt, double vn,
                                                             double f_last) {
  const double overlap = std::max(-k.dn, 0.0);  // m
  const LinearStep step = k.linear_step ? cached_linear_step(*k.linear_step, law.kn, law.alpha_n, k.m_eff, dt)
                                        : linear_step(law.kn, law.alpha_n, k.m_eff, dt);
  const double f_last_unit = kLone ? f_last : (h.weight > 0.0 ? f_last / h.weight : 0.0);  // N, per unit weight
  const double f_rest = rest_of_world(f_last_unit, k.m_eff, dt, -vn, -k.v_end.dot(k.normal));  // N
  const double u = k.weight * step.force(-k.dn, -vn, f_rest);  // N, unclamped, signed: -dn inside the overlap
  NormalForce out;
  out.sampled = true;
  if (overlap > 0.0 && h.gap >= 0.0 && vn < 0.0 && k.patch_depth >= 0.0) {
    const ExactOnset onset = exact_onset_force(law.kn, law.alpha_n, k.m_eff, dt, overlap, -vn);
    out.fp = k.weight * onset.force;
    out.since_touch = onset.since_touch;
  } else if (overlap > 0.0 && u > 0.0) {
    out.fp = u;
    const GluedAheadOf<double> next = glued_ahead(step, k.m_eff, dt, overlap, -vn, u / k.weight, f_rest);
    if (next.u <= 0.0) [[unlikely]] {  // it lets go within the step
      double push = release_ahead(u / k.weight, next.u, dt);  // N per unit weight
      // The overlap ends by a + 1 past the band (0 without cohesion): the kernels will not see
      // the contact there, so its push behind is given now (en 0.9 at 0.3 x critical: 3.5% -> 0.4%).
      if (-next.x >= (law.cohesion ? law.dncut : 0.0)) push += release_behind(u / k.weight, next.u, dt);
      out.push = k.weight * push;
    }
  }
  if (f_last > 0.0 && u <= 0.0) out.push = release_behind(f_last, u, dt);
  return out;
}

// s, how long a spring on within gap `edge` (m) has been on (spring_on_time): where the exact
// onset is taken, from its arc's touch, the normal impact being the exact one shifted by that
// lag (rolling impact at 0.3 x critical, worst of 16 touch places: 3.95e-2 -> 1.13e-2).
[[gnu::always_inline]] inline double springs_on_time(const NormalForce& normal, double edge, double gap_last,
                                                     double dn, double vn, double dt) {
  if (gap_last < edge || dn >= edge || vn >= 0.0) [[likely]] return dt;  // on the whole step
  if (normal.since_touch > 0.0 && edge == 0.0) return normal.since_touch;
  return spring_on_time(edge, gap_last, dn, vn, dt);
}

// N (N m), added to a spring that slips under the exact step, `capped` at the cap the force at
// n+1 gives (fp, N: what the stick test compares): the kicks take the cap of the `sampled` force
// (N) instead, a hat average whose impulses sum to the normal impulse, so a slip's impulse is the
// cap's (rolling impact at 0.3 x critical: 1.13e-2 -> 3.72e-3, the release's kink no longer cut).
[[gnu::noinline]] inline Vec3 sampled_cap_push(const Vec3& capped, double sampled, double fp) {
  if (fp <= 0.0) return Vec3::Zero();  // capped at 0: nothing to scale
  return (sampled / fp - 1.0) * capped;
}

// N, the tangential dashpot's share of the cap at n (N, the cap mu fp then), for the slip push of
// a spring that stuck then: its force at the velocity at n, 2 vt - vt_end (vt at n+1/2, vt_end the
// prediction at n+1, half a kick of the same forces further; m/s), nu_t_w (N s/m) the dashpot.
[[gnu::noinline]] inline double last_dashpot_share(const Vec3& vt, const Vec3& vt_end, double nu_t_w, double cap) {
  return std::min(nu_t_w * (2.0 * vt - vt_end).norm(), cap);
}

// N, fp at n: the last step's clamped normal force (without its push).
template <class Normal, bool kLone>
[[gnu::always_inline]] inline double last_normal_force(const LawParams& law, const ContactKinematics& k,
                                                       const ContactHistory& h) {
  const double weight_last = kLone ? 1.0 : h.weight;  // -
  return h.fd + Normal::spring(law, k.r_star, weight_last, std::max(-h.gap, 0.0));
}

// s, how long the tangential spring has been on over this step where it was zero at n (`on`,
// s: the time since the touch; share_opened_time): the margin the dashpot left under the cap at
// n (its force at the velocity at n, 2 vt - vt_end; fp_last, N, the normal force then) and now
// (cap, N, mu fp; nu_t_w, N s/m, the dashpot now; nu_t_last, then).
[[gnu::noinline]] inline double spring_free_time(const Vec3& vt, const Vec3& vt_end, double nu_t_w, double nu_t_last,
                                                 double cap, double cap_last, double on, double dt) {
  if (on != dt) return on;  // it started this step: from the touch
  return share_opened_time(cap_last - nu_t_last * (2.0 * vt - vt_end).norm(), cap - nu_t_w * vt_end.norm(), dt);
}

// The end-of-step dashpot (second_order.hpp) with the onset and release pushes.
template <class Normal, bool kLone>
[[gnu::always_inline]] inline NormalForce dashpot_normal_force(const LawParams& law, const ContactKinematics& k,
                                                               const ContactHistory& h, double dt, double vn,
                                                               double spring, double f_last) {
  const double overlap = std::max(-k.dn, 0.0);  // m
  const double nu_pair = k.nu >= 0.0 ? k.nu : Normal::pair_damping(law, k.m_eff, k.r_star);  // N s/m
  const double c = Normal::damping(nu_pair, overlap);  // N s/m, per unit weight
  const double f_last_unit = kLone ? f_last : (h.weight > 0.0 ? f_last / h.weight : 0.0);  // N, per unit weight
  const double spring_unit = kLone ? spring : Normal::spring(law, k.r_star, 1.0, overlap);  // N (kLone: weight 1)
  NormalForce out;
  if constexpr (Normal::kCurved) {
    const double nu = k.weight * nu_pair;  // N s/m
    // Both corrections in fp, the dashpot's share, so the ledger counts their work: kept out, as
    // the linear law's push, en 0.9's ledger after an impact at 0.3 x critical was 3.2% off, in
    // fp 2.0% (2.7% before them; the kernel alone, worst of 16 touch places).
    if (overlap > 0.0 && h.gap >= 0.0 && vn < 0.0 && k.patch_depth >= 0.0) {
      out.fp = Normal::onset_force(law, k.r_star, k.weight, nu, k.m_eff, overlap, -vn, dt);
    } else if (overlap > 0.0) {
      const double inv_m = 1.0 / k.m_eff, vn_end = k.v_end.dot(k.normal);  // 1/kg, m/s
      // m/s, closing: the velocity at n to O(dt^3), v(n-1/2) + a(n-1) dt/6 + a(n) dt/3 (README, Hertz).
      const double r = -implicit_velocity(vn_end, spring_unit, c, f_last_unit, dt / 3.0 * inv_m);
      // Undamped, velocity Verlet's spring sample is second order in en (the hat: 9.3e-4 at 0.1 x critical for 6.2e-4).
      const double f = c > 0.0 ? k.weight * Normal::hat_force(law, k.r_star, nu_pair, spring_unit, c, overlap, r,
                                                              vn - vn_end, f_last_unit, inv_m, dt)
                               : spring;  // N
      out.fp = std::max(f, 0.0);
      if (r < 0.0) out.fp = Normal::released_force(law, k.r_star, k.weight, nu, overlap, r, dt, out.fp);
    }
  } else {
    const double vn_e = dashpot_velocity(k.v_end.dot(k.normal), spring_unit, c, f_last_unit, k.m_eff, 0.5 * dt);  // m/s
    const double nu_w = k.weight * c;  // N s/m
    // N, unclamped and signed: the spring at -dn is `spring` inside the overlap (one evaluation).
    const double u = Normal::spring(law, k.r_star, k.weight, -k.dn) - nu_w * vn_e;
    if (overlap > 0.0) out.fp = std::max(u, 0.0);
    if (k.patch_push) [[unlikely]] {  // a patch whose sub-contacts start within the step (patch_push.hpp)
      out.patch_dashpot = std::max(-c * vn_e, 0.0) * k.patch_push->dashpot;
      if (c > 0.0) out.patch_spring = Normal::spring(law, k.r_star, 1.0, k.patch_push->spring);
      out.push = out.patch_dashpot + out.patch_spring;
      const double spring_moment = c > 0.0 ? Normal::spring(law, k.r_star, 1.0, k.patch_push->spring_moment) : 0.0;
      k.patch_push->moment = std::max(-c * vn_e, 0.0) * k.patch_push->dashpot_moment + spring_moment;  // N s^2
      if (f_last > 0.0 && u <= 0.0) out.push += release_force(f_last, u, dt);  // its clamp lets go as well
    } else if (overlap > 0.0 && h.gap >= 0.0 && vn < 0.0 && k.patch_depth >= 0.0) {
      const OnsetForce onset = onset_force(std::max(overlap, k.patch_depth), vn, std::max(-nu_w * vn_e, 0.0), spring, dt);
      out.fp += onset.dashpot;
      // The spring's push pairs with the one where the clamp lets go, inside the overlap: an
      // undamped contact ends at x = 0, where the kernels no longer see it (band 0), so it
      // takes neither (pushing on one side only would add k v^2 dt^2/8 per contact).
      if (c > 0.0) out.push = onset.spring;
    } else if (f_last > 0.0 && u <= 0.0) {
      out.push = release_force(f_last, u, dt);
    }
  }
  return out;
}

template <class Normal, bool kLone>
[[gnu::always_inline]] inline NormalForce normal_force(const LawParams& law, const ContactKinematics& k,
                                                       const ContactHistory& h, double dt, double vn, double spring) {
  const double f_last = last_normal_force<Normal, kLone>(law, k, h);  // N
  if constexpr (!Normal::kCurved) {
    // Undamped, velocity Verlet's spring is exact but where it switches: its ledger stays closed.
    if (law.exact_step && (kLone || k.exact_step) && law.alpha_n > 0.0) return exact_normal_force<kLone>(law, k, h, dt, vn, f_last);
  }
  return dashpot_normal_force<Normal, kLone>(law, k, h, dt, vn, spring, f_last);
}

// N, the compressive force at n+1 the caps scale with where the exact step's force is a
// two-step average (a hat): the end-of-step dashpot's, second order in time as Coulomb's law
// wants it (oblique 45 deg at 0.3 x critical: 9.2e-3 with the sampled force, 2.7e-3). Out of
// line, with k's and h's scalars by value: their addresses passed out would keep the kernel's
// k and h whole in memory on every contact (+5% instructions on the sphere bed).
template <class Normal, bool kLone>
[[gnu::noinline]] double end_of_step_force(const LawParams& law, double dn, double vn_end, double m_eff, double weight,
                                           double nu, double r_star, double fd_last, double gap_last,
                                           double weight_last, double dt, double vn, double spring) {
  ContactKinematics k{};
  k.normal = Vec3::UnitZ(), k.v_end = Vec3(0.0, 0.0, vn_end);
  k.dn = dn, k.m_eff = m_eff, k.weight = weight, k.nu = nu, k.r_star = r_star;
  const ContactHistory h{Vec3::Zero(), fd_last, gap_last, weight_last};
  const NormalForce f = dashpot_normal_force<Normal, kLone>(law, k, h, dt, vn, spring, last_normal_force<Normal, kLone>(law, k, h));
  return f.fp + f.push;
}
}  // namespace law_detail

// Whether contact_force fills ContactForce::elastic. The kernels skip it: the ledger's stored
// energy is summed over the lists on output steps (ContactEngine::elastic), and its sqrt and pow
// (Hertz: x^2.5, Mindlin's kt) stay in the loop though unread, as calls that may set errno.
enum class Stored : bool { kSkip = false, kFill = true };

// The parts in order: normal with damping, cohesion, tangential spring (and dashpot), rolling.
// kLone: a contact alone in its pair, weight 1 throughout (the sphere path).
template <class Parts, bool kLone = false, Stored kStored = Stored::kFill>
[[gnu::always_inline]] inline ContactForce contact_force(const LawParams& law, const ContactKinematics& k,
                                                         ContactHistory& h, double dt) {
  using Normal = typename Parts::Normal;
  const bool cohesion = Parts::cohesion && law.cohesion, rolling = Parts::rolling && law.rolling;
  const bool tangential_damping = Parts::tangential_dashpot && law.tangential_damping;
  const double w = k.weight;
  ContactForce out{Vec3::Zero(), Vec3::Zero(), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const double reach = cohesion ? law.dncut : 0.0;  // m, beyond it the pair does not interact
  const double vn = k.v_rel.dot(k.normal);          // m/s, half-step, > 0 when separating
  if (k.dn >= reach) {
    // Out of reach: the springs let go and their energy is lost (the caller resets history
    // anyway); a normal force that fell to zero within the step leaves its last push.
    const EnergyParts released = released_energy<Parts>(law, h, k.r_star);
    out.dissipated = released.net;
    out.sliding = released.sliding;
    out.rolling = released.rolling;
    if (!Normal::kCurved && h.gap < 0.0) {
      out.fn = law_detail::normal_force<Normal, kLone>(law, k, h, dt, vn, 0.0).push;
      out.force = out.fn * k.normal;
    }
    h = ContactHistory{};
    return out;
  }
  const double overlap = std::max(-k.dn, 0.0);  // m
  const double spring = Normal::spring(law, k.r_star, w, overlap);  // N
  // A contact that starts: one step back it was a stroke vn dt away, with no dashpot force.
  if (h.gap == kNoGap) {
    h.fd = 0.0;
    h.gap = k.dn - vn * dt;
    h.weight = w;
  }
  const law_detail::NormalForce normal = law_detail::normal_force<Normal, kLone>(law, k, h, dt, vn, spring);
  out.fn = normal.fp + normal.push;  // N
  double fp = out.fn;  // N, the compressive force the caps scale with
  bool at_end = !normal.sampled;  // whether fp is the force at n+1 (end_of_step_force)
  // Where a spring passes the sampled force's cap, the caps read the force at n+1 instead: a
  // contact that sticks under it does not pay for it.
  const auto fp_at_slip = [&] {
    if (!at_end)
      fp = law_detail::end_of_step_force<Normal, kLone>(law, k.dn, k.v_end.dot(k.normal), k.m_eff, w, k.nu, k.r_star, h.fd,
                                                        h.gap, h.weight, dt, vn, spring);
    at_end = true;
    return fp;
  };
  const double fd = normal.fp - spring;  // N, the dashpot's share after the clamp
  out.dissipated = 0.5 * (h.fd + fd) * (h.gap - k.dn);  // trapezoid, as the kicks apply it
  const double overlap_last = std::max(-h.gap, 0.0);    // m
  out.patch = Normal::patch(law, k.r_star, overlap_last, overlap, h.weight, w);
  if (k.patch_push) [[unlikely]] {  // its impulse (N s) at n+1 works across the velocity there (m/s)
    const double stroke = k.v_end.dot(k.normal) * dt;  // m
    out.dissipated -= normal.patch_dashpot * stroke;  // the dashpot's
    out.patch += normal.patch_spring * stroke;        // the springs' under moving shares, as the weights'
  }
  if (cohesion) {
    out.fn += cohesion_force(w * law.fc, law.dncut, k.dn);
    out.dissipated += cohesion_dissipated(law, h.weight, h.gap, w, k.dn);
  }
  Vec3 damper = Vec3::Zero();  // N, tangential dashpot
  Vec3 push_t = Vec3::Zero();  // N, the tangential spring's push where it starts or starts to slip
  bool pushed = false;
  const double kt_w = w * Normal::tangential_stiffness(law, k.r_star, overlap);  // N/m
  if (law.mu > 0.0 && kt_w > 0.0) {
    out.patch += Normal::tangential_patch(law, k.r_star, h.ft, overlap_last, h.weight, overlap, w);
    const Vec3 vt = k.v_rel - vn * k.normal;  // m/s, tangential relative velocity
    if (tangential_damping) fp_at_slip();  // the dashpot takes its share of the cap first
    double ft_max = law.mu * fp;  // N
    const auto nu_t = [&] { return k.nu_t >= 0.0 ? k.nu_t : pair_tangential_damping(law, k.m_eff); };  // N s/m, before the weight
    const auto vt_end = [&] { return Vec3(k.v_end - k.v_end.dot(k.normal) * k.normal); };  // m/s, what the dashpot reads
    if (tangential_damping) damper = tangential_dashpot(vt_end(), vt, w * nu_t(), ft_max, out.dissipated, dt);
    // The linear spring is on within reach, Hertz's (kt ~ x^1/2) within the overlap.
    double dt_on = law_detail::springs_on_time(normal, Normal::kCurved ? 0.0 : reach, h.gap, k.dn, vn, dt);  // s
    if (tangential_damping && h.ft == Vec3::Zero()) [[unlikely]]  // held at zero by the dashpot, or new
      dt_on = law_detail::spring_free_time(vt, vt_end(), w * nu_t(), h.weight * nu_t(), law.mu * fp,
                                           law.mu * law_detail::last_normal_force<Normal, kLone>(law, k, h), dt_on, dt);
    // Where the exact normal step is taken (spheres, the same bits on the sphere and general
    // paths): on polyhedra an undamped cube heap stopped ringing with them (test_rest), not understood.
    const bool kink_pushes = law.exact_step && (kLone || k.exact_step);
    const auto on_slip = [&](double old2, const Vec3& trial_spring, double trial, double cap) {
      // Only where a spring that stuck at n starts to slip (a sliding one has no kink).
      if (!kink_pushes || h.slipping || cap <= 0.0) return;
      // The cap at n at least |old| (without it, 1.34e-2 at 0.26 x critical for 8.2e-3 at 0.2601),
      // less the dashpot's share then (at the velocity at n, vt less the kick's half: v_end - vt).
      const double fp_last = law_detail::last_normal_force<Normal, kLone>(law, k, h);  // N
      const double share = tangential_damping ? law_detail::last_dashpot_share(vt, vt_end(), h.weight * nu_t(), law.mu * fp_last) : 0.0;
      push_t = slip_start_push_along(old2, trial_spring, trial, cap, law.mu * fp_last - share);
      pushed = true;
    };
    out.sliding = tangential_spring(h.ft, k.normal, vt, kt_w, ft_max, dt_on,
                                    [&](double cap) { return at_end ? cap : law.mu * fp_at_slip(); }, on_slip);
    out.dissipated += out.sliding + started_spring_work(h.ft, vt, dt - dt_on);
    // Capped (a cap of 0 on a spring of 0 slips nothing: it cannot kink); kept only where the
    // pushes read it, so the checkpoints of contacts without them keep the slot byte a constant 1.
    h.slipping = kink_pushes && out.sliding != 0.0;
    if (kink_pushes && dt_on != dt && !h.slipping) [[unlikely]] {  // started and sticking: the ramp's push
      push_t = started_spring_push(vt, kt_w, dt_on, dt);
      pushed = true;
    }
    if (out.sliding != 0.0) [[unlikely]] {
      if (kink_pushes && normal.sampled) {  // spring and dashpot together at the cap
        push_t += law_detail::sampled_cap_push(tangential_damping ? Vec3(h.ft + damper) : h.ft, normal.fp + normal.push, fp);
        pushed = true;
      }
    }
    if (pushed) [[unlikely]] out.dissipated -= push_t.dot(vt) * dt;  // what the kicks take from the bodies for it
  } else if constexpr (Normal::kCurved) {
    // Hertz in the cohesion band (x = 0, so kt = 0): the tangential spring lets go.
    if (overlap == 0.0 && h.ft.squaredNorm() > 0.0) {
      out.sliding = spring_energy(h.ft, h.weight * Normal::tangential_stiffness(law, k.r_star, overlap_last));
      out.dissipated += out.sliding;
      h.ft = Vec3::Zero();
    }
  }
  if (rolling) {
    out.patch += reweighted(h.mr, law.kr, h.weight, w);
    // s, the rolling spring (kr constant) is on within reach: from the touch where it starts.
    const double on = law_detail::springs_on_time(normal, reach, h.gap, k.dn, vn, dt);
    const bool kink_pushes = law.exact_step && (kLone || k.exact_step);  // as the tangential spring's
    Vec3 push_r = Vec3::Zero();  // N m, the rolling spring's push where it starts or starts to slip
    const auto on_roll_slip = [&](double old2, const Vec3& trial_spring, double trial, double cap) {
      if (!kink_pushes || h.rolling_slipping || cap <= 0.0) return;  // as the tangential spring's
      push_r = slip_start_push_along(old2, trial_spring, trial, cap,
                                     law.mur * k.lever * law_detail::last_normal_force<Normal, kLone>(law, k, h));
    };
    rolling_spring(law, k, fp, on, h, out.rolling, fp_at_slip, on_roll_slip);
    out.dissipated += out.rolling + started_spring_work(h.mr, k.w_rel, dt - on);
    h.rolling_slipping = kink_pushes && out.rolling != 0.0;
    if (kink_pushes && on != dt && !h.rolling_slipping) [[unlikely]]  // started and sticking: the ramp's push
      push_r = started_spring_push(k.w_rel, w * law.kr, on, dt);
    if (out.rolling != 0.0) [[unlikely]] {
      if (kink_pushes && normal.sampled) push_r += law_detail::sampled_cap_push(h.mr, normal.fp + normal.push, fp);
    }
    out.moment = h.mr;
    if (push_r != Vec3::Zero()) [[unlikely]] {
      out.moment += push_r;
      out.dissipated -= push_r.dot(k.w_rel) * dt;  // what the kicks take from the bodies for it
    }
  }
  h.fd = fd;
  h.gap = k.dn;
  h.weight = w;
  out.force = out.fn * k.normal + h.ft;
  if (pushed) [[unlikely]] out.force += push_t;
  if (tangential_damping) out.force += damper;
  if constexpr (kStored == Stored::kFill) out.elastic = stored_energy<Parts>(law, h, k.r_star);  // J, for callers of one contact
  return out;
}

// The same, choosing the parts at run time from law (tests, energy sums on output steps,
// contacts that end in a hand-over).
inline StoredParts stored_parts(const LawParams& law, const ContactHistory& h, double r_star = 0.0) {
  return with_normal(law, [&](auto parts) { return stored_parts<decltype(parts)>(law, h, r_star); });
}
inline double stored_energy(const LawParams& law, const ContactHistory& h, double r_star = 0.0) {
  return with_normal(law, [&](auto parts) { return stored_energy<decltype(parts)>(law, h, r_star); });
}
inline EnergyParts released_energy(const LawParams& law, const ContactHistory& h, double r_star = 0.0) {
  return with_normal(law, [&](auto parts) { return released_energy<decltype(parts)>(law, h, r_star); });
}
inline ContactForce contact_force(const LawParams& law, const ContactKinematics& k, ContactHistory& h, double dt) {
  return with_normal(law, [&](auto parts) { return contact_force<decltype(parts)>(law, k, h, dt); });
}

}  // namespace polydem
