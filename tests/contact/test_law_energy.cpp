// Energy budget of the contact law and the stability limit behind critical_time_step.
// Budget: kinetic + elastic + sum(dissipated) - sum(patch) is constant up to the integrator's
// O(dt^2) error (law.hpp explains how each part is counted).
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/law.hpp"

using namespace polydem;

namespace {

constexpr double kMass = 0.01;    // kg
constexpr double kRadius = 0.01;  // m
constexpr double kInertia = 0.4 * kMass * kRadius * kRadius;  // kg m^2

struct Budget {
  double kinetic0;        // J, before the impact
  double kinetic1;        // J, after it
  double dissipated;      // J, summed over the steps
  double worst_drift;     // J, max |kinetic + elastic + dissipated - kinetic0| during the impact
};

// Sphere hitting the wall z = 0 with velocity v0 and spin w0, translation and rotation by
// velocity Verlet. The kernel sees the velocities the engine passes (kick, drift, forces, kick):
// the half-step ones, whose spring increments are the exact displacements of the step, and the
// predicted end-of-step ones for the dashpot.
Budget wall_impact(const LawParams& law, Vec3 v, Vec3 w, double dt) {
  Vec3 x(0, 0, kRadius + 10.3 * -v.z() * dt), a = Vec3::Zero(), alpha = Vec3::Zero();
  auto kinetic = [&] { return 0.5 * kMass * v.squaredNorm() + 0.5 * kInertia * w.squaredNorm(); };
  Budget b{kinetic(), 0.0, 0.0, 0.0};
  ContactHistory h;
  const double reach = law.cohesion ? law.dncut : 0.0;
  bool touched = false;
  for (int step = 0; step < 1000000; ++step) {
    v += 0.5 * dt * a;
    w += 0.5 * dt * alpha;
    x += dt * v;
    const double dn = x.z() - kRadius;
    const Vec3 arm = -kRadius * Vec3::UnitZ();
    const Vec3 v_end = v + 0.5 * dt * a + (w + 0.5 * dt * alpha).cross(arm);  // m/s
    const ContactKinematics k{Vec3::UnitZ(), dn, v + w.cross(arm), v_end, w, kMass, kRadius, 1.0};
    const ContactForce f = contact_force(law, k, h, dt);
    a = f.force / kMass;
    alpha = (arm.cross(f.force) + f.moment) / kInertia;
    v += 0.5 * dt * a;
    w += 0.5 * dt * alpha;
    b.dissipated += f.dissipated;
    b.worst_drift = std::max(b.worst_drift, std::abs(kinetic() + f.elastic + b.dissipated - b.kinetic0));
    touched = touched || dn < 0.0;
    if (touched && dn >= reach) break;
  }
  b.kinetic1 = kinetic();
  return b;
}

LawParams law_with(double en, double mu, double mur, double fc) {
  ContactParams p;
  p.kn = 1e4;
  p.kt = 1e4;
  p.mu = mu;
  p.kr = mur > 0.0 ? 1e-3 : 0.0;
  p.mur = mur;
  p.en = en;
  p.fc = fc;
  p.dncut = fc > 0.0 ? 5e-5 : 0.0;
  return prepare_law(p);
}

double period(const LawParams& law) { return 2 * kPi * std::sqrt(kMass / law.kn); }

}  // namespace

TEST_CASE("energy: an elastic frictionless impact conserves kinetic + elastic to O(dt^2)", "[law]") {
  const LawParams law = law_with(1.0, 0.0, 0.0, 0.0);
  const Budget coarse = wall_impact(law, Vec3(0, 0, -0.5), Vec3::Zero(), period(law) / 100);
  const Budget fine = wall_impact(law, Vec3(0, 0, -0.5), Vec3::Zero(), period(law) / 200);
  CHECK(fine.worst_drift < 1e-3 * fine.kinetic0);
  CHECK(coarse.worst_drift / fine.worst_drift == Approx(4.0).epsilon(0.25));  // second order
  CHECK(fine.kinetic1 == Approx(fine.kinetic0).epsilon(1e-4));
}

// Each term is counted by the trapezoid rule the kicks apply: the budget error is second order
// (counting the dashpot as -f_d vn dt, the half-step vn half a step behind the force, made it
// first order: ~alpha w0 dt/2 of the dashpot's share, 1.6% at e = 0.3, T/200).
TEST_CASE("energy: kinetic energy lost = sum of dissipated (damped, friction, rolling, cohesion)", "[law]") {
  struct Case {
    const char* name;
    double en, mu, mur, fc;
    Vec3 v, w;
  };
  const Case cases[] = {
      {"normal, damped", 0.3, 0.0, 0.0, 0.0, Vec3(0, 0, -0.5), Vec3::Zero()},
      {"oblique, sliding", 0.5, 0.3, 0.0, 0.0, Vec3(2.0, 0, -0.5), Vec3::Zero()},
      {"oblique, sticking then rolling", 0.5, 0.5, 0.0, 0.0, Vec3(0.2, 0, -0.5), Vec3::Zero()},
      {"spinning, rolling resistance", 0.7, 0.5, 0.2, 0.0, Vec3(0.1, 0.1, -0.5), Vec3(30, -20, 50)},
      {"cohesive, escaping", 0.5, 0.3, 0.0, 0.05, Vec3(0.3, 0, -0.5), Vec3::Zero()},
  };
  for (const Case& c : cases) {
    const LawParams law = law_with(c.en, c.mu, c.mur, c.fc);
    double mismatch[2];  // -, relative budget error at T/200 and T/400
    for (int refine = 0; refine < 2; ++refine) {
      const Budget b = wall_impact(law, c.v, c.w, period(law) / (200 << refine));
      REQUIRE(b.kinetic1 < 0.99 * b.kinetic0);
      mismatch[refine] = (b.kinetic0 - b.kinetic1 - b.dissipated) / (b.kinetic0 - b.kinetic1);
    }
    INFO(c.name << ": budget error " << mismatch[0] << " at T/200, " << mismatch[1] << " at T/400");
    CHECK(std::abs(mismatch[1]) < 1e-3);
    CHECK(std::abs(mismatch[1]) < 0.35 * std::abs(mismatch[0]));  // second order: 1/4 per halving
  }
}

