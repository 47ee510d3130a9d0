// A box's world vertices made where the walk reads them (made_pose.hpp, ContactSettings::made_vertices 1)
// against the same engine storing them each step (0): the determinism tests' pile of cubes and
// spheres (or cubes alone) thrown at each other and at the walls, each step's forces and torques on every body the
// same bits, through contacts that start and end and list rebuilds.
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

bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

// Steps the pile 2,000 times with made and with stored vertices under `config`: pair-steps
// touching, the made engine's rebuilds, and the steps whose forces or torques differ.
struct MadeAgainstStored {
  std::size_t touching = 0, rebuilds = 0, mismatches = 0;
};
MadeAgainstStored made_against_stored(const ContactParams& config, bool cubes_only = false) {
  const Pile pile(0.0, cubes_only);
  Simulation sim(pile.scene, pile.lib, pile.specs);
  ContactSettings made = kernel_settings(config, true), stored = made;
  made.made_vertices = 1;
  stored.made_vertices = 0;
  Bodies made_bodies = sim.bodies, stored_bodies = sim.bodies;
  Drivers made_drivers = sim.drivers, stored_drivers = sim.drivers;
  ContactEngine made_engine(sim.shapes(), all_owned(made_bodies), made);
  ContactEngine stored_engine(sim.shapes(), all_owned(stored_bodies), stored);
  const RotorGroups rotors = group_rotors(made_bodies);
  const Vec3 gravity(0, 0, -9.807);  // m/s^2
  const double dt = sim.dt();
  MadeAgainstStored out;
  for (int s = 0; s < 2000; ++s) {
    for (Bodies* b : {&made_bodies, &stored_bodies}) start_step(*b, 0.5 * dt, dt, rotors, gravity);
    made_engine.compute(all_owned(made_bodies), made_drivers, dt);
    stored_engine.compute(all_owned(stored_bodies), stored_drivers, dt);
    out.mismatches += !same_bits(made_bodies.force, stored_bodies.force) || !same_bits(made_bodies.torque, stored_bodies.torque);
    for (std::uint16_t t : made_engine.body_pairs().touching) out.touching += t;
    for (Bodies* b : {&made_bodies, &stored_bodies}) kick(*b, 0.5 * dt, rotors);
  }
  out.rebuilds = made_engine.stats().rebuilds;
  return out;
}

}  // namespace

TEST_CASE("contact: a box's vertices made where read give the stored vertices' bits", "[contact]") {
  const MadeAgainstStored run = made_against_stored(law(1e5, 0.5, 0.4, 1e5));
  INFO(run.touching << " touching pair-steps");
  CHECK(run.touching > 1000);  // the cubes met: the made corners were read
  CHECK(run.rebuilds > 1);
  CHECK(run.mismatches == 0);
}

// Cubes alone, alike: a made walk reads body 0's shape, scale and mass for every body (ShapeBoxes::body_mask).
TEST_CASE("contact: made boxes of alike cubes give the stored bits", "[contact]") {
  const MadeAgainstStored run = made_against_stored(law(1e5, 0.5, 0.4, 1e5), true);
  INFO(run.touching << " touching pair-steps");
  CHECK(run.touching > 1000);
  CHECK(run.mismatches == 0);
}

// The contact point's mass reads each side's rotation: a made box's, never its stale stored pose.
TEST_CASE("contact: made boxes give the stored bits where the dashpot takes the contact point's mass", "[contact]") {
  ContactParams config = law(1e5, 0.5, 0.4, 1e5);
  config.damping_contact_mass = true;
  const MadeAgainstStored run = made_against_stored(config);
  INFO(run.touching << " touching pair-steps");
  CHECK(run.touching > 1000);
  CHECK(run.mismatches == 0);
}
