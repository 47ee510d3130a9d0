#pragma once
// Slab decomposition: the domain cut across its longest side into parts holding equal numbers
// of bodies, a part owning the bodies whose centre lies in its slab; each part also sees, as
// ghosts, the bodies within `halo` of its slab (the pairs its owned bodies may form:
// sim/ghost_plan.hpp).
#include <vector>

#include "polydem/math.hpp"

namespace polydem {

struct Slabs {
  int axis = 0;              // 0, 1, 2: x, y, z
  std::vector<double> cuts;  // m, increasing: part p holds cuts[p-1] <= x[axis] < cuts[p]

  int parts() const { return int(cuts.size()) + 1; }
  int owner(const Vec3& x) const;
  // m, how far x lies outside part p's slab (0 inside).
  double distance(int p, const Vec3& x) const;
};

// Cuts the centres `x` into `parts` slabs along the longest side of their bounding box, at
// coordinates of the bodies of rank k n / parts (the same cuts for the same centres).
Slabs cut_slabs(const std::vector<Vec3>& x, int parts);

// m, the halo that holds every partner of an owned body: a pair is listed when its centres
// are closer than R_i + R_j + range, R the bounding radii, range the skin and cohesion band.
double ghost_halo(double max_bounding_radius, double range);

}  // namespace polydem
