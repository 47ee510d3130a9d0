#pragma once
// The fast kernels' checks against the general path, bit for bit: the laws they run under
// (both readings of the normal dashpot, the tangential dashpot, rolling with cohesion, Hertz),
// the spheres they run on and the engines' settings.
#include <random>
#include <vector>

#include "contact/contact_engine.hpp"
#include "pile.hpp"
#include "sim_fixtures.hpp"

namespace polydem::test {

struct LawCase {
  const char* name;
  ContactParams config;
  bool exact_step;
};

inline std::vector<LawCase> kernel_law_cases() {
  ContactParams dashpot = law(1e5, 0.5, 0.4, 0.8e5);
  dashpot.damp_tangential = 0.2;
  ContactParams rolling = law(1e5, 0.3, 0.5, 0.8e5);
  rolling.kr = 1e-3;
  rolling.mur = 0.1;
  rolling.fc = 0.05;
  rolling.dncut = 2e-4;
  ContactParams hertz = law(0.0, 0.5, 0.4);
  hertz.hertz = true;
  hertz.young = 5e6;
  hertz.poisson = 0.3;
  return {{"linear, exact step", law(1e5, 0.5, 0.4, 0.8e5), true},
          {"linear, end-of-step dashpot", law(1e5, 0.5, 0.4, 0.8e5), false},
          {"tangential dashpot", dashpot, true},
          {"rolling and cohesion", rolling, true},
          {"hertz", hertz, false}};
}

// 300 spheres of 5 mm thrown about a 9 cm box between side walls: 8 x 8 layers `pitch` (m)
// apart, jittered by 0.1 mm, thrown down and sideways and spun (`seed`: the draws).
struct ThrownSpheres {
  Scene scene;
  ShapeLibrary lib;
  std::vector<BodySpec> specs;
};
inline ThrownSpheres thrown_spheres(const ContactParams& config, bool exact_step, unsigned seed, double pitch) {
  ThrownSpheres out{base_scene(config, true, Vec3(0, 0, -9.807)), library({sphere_shape(0.005)}), {}};
  out.scene.simulation.exact_step = exact_step;
  add_side_walls(out.scene);
  std::mt19937_64 rng(seed);
  auto u = [&] { return double(rng() >> 11) * 0x1.0p-53 - 0.5; };
  for (int k = 0; k < 300; ++k) {
    const Vec3 x(pitch * (k % 8 - 3.5), pitch * ((k / 8) % 8 - 3.5), 0.006 + pitch * (k / 64));
    BodySpec b = body("sphere", x + 1e-4 * Vec3(u(), u(), u()), 1.5 * Vec3(u(), u(), u() - 0.5));
    b.angular_velocity = 100.0 * Vec3(u(), u(), u());  // rad/s
    out.specs.push_back(b);
  }
  return out;
}

// An engine's settings for `config` on particles and drivers, with a 0.5 mm skin.
inline ContactSettings kernel_settings(const ContactParams& config, bool exact_step) {
  ContactSettings s;
  s.particle = prepare_law(config);
  s.driver = prepare_law(config, &config);
  s.particle.exact_step = s.driver.exact_step = exact_step;
  s.skin = 0.0005;  // m
  return s;
}

}  // namespace polydem::test
