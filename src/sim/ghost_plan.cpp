#include "sim/ghost_plan.hpp"

#include <algorithm>

namespace polydem {

GhostPlan plan_ghosts(const DomainCut& cut, int p, const std::vector<Vec3>& x, double halo) {
  const int ranks = cut.parts();
  GhostPlan plan;
  plan.send.resize(ranks);
  plan.receive.resize(ranks);
  for (std::uint32_t b = 0; b < x.size(); ++b) {
    const int owner = cut.owner(x[b]);
    if (owner == p) {
      plan.local.push_back(b);
      plan.ghost.push_back(0);
      plan.owned.push_back(b);
      for (int q = 0; q < ranks; ++q)
        if (q != p && cut.distance(q, x[b]) < halo) plan.send[q].push_back(b);
    } else if (cut.distance(p, x[b]) < halo) {  // a ghost: within the halo of p's box
      plan.local.push_back(b);
      plan.ghost.push_back(1);
      plan.receive[owner].push_back(b);
    }
  }
  return plan;
}

namespace {

// `rows` sorted, each once.
void sort_unique(std::vector<std::uint32_t>& rows) {
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
}

}  // namespace

PairedRows paired_across(const std::vector<BodyPair>& pairs, const std::vector<int>& owner, int ranks) {
  PairedRows rows;
  rows.send.resize(ranks);
  rows.receive.resize(ranks);
  for (const BodyPair& p : pairs) {
    const int oi = owner[p.i], oj = owner[p.j];
    if ((oi < 0) == (oj < 0)) continue;  // both owned (or both ghosts: their owners' pair)
    const std::uint32_t mine = oi < 0 ? p.i : p.j, theirs = oi < 0 ? p.j : p.i;
    const int q = std::max(oi, oj);
    rows.send[q].push_back(mine);
    rows.receive[q].push_back(theirs);
  }
  for (int q = 0; q < ranks; ++q) {
    sort_unique(rows.send[q]);
    sort_unique(rows.receive[q]);
  }
  return rows;
}

}  // namespace polydem
