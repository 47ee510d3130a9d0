#pragma once
// What every part of the contact law reads and writes: the prepared coefficients, the
// kinematics of one sub-contact, its history, and the force and energies it returns.
#include <limits>

#include "polydem/math.hpp"

namespace polydem {

template <class T>
struct LinearStepOf;
using LinearStep = LinearStepOf<double>;  // exact_linear.hpp

// Prepared once per parameter set (config or config_driver) by prepare_law. One flat struct
// for every part (each part's header names its fields) rather than one struct per part: the
// parts are stateless, and tests and the step policy read kn, alpha_n directly. Chosen: flat.
// The normal part (with its damping) a law is made of.
enum class NormalModel { linear, hertz };

struct LawParams {
  double kn, kt, kr, mur, mu;  // N/m, N/m, N m/rad, -, - (kn, kt: the linear law)
  double alpha_n;              // -, damping ratio: from damp_rate, or solved so the clamped law returns en
  double alpha_t;              // -, tangential damping ratio (damp_tangential; 0: none)
  double fc, dncut;            // N, m (fc = 0: no cohesion)
  bool cohesion, rolling, tangential_damping;  // chosen once: the parts the scene's law is composed of
  NormalModel normal = NormalModel::linear;
  double e_star = 0.0, g_star = 0.0;  // Pa, Hertz: effective Young and shear moduli of the pair
  bool contact_mass = false;  // damping_mass: contact: the normal dashpot on the contact point's mass (contact_mass.hpp)
  bool exact_step = false;    // the linear law's damped normal pair stepped exactly where it can (exact_linear.hpp)
};

// m, the gap of a contact with no previous step (it starts now).
constexpr double kNoGap = std::numeric_limits<double>::max();

// The rolling part last: a contact without it touches the first 50 bytes alone (with the pending
// energy before them, a sphere slot's 81 of 128: ContactSlot).
struct ContactHistory {
  Vec3 ft = Vec3::Zero();  // N, tangential spring force
  // The last step, for the energy budget and the dashpot (its last force: second_order.hpp):
  double fd = 0.0;         // N, dashpot force (clamped normal force minus spring)
  double gap = kNoGap;     // m (negative: overlap)
  double weight = 1.0;     // -, patch share
  bool slipping = false;   // the tangential spring was capped (law.hpp: a push only where a stuck one starts to slip)
  bool rolling_slipping = false;  // the rolling spring was capped, likewise
  Vec3 mr = Vec3::Zero();  // N m, rolling spring moment
};

// A sub-contact's push where its patch's contact set changed within the step (patch_push.hpp):
// per unit of its dashpot's force (-) and, times kn, its spring's (m); the first moments about
// n+1 that the impulses at the steps miss, per the same units (s^2, m s^2); and, set by the law,
// that moment of its normal force (N s^2): what turns the bodies after the step (pair_kernel.hpp).
struct PatchPush {
  double dashpot = 0.0, spring = 0.0;                // -, m
  double dashpot_moment = 0.0, spring_moment = 0.0;  // s^2, m s^2
  double moment = 0.0;                               // N s^2
};

struct ContactKinematics {
  Vec3 normal;    // unit, from j to i
  double dn;      // m, gap (negative: overlap)
  Vec3 v_rel;     // m/s, velocity of i's contact point minus j's, at the half step (the springs' motion)
  Vec3 v_end;     // m/s, the same from the velocities predicted for the end of the step (the dashpots)
  Vec3 w_rel;     // rad/s, w_i - w_j
  double m_eff;   // kg, the normal dashpot's mass: m_i m_j/(m_i + m_j) (a driver: m_i), or the contact point's (damping_mass: contact)
  double lever;   // m, from i's centre to the contact point (rolling cap)
  double weight;  // -, patch share in (0, 1]: scales kn, kt, kr, nu and fc (1 for a lone contact)
  double nu = -1.0;  // N s/m, the pair's dashpot 2 alpha_n sqrt(kn m_eff) before the weight, set once
                     // per pair by the caller (one square root per pair, not per sub-contact); < 0: from m_eff
  double nu_t = -1.0;  // N s/m, the pair's tangential dashpot 2 alpha_t sqrt(kt m_eff), likewise
  double r_star = 0.0;  // m, the contact's curvature radius (normal_hertz.hpp; the linear law ignores it)
  // m_eff is the contact point's own mass along the normal (spheres, whose levers lie along it,
  // or damping_mass: contact): the linear law steps its normal pair exactly (exact_linear.hpp).
  bool exact_step = true;
  // The pair's cached k' and c' (exact_linear.hpp) where m_eff stays the pair's for the list's
  // life; null: computed for this contact (damping_mass: contact, callers of one contact).
  LinearStep* linear_step = nullptr;
  // m, where the overlap starts in a patch of several sub-contacts (pair_kernel.hpp, patch_onsets):
  // < 0, the patch overlapped at n, so its force does not start and the onset's pushes
  // (second_order.hpp) are not taken; else the deepest overlap of those starting with this one,
  // so the end-of-step dashpot's pushes date from the patch's touch (0: this contact alone).
  double patch_depth = 0.0;
  // The linear law's end-of-step dashpot takes this push instead of its onset's where set (null:
  // the pair's contact set did not change, or a lone contact).
  PatchPush* patch_push = nullptr;  // its `moment` written by the law
};

struct ContactForce {
  Vec3 force;         // N, on i (j gets the opposite)
  Vec3 moment;        // N m, rolling resistance moment on i (j gets the opposite)
  double fn;          // N, normal force (positive repulsive)
  double dissipated;  // J, dissipated this step by the dashpots, cohesion, sliding and rolling slip
  double elastic;     // J, stored in the normal, cohesion, tangential and rolling springs (0 in the kernels: Stored::kSkip)
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

}  // namespace polydem
