#include "sim/rank_contacts.hpp"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <utility>

#include "polydem/error.hpp"
#include "polydem/parallel.hpp"
#include "sim/body_exchange.hpp"
#include "sim/contact_table.hpp"
#include "sim/rank_energy.hpp"
#include "sim/rank_migration.hpp"
#include "sim/turned_pass.hpp"

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

// Adds what was sent between the counts `from` and `to` to `sum`.
void add_traffic(LinkCounts& sum, const LinkCounts& from, const LinkCounts& to) {
  sum.parcels += to.parcels - from.parcels;
  sum.parcel_bytes += to.parcel_bytes - from.parcel_bytes;
  sum.collectives += to.collectives - from.collectives;
  sum.collective_bytes += to.collective_bytes - from.collective_bytes;
  sum.collective_bytes_in += to.collective_bytes_in - from.collective_bytes_in;
}

RunError non_finite_position(std::size_t b) {
  return RunError("the neighbour search met a non-finite position (body " + std::to_string(b) + ")");
}

}  // namespace

RankContacts::RankContacts(const RankLink& link, const std::vector<Shape>& shapes, const Bodies& bodies,
                           ContactSettings settings)
    : link_(link), shapes_(shapes), settings_(settings), n_bodies_(bodies.size()) {
  settings_.spheres_only = std::all_of(bodies.shape.begin(), bodies.shape.end(), [&](int s) {
    return shapes[s].is_sphere();
  });
  const double band = settings_.particle.cohesion ? settings_.particle.dncut : 0.0;  // m
  // Pairs listed within R_i + R_j + (s_i + s_j) / 2 + band: the widest skins.
  const double widest = per_body_skins(settings_, settings_.spheres_only) ? settings_.skin_max : settings_.skin;  // m
  halo_ = ghost_halo(largest_bounding_radius(shapes, bodies), widest + band);
  // A sphere's orientation stays the identity; its spin's prediction is read only by the
  // tangential dashpot (sphere_kernel.hpp's v_end; a ghost's wall pairs are its owner's).
  motion_ = {!settings_.spheres_only, !settings_.spheres_only || settings_.particle.tangential_damping};
}

// This rank's word: a rebuild (none listed yet, or asked for), a stop, its owned bodies' margins.
// `ghosts_later`: the ghosts are a step old, measured once landed (fold_asks).
RankContacts::Ask RankContacts::ask_here(const Drivers& drivers, bool ghosts_later) {
  Ask mine{Requests(forced_ || rebuild_asked_ || !engine_) | Requests(stop_asked_) << 1, {}};
  if (!(mine.requests & 1)) mine.margins = engine_->owned_margins(store_.view(), drivers, watched_, ghosts_later);
  return mine;
}

bool RankContacts::lists_stale(const Drivers& drivers) {
  const Ask mine = ask_here(drivers, false);  // the store refreshed by exchange_ghosts
  std::vector<char> bytes;
  append_record(bytes, mine);
  std::vector<Ask> asks;
  for (const std::vector<char>& from : link_.all_gather_same(bytes)) {
    Ask theirs;
    std::memcpy(&theirs, from.data(), sizeof theirs);
    asks.push_back(theirs);
  }
  return decide(asks, drivers);
}

// One rank's request rebuilds every rank's lists, and so do two bodies anywhere that may have
// closed their pair's skin (the pair rule over every rank's owned bodies: the same answer on
// every rank, for any rank count); one rank's interrupt stops them all here.
bool RankContacts::decide(const std::vector<Ask>& asks, const Drivers& drivers) {
  Requests any = 0;
  std::vector<PairMargins> margins;
  for (const Ask& a : asks) {
    any |= a.requests;
    margins.push_back(a.margins);
  }
  stop_seen_ = (any >> 1) != 0;
  if (any & 1) return true;
  const RuleVerdict verdict = rule_verdict(margins.data(), margins.size(), settings_.skin);
  const bool past = std::any_of(margins.begin(), margins.end(), [](const PairMargins& m) { return m.past; });
  if (past && settings_.spheres_only) engine_->pair_rule_read();  // the next steps' points keep their margins in the pass
  if (verdict == RuleVerdict::measure) return measured_rule(drivers);
  return verdict == RuleVerdict::rebuild;
}

