#include "sim/rank_contacts.hpp"

#include <algorithm>

#include "polydem/error.hpp"
#include "sim/contact_table.hpp"
#include "sim/rank_energy.hpp"

namespace polydem {

namespace {

// m, the largest scaled bounding radius of the scene.
double largest_bounding_radius(const std::vector<Shape>& shapes, const Bodies& bodies) {
  double r = 0.0;
  for (std::size_t b = 0; b < bodies.size(); ++b) r = std::max(r, shapes[bodies.shape[b]].bounding_radius * bodies.scale[b]);
  return r;
}

// What a rank tells the others of a body it owns after the pair loop.
struct BodyShare {
  std::uint32_t id;
  double force[3], torque[3];  // N, N m: its contact sums
};

// A driver pair's reaction, for the sum in the one-process pair order (body, then driver).
struct ReactionShare {
  std::uint32_t i, j;
  double force_i[3], torque_j[3];  // N on body i, N m on driver j
};

void put(double out[3], const Vec3& v) { out[0] = v.x(); out[1] = v.y(); out[2] = v.z(); }
Vec3 get(const double in[3]) { return {in[0], in[1], in[2]}; }

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
  std::vector<char> body_bytes, driver_bytes;
  append_active(engine_->body_pairs(), store_, false, body_bytes);
  append_active(engine_->driver_pairs(), store_, true, driver_bytes);
  whole.body_pairs() = table_of(records_of<TableSlot>(link_.all_gather(body_bytes)));
  whole.driver_pairs() = table_of(records_of<TableSlot>(link_.all_gather(driver_bytes)));
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
  share_forces(bodies);
  share_driver_reactions(drivers);
  const RankEnergy total = sum_rank_energy(link_, engine_->body_pairs(), engine_->driver_pairs(), store_, bodies.size());
  energy_ = total.energy;
  contacts_ = total.contacts;
}

// force += the owner's contact sum, for every body: the one-process arithmetic.
void RankContacts::share_forces(Bodies& bodies) {
  std::vector<char> bytes;
  for (std::size_t k = 0; k < store_.global_id.size(); ++k) {
    if (store_.ghost[k]) continue;
    BodyShare s{store_.global_id[k], {}, {}};
    put(s.force, store_.force[k]);
    put(s.torque, store_.torque[k]);
    append_record(bytes, s);
  }
  for (const BodyShare& s : records_of<BodyShare>(link_.all_gather(bytes))) {
    bodies.force[s.id] += get(s.force);
    bodies.torque[s.id] += get(s.torque);
  }
}

// Each driver's reaction summed over the touching pairs in (body, driver) order, as one process.
void RankContacts::share_driver_reactions(Drivers& drivers) const {
  const PairList& list = engine_->driver_pairs();
  std::vector<char> bytes;
  for (std::size_t k = 0; k < list.size(); ++k) {
    if (!list.touching[k]) continue;
    ReactionShare r{store_.global_id[list.pairs[k].i], list.pairs[k].j, {}, {}};
    put(r.force_i, list.force_i[k]);
    put(r.torque_j, list.torque_j[k]);
    append_record(bytes, r);
  }
  std::vector<ReactionShare> all = records_of<ReactionShare>(link_.all_gather(bytes));
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
