#pragma once
// Recursive coordinate bisection (issue 20): the domain cut into one box per rank, each box
// holding an equal share of the bodies' weight (their measured contact work, so a pour's bed
// and its falling grains cost each rank alike). Each level halves the ranks (ceil(log2 N)
// levels; N = 2 is one plane, the slab cut): a plane across the longest side of the part's
// body centres, at the weighted quantile of the ranks on its lower side. A part owns the
// bodies whose centre lies in its box and sees as ghosts the bodies within the halo of it
// (sim/ghost_plan.hpp). Boxes are open to infinity at the domain's outside, so a body
// leaving the centres' bounding box between rebuilds keeps an owner.
#include <cstdint>
#include <vector>

#include "polydem/math.hpp"

namespace polydem {

struct PartBox {
  Vec3 lo, hi;  // m: the part holds lo <= x < hi on each axis (infinite at the outside)
};

struct DomainCut {
  // A plane x[axis] = at; children below and above it: a node's index, or -1 - part.
  struct Node {
    int axis;
    double at;  // m
    int lower, upper;
  };
  std::vector<Node> nodes;     // nodes[0] the root; empty: one part
  std::vector<PartBox> boxes;  // per part

  int parts() const { return int(boxes.size()); }
  int owner(const Vec3& x) const;
  // m, how far x lies outside part p's box (0 inside): Euclidean, the least distance from
  // x to any centre the part may own.
  double distance(int p, const Vec3& x) const;
};

// Cuts the centres `x` into `parts` boxes of equal shares of `weight` (one per body, > 0):
// the same cut for the same centres and weights, on every rank.
DomainCut cut_domain(const std::vector<Vec3>& x, const std::vector<double>& weight, int parts);

// Each part's sum of the weights of the bodies whose centre it holds.
std::vector<double> part_loads(const DomainCut& cut, const std::vector<Vec3>& x, const std::vector<double>& weight);
// The largest load over the mean (1: balanced; a rank's step waits for the most loaded).
double imbalance(const std::vector<double>& loads);

// When to cut again (ski rental): while a cut is kept, every step waits for its most loaded part's
// excess over the mean (instructions); a new cut costs about `cost` instructions (the sample
// gathered and cut, the movers sent and their pairs searched again). Cutting once the loss since
// the last cut passes the cost loses at most twice what the best schedule of cuts would, so a
// noisy load cuts again only when its imbalance lasts. `floor`: no cut at or below this imbalance.
struct RecutRule {
  double floor = 1.05;
  double lost = 0.0;  // instructions lost to the imbalance since the last cut
  // Adds `steps` steps at `loads` (the parts' loads, instructions a step); true when a new cut pays.
  bool pays(const std::vector<double>& loads, std::size_t steps, double cost);
  void cut() { lost = 0.0; }
};

// m, the halo that holds every partner of an owned body: a pair is listed when its centres
// are closer than R_i + R_j + range, R the bounding radii, range the skin and cohesion band.
double ghost_halo(double max_bounding_radius, double range);

}  // namespace polydem
