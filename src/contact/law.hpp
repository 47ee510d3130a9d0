#pragma once
// The contact force law (SPEC "Contact force law"): a pure kernel
// (const LawParams&, const ContactKinematics&, ContactHistory&) -> ContactForce, composed of
// slots in a fixed order as in LAMMPS GranularModel::calculate_forces: normal, damping,
// cohesion, tangential, rolling. Inline: it runs once per sub-contact per step.
//
// Energy budget, per sub-contact and step n -> n+1. Velocity Verlet's kicks apply F(n) and
// F(n+1) to the displacement of the step by the trapezoid rule (the kinetic energy changes by
// (F(n) + F(n+1))/2 . dx, up to dt^2/(8m) |F|^2, which does not accumulate), so each term is
// counted that way, second order in dt, and kinetic + elastic + sum(dissipated) - sum(patch)
// stays constant up to O(dt^2):
//  - the normal spring and cohesion are conservative: `elastic` holds 1/2 kn_w x^2 and the
//    cohesion potential (negative: energy is needed to pull the pair apart);
//  - the dashpot dissipates (f_d(n) + f_d(n+1))/2 (x(n+1) - x(n)), f_d = (clamped normal force)
//    - (spring force), x the overlap. Counting f_d(n+1) vn(n+1/2) dt instead (the force on the
//    velocity half a step before it) is first order: 1.5-3.5% of the input high at
//    dt = 0.1 x critical;
//  - the tangential and rolling springs store |f|^2/(2k); slip under the Coulomb cap
//    dissipates (capped_spring: already the trapezoid rule), and what they hold when the
//    contact ends is lost;
//  - patch weights change from step to step, so 1/2 kn_w x^2 and |f|^2/(2k_w) are not
//    potentials: `patch` is what a weight change adds to the springs (normal: 1/2 kn x(n)
//    x(n+1) (w(n+1) - w(n)), the trapezoid work minus the change of 1/2 kn w x^2), 0 for a
//    lone contact; the pair kernels count dissipated - patch in the ledger's `dissipated`
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
#include <limits>

#include "polydem/contact_params.hpp"
#include "polydem/math.hpp"