// The pair rule from every rank's owned points measured now: a second meeting, on the first step
// since a rebuild that some point passed skin/2 (the ranks' words carried no margins before it).
bool RankContacts::measured_rule(const Drivers& drivers) {
  std::vector<char> bytes;
  append_record(bytes, engine_->owned_point_margins(store_.view(), drivers));
  std::vector<PairMargins> all;
  for (const std::vector<char>& from : link_.all_gather_same(bytes)) {
    PairMargins theirs;
    std::memcpy(&theirs, from.data(), sizeof theirs);
    all.push_back(theirs);
  }
  return pair_rule_exceeded(all.data(), all.size(), settings_.skin);
}

// Every rank holds every body and `whole`'s table (the start, a resume, after sync_bodies):
// each cuts the domain alike, every body weighing the same (no lists yet), and takes its share
// into its store, then drops `bodies`' state where allowed (before its lists are built).
void RankContacts::redistribute(Bodies& bodies, const ContactEngine& whole) {
  for (std::size_t b = 0; b < bodies.size(); ++b)  // every rank sees the same state: all throw
    if (!bodies.position[b].allFinite()) throw non_finite_position(b);
  cut_ = cut_domain(bodies.position, std::vector<double>(bodies.size(), 1.0), link_.ranks());
  recut_.cut();
  ++cuts_;
  set_load_share(part_loads(cut_, bodies.position, std::vector<double>(bodies.size(), 1.0)));
  plan_ = plan_ghosts(cut_, link_.rank(), bodies.position, halo_);
  store_.select(bodies, plan_.local, plan_.ghost);
  bodies.drop_state();
  adopt(whole.body_pairs(), whole.driver_pairs());
}

void RankContacts::land(LandedShare share) {
  store_ = std::move(share.store);
  plan_ = GhostPlan{store_.global_id, store_.ghost, store_.global_id, {}, {}};
  plan_.send.resize(link_.ranks());
  plan_.receive.resize(link_.ranks());
  landed_body_ = std::move(share.body);
  landed_driver_ = std::move(share.driver);
  taken_ = share.flushed;
  RotorGroups groups = group_rotors(store_, store_.owned_rows(), shapes_);
  drop_sphere_orientations(store_, groups);  // files of older builds turned them
  owned_rotors_ = with_runs(std::move(groups));
  external_rows_ = ~std::size_t(0);
  engine_.reset();  // the lists of the cut before: the next step lists the share's owners' bodies
  forced_ = landed_ = true;
  rebuild_asked_ = false;
}

// A resume's share (land) at its first contact stage: a cut of every rank's sample of its
// share's centres (each body weighing the same: no lists yet), each body and slot sent to its
// owner (land_share), then the ghosts to their holders.
void RankContacts::spread_landed() {
  const long bad = least_over_ranks(link_, first_non_finite_position());
  if (bad >= 0) throw non_finite_position(std::size_t(bad));  // the same message on every rank
  const std::vector<std::uint32_t> rows = store_.owned_rows();
  const std::vector<std::uint64_t> w(rows.size(), 1);  // equal weights: no lists yet
  cut_from_sample(rows, w);
  set_load_share(summed_loads(rows, w));
  LandedShare share{std::move(store_), std::move(landed_body_), std::move(landed_driver_), {}};
  Handover h = land_share(link_, cut_, halo_, share);
  store_ = std::move(h.owned);
  plan_ = share_ghosts(link_, cut_, halo_, store_);
  landed_ = false;
  adopt_slots(h.body_slots, h.driver_slots);
}

// A rebuild the motion asks for: each rank's owned bodies and ghosts are current in its store,
// no other; the movers, with their constants and histories, go to their new owners, then the
// ghosts to their holders, point to point (sim/rank_migration.hpp): no read of the global arrays.
void RankContacts::migrate_bodies() {
  const long bad = least_over_ranks(link_, first_non_finite_position());
  if (bad >= 0) throw non_finite_position(std::size_t(bad));  // the same message on every rank
  const std::vector<std::uint32_t> owned_rows = store_.owned_rows();
  recut_if_unbalanced(owned_rows);
  Handover h = migrate_lists(link_, cut_, store_, engine_->body_pairs(), engine_->driver_pairs(), row_owners());
  const std::vector<std::uint32_t> was = std::move(store_.global_id);
  store_ = std::move(h.owned);
  plan_ = share_ghosts(link_, cut_, halo_, store_);
  // The pairs still local keep their searches: a pile's rebuild searches only its movers again.
  CandidateMemory searches = std::move(engine_->searches());
  searches.relabel(was, store_.global_id);
  // The pairs this rank held and lists again keep their slots here; the others came (migrate_lists).
  const std::vector<std::uint32_t> row_now = rows_now(was, store_.global_id);
  PairList body = kept_table(engine_->body_pairs(), row_now, store_.ghost, false,
                             local_table(h.body_slots, store_.global_id, false));
  PairList driver = kept_table(engine_->driver_pairs(), row_now, store_.ghost, true,
                               local_table(h.driver_slots, store_.global_id, true));
  new_engine();
  engine_->body_pairs() = std::move(body);
  engine_->driver_pairs() = std::move(driver);
  engine_->searches() = std::move(searches);
}

