#pragma once
// The contact force law (SPEC "Contact force law"): a pure kernel
// (const LawParams&, const ContactKinematics&, ContactHistory&) -> ContactForce, composed of
// slots in a fixed order as in LAMMPS GranularModel::calculate_forces: normal, damping,
// cohesion, tangential, rolling. Inline: it runs once per sub-contact per step.
//
// Energy budget, per sub-contact and step: the work of the contact force on the two bodies
// equals -(change of `elastic`) - `dissipated`, so kinetic + elastic + sum(dissipated) stays
// constant up to the integrator's O(dt^2) error:
//  - normal spring and cohesion are conservative: their potentials are in `elastic`
//    (the cohesion potential is negative: energy is needed to pull the pair apart);
//  - the dashpot dissipates -f_d vn dt, f_d = (clamped normal force) - (spring force);
//  - the tangential and rolling springs store |f|^2/(2k); slip under the Coulomb cap
//    dissipates (see capped_spring), and what they hold when released is lost too.
//
// Coulomb and rolling caps use the compressive force fp = max(kn_w x - nu_w vn, 0) (cohesion
// excluded), not SPEC's elastic part kn_w x: with the no-pull clamp the contact releases
// while x > 0, and kn_w x keeps a friction force with no normal force on the tail, so the
// tangential impulse is mu (J_n - nu x_c/2) and the oblique sliding law is off by
// 2 alpha^2 e/(1+e) (11% of the spin at e = 0.3); with fp it is exact (test_law_oblique.cpp).
#include <algorithm>
#include <cmath>

#include "polydem/contact_params.hpp"
#include "polydem/math.hpp"

