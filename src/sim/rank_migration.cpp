#include "sim/rank_migration.hpp"

#include <algorithm>
#include <cmath>

#include "sim/body_exchange.hpp"

namespace polydem {

namespace {

// A section of raw bytes (a count, then the bytes), read back by read_section<char>.
void append_bytes(std::vector<char>& out, const std::vector<char>& bytes) {
  append_record(out, std::uint64_t(bytes.size()));
  out.insert(out.end(), bytes.begin(), bytes.end());
}

// m, the least distance between a point of box a and a point of box b (infinite sides give 0).
double box_distance(const PartBox& a, const PartBox& b) {
  return (b.lo - a.hi).cwiseMax(a.lo - b.hi).cwiseMax(Vec3::Zero()).norm();
}

// The parts other than `p` whose box lies within `halo` of p's: the only ones p's owned
// bodies can be ghosts of (an owned centre is in p's box, so no nearer to another box).
std::vector<int> near_parts(const DomainCut& cut, int p, double halo) {
  std::vector<int> near;
  for (int q = 0; q < cut.parts(); ++q)
    if (q != p && box_distance(cut.boxes[p], cut.boxes[q]) < halo) near.push_back(q);
  return near;
}

}  // namespace

namespace {

// The slots each rank is sent (per rank: body pairs, driver pairs; global ids).
struct SlotsTo {
  std::vector<std::vector<TableSlot>> body, driver;
  explicit SlotsTo(int ranks) : body(ranks), driver(ranks) {}
};

// Each owned row of `store` to its new owner `owner[row]` with `to`'s slots; the movers that come
// merged with the kept rows, and the slots that come after this rank's own `to` ones (a collective).
Handover send_movers(const RankLink& link, const LocalStore& store, const std::vector<int>& owner, SlotsTo to) {
  const int me = link.rank();
  std::vector<std::vector<std::uint32_t>> movers(link.ranks());  // store rows
  std::vector<std::uint32_t> kept;
  for (std::uint32_t k : store.owned_rows()) (owner[k] == me ? kept : movers[owner[k]]).push_back(k);
  std::vector<Parcel> parcels;
  for (int q = 0; q < link.ranks(); ++q) {
    if (q == me || (movers[q].empty() && to.body[q].empty() && to.driver[q].empty())) continue;
    Parcel p{q, {}};
    append_bytes(p.bytes, pack_movers(store, movers[q]));
    append_section(p.bytes, to.body[q]);
    append_section(p.bytes, to.driver[q]);
    parcels.push_back(std::move(p));
  }
  LocalStore landed;  // the movers that come, few: then merged with the kept rows, each field written once
  Handover out;
  out.body_slots = std::move(to.body[me]);  // each pair's slots from one rank: the old owner of i
  out.driver_slots = std::move(to.driver[me]);
  for (const Parcel& p : link.deliver(std::move(parcels))) {
    std::size_t at = 0;
    unpack_movers(read_section<char>(p.bytes, at), landed);
    for (const TableSlot& t : read_section<TableSlot>(p.bytes, at)) out.body_slots.push_back(t);
    for (const TableSlot& t : read_section<TableSlot>(p.bytes, at)) out.driver_slots.push_back(t);
  }
  landed.sort_by_id();
  const auto ghosts = std::size_t(std::count(store.ghost.begin(), store.ghost.end(), std::uint8_t(1)));
  out.owned.merge_of(store, kept, landed, ghosts + ghosts / 8 + 16);  // room for about as many ghosts as before
  return out;
}

std::vector<int> new_owners(const DomainCut& cut, const LocalStore& store) {
  std::vector<int> owner(store.size());  // each row's new owner
  for (std::size_t k = 0; k < store.size(); ++k) owner[k] = cut.owner(store.position[k]);
  return owner;
}

}  // namespace

Handover migrate(const RankLink& link, const DomainCut& cut, const LocalStore& store,
                 const std::vector<TableSlot>& body, const std::vector<TableSlot>& driver) {
  const std::vector<int> owner = new_owners(cut, store);
  SlotsTo to(link.ranks());
  RowCursor rows{store.global_id};  // the slots come in pair order: i increasing, j > i
  for (const TableSlot& t : body) {  // a pair to both new owners: each lists it
    const std::size_t i = rows.at(t.i);
    const int to_i = owner[i], to_j = owner[rows.after(i, t.j)];
    to.body[to_i].push_back(t);
    if (to_j != to_i) to.body[to_j].push_back(t);
  }
  RowCursor driver_rows{store.global_id};
  for (const TableSlot& t : driver) to.driver[owner[driver_rows.at(t.i)]].push_back(t);
  return send_movers(link, store, owner, std::move(to));
}

Handover migrate_lists(const RankLink& link, const DomainCut& cut, const LocalStore& store, const PairList& body,
                       const PairList& driver, const std::vector<int>& was_owner) {
  const int me = link.rank();
  const std::vector<int> owner = new_owners(cut, store);
  SlotsTo to(link.ranks());
  for (std::size_t k = 0; k < body.size(); ++k) {
    const BodyPair p = body.pairs[k];
    if (store.ghost[p.i]) continue;  // the owner of i answers for the pair
    const int to_i = owner[p.i], to_j = owner[p.j], held = was_owner[p.j];  // this rank and j's owner hold it
    if (to_i != me && to_i != held) append_pair_slots(body, k, store.global_id, false, to.body[to_i]);
    if (to_j != to_i && to_j != me && to_j != held) append_pair_slots(body, k, store.global_id, false, to.body[to_j]);
  }
  for (std::size_t k = 0; k < driver.size(); ++k) {
    const std::uint32_t i = driver.pairs[k].i;
    if (!store.ghost[i] && owner[i] != me) append_pair_slots(driver, k, store.global_id, true, to.driver[owner[i]]);
  }
  return send_movers(link, store, owner, std::move(to));
}

GhostPlan share_ghosts(const RankLink& link, const DomainCut& cut, double halo, LocalStore& store) {
  const int me = link.rank();
  GhostPlan plan;
  plan.send.resize(link.ranks());
  plan.receive.resize(link.ranks());
  plan.owned = store.global_id;
  const std::vector<int> near = near_parts(cut, me, halo);
  std::vector<std::vector<std::uint32_t>> rows(link.ranks());  // store rows of plan.send
  for (std::uint32_t k = 0; k < store.size(); ++k)
    for (int q : near)
      if (cut.distance(q, store.position[k]) < halo) {
        plan.send[q].push_back(store.global_id[k]);
        rows[q].push_back(k);
      }
  std::vector<Parcel> parcels;
  for (int q : near) {
    if (plan.send[q].empty()) continue;
    Parcel p{q, {}};
    append_section(p.bytes, plan.send[q]);
    append_bytes(p.bytes, pack_ghosts(store, rows[q]));
    parcels.push_back(std::move(p));
  }
  LocalStore ghosts;  // then merged into the owned rows in place
  for (const Parcel& p : link.deliver(std::move(parcels))) {
    std::size_t at = 0;
    plan.receive[p.rank] = read_section<std::uint32_t>(p.bytes, at);
    unpack_ghosts(read_section<char>(p.bytes, at), plan.receive[p.rank], ghosts);
  }
  ghosts.sort_by_id();
  store.merge_in(ghosts);
  plan.local = store.global_id;
  plan.ghost = store.ghost;
  return plan;
}

long least_over_ranks(const RankLink& link, long mine) {
  std::vector<char> bytes;
  append_record(bytes, std::int64_t(mine));
  long least = -1;
  for (const std::vector<char>& from : link.all_gather_same(bytes)) {
    std::int64_t b = -1;
    std::memcpy(&b, from.data(), sizeof b);
    if (b >= 0 && (least < 0 || b < least)) least = long(b);
  }
  return least;
}

}  // namespace polydem
