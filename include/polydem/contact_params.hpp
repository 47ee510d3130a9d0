#pragma once
// Parameters of the contact force law as the user types them (`config`, `config_driver`).

namespace polydem {

struct ContactParams {
  bool hertz = false;      // model: hertz (Hertz-Mindlin from E and poisson); else linear (kn, kt)
  double young = 0.0;      // Pa, E: Young modulus of the material (hertz: config the particles', config_driver the drivers')
  double poisson = 0.0;    // -, poisson: Poisson ratio of that material, in [0, 0.5]
  double kn = 0.0;         // N/m, normal stiffness
  double kt = 0.0;         // N/m, tangential stiffness
  double kr = 0.0;         // N m/rad, rolling stiffness (0: no rolling resistance)
  double mur = 0.0;        // -, rolling friction coefficient (cap mur * l * fn)
  double mu = 0.0;         // -, Coulomb friction coefficient
  double en = -1.0;        // -, normal restitution in (0, 1]; < 0 when damp_rate is given
  double damp_rate = -1.0; // -, damping ratio alpha_n in [0, 1); < 0 when en is given
  double damp_tangential = 0.0;  // -, tangential damping ratio alpha_t in [0, 1) (0: SPEC's spring alone)
  double fc = 0.0;         // N, cohesion force at touching (0: no cohesion)
  double dncut = 0.0;      // m, width of the cohesion band beyond touching
  bool damping_contact_mass = false;  // damping_mass: contact (the normal dashpot on the contact point's mass); pair: m_i m_j/(m_i + m_j)
};

}  // namespace polydem