namespace polydem {

// Prepared once per parameter set (config or config_driver) by prepare_law.
struct LawParams {
  double kn, kt, kr, mur, mu;  // N/m, N/m, N m/rad, -, -
  double alpha_n;              // -, damping ratio: from damp_rate, or solved so the clamped law returns en
  double alpha_t;              // -, tangential damping ratio (damp_tangential; 0: none)
  double fc, dncut;            // N, m (fc = 0: no cohesion)
  bool cohesion, rolling, tangential_damping;  // chosen once: skip the branches the scene does not need
};

// Validates p (InputError naming the key) and solves alpha_n from en when en is given.
LawParams prepare_law(const ContactParams& p);

// s, the velocity Verlet stability limit of the contact oscillator w0 = sqrt(kn/m_eff):
// dt < 2/w0 (sqrt(1 + a^2) - a) with a dashpot of ratio a evaluated from the half-step
// velocity (Belytschko, Liu & Moran, Nonlinear Finite Elements, 2000: central difference
// with damping; checked in tests/contact/test_law_energy.cpp). For a = 0 this is
// 2 sqrt(m_eff/kn) = T/pi, T = 2 pi sqrt(m_eff/kn) the undamped period. Use a fraction of it.
double critical_time_step(double kn, double m_eff, double alpha_n = 0.0);

// m, the gap of a contact with no previous step (it starts now).
constexpr double kNoGap = std::numeric_limits<double>::max();

struct ContactHistory {
  Vec3 ft = Vec3::Zero();  // N, tangential spring force
  Vec3 mr = Vec3::Zero();  // N m, rolling spring moment
  // The last step, for the energy budget only (the force does not read them):
  double fd = 0.0;         // N, dashpot force (clamped normal force minus spring)
  double gap = kNoGap;     // m (negative: overlap)
  double weight = 1.0;     // -, patch share
};

struct ContactKinematics {
  Vec3 normal;    // unit, from j to i
  double dn;      // m, gap (negative: overlap)
  Vec3 v_rel;     // m/s, velocity of i's contact point minus j's
  Vec3 w_rel;     // rad/s, w_i - w_j
  double m_eff;   // kg, m_i m_j/(m_i + m_j) (a driver: m_i)
  double lever;   // m, from i's centre to the contact point (rolling cap)
  double weight;  // -, patch share in (0, 1]: scales kn, kt, kr, nu and fc (1 for a lone contact)
  double nu = -1.0;  // N s/m, the pair's dashpot 2 alpha_n sqrt(kn m_eff) before the weight, set once
                     // per pair by the caller (one square root per pair, not per sub-contact); < 0: from m_eff
  double nu_t = -1.0;  // N s/m, the pair's tangential dashpot 2 alpha_t sqrt(kt m_eff), likewise
};

// N s/m, the dashpot coefficient of a pair of effective mass m_eff (kg), before patch weights.
inline double pair_damping(const LawParams& law, double m_eff) { return 2.0 * law.alpha_n * std::sqrt(law.kn * m_eff); }
// N s/m, the tangential dashpot of that pair (0 without damp_tangential).
inline double pair_tangential_damping(const LawParams& law, double m_eff) {
  return law.tangential_damping ? 2.0 * law.alpha_t * std::sqrt(law.kt * m_eff) : 0.0;
}

struct ContactForce {
  Vec3 force;         // N, on i (j gets the opposite)
  Vec3 moment;        // N m, rolling resistance moment on i (j gets the opposite)
  double fn;          // N, normal force (positive repulsive)
  double dissipated;  // J, dissipated this step by the dashpots, cohesion, sliding and rolling slip
  double elastic;     // J, stored in the normal, cohesion, tangential and rolling springs
  double patch = 0.0; // J, added to the springs this step by the change of the patch weight
  double sliding = 0.0;  // J, the Coulomb slip's share of `dissipated` (tangential springs let go included)
  double rolling = 0.0;  // J, the rolling slip's share of `dissipated` (rolling springs let go included)
};

// J over a step, by mechanism, summed per pair and over the run (energy.csv): `net` is the
// ledger's `dissipated` (all dissipation less the patch work), `sliding` and `rolling` are
// shares of it, `patch` what patch weight changes added to the springs.
struct EnergyParts {
  double net = 0.0, sliding = 0.0, rolling = 0.0, patch = 0.0;
  EnergyParts& operator+=(const EnergyParts& o) {
    net += o.net; sliding += o.sliding; rolling += o.rolling; patch += o.patch;
    return *this;
  }
};

inline EnergyParts energy_parts(const ContactForce& f) { return {f.dissipated - f.patch, f.sliding, f.rolling, f.patch}; }

// J, stored by a contact, per spring (energy.csv's elastic_* columns; their sum is `elastic`).
struct StoredParts {
  double normal = 0.0, tangential = 0.0, rolling = 0.0;  // normal: spring and cohesion
  StoredParts& operator+=(const StoredParts& o) {
    normal += o.normal; tangential += o.tangential; rolling += o.rolling;
    return *this;
  }
};

namespace law_slot {

// Normal + damping slots for overlap x = -dn > 0, N: fn = max(kn_w x - nu_w vn, 0) (no pull).
inline double normal_damped(double kn_w, double nu_w, double overlap, double vn) {
  return std::max(kn_w * overlap - nu_w * vn, 0.0);
}

// Cohesion slot, N (negative: attractive): -fc_w in the overlap, fc_w (dn/dncut - 1) in the band.
inline double cohesion_force(double fc_w, double dncut, double dn) {
  return dn < 0.0 ? -fc_w : fc_w * (dn / dncut - 1.0);
}
// J, potential of cohesion_force (zero at dncut, -fc_w dncut/2 at touching, slope fc_w inside).
inline double cohesion_potential(double fc_w, double dncut, double dn) {
  if (dn < 0.0) return fc_w * (dn - 0.5 * dncut);
  if (dn >= dncut) return 0.0;
  const double rest = dncut - dn;
  return -0.5 * fc_w * rest * rest / dncut;
}

// Adds an increment to a spring (force or moment) and caps its length at `cap`, back-solving
// the spring to the Coulomb limit (Luding 2008, Granular Matter 10:235, eqs. 17-19).
// Returns J, the slip work: the work of the relative motion on the spring over the step (the
// trapezoid rule velocity Verlet applies) minus the change of its energy, which reduces to
// (|trial| - cap)(old . trial/|trial| + cap)/(2k): cap times the slip when sliding steadily,
// the stored energy when the cap drops to 0, and 0 while sticking.
[[gnu::always_inline]] inline double capped_spring(Vec3& spring, const Vec3& increment, double stiffness, double cap) {
  const Vec3 old = spring;
  spring += increment;
  const double trial2 = spring.squaredNorm();
  if (trial2 <= cap * cap) return 0.0;  // sticking, the common case: no square root
  const double trial = std::sqrt(trial2);
  const double along = old.dot(spring) / trial;  // old spring along the trial direction
  spring *= cap / trial;
  return (trial - cap) * (along + cap) / (2.0 * stiffness);
}

// Tangential slot: rotate ft into the plane normal to n keeping its length, add -kt_w vt dt,
// cap |ft| <= ft_max = mu fp (LAMMPS granular "linear_history" tangential model). Returns J, slip.
[[gnu::always_inline]] inline double tangential_spring(Vec3& ft, const Vec3& n, const Vec3& vt, double kt_w,
                                                       double ft_max, double dt) {
  const double length2 = ft.squaredNorm();
  ft -= ft.dot(n) * n;
  const double in_plane2 = ft.squaredNorm();
  if (in_plane2 > 0.0) ft *= std::sqrt(length2 / in_plane2);
  return capped_spring(ft, -kt_w * dt * vt, kt_w, ft_max);
}

// Tangential dashpot -nu_t_w vt beside the spring (damp_tangential), N. Spring plus dashpot stay
// within the Coulomb cap: the dashpot takes its share first (at most all of it) and the spring
// is capped at what is left, so steady sliding still carries exactly mu fp. Adds the dashpot's
// work nu_t_w |vt|^2 dt (J, the half-step velocity on the force it makes; over a contact's life
// it differs from the kicks' trapezoid by nu_t dt (|vt_first|^2 - |vt_after|^2)/4, as no
// history keeps the last step's dashpot force) to `dissipated` and leaves the spring's cap in
// `ft_max`.
inline Vec3 tangential_dashpot(const Vec3& vt, double nu_t_w, double& ft_max, double& dissipated, double dt) {
  Vec3 damper = -nu_t_w * vt;
  const double size = damper.norm();  // N
  if (size > ft_max) damper *= ft_max / size;
  ft_max -= std::min(size, ft_max);
  dissipated -= damper.dot(vt) * dt;
  return damper;
}

// J, energy held by a spring of stiffness k (0 for k = 0: that spring is off).
inline double spring_energy(const Vec3& f, double k) { return k > 0.0 ? 0.5 * f.squaredNorm() / k : 0.0; }

// J, what a weight change from w_old to w_new adds to a spring of base stiffness k holding
// f at fixed f: |f|^2/(2 k w_new) - |f|^2/(2 k w_old) (0 when the weight stays).
inline double reweighted(const Vec3& f, double k, double w_old, double w_new) {
  if (w_old == w_new) return 0.0;  // a lone contact, a steady patch: no division
  return 0.5 * f.squaredNorm() * (w_old - w_new) / (k * w_old * w_new);
}

// J, cohesion potential at gap dn with weight w, 0 beyond the band.
inline double cohesion_energy(const LawParams& law, double w, double dn) {
  return dn < law.dncut ? cohesion_potential(w * law.fc, law.dncut, dn) : 0.0;
}

// J, cohesion over the step from gap dn0 to dn1 (weights w0, w1): trapezoid work taken from
// the bodies minus the potential gained (0 within one linear piece at a fixed weight).
inline double cohesion_dissipated(const LawParams& law, double w0, double dn0, double w1, double dn1) {
  const double f0 = dn0 < law.dncut ? cohesion_force(w0 * law.fc, law.dncut, dn0) : 0.0;
  const double f1 = dn1 < law.dncut ? cohesion_force(w1 * law.fc, law.dncut, dn1) : 0.0;
  return 0.5 * (f0 + f1) * (dn0 - dn1) + cohesion_energy(law, w0, dn0) - cohesion_energy(law, w1, dn1);
}

}  // namespace law_slot

// J, stored in the normal, cohesion, tangential and rolling springs of a contact whose last
// step left h (0 for one with no last step), per spring: energy.csv sums them on output steps.
inline StoredParts stored_parts(const LawParams& law, const ContactHistory& h) {
  const double w = h.weight;
  const double overlap = std::max(-h.gap, 0.0);  // m
  const double spring = w * law.kn * overlap;    // N
  StoredParts e;
  e.normal = 0.5 * spring * overlap;
  if (law.cohesion) e.normal += law_slot::cohesion_potential(w * law.fc, law.dncut, h.gap);
  if (law.mu > 0.0 && w * law.kt > 0.0) e.tangential = law_slot::spring_energy(h.ft, w * law.kt);
  if (law.rolling) e.rolling = law_slot::spring_energy(h.mr, w * law.kr);
  return e;
}
// J, their sum (ContactForce::elastic, for callers of one contact).
inline double stored_energy(const LawParams& law, const ContactHistory& h) {
  const StoredParts e = stored_parts(law, h);
  return e.normal + e.tangential + e.rolling;
}

// J, dissipated by a contact that ends (its last state in h): the dashpot's last force over
// the way out to zero overlap (with the clamp on, all the normal spring held), cohesion out to
// the band edge, and the energy of the tangential (`sliding`) and rolling springs. Nothing for
// a contact with no last step (h.gap = kNoGap, fd = 0) but its springs.
inline EnergyParts released_energy(const LawParams& law, const ContactHistory& h) {
  EnergyParts e;
  e.sliding = law_slot::spring_energy(h.ft, h.weight * law.kt);
  e.rolling = law_slot::spring_energy(h.mr, h.weight * law.kr);
  e.net = 0.5 * h.fd * std::min(h.gap, 0.0) + e.sliding + e.rolling;
  if (law.cohesion) e.net += law_slot::cohesion_dissipated(law, h.weight, std::min(h.gap, law.dncut), h.weight, law.dncut);
  return e;
}

// The law's optional slots (cohesion, rolling, tangential dashpot), fixed at compile time for
// the pair loops: `all` follows LawParams' flags, `plain` has none of them, so its loop carries
// no branch and no dead store for them. The contact engine picks `plain` once when it can.
enum class LawSlots { plain, all };
inline LawSlots law_slots(const LawParams& law) {
  return law.cohesion || law.rolling || law.tangential_damping ? LawSlots::all : LawSlots::plain;
}

template <LawSlots kSlots = LawSlots::all>
[[gnu::always_inline]] inline ContactForce contact_force(const LawParams& law, const ContactKinematics& k,
                                                         ContactHistory& h, double dt) {
  constexpr bool kOptional = kSlots == LawSlots::all;
  const bool cohesion = kOptional && law.cohesion, rolling = kOptional && law.rolling;
  const bool tangential_damping = kOptional && law.tangential_damping;
  const double w = k.weight;
  const double kt_w = w * law.kt, kr_w = w * law.kr;
  ContactForce out{Vec3::Zero(), Vec3::Zero(), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const double reach = cohesion ? law.dncut : 0.0;  // m, beyond it the pair does not interact
  if (k.dn >= reach) {
    // Out of reach: the springs let go and their energy is lost (the caller resets history anyway).
    const EnergyParts released = released_energy(law, h);
    out.dissipated = released.net;
    out.sliding = released.sliding;
    out.rolling = released.rolling;
    h = ContactHistory{};
    return out;
  }
  const double kn_w = w * law.kn;
  const double overlap = std::max(-k.dn, 0.0);  // m
  const double vn = k.v_rel.dot(k.normal);       // m/s, > 0 when separating
  double fp = 0.0;  // N, the compressive force the caps scale with
  if (overlap > 0.0) {
    const double nu_w = w * (k.nu >= 0.0 ? k.nu : pair_damping(law, k.m_eff));  // N s/m
    fp = law_slot::normal_damped(kn_w, nu_w, overlap, vn);
  }
  out.fn = fp;
  // A contact that starts: one step back it was a stroke vn dt away, with no dashpot force.
  if (h.gap == kNoGap) h = ContactHistory{h.ft, h.mr, 0.0, k.dn - vn * dt, w};
  const double fd = fp - kn_w * overlap;  // N, the dashpot's share after the clamp
  out.dissipated = 0.5 * (h.fd + fd) * (h.gap - k.dn);  // trapezoid, as the kicks apply it
  // 1/2 kn w x^2 at the new weight minus at the old one, over the step (trapezoid in x).
  out.patch = 0.5 * law.kn * std::max(-h.gap, 0.0) * overlap * (w - h.weight);
  if (cohesion) {
    out.fn += law_slot::cohesion_force(w * law.fc, law.dncut, k.dn);
    out.dissipated += law_slot::cohesion_dissipated(law, h.weight, h.gap, w, k.dn);
  }
  Vec3 damper = Vec3::Zero();  // N, tangential dashpot
  if (law.mu > 0.0 && kt_w > 0.0) {
    out.patch += law_slot::reweighted(h.ft, law.kt, h.weight, w);
    const Vec3 vt = k.v_rel - vn * k.normal;  // m/s, tangential relative velocity
    double ft_max = law.mu * fp;              // N
    if (tangential_damping) {
      const double nu_t_w = w * (k.nu_t >= 0.0 ? k.nu_t : pair_tangential_damping(law, k.m_eff));  // N s/m
      damper = law_slot::tangential_dashpot(vt, nu_t_w, ft_max, out.dissipated, dt);
    }
    out.sliding = law_slot::tangential_spring(h.ft, k.normal, vt, kt_w, ft_max, dt);
    out.dissipated += out.sliding;
  }
  if (rolling) {
    const double mr_max = law.mur * k.lever * fp;  // N m
    out.patch += law_slot::reweighted(h.mr, law.kr, h.weight, w);
    out.rolling = law_slot::capped_spring(h.mr, -kr_w * dt * k.w_rel, kr_w, mr_max);
    out.dissipated += out.rolling;
    out.moment = h.mr;
  }
  h.fd = fd;
  h.gap = k.dn;
  h.weight = w;
  out.force = out.fn * k.normal + h.ft;
  if (tangential_damping) out.force += damper;
  out.elastic = stored_energy(law, h);  // for callers of one contact: the pair kernels leave it unread (inlined: no cost)
  return out;
}

}  // namespace polydem
