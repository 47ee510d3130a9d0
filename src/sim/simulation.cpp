#include "sim/simulation.hpp"

#include <cmath>
#include <utility>

#include "integrate/integrate.hpp"
#include "polydem/error.hpp"
#include "polydem/line_audit.hpp"
#include "polydem/parallel.hpp"
#include "sim/body_order.hpp"
#include "sim/build_bodies.hpp"
#include "sim/turned_pass.hpp"

namespace polydem {

namespace {

int scene_line(const Scene& scene, const std::string& key);

ContactSettings contact_settings(const Scene& scene, const Bodies& bodies, const std::vector<Shape>& shapes) {
  const ContactOperator& op = scene.forces.contact;
  ContactSettings s{};
  if (op.present) {  // a scene without a contact operator (drag only) has no law to prepare
    s.particle = prepare_law(op.config);
    s.driver = prepare_law(op.config_driver, &op.config);  // the parser made config_driver config when absent
    s.particle.exact_step = s.driver.exact_step = scene.simulation.exact_step;
    for (std::size_t b = 0; b < bodies.size() && op.config.hertz; ++b)
      if (!(shapes[bodies.shape[b]].radius > 0.0))
        throw InputError(input_message(op.loc.file, op.loc.line, "model",
                                       "hertz needs rounded shapes (its R* is the rounding radius); shape '" +
                                           shapes[bodies.shape[b]].name + "' has radius 0"));
  }
  if (scene.simulation.skin) {
    s.skin = *scene.simulation.skin;
  } else {  // 10% of the smallest bounding radius: few candidates, rebuilds every ~tens of steps
    double r_min = std::numeric_limits<double>::infinity();
    for (std::size_t b = 0; b < bodies.size(); ++b)
      r_min = std::min(r_min, shapes[bodies.shape[b]].bounding_radius * bodies.scale[b]);
    s.skin = bodies.size() ? 0.1 * r_min : 0.0;
  }
  s.skin_max = scene.simulation.skin_max.value_or(kSkinMaxFactor * s.skin);
  if (s.skin_max < s.skin)  // the skin was chosen here (10% of the smallest radius): a given one is checked when read
    throw InputError(input_message(scene.path, scene_line(scene, "simulation.skin_max"), "skin_max",
                                   "below the automatic skin " + std::to_string(s.skin) + " m: give a skin too, or a larger skin_max"));
  return s;
}

// The law's contacts take its exact step (contact/law/exact_linear.hpp) where their dashpot's
// mass is fixed: the step is on, the law linear and damped.
bool exact_law(const LawParams& law) { return law.exact_step && law.normal == NormalModel::linear && law.alpha_n > 0.0; }

// Every contact takes the linear law's exact step: the laws are exact and every body is a
// sphere (its pair mass is its point's).
bool exact_everywhere(const ContactSettings& cs, const Bodies& bodies, const std::vector<Shape>& shapes,
                      bool drivers) {
  if (bodies.size() == 0 || !exact_law(cs.particle) || (drivers && !exact_law(cs.driver))) return false;
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (!shapes[bodies.shape[b]].is_sphere()) return false;
  return true;
}

// Which measured impacts bound the scene's (sim/step_accuracy.hpp): from its bodies' shapes
// and the laws its contacts take (between bodies where there are two, on drivers where there
// are drivers; Hertz's tangential spring is Mindlin's, kt unused).
ImpactModel impact_model(const ContactSettings& cs, const Bodies& bodies, const std::vector<Shape>& shapes,
                         bool drivers) {
  ImpactModel model;
  model.exact = exact_everywhere(cs, bodies, shapes, drivers);
  for (std::size_t b = 0; b < bodies.size(); ++b) model.polyhedra |= !shapes[bodies.shape[b]].is_sphere();
  bool any_law = false, every_contact_mass = true;  // damping_mass: contact on every law taken, stepped exactly
  for (const LawParams* law : {bodies.size() > 1 ? &cs.particle : nullptr, drivers ? &cs.driver : nullptr}) {
    if (!law) continue;
    model.hertz |= law->normal == NormalModel::hertz;
    model.friction |= law->mu > 0.0 && (law->kt > 0.0 || law->normal == NormalModel::hertz);
    any_law = true;
    every_contact_mass &= law->contact_mass && exact_law(*law);
  }
  model.contact_mass = any_law && every_contact_mass;
  return model;
}

// The line of a given key ("simulation.dt"), else of its block ("simulation"), else 0.
int scene_line(const Scene& scene, const std::string& key) {
  auto it = scene.key_locs.find(key);
  if (it == scene.key_locs.end()) it = scene.key_locs.find(key.substr(0, key.find('.')));
  return it == scene.key_locs.end() ? 0 : it->second.line;
}

}  // namespace

Simulation::Simulation(const Scene& scene, const ShapeLibrary& library, std::vector<BodySpec> specs,
                       const RankLink* link, std::optional<std::vector<std::uint32_t>> order)
    : drivers(scene.drivers), scene_(scene), library_(library), link_(link) {
  if (!order)
    order = scene.simulation.body_order == SimulationSettings::BodyOrder::space ? spatial_order(specs, library)
                                                                                : identity_order(specs.size());
  if (!is_order_of(*order, specs.size()))
    throw InputError("a body order of " + std::to_string(order->size()) + " entries for " +
                     std::to_string(specs.size()) + " bodies, or an id twice");
  bodies = build_bodies(in_order(std::move(specs), *order), library);
  bodies.id = std::move(*order);
  rotors_ = group_rotors(bodies, library_.shapes);
  trailing_.choose(rotors_, bodies);
  drop_sphere_orientations();  // before anything copies the bodies (a rank's store)
  if (scene.forces.gravity) gravity_ = *scene.forces.gravity;
  const ContactSettings cs = contact_settings(scene_, bodies, library_.shapes);
  const bool many = link && link->ranks() > 1;
  // A rank's engine() only holds the table of histories (gathers, checkpoints): no body's
  // geometry (28 bytes a sphere, ~300 a cube, for every body of the scene on every rank).
  Bodies none;
  engine_ = std::make_unique<ContactEngine>(library_.shapes, all_owned(many ? none : bodies), cs);
  if (many) ranks_ = std::make_unique<RankContacts>(*link, library_.shapes, bodies, cs);
  else engine_->weigh_passes(pass_weights(rotors_, bodies.size()));
  for (std::uint32_t j = 0; j < drivers.size(); ++j) {
    const MotionSettings& m = drivers.motion(j);
    drivers_move_ |= m.rotates || m.velocity != Vec3::Zero() || m.force || m.pressure;
  }
  const bool contacts = scene.forces.contact.present;
  const ImpactModel model = contacts ? impact_model(cs, bodies, library_.shapes, !drivers.empty()) : ImpactModel{};
  dt_estimate_ = estimate_time_step(bodies, library_.shapes, cs.particle, drivers.empty() ? nullptr : &cs.driver,
                                    scene.simulation.dt, expected_impact_speed(bodies, library_.shapes, drivers, gravity_),
                                    scene.simulation.accuracy, model);
  if (!contacts && !scene.simulation.dt)
    throw InputError(input_message(scene.path, scene_line(scene, "simulation.dt"), "dt",
                                   "'auto' needs a contact law to estimate the critical step; give a number"));
  dt_ = dt_estimate_.chosen;
  engine_->set_step(dt_);  // each body's own skin lasts so many steps (skin_max)
  drivers.set_contact_stiffness(dt_estimate_.kn_driver, dt_estimate_.critical_normal);  // a servo's default gain
  if (!std::isfinite(dt_) || dt_ <= 0.0)
    throw InputError(input_message(scene.path, scene_line(scene, "simulation.dt"), "dt",
                                   "cannot choose a time step automatically for this scene; give simulation.dt"));
  StateEnergy start;  // the mass moment summed as energy() sums it (exactly): no gravity work at t = 0
  for (std::size_t b = 0; b < bodies.size(); ++b) start.add_body(bodies, b);
  ledger.initial_mass_moment = start.mass_moment();
  if (ExternalForces::wanted(scene.forces))
    external_ = std::make_unique<ExternalForces>(scene.forces, library_.shapes, bodies);
  if (ranks_ && !external_) ranks_->only_gravity(gravity_);
  // One process with nothing but gravity and the contacts acting: most steps trail the walk (trails_walk)
  if (!ranks_) engine_->trail_walks(trailing_.kind() != TrailKind::none && !external_);
  if (contacts && rank() == 0)  // before a rank's cut drops the state it reads
    impact_warning_ = polydem::fast_impact_warning(bodies, library_.shapes, drivers, dt_estimate_.kn_particle,
                                                   dt_estimate_.kn_driver, dt_);
  external_forces();
  ledger.external_work = 0.0;  // forces at t = 0: no step taken, no work done yet
  predict_end_velocities(bodies, 0.0, rotors_);  // full-step velocities at t = 0
  if (contacts) {
    contact_stage();
    // No step taken: its energies are not counted (the ledger starts at zero), its turns not taken.
    if (ranks_) ranks_->drop_energy();
    else engine_->take_energy(nullptr), engine_->take_turns(nullptr);
  }
}

// One process: the engine over all bodies; many: this rank's share, then shared.
void Simulation::contact_stage() {
  if (ranks_) {
    ranks_->compute(bodies, drivers, dt_, *engine_);
    ranks_->add_sums();
  } else {
    engine_->compute(all_owned(bodies), drivers, dt_);
  }
}

void Simulation::force_rebuild(bool table_on_every_rank) {
  engine_->force_rebuild();
  if (!ranks_) return;
  if (table_on_every_rank) ranks_->force_rebuild(bodies);
  else ranks_->rebuild_next_step();
}

void Simulation::land_share(LandedShare share) {
  engine_->force_rebuild();
  engine_->body_pairs() = table_of({});
  engine_->driver_pairs() = table_of({});
  engine_->flushed() = ExactEnergy{};
  ranks_->land(std::move(share));
}

void Simulation::gather_state(bool onto_every_rank) {
  if (!ranks_) return;
  ranks_->sync_bodies(bodies, !onto_every_rank);
  ranks_->gather_table(*engine_, !onto_every_rank);
}

void Simulation::sum_energy() {
  if (ranks_) summed_ = ranks_->state_energy(bodies, drivers);
}

StateEnergy Simulation::state_energy() const {
  if (ranks_) return summed_;
  StateEnergy s;
  s.add_bodies(bodies, bodies.size());
  s.elastic = engine_->elastic(drivers);
  s.open = engine_->open_energy(nullptr);
  return s;
}

void Simulation::close_ledger() {
  if (!scene_.forces.contact.present) return;
  const EnergyParts e = ranks_ ? ranks_->take_energy() : engine_->take_energy(nullptr).value();  // J
  ledger.dissipated += e.net;
  ledger.sliding += e.sliding;
  ledger.rolling += e.rolling;
  ledger.patch_work += e.patch;
}

long Simulation::first_non_finite() const {
  return ranks_ ? ranks_->first_non_finite() : first_non_finite_body(bodies);
}

void Simulation::external_forces() {
  const std::size_t n = bodies.size();
  parallel_for(n, [&](std::size_t b) {
    bodies.force[b] = bodies.mass[b] * gravity_;
    bodies.torque[b].setZero();
  });
  // f(t + dt) . v(t + dt/2) dt: the midpoint rule for the velocity-dependent drag
  if (external_) ledger.external_work += external_->add(bodies) * dt_;
}

// Drag and fluid forces of this step (W): each rank's on the bodies it moves (its store), their
// power summed exactly over the ranks; one process, or ranks without a contact stage (each
// moves every body), on `bodies`.
double Simulation::external_power() {
  external_split_ = ranks_ && scene_.forces.contact.present;
  return external_split_ ? ranks_->add_external(*external_) : external_->add(bodies);
}

std::size_t Simulation::bodies_outside_grid() const {
  if (!external_) return 0;
  return external_split_ ? std::size_t(link_->sum({external_->outside()}).at(0)) : external_->outside();
}

// Particles get -force and -torque (about the centre) of each driver.
void Simulation::driver_work_half() {
  for (std::uint32_t j = 0; j < drivers.size(); ++j) {
    const DriverState& d = drivers[j];
    ledger.driver_work -= 0.5 * (d.force.dot(drivers.velocity_at(j, drivers.center(j))) + d.torque.dot(d.omega)) * dt_;
  }
}

// Two parallel regions a normal step (one more at a rebuild, one with drag or fluid forces):
// each stage inside is a work-shared loop, so the threads wake twice, not once per stage, and
// meet at the regions' ends alone (spheres, the closing kick left open: the opening pass moves
// and checks its thread's bodies; the pair loops' results are read after the join), else after
// the pair loops too (a closing kick in the region reads every body's sum). Many ranks: the
// contact stage runs between the regions, exchanges and all, and each rank moves the bodies it owns.
void Simulation::step(bool leave_kick_open) {
  const bool contacts = scene_.forces.contact.present;
  const bool one_process = !ranks_;
  const bool team = bodies.size() >= kParallelMinItems;
  // The bodies this rank moves (all without a contact stage: nothing to cut); a rebuild in
  // the contact stage hands some to other ranks before the closing kick (a reference: it
  // reads the new owners).
  const RotorGroups& moved = rotors_;  // a rank's own passes move its owned bodies, in its store
  const bool rank_passes = !one_process && contacts;
  const bool close_last = std::exchange(kick_open_, false);  // the last step's sums are still in the engine
  const bool ahead = std::exchange(trailed_, false);  // the last step's walk moved most bodies (trails_walk)
  if (close_last) keep_turns();  // the joined pass turns each body between its closing kick and its drift
  const bool turning = !kept_turns_.empty();  // one process's kept turns (a rank keeps its own)
  // Each thread moves the bodies whose pairs it walks, or the passes' own cut (one process: the contact stage's).
  const TeamCut cut = contacts && one_process ? engine_->pass_cut() : TeamCut{};
  // Nothing but gravity acts: the joined pass makes the forces in registers and, for spheres'
  // lists, runs the rebuild trigger's test on each position it moves (no pass of its own).
  // A rank's pass the same on its owned bodies (only_gravity).
  const bool from_gravity = close_last && !external_;
  PointWatch watch;
  const bool watched =
      from_gravity && (one_process ? engine_->watch_motion(all_owned(bodies), watch) : ranks_->watch_motion(watch));
  // Polyhedra: the same pass makes the rebuild trigger's bounds (no turns: their pass has none).
  BoundWatch bounds;
  const bool bounded = contacts && one_process && from_gravity && !watched && !turning &&
                       engine_->watch_bounds(all_owned(bodies), bounds);
  audit::serial(audit::kSerial);
  in_team(team, [&] {
    const audit::Scope passes(audit::kPasses);
    // The rebuild check reads the bodies of this thread's share of the cut, which its pass moved:
    // no barrier between them when the cut is this team's (the region's end is the one needed).
    const bool wait = cut.threads != omp_get_num_threads();
    if (close_last && !one_process)
      ranks_->close_and_start(0.5 * dt_, dt_, gravity_, watched ? &watch : nullptr);
    else if (ahead) {  // the bodies the walk left (spheres' lists, watched; cubes, bounded and posed)
      const PassTurns kept = kept_turns_.pass();  // a cube's turn, the rest's (its thread's walk left it alone)
      trailing_.rest(closing_sums(), turning ? &kept : nullptr);
    }
    else if (watched)  // points (spheres' lists): no turns
      close_and_start_step<true>(bodies, 0.5 * dt_, dt_, moved, gravity_, closing_sums(), cut, watch, wait);
    else if (turning)  // kept only where close_last
      close_turn_and_start(bodies, 0.5 * dt_, dt_, moved, gravity_, closing_sums(), from_gravity, kept_turns_.pass(),
                           cut, wait);
    else if (bounded)
      close_and_start_step<true>(bodies, 0.5 * dt_, dt_, moved, gravity_, closing_sums(), cut, bounds, wait);
    else if (from_gravity)
      close_and_start_step<true>(bodies, 0.5 * dt_, dt_, moved, gravity_, closing_sums(), cut, NoWatch{}, wait);
    else if (close_last)
      close_and_start_step(bodies, 0.5 * dt_, dt_, moved, gravity_, closing_sums(), cut, NoWatch{}, wait);
    else if (rank_passes)
      ranks_->start(0.5 * dt_, dt_, gravity_);
    else
      start_step(bodies, 0.5 * dt_, dt_, moved, gravity_, cut);  // kick, drift, predict, gravity
    if (contacts && one_process) {
      engine_->measure_motion(all_owned(bodies), watched || bounded);
      if (!(ahead && trailing_.kind() == TrailKind::isotropic))  // else posed behind the walk and in rest
        engine_->pose_before_forces(all_owned(bodies));
    }
  });
  if (close_last) sums_taken(), book_kept_turns();
  drivers.advance(time(), dt_);
  // f(t + dt) . v(t + dt/2) dt: the midpoint rule for the velocity-dependent drag
  if (external_) ledger.external_work += external_power() * dt_;
  bool stale = false;
  if (contacts) {
    // Driver work over the step by the trapezoid rule, as the kicks apply it (law.hpp): half
    // of the last step's reaction and half of this step's, on this step's driver motion.
    driver_work_half();
    if (!one_process) {
      ranks_->compute(bodies, drivers, dt_, *engine_);
    } else {
      stale = engine_->stale_after_measure(all_owned(bodies), drivers);
      audit::serial(audit::kRebuild);
      if (stale) engine_->rebuild(all_owned(bodies), drivers, true);  // region 1 posed the listed bodies
      audit::serial(audit::kSerial);
    }
  }
  PointWatch next_watch;
  BoundWatch next_bounds;
  const bool trailing = trails_walk(leave_kick_open && open_steps_follow_, next_watch, next_bounds);
  WalkTrail trail{};
  if (trailing && trailing_.kind() == TrailKind::spheres)
    trail = trailing_.open(bodies, 0.5 * dt_, dt_, gravity_, closing_sums(), next_watch);
  else if (trailing)
    trail = trailing_.open(bodies, 0.5 * dt_, dt_, gravity_, closing_sums(), next_bounds,
                           engine_->listed_poses(all_owned(bodies)));
  in_team(team, [&] {
    if (contacts && one_process) {
      const LocalBodies local = all_owned(bodies);
      using Then = ContactEngine::AfterPairs;
      engine_->forces(local, drivers, dt_, false, leave_kick_open ? Then::region_ends : Then::read_sums,
                      trailing ? &trail : nullptr);
      const audit::Scope kick(audit::kKick);
      if (!leave_kick_open) kick_after(bodies, 0.5 * dt_, moved, closing_sums(), engine_->pass_cut(), false);
    } else if (contacts) {
      if (!leave_kick_open) ranks_->kick_closing(0.5 * dt_);
    } else {
      kick(bodies, 0.5 * dt_, moved);
    }
  });
  if (trailing) trailing_.close(bodies.size());
  trailed_ = trailing;
  audit::serial(audit::kClose);
  if (contacts && one_process) engine_->close_forces(all_owned(bodies), drivers);
  audit::serial(audit::kSerial);
  if (contacts && !leave_kick_open) sums_taken(), turn_bodies_left();
  if (contacts) driver_work_half();
  kick_open_ = leave_kick_open && contacts;
  // Turns left open with the kick follow it in the next step's joined pass; their work must fall
  // in this step's ledger period, as with the kick closed, so a step that closes it closes its kick.
  if (kick_open_ && turns_left() && ledger_closes(step_ + 1)) close_step();
  ++step_;
  if (ledger_closes(step_)) close_ledger();
  audit::step_end();
}

void Simulation::close_step() {
  if (trailed_) return;  // the next step's joined pass has begun (the runner's interrupt: one more step)
  if (!std::exchange(kick_open_, false)) return;
  in_team(bodies.size() >= kParallelMinItems, [&] {
    if (ranks_)
      ranks_->kick_closing(0.5 * dt_);
    else
      kick_after(bodies, 0.5 * dt_, rotors_, closing_sums(), engine_->pass_cut(), false);
  });
  sums_taken();
  turn_bodies_left();
}

bool Simulation::turns_left() const { return ranks_ ? ranks_->turns_left() : engine_->turns_left(); }

void Simulation::turn_bodies_left() {
  if (ranks_) return ranks_->turn_owned();
  if (!engine_->turns_left()) return;
  turn_bodies(bodies, engine_->take_turns(nullptr), library_.shapes, [&](double work) { engine_->book_turn(work); });
}

void Simulation::keep_turns() {
  if (ranks_) return ranks_->keep_turns();
  if (engine_->turns_left()) kept_turns_.take(bodies, engine_->take_turns(nullptr), library_.shapes);
}

void Simulation::book_kept_turns() {
  if (ranks_) return ranks_->book_kept_turns();
  kept_turns_.book([&](double work) { engine_->book_turn(work); });
}

// One process, the kick left open and the next step to follow, with nothing but gravity and the
// contacts acting: the next step's joined pass (its watched one) can run behind this step's walk,
// `watch` its rebuild test (spheres' lists), or `bounds` (isotropic polyhedra, but where the ledger
// closes after the next step: a turn left now falls in this period only with the kick closed).
bool Simulation::trails_walk(bool next_follows, PointWatch& watch, BoundWatch& bounds) {
  if (!next_follows || !scene_.forces.contact.present || ranks_ || external_) return false;
  if (trailing_.kind() == TrailKind::isotropic)
    return !engine_->spheres_only() && !ledger_closes(step_ + 1) && engine_->watch_bounds(all_owned(bodies), bounds);
  return engine_->spheres_only() && trailing_.kind() == TrailKind::spheres &&
         engine_->watch_motion(all_owned(bodies), watch);
}

// One process: the sums a closing pass adds, from m gravity where nothing else acts (the
// opening pass may not have kept it: close_and_start_step<true>).
ForceSums Simulation::closing_sums() {
  ForceSums sums = engine_->force_sums(all_owned(bodies));
  if (!external_) sums.gravity_mass = bodies.mass.data(), sums.gravity = gravity_;
  return sums;
}

// Every owned body's contact sum was read (by a closing kick): the next pair loop starts from zeros.
void Simulation::sums_taken() {
  if (ranks_)
    ranks_->sums_taken();
  else
    engine_->sums_taken();
}

EnergyRow Simulation::energy() const {
  EnergyRow e{};
  const StateEnergy s = state_energy();
  e.kinetic = s.kinetic.value();
  e.rotational = s.rotational.value();
  e.elastic_parts = s.elastic.value();
  e.elastic = e.elastic_parts.normal + e.elastic_parts.tangential + e.elastic_parts.rolling;
  // J, since the ledger last closed
  const EnergyParts open = scene_.forces.contact.present ? s.open.value() : EnergyParts{};
  e.dissipated = ledger.dissipated + open.net;
  e.dissipated_sliding = ledger.sliding + open.sliding;
  e.dissipated_rolling = ledger.rolling + open.rolling;
  e.patch_work = ledger.patch_work + open.patch;
  // the dashpots (normal, tangential) and cohesion: what the other two mechanisms leave
  e.dissipated_dashpot = e.dissipated + e.patch_work - e.dissipated_sliding - e.dissipated_rolling;
  e.gravity_work = gravity_.dot(s.mass_moment() - ledger.initial_mass_moment);
  e.driver_work = ledger.driver_work;
  e.external_work = ledger.external_work;
  e.contacts = contacts();
  return e;
}

long first_non_finite_body(const Bodies& bodies) {
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (!finite_state(bodies, b)) return long(b);
  return -1;
}

}  // namespace polydem
