#include "sim/domain_cut.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace polydem {

int DomainCut::owner(const Vec3& x) const {
  if (nodes.empty()) return 0;
  int at = 0;
  while (at >= 0) at = x[nodes[at].axis] < nodes[at].at ? nodes[at].lower : nodes[at].upper;
  return -1 - at;
}

double DomainCut::distance(int p, const Vec3& x) const {
  const PartBox& b = boxes[p];
  const Vec3 out = (b.lo - x).cwiseMax(x - b.hi).cwiseMax(Vec3::Zero());  // m, per axis (infinities give 0)
  return out.norm();
}

namespace {

// The longest side of the centres `ids`' bounding box (x for none).
int longest_axis(const std::vector<Vec3>& x, const std::vector<std::uint32_t>& ids) {
  if (ids.empty()) return 0;
  Vec3 lo = x[ids[0]], hi = x[ids[0]];
  for (std::uint32_t b : ids) {
    lo = lo.cwiseMin(x[b]);
    hi = hi.cwiseMax(x[b]);
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  return axis;
}

// m, the plane that leaves the share `lower_parts / parts` of the weight of `ids` (sorted
// along `axis`) below it: between two distinct coordinates (a layer of equal ones stays on
// one side), where the weight below is nearest that share.
double weighted_cut(const std::vector<Vec3>& x, const std::vector<double>& w, const std::vector<std::uint32_t>& ids,
                    int axis, int lower_parts, int parts) {
  double total = 0.0;
  for (std::uint32_t b : ids) total += w[b];
  const double target = total * double(lower_parts) / double(parts);
  double below = 0.0, best_miss = std::numeric_limits<double>::infinity();
  std::size_t best = 0;  // all coordinates equal: every body above
  for (std::size_t k = 1; k < ids.size(); ++k) {
    below += w[ids[k - 1]];
    if (x[ids[k - 1]][axis] == x[ids[k]][axis]) continue;
    const double miss = std::abs(below - target);
    if (miss < best_miss) best = k, best_miss = miss;
  }
  return x[ids[best]][axis];
}

// Cuts the bodies `ids` inside `box` among the parts [first, first + parts); returns the
// subtree's code (a node's index, or -1 - part).
int bisect(const std::vector<Vec3>& x, const std::vector<double>& w, std::vector<std::uint32_t> ids, int first,
           int parts, const PartBox& box, DomainCut& cut) {
  if (parts == 1) {
    cut.boxes[first] = box;
    return -1 - first;
  }
  const int lower_parts = parts / 2;
  const int axis = longest_axis(x, ids);
  std::sort(ids.begin(), ids.end(), [&](std::uint32_t a, std::uint32_t b) {
    return x[a][axis] != x[b][axis] ? x[a][axis] < x[b][axis] : a < b;
  });
  const double at = ids.empty() ? std::clamp(0.0, box.lo[axis], box.hi[axis])  // m, no bodies: any plane in the box
                                : weighted_cut(x, w, ids, axis, lower_parts, parts);
  const auto split = std::partition_point(ids.begin(), ids.end(), [&](std::uint32_t b) { return x[b][axis] < at; });
  PartBox below = box, above = box;
  below.hi[axis] = above.lo[axis] = at;
  const int node = int(cut.nodes.size());
  cut.nodes.push_back({axis, at, 0, 0});
  const int lower = bisect(x, w, std::vector<std::uint32_t>(ids.begin(), split), first, lower_parts, below, cut);
  const int upper = bisect(x, w, std::vector<std::uint32_t>(split, ids.end()), first + lower_parts,
                           parts - lower_parts, above, cut);
  cut.nodes[node].lower = lower;
  cut.nodes[node].upper = upper;
  return node;
}

}  // namespace

DomainCut cut_domain(const std::vector<Vec3>& x, const std::vector<double>& weight, int parts) {
  DomainCut cut;
  const double inf = std::numeric_limits<double>::infinity();
  cut.boxes.resize(std::max(parts, 1), PartBox{Vec3::Constant(-inf), Vec3::Constant(inf)});
  if (parts < 2) return cut;
  std::vector<std::uint32_t> ids(x.size());
  for (std::uint32_t b = 0; b < ids.size(); ++b) ids[b] = b;
  bisect(x, weight, std::move(ids), 0, parts, cut.boxes[0], cut);
  return cut;
}

std::vector<double> part_loads(const DomainCut& cut, const std::vector<Vec3>& x, const std::vector<double>& weight) {
  std::vector<double> loads(cut.parts(), 0.0);
  for (std::size_t b = 0; b < x.size(); ++b) loads[cut.owner(x[b])] += weight[b];
  return loads;
}

double imbalance(const std::vector<double>& loads) {
  double total = 0.0, most = 0.0;
  for (double l : loads) {
    total += l;
    most = std::max(most, l);
  }
  return total > 0.0 ? most * double(loads.size()) / total : 1.0;
}

bool RecutRule::pays(const std::vector<double>& loads, std::size_t steps, double cost) {
  double total = 0.0, most = 0.0;
  for (double l : loads) {
    total += l;
    most = std::max(most, l);
  }
  lost += (most - total / double(std::max<std::size_t>(loads.size(), 1))) * double(steps);
  return imbalance(loads) > floor && lost > cost;
}

// A part in a million over the reach: the box distance and the pair test round differently.
double ghost_halo(double max_bounding_radius, double range) { return (2.0 * max_bounding_radius + range) * (1.0 + 1e-6); }

}  // namespace polydem
