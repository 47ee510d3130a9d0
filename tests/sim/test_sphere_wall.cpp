// The sphere-wall kernel (sphere_wall.hpp) against the general path it replaces (pair_forces
// with a DriverPartner, forced by spheres_only = 0): spheres thrown at the walls of a box, one
// wall moving and turning, stepped with one engine's forces while a second engine of the
// general path sees the same states; every wall pair's force, torques, contact count, slot
// history and energy must be the same bits at every step, through contacts that start and end.
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

bool same_history(const ContactHistory& a, const ContactHistory& b) {
  return same_bits(a.ft, b.ft) && same_bits(a.mr, b.mr) && same_bits(a.fd, b.fd) && same_bits(a.gap, b.gap) &&
         same_bits(a.weight, b.weight);
}

// Counts the wall pairs (and slots, pair energies) whose results differ by a bit.
std::size_t wall_pair_mismatches(const PairList& a, const PairList& b) {
  if (a.pairs.size() != b.pairs.size() || a.slot_count() != b.slot_count()) return 1;
  std::size_t bad = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    bad += !(same_bits(a.force_i[k], b.force_i[k]) && same_bits(a.torque_i[k], b.torque_i[k]) &&
             same_bits(a.torque_j[k], b.torque_j[k]) && a.touching[k] == b.touching[k]);
  for (std::uint32_t s = 0; s < a.slot_count(); ++s)  // an active slot's state (a sparse list keeps no other)
    bad += !(a.active[s] == b.active[s] &&
             (!a.active[s] || (same_history(a.history(s), b.history(s)) &&
                               same_bits(a.record(s).point, b.record(s).point) && same_bits(a.record(s).fn, b.record(s).fn))));
  for (std::size_t k = 0; k < a.size(); ++k) {
    const EnergyParts ea = a.open_energy_or_zero(k), eb = b.open_energy_or_zero(k);  // J
    bad += !(same_bits(ea.net, eb.net) && same_bits(ea.sliding, eb.sliding) && same_bits(ea.rolling, eb.rolling) &&
             same_bits(ea.patch, eb.patch));
  }
  return bad;
}

struct WallRun {
  std::size_t mismatches = 0, wall_contacts = 0, starts = 0, ends = 0;
};

// 300 spheres of 5 mm thrown about a 9 cm box; `config` for particles and walls.
WallRun run_walls(const ContactParams& config, bool exact_step, int steps) {
  const ThrownSpheres thrown = thrown_spheres(config, exact_step, 11, 0.0105);
  Simulation sim(thrown.scene, thrown.lib, thrown.specs);
  Bodies bodies = sim.bodies;
  const ContactSettings fast = kernel_settings(config, exact_step);
  ContactSettings general = fast;
  general.spheres_only = 0;  // the general path for every pair
  Drivers drivers_fast = sim.drivers, drivers_general = sim.drivers;
  for (Drivers* d : {&drivers_fast, &drivers_general}) {  // the floor slides and turns about a point off the box
    (*d)[0].velocity = Vec3(0.02, -0.01, 0.003);
    (*d)[0].omega = Vec3(0.3, -0.2, 0.1);
    (*d)[0].pivot = Vec3(0.1, 0.02, -0.03);
  }
  ContactEngine engine_fast(sim.shapes(), all_owned(bodies), fast);
  ContactEngine engine_general(sim.shapes(), all_owned(bodies), general);
  const RotorGroups rotors = group_rotors(bodies);
  const Vec3 gravity(0, 0, -9.807);  // m/s^2
  const double dt = sim.dt();
  WallRun out;
  std::vector<std::uint8_t> was_active;
  for (int s = 0; s < steps; ++s) {
    start_step(bodies, 0.5 * dt, dt, rotors, gravity);
    Bodies copy = bodies;  // the general engine's forces go to a copy: the run follows the fast one
    engine_fast.compute(all_owned(bodies), drivers_fast, dt);
    engine_general.compute(all_owned(copy), drivers_general, dt);
    const PairList& walls = engine_fast.driver_pairs();
    out.mismatches += wall_pair_mismatches(walls, engine_general.driver_pairs());
    for (std::uint16_t t : walls.touching) out.wall_contacts += t;
    if (was_active.size() == walls.active.size())
      for (std::size_t k = 0; k < walls.active.size(); ++k) {
        out.starts += walls.active[k] && !was_active[k];
        out.ends += !walls.active[k] && was_active[k];
      }
    was_active = walls.active;
    kick(bodies, 0.5 * dt, rotors);
  }
  return out;
}

}  // namespace

TEST_CASE("contact: the sphere-wall kernel gives the general path's bits", "[contact][sphere]") {
  std::vector<LawCase> cases = kernel_law_cases();
  ContactParams contact_mass = law(1e5, 0.5, 0.4, 0.8e5);
  contact_mass.damping_contact_mass = true;
  cases.push_back({"damping_mass: contact", contact_mass, true});
  for (const LawCase& c : cases) {
    INFO(c.name);
    const WallRun r = run_walls(c.config, c.exact_step, 400);
    CHECK(r.mismatches == 0);
    CHECK(r.wall_contacts > 2000);  // about 10 wall contacts a step
    CHECK(r.starts > 10);           // contacts start and end: the hand-over paths run
    CHECK(r.ends > 10);
  }
}

TEST_CASE("fixed walls' reactions summed only at the steps read: the same reactions and driver work there",
          "[contact][sphere]") {
  const ThrownSpheres thrown = thrown_spheres(law(1e5, 0.5, 0.4, 0.8e5), true, 5, 0.0105);
  Simulation every(thrown.scene, thrown.lib, thrown.specs), some(thrown.scene, thrown.lib, thrown.specs);
  const std::size_t walls = every.drivers.size();
  std::vector<Vec3> last(walls, Vec3::Zero());  // N, `some`'s reactions at its last read step
  int read_touching = 0, kept_between = 0, moved_between = 0;
  for (int s = 1; s <= 400; ++s) {
    const bool read = s % 25 == 0;  // as the run loop asks before an output step
    some.want_driver_reactions(read);
    every.step();
    some.step();
    INFO("step " << s);
    for (std::size_t j = 0; j < walls; ++j) {
      if (read) {
        CHECK(same_bits(every.drivers[j].force, some.drivers[j].force));
        CHECK(same_bits(every.drivers[j].torque, some.drivers[j].torque));
        read_touching += every.drivers[j].force != Vec3::Zero();
        last[j] = some.drivers[j].force;
      } else {
        CHECK(same_bits(some.drivers[j].force, last[j]));  // left as they were: nothing summed
        kept_between += 1;
        moved_between += every.drivers[j].force != last[j];
      }
    }
    CHECK(same_bits(every.ledger.driver_work, some.ledger.driver_work));  // fixed walls: +0 either way
  }
  CHECK(read_touching > 20);  // walls touched at the read steps
  CHECK(moved_between > kept_between / 4);  // summed every step, they would have changed (619 of 1,920)
}