namespace polydem {

// Prepared once per parameter set (config or config_driver) by prepare_law.
struct LawParams {
  double kn, kt, kr, mur, mu;  // N/m, N/m, N m/rad, -, -
  double alpha_n;              // -, damping ratio: from damp_rate, or solved so the clamped law returns en
  double fc, dncut;            // N, m (fc = 0: no cohesion)
  bool cohesion, rolling;      // chosen once: skip the branches the scene does not need
};

// Validates p (InputError naming the key) and solves alpha_n from en when en is given.
LawParams prepare_law(const ContactParams& p);

// s, the velocity Verlet stability limit of the contact oscillator w0 = sqrt(kn/m_eff):
// dt < 2/w0 (sqrt(1 + a^2) - a) with a dashpot of ratio a evaluated from the half-step
// velocity (Belytschko, Liu & Moran, Nonlinear Finite Elements, 2000: central difference
// with damping; checked in tests/contact/test_law_energy.cpp). For a = 0 this is
// 2 sqrt(m_eff/kn) = T/pi, T = 2 pi sqrt(m_eff/kn) the undamped period. Use a fraction of it.
double critical_time_step(double kn, double m_eff, double alpha_n = 0.0);

struct ContactHistory {
  Vec3 ft = Vec3::Zero();  // N, tangential spring force
  Vec3 mr = Vec3::Zero();  // N m, rolling spring moment
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
};

// N s/m, the dashpot coefficient of a pair of effective mass m_eff (kg), before patch weights.
inline double pair_damping(const LawParams& law, double m_eff) { return 2.0 * law.alpha_n * std::sqrt(law.kn * m_eff); }

struct ContactForce {
  Vec3 force;         // N, on i (j gets the opposite)
  Vec3 moment;        // N m, rolling resistance moment on i (j gets the opposite)
  double fn;          // N, normal force (positive repulsive)
  double dissipated;  // J, dissipated this step by the dashpot, sliding and rolling slip
  double elastic;     // J, stored in the normal, cohesion, tangential and rolling springs
};

namespace law_slot {

// Normal + damping slots for overlap x = -dn > 0: fn = max(kn_w x - nu_w vn, 0) (no pull).
struct NormalPart {
  double fn;          // N
  double elastic;     // J, 1/2 kn_w x^2
  double dissipated;  // J, -f_d vn dt with f_d = fn - kn_w x the dashpot's actual force
};
inline NormalPart normal_damped(double kn_w, double nu_w, double overlap, double vn, double dt) {
  const double spring = kn_w * overlap;
  const double fn = std::max(spring - nu_w * vn, 0.0);
  return {fn, 0.5 * spring * overlap, (spring - fn) * vn * dt};
}

// Cohesion slot, N (negative: attractive): -fc_w in the overlap, fc_w (dn/dncut - 1) in the band.
inline double cohesion_force(double fc_w, double dncut, double dn) {
  return dn < 0.0 ? -fc_w : fc_w * (dn / dncut - 1.0);
}
// J, potential of cohesion_force (zero at dncut, -fc_w dncut/2 at touching, slope fc_w inside).
inline double cohesion_potential(double fc_w, double dncut, double dn) {
  if (dn < 0.0) return fc_w * (dn - 0.5 * dncut);
  const double rest = dncut - dn;
  return -0.5 * fc_w * rest * rest / dncut;
}

// Adds an increment to a spring (force or moment) and caps its length at `cap`, back-solving
// the spring to the Coulomb limit (Luding 2008, Granular Matter 10:235, eqs. 17-19).
// Returns J, the slip work: the work of the relative motion on the spring over the step (the
// trapezoid rule velocity Verlet applies) minus the change of its energy, which reduces to
// (|trial| - cap)(old . trial/|trial| + cap)/(2k): cap times the slip when sliding steadily,
// the stored energy when the cap drops to 0, and 0 while sticking.
inline double capped_spring(Vec3& spring, const Vec3& increment, double stiffness, double cap) {
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
inline double tangential_spring(Vec3& ft, const Vec3& n, const Vec3& v_rel, double kt_w,
                                double ft_max, double dt) {
  const double length2 = ft.squaredNorm();
  ft -= ft.dot(n) * n;
  const double in_plane2 = ft.squaredNorm();
  if (in_plane2 > 0.0) ft *= std::sqrt(length2 / in_plane2);
  const Vec3 vt = v_rel - v_rel.dot(n) * n;  // m/s, tangential relative velocity
  return capped_spring(ft, -kt_w * dt * vt, kt_w, ft_max);
}

// J, energy held by a spring of stiffness k (0 for k = 0: that spring is off).
inline double spring_energy(const Vec3& f, double k) { return k > 0.0 ? 0.5 * f.squaredNorm() / k : 0.0; }

}  // namespace law_slot

[[gnu::always_inline]] inline ContactForce contact_force(const LawParams& law, const ContactKinematics& k, ContactHistory& h,
                                  double dt) {
  const double w = k.weight;
  const double kt_w = w * law.kt, kr_w = w * law.kr;
  ContactForce out{Vec3::Zero(), Vec3::Zero(), 0.0, 0.0, 0.0};
  const double reach = law.cohesion ? law.dncut : 0.0;  // m, beyond it the pair does not interact
  if (k.dn >= reach) {
    // Out of reach: the springs let go and their energy is lost (the caller resets history anyway).
    out.dissipated = law_slot::spring_energy(h.ft, kt_w) + law_slot::spring_energy(h.mr, kr_w);
    h = ContactHistory{};
    return out;
  }
  const double kn_w = w * law.kn;
  const double overlap = std::max(-k.dn, 0.0);  // m
  const double vn = k.v_rel.dot(k.normal);       // m/s, > 0 when separating
  law_slot::NormalPart normal{0.0, 0.0, 0.0};  // normal.fn is fp, the force the caps scale with
  if (overlap > 0.0) {
    const double nu_w = w * (k.nu >= 0.0 ? k.nu : pair_damping(law, k.m_eff));  // N s/m
    normal = law_slot::normal_damped(kn_w, nu_w, overlap, vn, dt);
  }
  out.fn = normal.fn;
  out.elastic = normal.elastic;
  out.dissipated = normal.dissipated;
  if (law.cohesion) {
    out.fn += law_slot::cohesion_force(w * law.fc, law.dncut, k.dn);
    out.elastic += law_slot::cohesion_potential(w * law.fc, law.dncut, k.dn);
  }
  if (law.mu > 0.0 && kt_w > 0.0) {
    out.dissipated += law_slot::tangential_spring(h.ft, k.normal, k.v_rel, kt_w, law.mu * normal.fn, dt);
    out.elastic += law_slot::spring_energy(h.ft, kt_w);
  }
  if (law.rolling) {
    const double mr_max = law.mur * k.lever * normal.fn;  // N m
    out.dissipated += law_slot::capped_spring(h.mr, -kr_w * dt * k.w_rel, kr_w, mr_max);
    out.elastic += law_slot::spring_energy(h.mr, kr_w);
    out.moment = h.mr;
  }
  out.force = out.fn * k.normal + h.ft;
  return out;
}

}  // namespace polydem
