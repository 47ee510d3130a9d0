// The sphere kernel for equal spheres (one radius, pair mass and k', c' for all pairs:
// sphere_loop.cpp) against the same kernel reading each sphere's (ContactSettings::equal_spheres
// false): equal spheres thrown about a box, stepped with the first engine's forces while the
// second sees the same states; every body's force and torque, every slot's history and the
// step's energy must be the same bits at every step, through contacts that start and end.
#include <catch2/catch.hpp>

#include <cstring>

#include "contact/contact_engine.hpp"
#include "integrate/integrate.hpp"
#include "law_cases.hpp"
#include "pile.hpp"
#include "sim_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

template <class T>
bool same_bits(const T& a, const T& b) { return std::memcmp(&a, &b, sizeof(T)) == 0; }

// Counts the bodies, slots and energies that differ by a bit.
std::size_t mismatches(const Bodies& a, const Bodies& b, const ContactEngine& ea, const ContactEngine& eb) {
  std::size_t bad = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    bad += !(same_bits(a.force[k], b.force[k]) && same_bits(a.torque[k], b.torque[k]));
  const PairList &la = ea.body_pairs(), &lb = eb.body_pairs();
  if (la.slots.size() != lb.slots.size()) return bad + 1;
  for (std::size_t s = 0; s < la.slots.size(); ++s) {
    const ContactHistory &ha = la.slots[s].history, &hb = lb.slots[s].history;
    bad += !(la.active[s] == lb.active[s] && same_bits(ha.ft, hb.ft) && same_bits(ha.mr, hb.mr) &&
             same_bits(ha.fd, hb.fd) && same_bits(ha.gap, hb.gap));
  }
  for (std::size_t k = 0; k < la.size(); ++k) bad += !same_bits(la.open_energy_or_zero(k), lb.open_energy_or_zero(k));  // J, each pair's
  return bad;
}

struct EqualRun {
  std::size_t mismatches = 0, contacts = 0;
  bool equal_path = false;  // the equal engine's list kept no k', c' per pair
};

// 300 spheres of 5 mm thrown about a 9 cm box.
EqualRun run_equal(const ContactParams& config, bool exact_step, int steps) {
  const ThrownSpheres thrown = thrown_spheres(config, exact_step, 7, 0.0102);
  Simulation sim(thrown.scene, thrown.lib, thrown.specs);
  Bodies bodies = sim.bodies;
  const ContactSettings equal = kernel_settings(config, exact_step);
  ContactSettings each = equal;
  each.equal_spheres = false;
  Drivers drivers_equal = sim.drivers, drivers_each = sim.drivers;
  ContactEngine engine_equal(sim.shapes(), all_owned(bodies), equal);
  ContactEngine engine_each(sim.shapes(), all_owned(bodies), each);
  const RotorGroups rotors = group_rotors(bodies);
  const Vec3 gravity(0, 0, -9.807);  // m/s^2
  const double dt = sim.dt();
  EqualRun out;
  for (int s = 0; s < steps; ++s) {
    start_step(bodies, 0.5 * dt, dt, rotors, gravity);
    Bodies copy = bodies;  // the second engine's forces go to a copy: the run follows the first
    engine_equal.compute(all_owned(bodies), drivers_equal, dt);
    engine_each.compute(all_owned(copy), drivers_each, dt);
    out.mismatches += mismatches(bodies, copy, engine_equal, engine_each);
    out.contacts += engine_equal.stats().contacts;
    out.equal_path = engine_equal.body_pairs().linear_steps.empty() && !engine_each.body_pairs().linear_steps.empty();
    kick(bodies, 0.5 * dt, rotors);
  }
  return out;
}

}  // namespace

TEST_CASE("contact: the equal-sphere kernel gives the per-sphere kernel's bits", "[contact][sphere]") {
  for (const LawCase& c : kernel_law_cases()) {
    INFO(c.name);
    const EqualRun r = run_equal(c.config, c.exact_step, 200);
    CHECK(r.equal_path);
    CHECK(r.mismatches == 0);
    CHECK(r.contacts > 2000);  // contacts between the spheres and with the walls, ~10 or more a step
  }
}
