// The contact stage on a local view (owned bodies plus ghosts, in global id order): cut into
// boxes, each part computing the pairs of its owned bodies, the pile's forces and torques are
// the bits of the whole at every step, through rebuilds and contact histories.
#include <catch2/catch.hpp>

#include <memory>

#include "integrate/integrate.hpp"
#include "pile.hpp"
#include "sim/local_store.hpp"
#include "sim/ghost_plan.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

ContactSettings pile_settings(const Scene& scene) {
  ContactSettings s;
  s.particle = prepare_law(scene.forces.contact.config);
  s.driver = prepare_law(scene.forces.contact.config_driver, &scene.forces.contact.config);
  s.skin = 0.0005;  // m
  s.pair_trigger = false;  // each part's bodies skin/2 apiece, ORed over the parts
  return s;
}

// One part of the cut: its bodies, its engine and its copy of the drivers (their reactions
// are its own pairs' alone).
struct Part {
  LocalStore store;
  Drivers drivers;
  std::unique_ptr<ContactEngine> engine;
};

double max_bounding_radius(const Bodies& bodies, const std::vector<Shape>& shapes) {
  double r = 0.0;  // m
  for (std::size_t b = 0; b < bodies.size(); ++b) r = std::max(r, shapes[bodies.shape[b]].bounding_radius * bodies.scale[b]);
  return r;
}

struct SplitRun {
  std::size_t rebuilds = 0, max_contacts = 0, ghosts = 0, mismatches = 0;
};

// From the pile once it holds 150 contacts, steps `steps` times with the whole engine and,
// beside it, `parts` parts (equal body counts) whose ghost sets (the halo plus `margin`, m; none without
// `ghosts`) are chosen once; counts the owned bodies whose force or torque differs from the
// whole's by a bit.
SplitRun run_split(int parts, int steps, double margin, bool ghosts = true) {
  Pile p;
  Simulation sim(p.scene, p.lib, p.specs);
  for (int s = 0; s < 100000 && sim.engine().stats().contacts < 150; ++s) sim.step();
  REQUIRE(sim.engine().stats().contacts >= 150);
  Bodies bodies = sim.bodies;
  Drivers drivers = sim.drivers;
  const ContactSettings settings = pile_settings(p.scene);
  const RotorGroups rotors = group_rotors(bodies);
  ContactEngine whole(sim.shapes(), all_owned(bodies), settings);
  const DomainCut cut = cut_domain(bodies.position, std::vector<double>(bodies.size(), 1.0), parts);
  const double halo = ghosts ? ghost_halo(max_bounding_radius(bodies, sim.shapes()), settings.skin) + margin : 0.0;
  std::vector<Part> split;
  SplitRun out;
  for (int k = 0; k < parts; ++k) {
    GhostPlan plan = plan_ghosts(cut, k, bodies.position, halo);
    for (std::uint8_t g : plan.ghost) out.ghosts += g;
    Part& part = split.emplace_back(Part{LocalStore{}, drivers, nullptr});
    part.store.select(bodies, std::move(plan.local), std::move(plan.ghost));
    part.engine = std::make_unique<ContactEngine>(sim.shapes(), part.store.view(), settings);
  }
  const Vec3 gravity = *p.scene.forces.gravity;  // m/s^2
  const double dt = sim.dt();
  for (int s = 0; s < steps; ++s) {
    kick(bodies, 0.5 * dt, rotors);
    drift(bodies, dt, rotors);
    std::fill(bodies.force.begin(), bodies.force.end(), Vec3::Zero());
    std::fill(bodies.torque.begin(), bodies.torque.end(), Vec3::Zero());
    const bool stale = whole.lists_stale(all_owned(bodies), drivers);
    bool any_stale = false;  // the global decision: every part measures its bodies
    for (Part& part : split) {
      part.store.select(bodies, part.store.global_id, part.store.ghost);  // the state now, forces zero
      any_stale = part.engine->lists_stale(part.store.view(), part.drivers) || any_stale;
    }
    REQUIRE(any_stale == stale);
    whole.compute(all_owned(bodies), drivers, dt, stale);
    for (Part& part : split) {
      part.engine->compute(part.store.view(), part.drivers, dt, stale);
      for (std::size_t b = 0; b < part.store.global_id.size(); ++b) {
        if (part.store.ghost[b]) continue;
        const std::uint32_t g = part.store.global_id[b];
        if (part.store.force[b] != bodies.force[g] || part.store.torque[b] != bodies.torque[g]) ++out.mismatches;
      }
    }
    for (std::size_t b = 0; b < bodies.size(); ++b) bodies.force[b] += bodies.mass[b] * gravity;
    kick(bodies, 0.5 * dt, rotors);
    out.max_contacts = std::max(out.max_contacts, whole.stats().contacts);
  }
  out.rebuilds = whole.stats().rebuilds;
  return out;
}

}  // namespace

