#include "sim/rank_landing.hpp"

#include <algorithm>

#include "sim/body_exchange.hpp"

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

// What goes to one rank.
struct Outgoing {
  std::vector<std::uint32_t> rows;  // store rows
  std::vector<TableSlot> body, driver;
};

}  // namespace

Handover land_share(const RankLink& link, const DomainCut& cut, double halo, const LandedShare& share) {
  const int me = link.rank();
  const LocalStore& store = share.store;
  std::vector<Outgoing> to(link.ranks());
  for (std::uint32_t k = 0; k < store.size(); ++k) to[cut.owner(store.position[k])].rows.push_back(k);
  for (const TableSlot& t : share.driver) to[cut.owner(store.position[store.local_of(t.i)])].driver.push_back(t);
  for (const TableSlot& t : share.body) {
    const Vec3& x = store.position[store.local_of(t.i)];
    const int owner = cut.owner(x);
    to[owner].body.push_back(t);
    for (int q : ghost_holders(cut, owner, x, halo)) to[q].body.push_back(t);
  }
  std::vector<Parcel> parcels;
  for (int q = 0; q < link.ranks(); ++q) {
    if (q == me || (to[q].rows.empty() && to[q].body.empty() && to[q].driver.empty())) continue;
    Parcel p{q, {}};
    const std::vector<char> movers = pack_movers(store, to[q].rows);
    append_section(p.bytes, movers);
    append_section(p.bytes, to[q].body);
    append_section(p.bytes, to[q].driver);
    parcels.push_back(std::move(p));
  }
  Handover out;
  out.owned.append(store, to[me].rows);
  std::vector<TableSlot> body = std::move(to[me].body), driver = std::move(to[me].driver);
  for (const Parcel& p : link.deliver(std::move(parcels))) {
    std::size_t at = 0;
    unpack_movers(read_section<char>(p.bytes, at), out.owned);
    for (const TableSlot& t : read_section<TableSlot>(p.bytes, at)) body.push_back(t);
    for (const TableSlot& t : read_section<TableSlot>(p.bytes, at)) driver.push_back(t);
  }
  out.owned.sort_by_id();
  const std::vector<std::uint32_t>& owned = out.owned.global_id;
  std::erase_if(body, [&](const TableSlot& t) { return !holds(owned, t.i) && !holds(owned, t.j); });
  out.body_table = table_of(std::move(body));  // each pair's slots from one rank: the reader of i's piece
  out.driver_table = table_of(std::move(driver));
  return out;
}

}  // namespace polydem
