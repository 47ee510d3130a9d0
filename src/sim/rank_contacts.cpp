#include "sim/rank_contacts.hpp"

#include <algorithm>

#include "polydem/error.hpp"
#include "sim/contact_table.hpp"
#include "sim/rank_energy.hpp"

namespace polydem {

namespace {

void put(double out[3], const Vec3& v) { out[0] = v.x(); out[1] = v.y(); out[2] = v.z(); }
Vec3 get(const double in[3]) { return {in[0], in[1], in[2]}; }

// m, the largest scaled bounding radius of the scene.
double largest_bounding_radius(const std::vector<Shape>& shapes, const Bodies& bodies) {
  double r = 0.0;
  for (std::size_t b = 0; b < bodies.size(); ++b) r = std::max(r, shapes[bodies.shape[b]].bounding_radius * bodies.scale[b]);
  return r;
}

}  // namespace

RankContacts::RankContacts(const RankLink& link, const std::vector<Shape>& shapes, const Bodies& bodies,
                           ContactSettings settings)
    : link_(link), shapes_(shapes), settings_(settings) {
  const double band = settings_.particle.cohesion ? settings_.particle.dncut : 0.0;  // m
  halo_ = ghost_halo(largest_bounding_radius(shapes, bodies), settings_.skin + band);
  settings_.spheres_only = std::all_of(bodies.shape.begin(), bodies.shape.end(), [&](int s) {
    return shapes[s].is_sphere();
  });
  settings_.pair_energies = true;
}

bool RankContacts::lists_stale(const Bodies& bodies, const Drivers& drivers) {
  bool stale = forced_ || !engine_;
  if (!stale) {
    store_.refresh(bodies);
    stale = engine_->lists_stale(store_.view(), drivers);
  }
  return link_.any(stale);  // one rank's moved body rebuilds every rank's lists
}

void RankContacts::redistribute(const Bodies& bodies, const ContactEngine& whole) {
  for (std::size_t b = 0; b < bodies.size(); ++b)  // every rank sees the same state: all throw
    if (!bodies.position[b].allFinite())
      throw RunError("the neighbour search met a non-finite position (body " + std::to_string(b) + ")");
  const Slabs slabs = cut_slabs(bodies.position, link_.ranks());
  std::vector<std::uint32_t> ids;
  std::vector<std::uint8_t> ghost;
  local_bodies_of(slabs, link_.rank(), bodies.position, halo_, ids, ghost);
  local_of_.assign(bodies.size(), -1);
  for (std::size_t k = 0; k < ids.size(); ++k) local_of_[ids[k]] = std::int32_t(k);
  store_.select(bodies, std::move(ids), std::move(ghost));
  engine_ = std::make_unique<ContactEngine>(shapes_, store_.view(), settings_);
  engine_->body_pairs() = localise(whole.body_pairs(), local_of_, false);  // handed over by the rebuild
  engine_->driver_pairs() = localise(whole.driver_pairs(), local_of_, true);
}

void RankContacts::gather_table(ContactEngine& whole) const {
  if (!engine_) return;  // no step yet: whole's lists are the table
  std::vector<char> bytes;
  append_section(bytes, active_slots(engine_->body_pairs(), store_, false));
  append_section(bytes, active_slots(engine_->driver_pairs(), store_, true));
  std::vector<TableSlot> body, driver;
  for (const std::vector<char>& from : link_.all_gather(bytes)) {
    std::size_t at = 0;
    for (const TableSlot& t : read_section<TableSlot>(from, at)) body.push_back(t);
    for (const TableSlot& t : read_section<TableSlot>(from, at)) driver.push_back(t);
  }
  whole.body_pairs() = table_of(std::move(body));
  whole.driver_pairs() = table_of(std::move(driver));
}

void RankContacts::compute(Bodies& bodies, Drivers& drivers, double dt, ContactEngine& whole) {
  const bool stale = lists_stale(bodies, drivers);
  if (stale) {
    if (!forced_) gather_table(whole);  // forced: whole's lists hold the table already
    redistribute(bodies, whole);
    forced_ = false;
    ++rebuilds_;
  }
  engine_->compute(store_.view(), drivers, dt, stale);
  share_results(bodies, drivers);
}

// One gather: the owned bodies' contact sums, the driver pairs' reactions, the pair energies.
void RankContacts::share_results(Bodies& bodies, Drivers& drivers) {
  const EnergyShare mine = energy_share(engine_->body_pairs(), engine_->driver_pairs(), store_);
  std::vector<char> bytes;
  append_section(bytes, body_shares());
  append_section(bytes, reaction_shares());
  append_section(bytes, mine.counts);
  append_section(bytes, mine.pairs);
  append_section(bytes, std::vector<std::uint64_t>{mine.contacts});
  std::vector<BodyShare> forces;
  std::vector<ReactionShare> reactions;
  std::vector<EnergyShare> energies(link_.ranks());
  const std::vector<std::vector<char>> all = link_.all_gather(bytes);
  for (int r = 0; r < link_.ranks(); ++r) {
    std::size_t at = 0;
    for (const BodyShare& b : read_section<BodyShare>(all[r], at)) forces.push_back(b);
    for (const ReactionShare& x : read_section<ReactionShare>(all[r], at)) reactions.push_back(x);
    energies[r].counts = read_section<PairCounts>(all[r], at);
    energies[r].pairs = read_section<PairEnergy>(all[r], at);
    energies[r].contacts = read_section<std::uint64_t>(all[r], at).at(0);
  }
  for (const BodyShare& b : forces) {  // force += the owner's contact sum, for every body: one process's arithmetic
    bodies.force[b.id] += get(b.force);
    bodies.torque[b.id] += get(b.torque);
  }
  add_reactions(std::move(reactions), drivers);
  const RankEnergy total = total_energy(energies, bodies.size());
  energy_ = total.energy;
  contacts_ = total.contacts;
}

std::vector<BodyShare> RankContacts::body_shares() const {
  std::vector<BodyShare> out;
  for (std::size_t k = 0; k < store_.global_id.size(); ++k) {
    if (store_.ghost[k]) continue;
    BodyShare s{store_.global_id[k], {}, {}};
    put(s.force, store_.force[k]);
    put(s.torque, store_.torque[k]);
    out.push_back(s);
  }
  return out;
}

std::vector<ReactionShare> RankContacts::reaction_shares() const {
  const PairList& list = engine_->driver_pairs();
  std::vector<ReactionShare> out;
  for (std::size_t k = 0; k < list.size(); ++k) {
    if (!list.touching[k]) continue;
    ReactionShare r{store_.global_id[list.pairs[k].i], list.pairs[k].j, {}, {}};
    put(r.force_i, list.force_i[k]);
    put(r.torque_j, list.torque_j[k]);
    out.push_back(r);
  }
  return out;
}

// Each driver's reaction summed over the touching pairs in (body, driver) order, as one process.
void add_reactions(std::vector<ReactionShare> all, Drivers& drivers) {
  std::sort(all.begin(), all.end(), [](const ReactionShare& a, const ReactionShare& b) {
    return a.i != b.i ? a.i < b.i : a.j < b.j;
  });
  for (std::size_t j = 0; j < drivers.size(); ++j) drivers[j].force = drivers[j].torque = Vec3::Zero();
  for (const ReactionShare& r : all) {
    drivers[r.j].force -= get(r.force_i);
    drivers[r.j].torque += get(r.torque_j);
  }
}

}  // namespace polydem