TEST_CASE("a pile cut into 2 or 3 boxes with ghosts gets the force bits of the whole at every step") {
  for (int parts : {2, 3}) {
    const SplitRun r = run_split(parts, 600, 0.003);
    INFO(parts << " parts: " << r.rebuilds << " rebuilds, " << r.max_contacts << " contacts, " << r.ghosts << " ghosts");
    CHECK(r.rebuilds > 3);        // histories carried across rebuilds
    CHECK(r.max_contacts > 100);  // a pile, not bodies in flight
    CHECK(r.ghosts > 0);
    CHECK(r.ghosts < 150 * (parts - 1));  // ghosts are the bodies near a cut, not all
    CHECK(r.mismatches == 0);
  }
}

TEST_CASE("parts without ghosts miss the pairs across the cut: the comparison sees them") {
  const SplitRun r = run_split(2, 50, 0.0, false);
  CHECK(r.ghosts == 0);
  CHECK(r.mismatches > 0);
}

// A rank's rebuild makes its engine anew over its new bodies, lent the old engine's poses'
// storage (ContactEngine's `was`): rows left from other bodies are posed again before any read,
// so the lists, their candidates and the forces are a new engine's, step after step.
TEST_CASE("an engine lent the poses of the engine before lists and forces as a new one") {
  Pile p;
  Simulation sim(p.scene, p.lib, p.specs);
  for (int s = 0; s < 100000 && sim.engine().stats().contacts < 150; ++s) sim.step();
  REQUIRE(sim.engine().stats().contacts >= 150);
  Bodies bodies = sim.bodies;
  Drivers drivers = sim.drivers, drivers_lent = sim.drivers;
  const ContactSettings settings = pile_settings(p.scene);
  ContactEngine before(sim.shapes(), all_owned(bodies), settings);  // every body posed, in global ids
  before.compute(all_owned(bodies), drivers, sim.dt(), true);
  const DomainCut cut = cut_domain(bodies.position, std::vector<double>(bodies.size(), 1.0), 3);
  GhostPlan plan = plan_ghosts(cut, 1, bodies.position, max_bounding_radius(bodies, sim.shapes()));  // m: some ghosts
  LocalStore fresh_store;
  fresh_store.select(bodies, std::move(plan.local), std::move(plan.ghost));
  LocalStore lent_store = fresh_store;
  REQUIRE(fresh_store.size() < bodies.size());  // the lent rows outnumber the new bodies: none cleared
  ContactEngine fresh(sim.shapes(), fresh_store.view(), settings);
  ContactEngine lent(sim.shapes(), lent_store.view(), settings, &before);
  std::size_t contacts = 0;
  for (int s = 0; s < 40; ++s) {  // the state held: each step's lists and forces on the same bodies
    const bool stale = s == 0 || fresh.lists_stale(fresh_store.view(), drivers);
    CHECK((s == 0 || lent.lists_stale(lent_store.view(), drivers_lent)) == stale);
    fresh.compute(fresh_store.view(), drivers, sim.dt(), stale);
    lent.compute(lent_store.view(), drivers_lent, sim.dt(), stale);
    REQUIRE(lent.body_pairs().pairs == fresh.body_pairs().pairs);
    const std::vector<FeaturePair>&a = lent.body_pairs().features, &b = fresh.body_pairs().features;  // the candidates
    REQUIRE(a.size() == b.size());
    for (std::size_t k = 0; k < a.size(); ++k) CHECK((a[k].type == b[k].type && a[k].a == b[k].a && a[k].b == b[k].b));
    CHECK(lent.driver_pairs().pairs == fresh.driver_pairs().pairs);
    CHECK(lent_store.force == fresh_store.force);
    CHECK(lent_store.torque == fresh_store.torque);
    contacts = std::max(contacts, fresh.stats().contacts);
  }
  CHECK(contacts > 20);  // pairs in contact, not an empty list
}
