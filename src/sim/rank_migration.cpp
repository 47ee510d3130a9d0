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

Handover migrate(const RankLink& link, const DomainCut& cut, const std::vector<std::uint32_t>& owned,
                 const std::vector<TableSlot>& body, const std::vector<TableSlot>& driver, Bodies& bodies) {
  const int me = link.rank();
  std::vector<std::vector<std::uint32_t>> movers(link.ranks());
  std::vector<std::vector<TableSlot>> body_to(link.ranks()), driver_to(link.ranks());
  Handover out;
  for (std::uint32_t b : owned) {
    const int to = cut.owner(bodies.position[b]);
    (to == me ? out.owned : movers[to]).push_back(b);
  }
  for (const TableSlot& t : body) {  // a pair to both new owners: each lists it
    const int to_i = cut.owner(bodies.position[t.i]), to_j = cut.owner(bodies.position[t.j]);
    body_to[to_i].push_back(t);
    if (to_j != to_i) body_to[to_j].push_back(t);
  }
  for (const TableSlot& t : driver) driver_to[cut.owner(bodies.position[t.i])].push_back(t);
  std::vector<Parcel> parcels;
  for (int q = 0; q < link.ranks(); ++q) {
    if (q == me || (movers[q].empty() && body_to[q].empty() && driver_to[q].empty())) continue;
    Parcel p{q, {}};
    append_bytes(p.bytes, pack_owned(bodies, movers[q]));
    append_section(p.bytes, body_to[q]);
    append_section(p.bytes, driver_to[q]);
    parcels.push_back(std::move(p));
  }
  std::vector<TableSlot> body_slots = std::move(body_to[me]), driver_slots = std::move(driver_to[me]);
  for (const Parcel& p : link.deliver(std::move(parcels))) {
    std::size_t at = 0;
    for (std::uint32_t b : unpack_owned(read_section<char>(p.bytes, at), bodies)) out.owned.push_back(b);
    for (const TableSlot& t : read_section<TableSlot>(p.bytes, at)) body_slots.push_back(t);
    for (const TableSlot& t : read_section<TableSlot>(p.bytes, at)) driver_slots.push_back(t);
  }
  std::sort(out.owned.begin(), out.owned.end());
  out.body_table = table_of(std::move(body_slots));  // each pair's slots from one rank: the old owner of i
  out.driver_table = table_of(std::move(driver_slots));
  return out;
}

GhostPlan share_ghosts(const RankLink& link, const DomainCut& cut, std::vector<std::uint32_t> owned, double halo,
                       Bodies& bodies) {
  const int me = link.rank();
  GhostPlan plan;
  plan.send.resize(link.ranks());
  plan.receive.resize(link.ranks());
  const std::vector<int> near = near_parts(cut, me, halo);
  for (std::uint32_t b : owned)
    for (int q : near)
      if (cut.distance(q, bodies.position[b]) < halo) plan.send[q].push_back(b);
  std::vector<Parcel> parcels;
  for (int q : near) {
    if (plan.send[q].empty()) continue;
    Parcel p{q, {}};
    append_section(p.bytes, plan.send[q]);
    append_bytes(p.bytes, pack_ghosts(bodies, plan.send[q]));
    parcels.push_back(std::move(p));
  }
  std::vector<std::pair<std::uint32_t, std::uint8_t>> local;  // (id, ghost)
  for (std::uint32_t b : owned) local.push_back({b, 0});
  for (const Parcel& p : link.deliver(std::move(parcels))) {
    std::size_t at = 0;
    plan.receive[p.rank] = read_section<std::uint32_t>(p.bytes, at);
    unpack_ghosts(read_section<char>(p.bytes, at), plan.receive[p.rank], bodies);
    for (std::uint32_t b : plan.receive[p.rank]) local.push_back({b, 1});
  }
  std::sort(local.begin(), local.end());
  for (const auto& [b, ghost] : local) {
    plan.local.push_back(b);
    plan.ghost.push_back(ghost);
  }
  plan.owned = std::move(owned);
  return plan;
}

long least_over_ranks(const RankLink& link, long mine) {
  std::vector<char> bytes;
  append_record(bytes, std::int64_t(mine));
  long least = -1;
  for (const std::vector<char>& from : link.all_gather(bytes)) {
    std::int64_t b = -1;
    std::memcpy(&b, from.data(), sizeof b);
    if (b >= 0 && (least < 0 || b < least)) least = long(b);
  }
  return least;
}

}  // namespace polydem
