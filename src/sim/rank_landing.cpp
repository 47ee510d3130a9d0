#include "sim/rank_landing.hpp"

#include <algorithm>

namespace polydem {

namespace {

// The ranks other than `owner` whose box lies within `halo` of x: those that hold x's body as a ghost.
std::vector<int> ghost_holders(const DomainCut& cut, int owner, const Vec3& x, double halo) {
  std::vector<int> holders;
  for (int q = 0; q < cut.parts(); ++q)
    if (q != owner && cut.distance(q, x) < halo) holders.push_back(q);
  return holders;
}

bool holds(const std::vector<std::uint32_t>& increasing, std::uint32_t g) {
  return std::binary_search(increasing.begin(), increasing.end(), g);
}

}  // namespace

Handover land_share(const RankLink& link, const DomainCut& cut, double halo, const LandedShare& share) {
  Handover out = migrate(link, cut, share.store, {}, share.driver);  // the bodies and their driver slots
  // Then the body slots, whose other body this rank may not hold (migrate reads both bodies').
  const LocalStore& store = share.store;
  std::vector<std::vector<TableSlot>> to(link.ranks());
  for (const TableSlot& t : share.body) {
    const Vec3& x = store.position[store.local_of(t.i)];
    const int owner = cut.owner(x);
    to[owner].push_back(t);
    for (int q : ghost_holders(cut, owner, x, halo)) to[q].push_back(t);
  }
  std::vector<TableSlot> body = std::move(to[link.rank()]);
  std::vector<Parcel> parcels;
  for (int q = 0; q < link.ranks(); ++q)
    if (q != link.rank() && !to[q].empty()) {
      parcels.push_back({q, {}});
      append_section(parcels.back().bytes, to[q]);
    }
  for (const Parcel& p : link.deliver(std::move(parcels))) {
    std::size_t at = 0;
    for (const TableSlot& t : read_section<TableSlot>(p.bytes, at)) body.push_back(t);
  }
  const std::vector<std::uint32_t>& owned = out.owned.global_id;
  std::erase_if(body, [&](const TableSlot& t) { return !holds(owned, t.i) && !holds(owned, t.j); });
  out.body_slots = std::move(body);  // each pair's slots from one rank: the reader of i's piece
  return out;
}

}  // namespace polydem