// Each row's owner: this rank, or for a ghost some listed pair reads (narrow_parcels), the rank
// its motion parcel comes from; -1 for the other ghosts.
std::vector<int> RankContacts::row_owners() const {
  std::vector<int> owner(store_.size(), -1);
  for (std::size_t k = 0; k < store_.size(); ++k)
    if (!store_.ghost[k]) owner[k] = link_.rank();
  for (std::size_t k = 0; k < in_.size(); ++k)
    for (std::uint32_t l : receive_local_[k]) owner[l] = in_[k].rank;
  return owner;
}

// The smallest id of an owned body whose centre is not finite, or -1.
long RankContacts::first_non_finite_position() const {
  for (std::size_t k = 0; k < store_.size(); ++k)  // increasing ids: the first is the smallest
    if (!store_.ghost[k] && !store_.position[k].allFinite()) return long(store_.global_id[k]);
  return -1;
}

// Lists this rank's bodies (plan_, their state in store_) and hands their histories over from
// `body_table` and `driver_table` (global ids; pairs of other bodies are left out).
void RankContacts::adopt(const PairList& body_table, const PairList& driver_table) {
  new_engine();
  engine_->body_pairs() = localise(body_table, store_.global_id, false);
  engine_->driver_pairs() = localise(driver_table, store_.global_id, true);
}

// The same from the slots a rebuild handed over (global ids), laid out once (local_table).
void RankContacts::adopt_slots(const std::vector<TableSlot>& body, const std::vector<TableSlot>& driver) {
  new_engine();
  engine_->body_pairs() = local_table(body, store_.global_id, false);
  engine_->driver_pairs() = local_table(driver, store_.global_id, true);
}

// An engine of the store's bodies (plan_), its lists to be set; the passes' groups and parcels for them.
void RankContacts::new_engine() {
  paired_ghosts_.clear();  // narrow_parcels, once listed
  owned_rotors_ = with_runs(group_rotors(store_, store_.owned_rows(), shapes_));
  size_parcels();
  engine_ = std::make_unique<ContactEngine>(shapes_, store_.view(), settings_, engine_.get());
  engine_->want_reactions(false);  // a rank's own pairs' sum is not a reaction: share_results sums every rank's
}

void RankContacts::gather_table(ContactEngine& whole, bool to_root) const {
  if (!engine_) return;  // no step yet: whole's lists are the table
  std::vector<char> bytes;
  append_section(bytes, active_slots(engine_->body_pairs(), store_, false));
  append_section(bytes, active_slots(engine_->driver_pairs(), store_, true));
  const std::vector<std::vector<char>> all = to_root ? link_.gather(bytes, 0) : link_.all_gather(bytes);
  if (all.empty()) return;  // not rank 0 of a gather to it
  std::vector<TableSlot> body, driver;
  for (const std::vector<char>& from : all) {
    std::size_t at = 0;
    for (const TableSlot& t : read_section<TableSlot>(from, at)) body.push_back(t);
    for (const TableSlot& t : read_section<TableSlot>(from, at)) driver.push_back(t);
  }
  whole.body_pairs() = table_of(body);
  whole.driver_pairs() = table_of(driver);
}

