// Cohesion band, rolling resistance and patch weights of the contact law.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/law.hpp"

using namespace polydem;

namespace {

constexpr double kMass = 0.01;    // kg
constexpr double kRadius = 0.01;  // m
constexpr double kG = 9.807;      // m/s^2

LawParams cohesive_law() {
  ContactParams p;
  p.kn = 1e4;
  p.en = 0.5;
  p.fc = 0.05;
  p.dncut = 1e-4;
  return prepare_law(p);
}

ContactForce at_rest(const LawParams& law, double dn) {
  ContactHistory h;
  return contact_force(law, {Vec3::UnitZ(), dn, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), kMass, kRadius, 1.0}, h, 1e-5);
}

// Sphere on the wall z = 0 pulled up by a force ramped to `pull` over 0.5 s, then held 0.5 s.
// Returns the largest gap reached (m).
double pulled_gap(const LawParams& law, double pull) {
  const double dt = 2e-5;  // s, T/300
  double z = kRadius - law.fc / law.kn, v = 0.0, a = 0.0, gap = -1.0;  // at rest: kn x = fc
  ContactHistory h;
  for (int step = 1; step <= 50000; ++step) {
    v += 0.5 * dt * a;
    z += dt * v;
    const double dn = z - kRadius;
    const ContactKinematics k{Vec3::UnitZ(), dn, Vec3(0, 0, v), Vec3(0, 0, v + 0.5 * dt * a), Vec3::Zero(), kMass,
                              kRadius, 1.0};
    const ContactForce f = contact_force(law, k, h, dt);
    a = (f.force.z() + pull * std::min(step * dt / 0.5, 1.0)) / kMass;
    v += 0.5 * dt * a;
    gap = std::max(gap, dn);
  }
  return gap;
}

}  // namespace

TEST_CASE("cohesion: continuous at touching, -fc there, 0 at dncut, potential consistent", "[law]") {
  const LawParams law = cohesive_law();
  const double eps = 1e-12;  // m
  CHECK(at_rest(law, 0.0).fn == Approx(-law.fc));
  CHECK(std::abs(at_rest(law, eps).fn - at_rest(law, -eps).fn) < 2 * law.kn * eps + 1e-12);
  CHECK(std::abs(at_rest(law, law.dncut * (1 - 1e-9)).fn) < 1e-9 * law.fc);
  CHECK(at_rest(law, law.dncut).force.norm() == 0.0);
  CHECK(at_rest(law, 0.5 * law.dncut).force.z() == Approx(-0.5 * law.fc));
  // elastic is the potential of fn along dn: d(elastic)/d(dn) = -fn (central difference).
  for (double dn : {-3e-5, -1e-6, 2e-5, 7e-5}) {
    const double h = 1e-9;
    const double slope = (at_rest(law, dn + h).elastic - at_rest(law, dn - h).elastic) / (2 * h);
    INFO("dn = " << dn);
    CHECK(slope == Approx(-at_rest(law, dn).fn).epsilon(1e-6));
  }
}

TEST_CASE("cohesion: a resting pair pulled apart needs more than fc", "[law]") {
  const LawParams law = cohesive_law();
  CHECK(pulled_gap(law, 0.95 * law.fc) < 0.0);          // still overlapping
  CHECK(pulled_gap(law, 1.05 * law.fc) > law.dncut);    // torn off, beyond the band
}

TEST_CASE("rolling: the moment opposes w_rel and is capped at mur * lever * fn", "[law]") {
  ContactParams p;
  p.kn = 1e4;
  p.kt = 1e4;
  p.mu = 0.5;
  p.kr = 1e-2;
  p.mur = 0.1;
  p.en = 1.0;
  const LawParams law = prepare_law(p);
  REQUIRE(law.rolling);
  const Vec3 w_rel(0.0, 2.0, 0.5);  // rad/s
  const double dn = -1e-4, dt = 1e-4;
  const ContactKinematics k{Vec3::UnitZ(), dn, Vec3::Zero(), Vec3::Zero(), w_rel, kMass, kRadius, 1.0};
  ContactHistory h;
  ContactForce f = contact_force(law, k, h, dt);
  CHECK((f.moment + law.kr * w_rel * dt).norm() < 1e-18);  // first step: -kr w_rel dt
  for (int s = 0; s < 2000; ++s) f = contact_force(law, k, h, dt);
  CHECK(f.moment.norm() == Approx(law.mur * kRadius * law.kn * -dn).epsilon(1e-12));
  CHECK(f.moment.normalized().dot(-w_rel.normalized()) == Approx(1.0).epsilon(1e-12));
  p.mur = 0.0;  // the SPEC default: rolling off even with kr > 0
  ContactHistory off;
  CHECK(contact_force(prepare_law(p), k, off, dt).moment.norm() == 0.0);
}

