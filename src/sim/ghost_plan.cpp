#include "sim/ghost_plan.hpp"

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

}  // namespace polydem