void RankContacts::compute(Bodies& bodies, Drivers& drivers, double dt, ContactEngine& whole) {
  ++steps_listed_;
  const bool stale = !forced_ && engine_ ? exchange_ghosts(drivers, dt) : lists_stale(drivers);
  watched_ = false;  // the next step's pass tells again
  if (stale) {
    // The ended contacts' sum stays (a new engine); the pairs' pending energies move with their histories.
    if (engine_) taken_.add(std::exchange(engine_->flushed(), ExactEnergy{}));
    const LinkCounts before = link_.counts();
    if (landed_) {  // a resume's share: cut, then each body and slot sent to its owner
      spread_landed();
    } else if (forced_) {  // the start or a one-file resume: whole's lists hold the table
      const ExactEnergy resumed = std::exchange(whole.flushed(), ExactEnergy{});  // J, on every rank: rank 0's to count
      if (link_.rank() == 0) taken_.add(resumed);
      sync_bodies(bodies);  // a resume's first drift moved each rank's bodies of the cut before it
      redistribute(bodies, whole);
    } else {
      migrate_bodies();
    }
    forced_ = rebuild_asked_ = false;
    steps_listed_ = 0;
    ++rebuilds_;
    add_traffic(rebuild_traffic_, before, link_.counts());
  }
  engine_->record_contacts(whole.records_contacts() || stop_seen_);  // the run loop tells the whole engine
  const LocalBodies view = store_.view();
  if (stale) {
    engine_->set_step(dt);  // each body's own skin lasts kSkinSteps steps (skin_max)
    engine_->rebuild(view, drivers);  // poses the bodies it pairs
    split_listed();
    narrow_parcels();
  }
  // The bodies' sums stay in the lists: the closing kick adds them (owned_sums), as one process's does.
  // Posed: by the rebuild, else by exchange_ghosts.
  in_team(view.size() >= kParallelMinItems, [&] {
    engine_->forces(view, drivers, dt, false, ContactEngine::AfterPairs::region_ends);
  });
  engine_->close_forces(view, drivers);
  share_results(drivers);
}

void RankContacts::add_sums() {
  const ForceSums sums = engine_->force_sums(store_.view());
  for (std::size_t k = 0; k < store_.ghost.size(); ++k)
    if (!store_.ghost[k]) sums(k);
  sums_taken();
}

void RankContacts::start(double h, double dt, const Vec3& gravity) {
  start_pass(store_, h, dt, owned_rotors_, gravity);
}

// The last stage of its region (whose end is the barrier).
void RankContacts::kick_closing(double h) { kick_after(store_, h, owned_rotors_, closing_sums(), {}, false); }

// A watched pass moves points (spheres' lists), which take no turn.
void RankContacts::close_and_start(double h, double dt, const Vec3& gravity, const PointWatch* watch) {
  if (watch)
    close_and_start_step<true>(store_, h, dt, owned_rotors_, gravity, closing_sums(), {}, *watch);
  else if (!kept_turns_.empty())
    close_turn_and_start(store_, h, dt, owned_rotors_, gravity, closing_sums(), gravity_only_, kept_turns_.pass());
  else if (gravity_only_)
    close_and_start_step<true>(store_, h, dt, owned_rotors_, gravity, closing_sums());
  else
    close_and_start_step(store_, h, dt, owned_rotors_, gravity, closing_sums());
}

bool RankContacts::watch_motion(PointWatch& watch) {
  watched_ = gravity_only_ && engine_ && !forced_ && engine_->watch_motion(store_.view(), watch);
  return watched_;
}

// The sums a closing pass adds, from m gravity where nothing else acts (the opening pass may
// not have kept it: close_and_start_step<true>).
ForceSums RankContacts::closing_sums() {
  ForceSums sums = engine_->force_sums(store_.view());
  if (gravity_only_) sums.gravity_mass = store_.mass.data(), sums.gravity = gravity_;
  return sums;
}

void RankContacts::sums_taken() {
  const ForceSums sums = engine_->force_sums(store_.view());
  for (std::uint32_t k : paired_ghosts_) sums.body[k] = BodySum{};  // a ghost's sum is its owner's to add (none without a pair)
  engine_->sums_taken();
}