// Sphere rolling without slip on the wall z = 0 under gravity. The rolling moment
// M = mur R m g about the contact point (I_c = 7/5 m R^2) decelerates it at 5/7 mur g, so it
// stops after s = v0^2 / (2 * 5/7 mur g); with mur = 0 the kinetic energy is kept.
TEST_CASE("rolling: a sphere stops after v0^2/(10/7 mur g) with mur > 0, rolls on with mur = 0", "[law]") {
  for (double mur : {0.0, 0.1}) {
    ContactParams p;
    p.kn = 1e4;
    p.kt = 1e4;
    p.mu = 0.5;
    p.kr = 0.1;
    p.mur = mur;
    p.en = 0.5;
    const LawParams law = prepare_law(p);
    const double dt = 2e-5, inertia = 0.4 * kMass * kRadius * kRadius, v0 = 0.1;
    Vec3 x(0, 0, kRadius - kMass * kG / law.kn), v(v0, 0, 0), w(0, v0 / kRadius, 0);
    Vec3 a(0, 0, 0), alpha(0, 0, 0);
    const double energy0 = 0.5 * kMass * v.squaredNorm() + 0.5 * inertia * w.squaredNorm();
    ContactHistory h;
    double stop_x = -1.0;
    for (int step = 0; step < 15000 && stop_x < 0.0; ++step) {
      v += 0.5 * dt * a;
      w += 0.5 * dt * alpha;
      x += dt * v;
      // As the engine: the half-step velocities for the springs, the predicted end-of-step ones for the dashpot.
      const Vec3 arm = -kRadius * Vec3::UnitZ(), v_end = v + 0.5 * dt * a + (w + 0.5 * dt * alpha).cross(arm);
      const ContactKinematics k{Vec3::UnitZ(), x.z() - kRadius, v + w.cross(arm), v_end, w, kMass, kRadius, 1.0};
      const ContactForce f = contact_force(law, k, h, dt);
      a = f.force / kMass - kG * Vec3::UnitZ();
      alpha = (arm.cross(f.force) + f.moment) / inertia;
      v += 0.5 * dt * a;
      w += 0.5 * dt * alpha;
      if (v.x() <= 0.0) stop_x = x.x();
    }
    const double energy = 0.5 * kMass * v.squaredNorm() + 0.5 * inertia * w.squaredNorm();
    INFO("mur = " << mur);
    if (mur == 0.0) {
      CHECK(stop_x < 0.0);
      CHECK(energy == Approx(energy0).epsilon(1e-6));
    } else {
      CHECK(stop_x == Approx(v0 * v0 / (10.0 / 7.0 * mur * kG)).epsilon(0.02));
    }
  }
}

TEST_CASE("patch weights: n sub-contacts of weight 1/n act as one contact of weight 1", "[law]") {
  ContactParams p;
  p.kn = 1e4;
  p.kt = 5e3;
  p.mu = 0.3;
  p.kr = 1e-2;
  p.mur = 0.05;
  p.en = 0.4;
  p.fc = 0.02;
  p.dncut = 1e-4;
  const LawParams law = prepare_law(p);
  const int n = 4;
  ContactHistory one, parts[n];
  for (int s = 0; s < 300; ++s) {
    const double t = s * 1e-5;
    const double dn = -1e-4 * std::sin(2e3 * t + 0.1);  // m, in and out of the overlap
    const Vec3 v_rel(0.3 * std::cos(3e3 * t), 0.2, 0.2 * std::cos(2e3 * t));
    ContactKinematics k{Vec3::UnitZ(), dn, v_rel, v_rel, Vec3(1.0, -2.0, 0.5), kMass, kRadius, 1.0};
    const ContactForce whole = contact_force(law, k, one, 1e-5);
    k.weight = 1.0 / n;
    ContactForce sum{Vec3::Zero(), Vec3::Zero(), 0.0, 0.0, 0.0};
    for (ContactHistory& h : parts) {
      const ContactForce f = contact_force(law, k, h, 1e-5);
      sum.force += f.force;
      sum.moment += f.moment;
      sum.elastic += f.elastic;
      sum.dissipated += f.dissipated;
    }
    INFO("step " << s);
    CHECK((sum.force - whole.force).norm() <= 1e-12 * (1.0 + whole.force.norm()));
    CHECK((sum.moment - whole.moment).norm() <= 1e-12 * (1e-4 + whole.moment.norm()));
    CHECK(sum.elastic == Approx(whole.elastic).epsilon(1e-12).margin(1e-15));
    CHECK(sum.dissipated == Approx(whole.dissipated).epsilon(1e-12).margin(1e-15));
  }
}