// Linear oscillator inside the overlap (a constant force presses the body onto the wall), fed
// as the engine feeds the kernel: the dashpot's own force is implicit (second_order.hpp), so the
// limit is the undamped one, 2/w0, for any damping: stable at 0.98 of it, unstable at 1.02.
// critical_time_step, the limit with a dashpot on the half-step velocity (as LAMMPS), is below.
TEST_CASE("velocity Verlet with the end-of-step dashpot is stable up to 2/w0 for any damping", "[law]") {
  for (double alpha : {0.0, 0.3, 1.0, 3.0}) {
    ContactParams p;
    p.kn = 1e4;
    p.damp_rate = alpha;
    const LawParams law = prepare_law(p);
    const double dt_crit = period(law) / kPi;  // s, 2/w0
    CHECK(critical_time_step(law.kn, kMass, alpha) <= dt_crit * (1.0 + 1e-12));
    if (alpha == 0.0) CHECK(critical_time_step(law.kn, kMass, alpha) == Approx(dt_crit));
    const double press = 1.0, x_eq = press / law.kn, kick = 1e-6 * x_eq;  // N, m, m
    for (double factor : {0.98, 1.02}) {
      const double dt = factor * dt_crit;
      double x = x_eq + kick, v = 0.0, a = 0.0, worst = 0.0;  // x: overlap
      ContactHistory h;
      for (int step = 0; step < 5000 && worst < 1e3 * kick; ++step) {
        v += 0.5 * dt * a;
        x += dt * v;
        const ContactKinematics k{Vec3::UnitZ(), -x, Vec3(0, 0, -v), Vec3(0, 0, -v - 0.5 * dt * a), Vec3::Zero(),
                                  kMass, kRadius, 1.0};
        const ContactForce f = contact_force(law, k, h, dt);
        a = (press - f.fn) / kMass;
        v += 0.5 * dt * a;
        worst = std::max(worst, std::abs(x - x_eq));
      }
      INFO("alpha = " << alpha << ", dt = " << factor << " dt_crit, worst/kick = " << worst / kick);
      if (factor < 1.0) CHECK(worst < 10 * kick);
      else CHECK(worst >= 1e3 * kick);
    }
  }
}

// The patch share is not a potential: at a fixed overlap x and spring force f, a weight change
// from w0 to w1 adds 1/2 kn x^2 (w1 - w0) to the normal spring (trapezoid work is zero: x
// does not move) and |f|^2/(2 kt) (1/w1 - 1/w0) to the tangential one; `patch` reports both and
// `dissipated` none of it.
TEST_CASE("energy: a patch weight change at rest is reported in patch, not dissipated", "[law]") {
  const LawParams law = law_with(1.0, 0.5, 0.0, 0.0);
  const double x = 1e-5, w0 = 0.5, w1 = 0.8;  // m, -, -
  ContactHistory h;
  const ContactKinematics at_w0{Vec3::UnitZ(), -x, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), kMass, kRadius, w0};
  contact_force(law, at_w0, h, 1e-6);
  h.ft = Vec3(0.01, 0.0, 0.0);  // N, below the cap mu kn w x
  ContactKinematics at_w1 = at_w0;
  at_w1.weight = w1;
  const ContactForce f = contact_force(law, at_w1, h, 1e-6);
  const double expected = 0.5 * law.kn * x * x * (w1 - w0) + 0.5 * 1e-4 / law.kt * (1.0 / w1 - 1.0 / w0);  // J
  CHECK(f.patch == Approx(expected).epsilon(1e-12));
  CHECK(f.dissipated == 0.0);
}

// A contact that separates with the dashpot clamp on (fn = 0 while x > 0) ends with all its
// normal spring energy dissipated; an elastic one gives it back (nothing dissipated). A fresh
// contact counts as pressing one step back (its stroke), so its first clamped step is the
// step the clamp lets go (a push, second_order.hpp): the second one is clamped through.
TEST_CASE("energy: a contact ending under the clamp dissipates the spring energy it held", "[law]") {
  for (double en : {0.5, 1.0}) {
    const LawParams law = law_with(en, 0.0, 0.0, 0.0);
    const double x = 1e-6, vn = 1.0, dt = 1e-6;  // m, m/s (separating), s
    ContactHistory h;
    const ContactKinematics last{Vec3::UnitZ(), -x, Vec3(0, 0, vn), Vec3(0, 0, vn), Vec3::Zero(), kMass, kRadius, 1.0};
    const ContactForce let_go = contact_force(law, last, h, dt);
    const ContactForce f = contact_force(law, last, h, dt);
    const ContactKinematics apart{Vec3::UnitZ(), x, Vec3(0, 0, vn), Vec3(0, 0, vn), Vec3::Zero(), kMass, kRadius, 1.0};
    const ContactForce end = contact_force(law, apart, h, dt);
    INFO("en = " << en);
    if (en < 1.0) {
      CHECK(let_go.fn > 0.0);
      REQUIRE(f.fn == 0.0);  // clamped: nu vn > kn x
      CHECK(end.dissipated == Approx(0.5 * law.kn * x * x).epsilon(1e-12));
    } else {
      CHECK(end.dissipated == 0.0);
    }
  }
}