// Point to point: each owned body to the ranks that hold it as a ghost, each ghost from its
// owner, written into the store when it lands; then whether some rank's lists are stale. While
// the parcels travel this rank poses its own listed bodies: no ghost is read before finish (in_'s
// bytes are undefined until then; the thread link's test poisons them). Those poses are wasted
// only where a rebuild follows (it poses its new lists); the ghosts are posed once landed.
bool RankContacts::exchange_ghosts(const Drivers& drivers, double dt) {
  const Ask mine = fold_ ? ask_here(drivers, true) : Ask{};  // its owned bodies measured (polyhedral ghosts: once landed)
  pack_parcels(mine);
  link_.post(out_, in_);
  if (!mine.rebuild_here()) engine_->pose_listed(store_.view(), owned_listed_);  // no rebuild asked here
  link_.finish(out_, in_);
  unpack_parcels(dt);
  const bool stale = fold_ ? fold_asks(mine, drivers) : lists_stale(drivers);
  if (!stale) engine_->pose_listed(store_.view(), ghost_listed_);
  return stale;
}

// Each owned body's motion into the parcels of the ranks that hold it, then (fold_) the word.
void RankContacts::pack_parcels(const Ask& mine) {
  for (std::size_t k = 0; k < out_.size(); ++k) {
    Parcel& p = out_[k];
    pack_motion(store_, send_local_[k], motion_, p.bytes.data());
    if (fold_) std::memcpy(p.bytes.data() + p.bytes.size() - sizeof mine, &mine, sizeof mine);
  }
}

// Each landed motion parcel into the store's ghosts, drifted by dt (s).
void RankContacts::unpack_parcels(double dt) {
  for (std::size_t k = 0; k < in_.size(); ++k)
    unpack_motion(in_[k].bytes.data(), {receive_local_[k], drifted_[k].data()}, motion_, dt, store_);
}

// The step's decision where the ghost parcels carry it (fold_: every rank a neighbour of every
// other), so a step meets the other ranks once: `mine`, measured on the store with its ghosts a
// step old (left out: their owners answer for them), and each landed parcel's word; the ghosts
// are measured again once landed (the pair loop's skip test reads their bounds).
bool RankContacts::fold_asks(const Ask& mine, const Drivers& drivers) {
  std::vector<Ask> asks{mine};
  for (const Parcel& p : in_) {
    Ask theirs;
    std::memcpy(&theirs, p.bytes.data() + p.bytes.size() - sizeof theirs, sizeof theirs);
    asks.push_back(theirs);
  }
  engine_->remeasure(store_.view(), paired_ghosts_);
  return decide(asks, drivers);
}

// The lists' bodies by kind, for exchange_ghosts' two parts of the poses.
void RankContacts::split_listed() {
  owned_listed_.clear();
  ghost_listed_.clear();
  for (std::uint32_t b : engine_->listed()) (store_.ghost[b] ? ghost_listed_ : owned_listed_).push_back(b);
}

// The ghost exchange's parcels, sized once per plan (no allocation a step), the local indices
// of each parcel's bodies (the store's local_of) and the received ones' positions now (the store
// just selected), which the next steps drift. The parcels carry the step's
// requests when every rank sends to and receives from every other (a collective: all agree).
void RankContacts::size_parcels() {
  out_.clear();
  in_.clear();
  send_local_.clear();
  receive_local_.clear();
  drifted_.clear();
  std::uint64_t links = 0;  // other ranks this one sends to and receives from
  for (int q = 0; q < link_.ranks(); ++q) links += !plan_.send[q].empty() && !plan_.receive[q].empty();
  fold_ = link_.ranks() > 1 && link_.sum({links}).at(0) == std::uint64_t(link_.ranks()) * (link_.ranks() - 1);
  const std::size_t word = fold_ ? sizeof(Ask) : 0;  // bytes after the ghosts
  const std::size_t body = motion_bytes(motion_);
  for (int q = 0; q < link_.ranks(); ++q) {
    if (!plan_.send[q].empty()) {
      out_.push_back({q, std::vector<char>(plan_.send[q].size() * body + word)});
      std::vector<std::uint32_t>& local = send_local_.emplace_back();
      for (std::uint32_t b : plan_.send[q]) local.push_back(store_.local_of(b));
    }
    if (plan_.receive[q].empty()) continue;
    in_.push_back({q, std::vector<char>(plan_.receive[q].size() * body + word)});
    std::vector<std::uint32_t>& local = receive_local_.emplace_back();
    std::vector<Vec3>& x = drifted_.emplace_back();
    for (std::uint32_t b : plan_.receive[q]) {
      local.push_back(store_.local_of(b));
      x.push_back(store_.position[local.back()]);
    }
  }
}

