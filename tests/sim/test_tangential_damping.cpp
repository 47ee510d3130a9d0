// The tangential dashpot (`damp_tangential`, alpha_t): -nu_t vt beside the tangential spring,
// nu_t = 2 alpha_t sqrt(kt m_eff), the sum capped at mu fp.
//
// A sphere resting on a floor and sticking is a damped oscillator in the slip u of its contact
// point: the force F = -kt u - nu_t u' gives the centre m v' = F and the spin I w' = R x F, so
// u'' = F / m_t with 1/m_t = 1/m + R^2/I = 3.5/m (solid sphere). Hence (Meirovitch, Elements of
// Vibration Analysis, 1986, sec. 1.7) u' rings at w_d = w0 sqrt(1 - z^2), w0 = sqrt(kt/m_t),
// z = nu_t / (2 sqrt(kt m_t)) = alpha_t sqrt(m/m_t), and successive maxima fall by the
// logarithmic decrement 2 pi z / sqrt(1 - z^2). Without the dashpot (SPEC) they do not fall.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "sim_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

constexpr double kG = 9.807;       // m/s^2
constexpr double kRadius = 0.005;  // m
constexpr double kStiffness = 1e5; // N/m, kn = kt

struct Ringing {
  double decrement = 0.0;  // -, mean ln(u'_max(k) / u'_max(k+1))
  double period = 0.0;     // s, mean time between maxima
};

// Sets a resting, sticking sphere's contact point slipping at v0 and follows the maxima of u'.
Ringing ring(double alpha_t) {
  ContactParams p = law(kStiffness, 0.5, 10.0, kStiffness);  // mu 10: the spring never reaches the cap
  p.damp_tangential = alpha_t;
  Scene scene = base_scene(p, true, Vec3(0, 0, -kG));
  const ShapeLibrary lib = library({sphere_shape(kRadius)});
  const double m = 2700.0 * lib.shapes[0].volume, w0 = std::sqrt(3.5 * kStiffness / m);  // kg, rad/s
  scene.simulation.dt = 2.0 * kPi / w0 / 400.0;  // 400 steps per period: test the law, not dt
  const double overlap = m * kG / kStiffness;  // m, at rest on the floor: no normal ringing
  Simulation sim(scene, lib, {body("sphere", {0, 0, kRadius - overlap}, {1e-3, 0, 0})});
  std::vector<double> peak_time, peak;
  double before = 0.0, last = 0.0;  // u' two steps and one step back
  for (int s = 0; s < 2400; ++s) {  // six periods
    sim.step();
    const double slip = sim.bodies.velocity[0].x() - kRadius * sim.bodies.angular_velocity[0].y();  // m/s
    if (s >= 2 && last > before && last >= slip) {  // a maximum at the last step: a parabola through the three
      const double curvature = before - 2.0 * last + slip, shift = 0.5 * (before - slip) / curvature;
      peak_time.push_back(sim.time() - (1.0 - shift) * sim.dt());
      peak.push_back(last - 0.25 * (before - slip) * shift);
    }
    before = last;
    last = slip;
  }
  REQUIRE(peak.size() >= 4);
  Ringing r;
  const std::size_t n = peak.size() - 1;
  r.decrement = std::log(peak.front() / peak.back()) / double(n);
  r.period = (peak_time.back() - peak_time.front()) / double(n);
  return r;
}

}  // namespace

TEST_CASE("the tangential dashpot rings a sticking contact down at its damping ratio", "[friction][damping]") {
  const double m_over_mt = 3.5;
  for (double alpha_t : {0.02, 0.1}) {
    const Ringing r = ring(alpha_t);
    const double z = alpha_t * std::sqrt(m_over_mt);
    const double m = 2700.0 * 4.0 / 3.0 * kPi * std::pow(kRadius, 3);
    const double w_d = std::sqrt(m_over_mt * kStiffness / m) * std::sqrt(1.0 - z * z);
    INFO("alpha_t " << alpha_t << ": decrement " << r.decrement << " period " << r.period);
    CHECK(r.decrement == Approx(2.0 * kPi * z / std::sqrt(1.0 - z * z)).epsilon(0.01));
    CHECK(r.period == Approx(2.0 * kPi / w_d).epsilon(0.002));
  }
  // The SPEC's spring alone: the slip rings on (the peaks stay within the time step's error).
  CHECK(std::abs(ring(0.0).decrement) < 1e-3);
}

TEST_CASE("with the tangential dashpot an oblique impact still follows the sliding law", "[friction][damping]") {
  // Sliding throughout, spring plus dashpot sit at the cap mu fp: the law v_t' = v_t - mu (1 + e) v_n
  // of test_oblique.cpp holds whatever alpha_t.
  const double mu = 0.3, vn = 1.0, vt = 6.0, en = 0.5;
  ContactParams p = law(kStiffness, en, mu, kStiffness);
  p.damp_tangential = 0.3;
  Scene scene = base_scene(p, true);
  const ShapeLibrary lib = library({sphere_shape(kRadius)});
  scene.simulation.dt = kPi * std::sqrt(2700.0 * lib.shapes[0].volume / kStiffness) / 400.0;
  Simulation sim(scene, lib, {body("sphere", {0, 0, kRadius + 1e-5}, {vt, 0, -vn})});
  REQUIRE(run_through_impact(sim, 20000));
  CHECK(sim.bodies.velocity[0].z() / vn == Approx(en).epsilon(0.005));
  CHECK(sim.bodies.velocity[0].x() == Approx(vt - mu * (1 + en) * vn).epsilon(0.01));
  CHECK(sim.bodies.angular_velocity[0].y() * kRadius == Approx(2.5 * mu * (1 + en) * vn).epsilon(0.02));
}
