// The Hertz-Mindlin part of the law (contact/law/normal_hertz.hpp) on one contact: the moduli
// of two materials, the force, stored energy and tangential stiffness against Hertz's and
// Mindlin's closed forms, and impacts integrated with velocity Verlet (the kernel alone)
// against the closed-form duration and overlap and the en the Tsuji dashpot was solved for.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "contact/hertz_damping_table.hpp"
#include "contact/hertz_restitution.hpp"
#include "contact/law.hpp"

using namespace polydem;

namespace {

constexpr double kRStar = 0.004;  // m
constexpr double kMass = 0.002;   // kg

ContactParams material(double young, double poisson, double en = 1.0, double mu = 0.0) {
  ContactParams p;
  p.hertz = true;
  p.young = young;
  p.poisson = poisson;
  p.en = en;
  p.mu = mu;
  return p;
}

// v: the half-step velocity (springs), v_end: the predicted end-of-step one (dashpot).
ContactKinematics at_rest(double dn, Vec3 v = Vec3::Zero(), Vec3 v_end = Vec3::Zero()) {
  ContactKinematics k{Vec3::UnitZ(), dn, v, v_end, Vec3::Zero(), kMass, kRStar, 1.0};
  k.r_star = kRStar;
  return k;
}

struct Impact {
  double restitution, duration, max_overlap;  // -, s, m
};

// A sphere (mass kMass) hits a wall at v0 with the kernel and velocity Verlet, fed as the
// engine feeds it (test_law_impact.cpp).
Impact integrate(const LawParams& law, double v0, double dt) {
  double z = 0.5 * v0 * dt, v = -v0, a = 0.0, t = 0.0, t_touch = -1.0;
  ContactHistory h;
  Impact out{0, 0, 0};
  for (int step = 0; step < 10000000; ++step) {
    v += 0.5 * a * dt;
    z += v * dt;
    t += dt;
    const ContactForce f = contact_force(law, at_rest(z, Vec3(0, 0, v), Vec3(0, 0, v + 0.5 * a * dt)), h, dt);
    a = f.force.z() / kMass;
    v += 0.5 * a * dt;
    if (z < 0.0 && t_touch < 0.0) t_touch = t;
    out.max_overlap = std::max(out.max_overlap, -z);
    if (t_touch >= 0.0 && f.fn == 0.0) {
      out.duration = t - t_touch;
      break;
    }
  }
  out.restitution = v / v0;
  return out;
}

}  // namespace

TEST_CASE("hertz: E* and G* of two materials", "[law][hertz]") {
  const ContactParams steel = material(210e9, 0.3), glass = material(70e9, 0.22);
  const LawParams same = prepare_law(steel);
  CHECK(same.e_star == Approx(210e9 / (2 * (1 - 0.09))).epsilon(1e-12));
  const double g = 210e9 / (2 * 1.3);  // Pa, shear modulus
  CHECK(same.g_star == Approx(g / (2 * (2 - 0.3))).epsilon(1e-12));
  const LawParams mixed = prepare_law(glass, &steel);  // a glass driver under steel particles
  CHECK(mixed.e_star == Approx(1 / ((1 - 0.09) / 210e9 + (1 - 0.22 * 0.22) / 70e9)).epsilon(1e-12));
  CHECK(mixed.normal == NormalModel::hertz);
}

TEST_CASE("hertz: force 4/3 E* sqrt(R*) x^1.5, energy 8/15 E* sqrt(R*) x^2.5, Mindlin kt 8 G* sqrt(R* x)",
          "[law][hertz]") {
  const LawParams law = prepare_law(material(1e9, 0.25, 1.0, 10.0));  // mu 10: the spring sticks
  for (double x : {1e-6, 1e-5, 1e-4}) {
    ContactHistory h;
    const ContactForce f = contact_force(law, at_rest(-x), h, 1e-7);
    CHECK(f.fn == Approx(4.0 / 3.0 * law.e_star * std::sqrt(kRStar) * std::pow(x, 1.5)).epsilon(1e-12));
    CHECK(f.elastic == Approx(8.0 / 15.0 * law.e_star * std::sqrt(kRStar) * std::pow(x, 2.5)).epsilon(1e-12));
    // Shear by delta = vt dt at fixed overlap: ft = kt(x) delta.
    const double vt = 1e-3, dt = 1e-6;  // m/s, s
    const ContactForce g = contact_force(law, at_rest(-x, Vec3(vt, 0, 0)), h, dt);
    CHECK(-g.force.x() == Approx(8.0 * law.g_star * std::sqrt(kRStar * x) * vt * dt).epsilon(1e-12));
  }
}

TEST_CASE("hertz: elastic impact duration and overlap, and the solved en, with the kernel alone", "[law][hertz]") {
  const double v0 = 0.5;  // m/s
  const LawParams elastic = prepare_law(material(1e8, 0.3));
  const double e = elastic.e_star;
  const double t_c = 2.87 * std::pow(kMass * kMass / (kRStar * e * e * v0), 0.2);                  // s
  const double x_max = std::pow(15.0 * kMass * v0 * v0 / (16.0 * e * std::sqrt(kRStar)), 0.4);  // m
  const Impact r = integrate(elastic, v0, t_c / 2000);
  CHECK(r.duration == Approx(t_c).epsilon(0.005));
  CHECK(r.max_overlap == Approx(x_max).epsilon(0.005));
  CHECK(r.restitution == Approx(1.0).epsilon(0.005));
  CHECK(hertz_restitution_for_damping_ratio(0.0) == Approx(1.0).epsilon(1e-6));  // no dashpot: nothing lost
  for (double en : {0.1, 0.2, 0.3, 0.5, 0.7, 0.9}) {
    const LawParams law = prepare_law(material(1e8, 0.3, en));
    for (double v : {0.1, 2.0}) {  // the Tsuji dashpot: en does not depend on the speed
      const double t = 2.87 * std::pow(kMass * kMass / (kRStar * e * e * v), 0.2);
      INFO("en " << en << " v " << v << " alpha " << law.alpha_n);
      CHECK(integrate(law, v, t / 2000).restitution == Approx(en).epsilon(0.005));
    }
  }
}

TEST_CASE("hertz: the damping ratio table holds the solve's values to the last bit", "[law][hertz]") {
  // ~1 s a solve: the two ends of the common range; "[.hertz_damping_table]" checks every entry.
  for (double en : {0.1, 0.9}) {
    INFO("en " << en);
    CHECK(hertz_damping_ratio_for_restitution(en) == solve_hertz_damping_ratio(en));
  }
}

TEST_CASE("hertz: every damping ratio of the table gives its en back", "[law][hertz]") {
  // One impact integrated an entry (~25 ms): the table's rows are the solve's answers, not typos.
  for (int k = 1; k <= 99; ++k) {
    INFO("en " << k / 100.0);
    CHECK(hertz_restitution_for_damping_ratio(kHertzDampingRatio[k - 1]) == Approx(k / 100.0).margin(1e-8));
  }
}

TEST_CASE("hertz: print and check the damping ratio table", "[.hertz_damping_table]") {
  for (int k = 1; k <= 99; ++k) {
    const double solved = solve_hertz_damping_ratio(k / 100.0);
    std::printf("%a,%s", solved, k % 4 == 0 ? "\n" : " ");
    CHECK(kHertzDampingRatio[k - 1] == solved);
  }
  std::printf("\n");
}