// After a rebuild: the motion parcels carry only the bodies a pair across the cut reads
// (paired_across: ~56% of a settled cube bed's ghosts), the received ones drifted from here.
void RankContacts::narrow_parcels() {
  std::vector<int> owner(store_.size(), -1);  // a ghost's owner, per local row
  for (std::size_t k = 0; k < in_.size(); ++k)
    for (std::uint32_t l : receive_local_[k]) owner[l] = in_[k].rank;
  PairedRows paired = paired_across(engine_->body_pairs().pairs, owner, link_.ranks());
  const std::size_t word = fold_ ? sizeof(Ask) : 0;  // bytes after the ghosts
  const std::size_t body = motion_bytes(motion_);
  for (std::size_t k = 0; k < out_.size(); ++k) {
    send_local_[k] = std::move(paired.send[out_[k].rank]);
    out_[k].bytes.resize(send_local_[k].size() * body + word);
  }
  paired_ghosts_.clear();
  for (std::size_t k = 0; k < in_.size(); ++k) {
    receive_local_[k] = std::move(paired.receive[in_[k].rank]);
    in_[k].bytes.resize(receive_local_[k].size() * body + word);
    drifted_[k].clear();
    for (std::uint32_t l : receive_local_[k]) drifted_[k].push_back(store_.position[l]);
    paired_ghosts_.insert(paired_ghosts_.end(), receive_local_[k].begin(), receive_local_[k].end());
  }
}

void RankContacts::sync_bodies(Bodies& bodies, bool to_root) const {
  const std::vector<char> mine = pack_owned(store_, store_.owned_rows());
  const std::vector<std::vector<char>> all = to_root ? link_.gather(mine, 0) : link_.all_gather(mine);
  if (all.empty()) return;  // not rank 0 of a gather to it: no state grown here
  bodies.grow_state();
  store_.publish(bodies);
  for (int r = 0; r < int(all.size()); ++r)
    if (r != link_.rank()) unpack_owned(all[r], bodies);
}

double RankContacts::add_external(ExternalForces& forces) {
  FieldBodies rows = field_rows(store_);
  rows.ghost = store_.ghost.data();
  if (std::exchange(external_rows_, rebuilds_) != rebuilds_) forces.set_rows(rows);  // the store changes at rebuilds only
  const std::vector<std::uint64_t> words = link_.sum(forces.add(rows).words());  // integers: exact in any order
  return ExactSum::from_words(words.data(), std::uint64_t(link_.ranks())).value();
}

std::vector<std::uint32_t> RankContacts::output_bodies() const {
  if (engine_ || landed_) return plan_.owned;
  std::vector<std::uint32_t> every(link_.rank() == 0 ? n_bodies_ : 0);
  std::iota(every.begin(), every.end(), 0u);
  return every;
}

std::vector<TableSlot> RankContacts::output_slots(const ContactEngine& whole, bool driver) const {
  if (landed_) return driver ? landed_driver_ : landed_body_;
  if (engine_) return active_slots(driver ? engine_->driver_pairs() : engine_->body_pairs(), store_, driver);
  std::vector<TableSlot> slots;
  if (link_.rank() != 0) return slots;
  const PairList& list = driver ? whole.driver_pairs() : whole.body_pairs();
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::size_t first = slots.size();
    for (std::uint32_t s = list.slot_begin[k]; s < list.slot_begin[k + 1]; ++s)
      if (list.active[s])
        slots.push_back({list.pairs[k].i, list.pairs[k].j, list.features[s], {list.history(s), {}}, list.record(s)});
    if (slots.size() > first) slots[first].slot.pending = list.open_energy(k);
  }
  return slots;
}

ExactEnergy RankContacts::output_flushed(const ContactEngine& whole) const {
  if (landed_) return taken_;
  if (!engine_) return link_.rank() == 0 ? whole.flushed() : ExactEnergy{};
  ExactEnergy mine = taken_;  // J
  mine.add(engine_->flushed());
  return mine;
}

long RankContacts::first_non_finite() const { return least_over_ranks(link_, first_non_finite_owned()); }

long RankContacts::first_non_finite_owned() const {
  for (std::size_t k = 0; k < store_.ghost.size(); ++k)  // increasing ids: the first is the smallest
    if (!store_.ghost[k] && !finite_state(store_, k)) return long(store_.global_id[k]);
  return -1;
}

// The touching driver pairs' reactions, gathered at the steps that read them.
void RankContacts::share_results(Drivers& drivers) {
  if (!reactions_wanted_ && !stop_seen_) return;  // no collective: the drivers keep their last reactions
  std::vector<char> bytes;
  append_section(bytes, reaction_shares());
  std::vector<ReactionShare> all;
  for (const std::vector<char>& from : link_.all_gather(bytes)) {
    std::size_t at = 0;
    for (const ReactionShare& x : read_section<ReactionShare>(from, at)) all.push_back(x);
  }
  add_reactions(std::move(all), drivers);
}

EnergyParts RankContacts::take_energy() {
  ExactEnergy mine = std::exchange(taken_, ExactEnergy{});  // J
  if (engine_) mine.add(engine_->take_energy(&store_.ghost));
  return sum_over_ranks(link_, mine);
}

StateEnergy RankContacts::state_energy(const Bodies& bodies, const Drivers& drivers) {
  StateEnergy mine;
  with_output_rows(bodies, [&](const auto& arrays, const std::vector<std::uint32_t>& rows) {
    for (std::uint32_t k : rows) mine.add_body(arrays, k);  // before a cut: rank 0 every body
  });
  mine.open = taken_;  // J
  if (engine_) {
    mine.elastic = engine_->elastic(drivers, &store_.ghost);
    mine.open.add(engine_->open_energy(&store_.ghost));
  }
  std::vector<std::uint64_t> words = mine.words();
  words.push_back(engine_ ? owned_contacts(engine_->body_pairs(), engine_->driver_pairs(), store_) : 0);
  std::vector<std::uint64_t> total = link_.sum(words);  // integers: exact in any order
  contacts_ = total.back();
  total.pop_back();
  return StateEnergy::from_words(total, std::uint64_t(link_.ranks()));
}

void RankContacts::drop_energy() {
  taken_ = ExactEnergy{};
  if (engine_) engine_->take_energy(nullptr), engine_->take_turns(nullptr);
}

void RankContacts::turn_owned() {
  if (!turns_left()) return;
  turn_bodies(store_, engine_->take_turns(&store_.ghost), shapes_, [&](double work) { engine_->book_turn(work); });
}

void RankContacts::keep_turns() {
  if (turns_left()) kept_turns_.take(store_, engine_->take_turns(&store_.ghost), shapes_);
}

void RankContacts::book_kept_turns() {
  kept_turns_.book([&](double work) { engine_->book_turn(work); });
}

std::size_t RankContacts::pairs() const {
  return engine_ ? engine_->body_pairs().size() + engine_->driver_pairs().size() : 0;
}

std::size_t RankContacts::candidates() const {
  return engine_ ? engine_->body_pairs().slot_count() + engine_->driver_pairs().slot_count() : 0;
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

namespace {

bool before(const ReactionShare& a, const ReactionShare& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; }

// Into (body, driver) order: each rank's shares come in its list's order, already sorted, so
// the few runs are merged (O(n) a run; a sort of 56-byte records was 9% of a sphere bed's rank).
void order_shares(std::vector<ReactionShare>& all) {
  constexpr std::size_t kMaxRuns = 64;  // more: not the ranks' runs, sorted
  std::vector<std::size_t> ends;
  for (std::size_t k = 1; k < all.size() && ends.size() <= kMaxRuns; ++k)
    if (before(all[k], all[k - 1])) ends.push_back(k);
  if (ends.size() > kMaxRuns) return std::sort(all.begin(), all.end(), before);
  ends.push_back(all.size());
  for (std::size_t r = 0; r + 1 < ends.size(); ++r)  // the sorted prefix and the next run
    std::inplace_merge(all.begin(), all.begin() + std::ptrdiff_t(ends[r]), all.begin() + std::ptrdiff_t(ends[r + 1]),
                       before);
}

}  // namespace

// Each driver's reaction summed over the touching pairs in (body, driver) order, as one process.
void add_reactions(std::vector<ReactionShare> all, Drivers& drivers) {
  order_shares(all);
  for (std::size_t j = 0; j < drivers.size(); ++j) drivers[j].force = drivers[j].torque = Vec3::Zero();
  for (const ReactionShare& r : all) {
    drivers[r.j].force -= get(r.force_i);
    drivers[r.j].torque += get(r.torque_j);
  }
}

}  // namespace polydem
